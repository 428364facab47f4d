#!/bin/sh
# Install what orikin needs to build and test. Idempotent and quiet: only Debian packages that
# are missing are installed (apt-get), and the front-end/test packages of package.json are
# installed from package-lock.json (npm ci) when node_modules is missing or older than the
# lock file. Run as root (or with sudo available).
set -eu
cd "$(dirname "$0")/.."

PACKAGES="
build-essential
cmake
pkg-config
clang
libclang-rt-14-dev
libcriterion-dev
libjansson-dev
libxml2-dev
liblapacke-dev
libopenblas-dev
libsuitesparse-dev
libcairo2-dev
libpng-dev
libgif-dev
libmicrohttpd-dev
libgmp-dev
libqhull-dev
libdouble-conversion-dev
libsqlite3-dev
openmpi-bin
libopenmpi-dev
poppler-utils
chromium
python3-dev
python3-numpy
python3-pytest
python3-setuptools
python3-wheel
python3-matplotlib
python3-gdspy
python3-ezdxf
"
# Node.js and npm come with the machine on most set-ups; from Debian when they are missing.
if ! command -v npm >/dev/null 2>&1; then
    PACKAGES="$PACKAGES nodejs npm"
fi

missing=""
for p in $PACKAGES; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done

if [ -n "$missing" ]; then
    SUDO=""
    if [ "$(id -u)" -ne 0 ]; then
        SUDO="sudo"
    fi
    echo "install-deps: installing$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq >/dev/null
    # shellcheck disable=SC2086
    $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

# npm packages, exactly as locked. The stamp records the lock file the tree was installed from.
stamp=node_modules/.orikin-lock
if [ ! -f "$stamp" ] || ! cmp -s package-lock.json "$stamp"; then
    echo "install-deps: npm ci (package-lock.json)" >&2
    npm ci --no-audit --no-fund --loglevel=error >/dev/null
    cp package-lock.json "$stamp"
fi
