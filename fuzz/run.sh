#!/bin/sh
# Run every fuzz target (or the ones named after BUILD) seeded from the repository's examples and
# test data. Fails when a target reports a crash, leak, sanitizer error, an input slower than
# FUZZ_TIMEOUT seconds or one using more than FUZZ_RSS_MB of memory.
#
#   fuzz/run.sh BUILD [SECONDS_EACH] [TARGET...]
#
# Time: each target runs SECONDS_EACH seconds (default: FUZZ_SECONDS, else 60), but the whole run
# stays within FUZZ_BUDGET seconds (default 420, i.e. 7 minutes): with more targets than the
# budget allows at SECONDS_EACH, every target gets an equal share (at least 10 s). One target's
# time can be set with FUZZ_SECONDS_<name> (e.g. FUZZ_SECONDS_fold=120), which the budget does
# not reduce. New targets need nothing here but, optionally, a seeds line in the case below.
#
# FUZZ_SEED=N makes a run repeatable: libFuzzer's -seed=N and generated inputs drawn from N, so
# the inputs tried are a prefix of one fixed sequence however fast the machine (CI sets it; a
# random run, the default, explores further each time and belongs in fuzz-long).
#
# FUZZ_RUNS=FILE (lines "target runs") or FUZZ_RUNS_<name>=N also caps a target's inputs at N
# (libFuzzer's -runs): with FUZZ_SEED, a target then tries the same N inputs on any machine fast
# enough to finish them in its time (a slower one tries a prefix), so that a run which passed
# here passes in CI. CI uses fuzz/ci-runs (about 7 s a target on the 2-core machine).
set -eu
BUILD=$1
shift
SECONDS_EACH=${FUZZ_SECONDS:-60}
case ${1:-} in
    ''|*[!0-9]*) ;;
    *) SECONDS_EACH=$1; shift ;;
esac
BUDGET=${FUZZ_BUDGET:-420}
TIMEOUT=${FUZZ_TIMEOUT:-10}
RSS_MB=${FUZZ_RSS_MB:-2048}
SEED=${FUZZ_SEED:-}
RUNS_FILE=${FUZZ_RUNS:-}
[ -z "$RUNS_FILE" ] || [ -r "$RUNS_FILE" ] || { echo "fuzz: FUZZ_RUNS=$RUNS_FILE is not a readable file"; exit 1; }
seed_arg=""
# (-reload=0: libFuzzer otherwise re-reads the corpus directory every second, a timing-dependent input)
[ -n "$SEED" ] && seed_arg="-seed=$SEED -reload=0"
# and without address randomisation: libFuzzer's comparison dictionary picks up values compared
# in the code under test, addresses among them, so a run is repeatable only at fixed addresses
no_aslr=""
if [ -n "$SEED" ] && setarch "$(uname -m)" -R true 2>/dev/null; then no_aslr="setarch $(uname -m) -R"; fi
corpus=fuzz/corpus-run
rm -rf "$corpus"
mkdir -p "$corpus"

