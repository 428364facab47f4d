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

step "6. Pictures, animation and mesh of the fold (thesis ch. 9.6): orikin render, animate, export"
run 0 render examples/open-corner.seq.json --yaw 90 --grid -o "$OUT/corner-cube.png"
run 0 render examples/open-corner.seq.json --yaw 90 -o "$OUT/corner-cube.svg"
run 0 animate examples/open-corner.seq.json --yaw 90 --grid -o "$OUT/open-corner.gif"
run 0 export examples/open-corner.seq.json --animate -o "$OUT/open-corner.glb"
echo "The folded corner cube: $OUT/corner-cube.png (picture) and $OUT/corner-cube.svg (vector);"
echo "the two folds: $OUT/open-corner.gif (animation) and $OUT/open-corner.glb (glTF, one node per face)."
echo
# --- self-collision (docs/collision.md) --------------------------------------------------------
step "7. Self-collision along the motion: the open corner folds clean, two flaps collide"
echo "(every fold and sequence is checked by default; the first contact is located to 1e-6 deg)"
run 0 sequence examples/open-corner.seq.json --json >"$OUT/open-corner-sequence.json"
grep -o '"verdict":"valid"' "$OUT/open-corner-sequence.json" >/dev/null || {
    echo "demo: the open corner's sequence should be clean" >&2
    failed=1
}
echo "(open corner: verdict valid, \"collision\": null in $OUT/open-corner-sequence.json)"
echo
run 1 sequence examples/two-flaps.seq.json
run 1 fold examples/patterns/two-flaps.fold --frame 1 --fix 1 --drive 8 --lock 7 --to 180 --json \
    >"$OUT/two-flaps-fold.json"
grep -o '"collision":{[^}]*}' "$OUT/two-flaps-fold.json" || failed=1
echo
run 1 collide tests/data/collide-flaps-crossing.fold
# --- mech: hinges, Lorentz actuation and folding dynamics (issue 11) ---------------------------
step "8. Hinges, Lorentz-force actuation and folding dynamics (thesis ch. 2.2.2, 2.3, 5.3)"
echo "(the thesis' flap: 500 x 500 x 10 um silicon on a 0.6 um gold hinge, 20 mA in 0.1 T)"
run 0 actuate examples/patterns/thesis-flap.fold --fix 0 --drive 0 --to 180 --step 15
run 0 simulate examples/patterns/thesis-flap.fold --fix 0 --current 0.02 --duration 0.006 --frames 13 \
    -o "$OUT/thesis-flap-folding.fold"
echo "(the open corner with gold hinges, folded as the thesis does: two folds, one wire each)"
run 0 actuate examples/open-corner-gold.seq.json
run 0 simulate examples/open-corner-gold.seq.json --current 0.02 --duration 0.012 --damping 0.2 --frames 13 \
    -o "$OUT/open-corner-gold-folding.fold"
echo "(the sized device to its fabrication files: the lithography mask with its layer map, a laser"
echo " cutter's SVG of the paper model, and the tolerance of the first fold to 1 um vertex errors)"
run 0 fab examples/patterns/open-corner-gold.fold --fix 4 -o "$OUT/open-corner-gold.gds"
run 0 fab examples/patterns/open-corner.fold --scale 50 -o "$OUT/open-corner-laser.svg"
run 0 tolerance examples/patterns/open-corner-gold.fold --vertex-sigma 1um --fix 4 --drive 12 --lock 11 --to 90 \
    --step 10 --samples 200
# --- io: finding faces and edges; drawings from other tools ----------------------------------
step "9. Finding faces and edges by index and name; drawings in and out"
run 0 info "$OUT/open-corner.fold" --faces --edges
run 0 convert "$OUT/open-corner.fold" "$OUT/open-corner-labelled.svg" --labels all
run 0 convert tests/data/formats/bird.cp "$OUT/bird.fold"
run 0 generate miura --rows 4 --cols 6 -o "$OUT/miura.svg"

