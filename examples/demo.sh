#!/bin/sh
# make demo: the thesis' example scenario (ch. 10, SPEC 14) with the built-in open corner —
# build the crease pattern from the crease collection, show that a wrongly oriented first axis
# is invalid, fold the valid one into the corner cube in two folds, and fit the transfer
# functions. Every step checks its exit code, so the demo doubles as a smoke test.
#
# usage: examples/demo.sh [ORIKIN [OUTDIR]]
set -u
ORIKIN=${1:-build/orikin}
OUT=${2:-build/demo}
mkdir -p "$OUT"
failed=0

# run EXPECTED-EXIT COMMAND...: run a command, show it, and check its exit code.
run() {
    want=$1
    shift
    echo "\$ orikin $*"
    "$ORIKIN" "$@"
    got=$?
    if [ "$got" -ne "$want" ]; then
        echo "demo: expected exit $want, got $got" >&2
        failed=1
    fi
    echo
}

step() {
    echo "================================================================================"
    echo "$1"
    echo "================================================================================"
}

step "1. The open corner crease pattern, built with the crease collection (thesis fig. 10-1)"
echo "\$ sh examples/open-corner.sh (new --square 2; apply middle-h, middle-v, diagonal-left; edit)"
sh examples/open-corner.sh "$ORIKIN" "$OUT/open-corner.fold" >/dev/null || failed=1
run 0 tree "$OUT/open-corner.fold"
run 1 check "$OUT/open-corner.fold"

step "2. A wrongly oriented first axis is invalid (thesis fig. 10-2)"
run 0 edit "$OUT/open-corner.fold" --flip @0.5,0.5 -o "$OUT/open-corner-wrong.fold"
run 1 fold "$OUT/open-corner-wrong.fold" --fix 4 --drive 12 --lock 11 --to -90 --step 30

step "3. The valid assignment folds from flat into the corner cube in two folds (fig. 10-3)"
run 0 fold "$OUT/open-corner.fold" --fix 4 --drive 12 --lock 11 --to 90 --step 90 --json \
    >"$OUT/first-fold-90.json"
echo "(first fold at 90 deg, thesis fig. 5-4: see $OUT/first-fold-90.json for Frame A/B and the end effector)"
echo
run 0 sequence examples/open-corner.seq.json -o "$OUT/open-corner-folded.fold"
run 0 sequence examples/open-corner.seq.json --at 1.5

step "4. Transfer functions of the first fold, 4th degree (thesis fig. 5-5)"
run 0 fit "$OUT/open-corner.fold" --fix 4 --drive 12 --lock 11 --to 180 --step 10 --degree 4

step "5. Flat-foldability of single vertices (thesis ch. 4.3)"
run 0 mv-count 100 70 50 40 30 70 --list
run 0 check examples/patterns/degree4-vertex.fold
run 1 check examples/patterns/non-flat-foldable-vertex.fold

# --- layers (global flat-foldability) ---------------------------------------------------------
step "Global flat-foldability: every flat-folded state (layer order) of a Yoshimura pattern"
run 0 generate yoshimura --rows 4 --cols 4 -o "$OUT/yoshimura.fold"
run 0 layers "$OUT/yoshimura.fold" --svg "$OUT/yoshimura-layers.svg"
run 1 layers examples/patterns/non-flat-foldable-vertex.fold

if [ "$failed" -ne 0 ]; then
    echo "demo: some step did not give the expected result" >&2
    exit 1
fi
echo "The folded open corner (every step as a FOLD frame) is in $OUT/open-corner-folded.fold."
