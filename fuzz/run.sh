#!/bin/sh
# Run every fuzz target for SECONDS each, seeded from the repository's FOLD examples and test drawings.
set -eu
BUILD=$1
SECONDS_EACH=${2:-60}
corpus=fuzz/corpus-run
rm -rf "$corpus"
mkdir -p "$corpus/fold"
cp examples/patterns/*.fold "$corpus/fold/" 2>/dev/null || true
cp tests/data/*.fold "$corpus/fold/" 2>/dev/null || true
for ext in svg opx cp; do
    mkdir -p "$corpus/$ext"
    cp tests/data/formats/*."$ext" "$corpus/$ext/" 2>/dev/null || true
done
for t in "$BUILD"/fuzz/fuzz_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t" | sed 's/^fuzz_//')
    dir="$corpus/$name"
    mkdir -p "$dir"
    echo "fuzz: $name for ${SECONDS_EACH}s"
    ASAN_OPTIONS=detect_leaks=1 "$t" -max_total_time="$SECONDS_EACH" -max_len=65536 \
        -print_final_stats=1 "$dir" 2>&1 | tail -n 12
done
