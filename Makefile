# Thin wrapper over CMake: the README's two commands (make demo, make check) and friends.
BUILD      ?= build
BUILD_ASAN ?= build-asan
BUILD_FUZZ ?= build-fuzz
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
FUZZ_SECONDS ?= 60

.PHONY: all build deps demo check check-asan bench fuzz fuzz-run fuzz-long install clean

all: build

deps:
	@sh scripts/install-deps.sh

build:
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

demo: deps build
	@sh examples/demo.sh $(BUILD)/orikin

check: deps build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

check-asan: deps
	@cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=Debug -DORI_SANITIZE=ON >/dev/null
	@cmake --build $(BUILD_ASAN) -j $(JOBS)
	@ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(BUILD_ASAN) --output-on-failure -j $(JOBS)

bench: build
	@$(BUILD)/bench/orikin_bench

fuzz:
	@CC=clang CXX=clang++ cmake -S . -B $(BUILD_FUZZ) -DCMAKE_BUILD_TYPE=Debug -DORI_FUZZ=ON -DORI_TESTS=OFF >/dev/null
	@cmake --build $(BUILD_FUZZ) -j $(JOBS) --target fuzzers

fuzz-run: fuzz
	@sh fuzz/run.sh $(BUILD_FUZZ) $(FUZZ_SECONDS)

# Hour-long runs outside CI (an hour per target by default; FUZZ_LONG_SECONDS to change).
FUZZ_LONG_SECONDS ?= 3600
fuzz-long: fuzz
	@FUZZ_BUDGET=1000000 sh fuzz/run.sh $(BUILD_FUZZ) $(FUZZ_LONG_SECONDS)

install: build
	@cmake --install $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(BUILD_FUZZ)
