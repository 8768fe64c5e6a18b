#!/usr/bin/env bash
# Builds the browser testbed with Debian's emscripten into BUILD_DIR (default build-web):
# BUILD_DIR/web/site/ is then the whole site (index.html and pivot-web.js, the wasm inside).
# Debian's emscripten finds its acorn module through NODE_PATH when node is not Debian's.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-web}"
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
# The engine and scenes only: no tests, no Box2D. Exceptions on everywhere, so that the engine's
# refusals (pivot::Error) reach the page's calls instead of aborting.
emcmake cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-fexceptions \
    -DPIVOT_BUILD_TESTS=OFF -DPIVOT_BUILD_TESTBED=OFF -DPIVOT_BUILD_WEB=ON > /dev/null
cmake --build "$build" --target pivot-web
echo "the page: $build/web/site/index.html"
