#!/bin/sh
# Data-driven CLI tests. Each tests/cli/*.case file is:
#   line 1: arguments (run from the repository root; $ORIKIN is the binary)
#   line 2: expected exit code
#   rest:   text that stdout+stderr must contain, one fixed string per line (may be empty)
set -u
ORIKIN=$1
CASES=$2
ROOT=$3
cd "$ROOT" || exit 1
fail=0
total=0
for c in "$CASES"/*.case; do
    [ -e "$c" ] || continue
    total=$((total + 1))
    args=$(sed -n 1p "$c")
    want=$(sed -n 2p "$c")
    out=$(eval "\"$ORIKIN\" $args" 2>&1)
    got=$?
    if [ "$got" != "$want" ]; then
        echo "FAIL $(basename "$c"): exit $got, expected $want"
        echo "$out" | head -5
        fail=$((fail + 1))
        continue
    fi
    sed -n '3,$p' "$c" | while IFS= read -r line; do
        [ -z "$line" ] && continue
        if ! printf '%s\n' "$out" | grep -qF -- "$line"; then
            echo "FAIL $(basename "$c"): output lacks: $line"
            echo "$out" | head -5
            exit 1
        fi
    done || fail=$((fail + 1))
done
echo "cli cases: $((total - fail))/$total passed"
[ "$fail" -eq 0 ]
