#!/bin/sh
# make demo: the main job on the built-in examples.
set -eu
ORIKIN=${1:-build/orikin}
for f in examples/patterns/*.fold; do
    "$ORIKIN" info "$f"
    echo
done