# --- layers (global flat-foldability) ---------------------------------------------------------
step "10. Global flat-foldability: every flat-folded state (layer order) of a Yoshimura pattern"
run 0 generate yoshimura --rows 4 --cols 4 -o "$OUT/yoshimura.fold"
run 0 layers "$OUT/yoshimura.fold" --svg "$OUT/yoshimura-layers.svg"
run 1 layers examples/patterns/non-flat-foldable-vertex.fold


# --- several degrees of freedom, and where a fold stops ----------------------------------------
step "11. Several degrees of freedom: a waterbomb folded toward its targets; a fold that stops; a rounded drawing made exact"
run 0 generate waterbomb --rows 4 --cols 4 -o "$OUT/waterbomb.fold"
run 0 fold "$OUT/waterbomb.fold" --fix 0 --percent 100 --step 25 -o "$OUT/waterbomb-folded.fold"
run 0 fold tests/data/waterbomb-base.fold --fix 0 --drive 12 --to 60 --symmetric --step 30
run 1 fold tests/data/kin-issue14-vertex.fold --fix 3 --drive 10 --to -180 --step 60 -o "$OUT/blocked.fold"
# a drawing with rounded coordinates is rigid; moved by 2e-5 of its size it folds all the way
run 1 fold tests/data/rounded-miura.fold --fix 0 --percent 100
run 0 regularize tests/data/rounded-miura.fold --rigid -o "$OUT/miura-exact.fold"
run 0 fold "$OUT/miura-exact.fold" --fix 0 --percent 100

# --- unfolding ------------------------------------------------------------------------------------
step "12. Unfolding: a cube to its 11 nets and back; a folded Miura-ori back to its crease pattern; a polygon convexified (Streinu)"
run 0 unfold tests/data/unfold/cube.obj --all -o "$OUT/cube-net.fold" --svg "$OUT/cube-net.svg"
run 0 export tests/data/miura-4x4.fold --fix 0 --drive 4 --to 60 -o "$OUT/miura-folded.obj"
run 0 unfold "$OUT/miura-folded.obj" -o "$OUT/miura-cp.fold"
run 0 check "$OUT/miura-cp.fold"
run 0 unfold-linkage tests/data/unfold/star.fold -o "$OUT/star-motion.fold"

# --- studio (orikin view) -----------------------------------------------------------------
step "13. The studio: the thesis' GUI in the browser (orikin view, started and stopped here)"
echo "\$ orikin view examples/open-corner.seq.json --port 0 --no-browser"
"$ORIKIN" view examples/open-corner.seq.json --port 0 --no-browser >"$OUT/view.out" 2>&1 &
view_pid=$!
i=0
while [ $i -lt 100 ] && ! grep -q "^orikin view: http" "$OUT/view.out"; do
    sleep 0.1
    i=$((i + 1))
done
if grep -q "^orikin view: http" "$OUT/view.out"; then
    echo "(it served the open corner's two folds; stopped)"
else
    cat "$OUT/view.out"
    echo "demo: orikin view did not start" >&2
    failed=1
fi
kill -INT "$view_pid" 2>/dev/null
wait "$view_pid" || failed=1
echo
if [ "$failed" -ne 0 ]; then
    echo "demo: some step did not give the expected result" >&2
    exit 1
fi
echo "The folded open corner (every step as a FOLD frame) is in $OUT/open-corner-folded.fold."
echo "The simulated foldings (frames with frame_time) are in $OUT/thesis-flap-folding.fold and $OUT/open-corner-gold-folding.fold."
echo
echo "Open the studio on the open corner (author, check, fold and scrub the sequence in your browser;"
echo "Ctrl-C stops it):"
echo "    $ORIKIN view examples/open-corner.seq.json"
echo "or on the simulated flap, whose frames it plays in real time (seconds):"
echo "    $ORIKIN view $OUT/thesis-flap-folding.fold"
