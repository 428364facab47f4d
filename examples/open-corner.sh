#!/bin/sh
# The thesis' example scenario (ch. 10, SPEC 14): the crease pattern of an open corner (a
# corner-cube retro-reflector), built with the CLI the way the thesis' tool does it: MiddleH on
# the uncreased sheet, MiddleV on both halves, DiagonalL on the lower-left element, then the
# mountain-valley assignment: four valleys and one mountain, the left half of the horizontal
# middle crease. Five creases meet at the centre (1,1) with sector angles 45, 45, 90, 90, 90.
#
# usage: examples/open-corner.sh [ORIKIN [OUT.fold]]
#   ORIKIN    the orikin binary (default build/orikin)
#   OUT.fold  where to write (default examples/patterns/open-corner.fold beside this script)
set -eu
ORIKIN=${1:-build/orikin}
OUT=${2:-$(dirname "$0")/patterns/open-corner.fold}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$ORIKIN" new --square 2 -o "$tmp/sheet.fold" \
    --title "Open corner (corner-cube retro-reflector)" \
    --description "Thesis example scenario (SPEC 14), built by examples/open-corner.sh: a 2x2 sheet creased with MiddleH, MiddleV on both halves and DiagonalL on the lower-left element; five creases around the centre (1,1) with sector angles 45, 45, 90, 90, 90 degrees; four valleys and one mountain (the left half of the horizontal middle crease)."
# MiddleH: Obj1 -> Obj11 (upper half), Obj12 (lower half)
"$ORIKIN" apply "$tmp/sheet.fold" --pattern middle-h --face Obj1 --assign V -o "$tmp/1.fold"
# MiddleV on both halves: Obj11 -> Obj111 (upper left), Obj112; Obj12 -> Obj121 (lower left), Obj122
"$ORIKIN" apply "$tmp/1.fold" --pattern middle-v --face Obj11 --assign V -o "$tmp/2.fold"
"$ORIKIN" apply "$tmp/2.fold" --pattern middle-v --face Obj12 --assign V -o "$tmp/3.fold"
# DiagonalL on the lower-left element: Obj121 -> Obj1211 (above the diagonal), Obj1212
"$ORIKIN" apply "$tmp/3.fold" --pattern diagonal-left --face Obj121 --assign V -o "$tmp/4.fold"
# The mountain: the left half of the horizontal middle crease, the edge through (0.5, 1).
"$ORIKIN" edit "$tmp/4.fold" --assign @0.5,1=M -o "$tmp/5.fold"
"$ORIKIN" info "$tmp/5.fold"
cp "$tmp/5.fold" "$OUT"
