#!/bin/sh
# Run every fuzz target for SECONDS each, seeded from the repository's FOLD examples and test
# data. Fails when a target reports a crash, leak or sanitizer error.
set -eu
BUILD=$1
SECONDS_EACH=${2:-60}
corpus=fuzz/corpus-run
rm -rf "$corpus"
mkdir -p "$corpus"
status=0
for t in "$BUILD"/fuzz/fuzz_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t" | sed 's/^fuzz_//')
    dir="$corpus/$name"
    mkdir -p "$dir"
    # seeds: fuzz/seeds/<name>/* plus files with the target's extension from examples and tests
    [ -d "fuzz/seeds/$name" ] && cp fuzz/seeds/"$name"/* "$dir"/ 2>/dev/null || true
    for f in examples/patterns/*."$name" tests/data/*."$name" tests/data/formats/*."$name"; do
        [ -e "$f" ] && cp "$f" "$dir"/
    done
    echo "fuzz: $name for ${SECONDS_EACH}s"
    log="$corpus/$name.log"
    if ASAN_OPTIONS=detect_leaks=1 "$t" -max_total_time="$SECONDS_EACH" -max_len=65536 \
        -print_final_stats=1 -artifact_prefix="$corpus/$name-" "$dir" >"$log" 2>&1; then
        grep -E "^stat::number_of_executed_units|^#[0-9]+.*DONE" "$log" | tail -n 2
    else
        tail -n 40 "$log"
        echo "fuzz: $name FAILED"
        status=1
    fi
done
exit $status
