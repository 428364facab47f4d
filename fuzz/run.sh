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
    # seeds: fuzz/seeds/<name>/* and the repository's own inputs of that kind
    case $name in
        fold) seeds="examples/patterns/*.fold tests/data/*.fold" ;;
        composite) seeds="examples/composites/*.json tests/data/*composite*.json" ;;
        sequence) seeds="examples/*.seq.json" ;;
        arrangement) seeds="" ;;
        layers) seeds="tests/data/layers/*.fold examples/patterns/*.fold" ;;
        *) seeds="tests/data/formats/*.$name" ;;
    esac
    for f in fuzz/seeds/"$name"/* $seeds; do
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
