#!/usr/bin/env bash
# Installs whatever is missing (Debian packages, npm packages) and builds everything:
# native CLI + tests (build/native), the wasm module (wasm/dist), the demo site (web/dist).
# Sourced by .ci/demo and .ci/test; safe to run again (it only does what is needed).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

MIN_NODE_MAJOR=18
APT_PACKAGES=(g++ make cmake emscripten doctest-dev libeigen3-dev chromium ca-certificates zlib1g-dev clang-14 libclang-rt-14-dev)

missing=()
for p in "${APT_PACKAGES[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if ((${#missing[@]})); then
  echo "hexdual setup: installing Debian packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" = 0 ] || SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

node_major=$(node -p 'process.versions.node.split(".")[0]')
if [ "$node_major" -lt "$MIN_NODE_MAJOR" ]; then
  echo "hexdual setup: Node $(node --version) is too old; hexdual needs Node >= $MIN_NODE_MAJOR" >&2
  exit 1
fi

# npm install (not npm ci): the registry here lacks other platforms' optional packages.
if [ ! -d node_modules ] || [ package.json -nt node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "hexdual setup: npm install"
  npm install --no-audit --no-fund --loglevel=error
fi

JOBS=$(nproc 2>/dev/null || echo 2)
# Unity builds (sources compiled in batches of 8): about a third less compile time from a fresh
# clone (bench/README.md "The quick tier's time"). HEXDUAL_UNITY=OFF builds file by file.
UNITY=${HEXDUAL_UNITY:-ON}
echo "hexdual setup: native build"
cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD="$UNITY" >/dev/null
cmake --build build/native -j"$JOBS" >/dev/null

echo "hexdual setup: wasm build"
if ! grep -q "^CMAKE_UNITY_BUILD:BOOL=$UNITY\$" build/wasm/CMakeCache.txt 2>/dev/null; then
  emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release -DCMAKE_CROSSCOMPILING_EMULATOR=node -DCMAKE_UNITY_BUILD="$UNITY" >/dev/null
fi
cmake --build build/wasm -j"$JOBS" >/dev/null

echo "hexdual setup: web build"
npx vite build web --logLevel error