targets=""
for t in "$BUILD"/fuzz/fuzz_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t" | sed 's/^fuzz_//')
    if [ $# -gt 0 ]; then
        keep=no
        for want in "$@"; do [ "$want" = "$name" ] && keep=yes; done
        [ $keep = yes ] || continue
    fi
    targets="$targets $name"
done
count=$(echo $targets | wc -w)
[ "$count" -gt 0 ] || { echo "fuzz: no targets in $BUILD/fuzz"; exit 1; }
# Targets with their own time are outside the shared budget.
fixed=0
shared=0
for name in $targets; do
    own=$(eval "echo \${FUZZ_SECONDS_$name:-}")
    if [ -n "$own" ]; then fixed=$((fixed + own)); else shared=$((shared + 1)); fi
done
each=$SECONDS_EACH
if [ "$shared" -gt 0 ] && [ $((each * shared)) -gt $((BUDGET - fixed)) ]; then
    each=$(((BUDGET - fixed) / shared))
    [ "$each" -ge 10 ] || each=10
fi
echo "fuzz: $count target(s), ${each}s each (budget ${BUDGET}s), -timeout=$TIMEOUT -rss_limit_mb=$RSS_MB ${seed_arg:-(random seed)}${RUNS_FILE:+, runs from $RUNS_FILE}"

status=0
failed=""
for name in $targets; do
    t="$BUILD/fuzz/fuzz_$name"
    seconds=$(eval "echo \${FUZZ_SECONDS_$name:-$each}")
    dir="$corpus/$name"
    mkdir -p "$dir"
    extra=""
    # seeds: fuzz/seeds/<name>/* and the repository's own inputs of that kind
    case $name in
        fold) seeds="examples/patterns/*.fold tests/data/*.fold tests/data/layers/overlapping-creases.fold" ;;
        composite) seeds="examples/composites/*.json tests/data/*composite*.json" ;;
        sequence) seeds="examples/*.seq.json" ;;
        materials) seeds="data/materials.json tests/data/actuation/*.json" ;;
        design) seeds="examples/patterns/thesis-flap.fold examples/patterns/open-corner-gold.fold tests/data/actuation/*.fold" ;;
        arrangement)
            seeds=""
            # Long random inputs from the start (48 creases are 241 bytes): without them, libFuzzer's
            # gradual length growth kept inputs under 64 bytes (a dozen creases) for 8 minutes.
            i=0
            while [ $i -lt 16 ]; do
                if [ -n "$SEED" ]; then
                    python3 -c 'import random, sys; r = random.Random(int(sys.argv[1])); sys.stdout.buffer.write(bytes(r.getrandbits(8) for _ in range(int(sys.argv[2]))))' \
                        $((SEED * 16 + i)) $((64 + 16 * i)) >"$dir/random-$i"
                else
                    head -c $((64 + 16 * i)) /dev/urandom >"$dir/random-$i"
                fi
                i=$((i + 1))
            done
            extra="-max_len=512"
            ;;
        api) seeds="tests/data/server/*.req" ;;
        # raw FOLD documents (an input starting with '{') besides the generated patterns
        regularize) seeds="tests/data/rounded-miura.fold examples/patterns/degree*-vertex.fold examples/patterns/non-flat-foldable-vertex.fold" ;;
        layers) seeds="tests/data/layers/*.fold examples/patterns/*.fold" ;;
        flat) seeds="examples/patterns/*.fold tests/data/layers/*.fold" ;;
        # sweep specs (JSON); short, so that the few points a spec is checked at stay cheap
        sweep) seeds="examples/sweeps/*.json tests/data/sweep/*.json" ; extra="-max_len=4096 -dict=fuzz/sweep.dict" ;;
        # argv tokens, one a line; option names from fuzz/cli_args.dict
        cli_args) seeds="" ; extra="-max_len=1024 -dict=fuzz/cli_args.dict" ;;
        # the Python package in-process (fuzz/fuzz_python.py decodes): libFuzzer's leak check after
        # each new input scans the interpreter's whole heap (10 inputs/s instead of 130), so it is
        # off; LeakSanitizer still checks the run at exit, with the start-up excluded
        python) seeds="" ; extra="-detect_leaks=0 -max_len=4096" ;;
        *) seeds="tests/data/formats/*.$name" ;;
    esac
    for f in fuzz/seeds/"$name"/* $seeds; do
        [ -e "$f" ] && cp "$f" "$dir"/
    done
    runs=$(eval "echo \${FUZZ_RUNS_$name:-}")
    if [ -z "$runs" ] && [ -n "$RUNS_FILE" ]; then
        runs=$(awk -v t="$name" '$1 == t { print $2 }' "$RUNS_FILE")
    fi
    [ -z "$runs" ] || extra="$extra -runs=$runs"
    echo "fuzz: $name for ${seconds}s${runs:+ or $runs inputs}"
    log="$corpus/$name.log"
    # shellcheck disable=SC2086
    if ASAN_OPTIONS=detect_leaks=1 $no_aslr "$t" -max_total_time="$seconds" -max_len=65536 -timeout="$TIMEOUT" \
        -rss_limit_mb="$RSS_MB" -print_final_stats=1 -artifact_prefix="$corpus/$name-" $seed_arg $extra "$dir" >"$log" 2>&1; then
        grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE" "$log" | tail -n 3
    else
        tail -n 40 "$log"
        echo "fuzz: $name FAILED"
        failed="$failed $name"
        status=1
    fi
done
# CI shows only the end of its output: name what failed there, with each failure's first report
# line and the input that caused it (kept in fuzz/corpus-run).
if [ $status -ne 0 ]; then
    for name in $failed; do
        why=$(grep -m 1 -E "ERROR: |==[0-9]+==|runtime error|Timeout|out-of-memory|deadly signal" \
            "$corpus/$name.log" || echo "no report line")
        echo "fuzz: FAILED $name: $why"
        for a in "$corpus/$name"-*; do
            [ -e "$a" ] || continue
            echo "fuzz:   input $a: $(head -c 200 "$a" | od -An -c | tr -s ' ' | head -c 300)"
            # the whole input, to reproduce it from CI's log: base64 -d > x; build-fuzz/fuzz/fuzz_<name> x
            if [ "$(wc -c <"$a")" -le 4096 ]; then echo "fuzz:   base64 $(base64 -w 0 "$a")"; fi
        done
    done
fi
exit $status
