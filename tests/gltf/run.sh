#!/bin/sh
# glTF and GLB files written by `orikin export` pass the Khronos glTF validator (npm
# gltf-validator) with no errors: a static sheet, a thick solid, a sequence's and a fold's
# animation, a folded Miura-ori, a compliant fold's frame with strain vertex colours (COLOR_0),
# a compliant fold's motion as morph targets. Skipped (exit 77) when node or node_modules is missing.
#
# usage: tests/gltf/run.sh ORIKIN ROOT
set -u
ORIKIN=$1
ROOT=$2
cd "$ROOT" || exit 1
if ! command -v node >/dev/null 2>&1; then
    echo "skipped: node is not installed (make deps installs it)"
    exit 77
fi
if [ ! -f node_modules/gltf-validator/package.json ]; then
    echo "skipped: node_modules/gltf-validator is missing (make deps runs npm ci)"
    exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
export_to() {
    if ! "$ORIKIN" export "$@" >/dev/null; then
        echo "FAIL: orikin export $*"
        fail=1
    fi
}
export_to examples/open-corner.seq.json --at 0.5 -o "$tmp/corner.gltf"
export_to examples/open-corner.seq.json --thickness 0.05 -o "$tmp/corner-thick.glb"
export_to examples/open-corner.seq.json --animate -o "$tmp/corner-animated.gltf"
export_to examples/open-corner.seq.json --animate -o "$tmp/corner-animated.glb"
export_to examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 90 --animate -o "$tmp/fold.glb"
"$ORIKIN" generate miura --rows 6 --cols 6 -o "$tmp/miura.fold" >/dev/null || fail=1
export_to "$tmp/miura.fold" --fix 0 --drive 66 --to -120 -o "$tmp/miura.glb"
"$ORIKIN" fold examples/patterns/open-corner.fold --compliant --percent 40 -o "$tmp/compliant.fold" >/dev/null || fail=1
export_to "$tmp/compliant.fold" --frame 1 -o "$tmp/compliant-strain.gltf"
export_to "$tmp/compliant.fold" --frame 1 --thickness 0.05 -o "$tmp/compliant-strain-thick.glb"
if ! grep -q '"COLOR_0"' "$tmp/compliant-strain.gltf"; then
    echo "FAIL: the compliant frame's glTF has no COLOR_0"
    fail=1
fi
export_to examples/patterns/open-corner.fold --compliant --percent 40 --animate -o "$tmp/compliant-morph.glb"
export_to examples/patterns/open-corner.fold --compliant --percent 40 --dynamic --animate -o "$tmp/compliant-morph.gltf"
if ! grep -q '"targets"' "$tmp/compliant-morph.gltf"; then
    echo "FAIL: the compliant motion's glTF has no morph targets"
    fail=1
fi
node tests/gltf/validate.js "$tmp"/*.gltf "$tmp"/*.glb || fail=1
exit $fail
