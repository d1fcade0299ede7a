#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, address + undefined-behaviour sanitizers) and runs each
# for SECONDS (default 20) on a seed corpus generated here. Usage: fuzz/run.sh [SECONDS] [TARGET...]
# With HEXDUAL_FUZZ_RUNS=N each target runs exactly N inputs instead (CI does this): with the fixed
# seed and a fresh corpus the run is then the same on every machine, so CI cannot turn red by chance.
# Targets: vtk vtu msh mesh meshb hxd inflate oplog. Findings (crash-*, leak-*, timeout-*) are
# written to build/fuzz/findings/TARGET/ and the script fails.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-20}
shift || true
ALL=(vtk vtu msh mesh meshb hxd inflate oplog)
TARGETS=("${@:-${ALL[@]}}")
[ $# -eq 0 ] && TARGETS=("${ALL[@]}")
CXX=${FUZZ_CXX:-clang++-14}
command -v "$CXX" >/dev/null || CXX=clang++
OUT=build/fuzz
mkdir -p "$OUT/obj"
FLAGS=(-std=c++20 -O1 -g -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -Icore -isystem /usr/include/eigen3)

# The core sources the readers and the op log need (objects rebuilt only when sources change).
SOURCES=(core/io/*.cpp core/complex/*.cpp core/ops/*.cpp core/dual/*.cpp core/dual/tracker/*.cpp core/geometry/*.cpp core/analysis/*.cpp)
OBJS=()
for src in "${SOURCES[@]}"; do
  obj="$OUT/obj/$(echo "$src" | tr / _).o"
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ]; then "$CXX" "${FLAGS[@]}" -c "$src" -o "$obj"; fi
  OBJS+=("$obj")
done

target_id() { case $1 in vtk) echo 1;; vtu) echo 2;; msh) echo 3;; mesh) echo 4;; meshb) echo 5;; hxd) echo 6;; inflate) echo 7;; oplog) echo 8;; *) echo "unknown target $1" >&2; exit 2;; esac; }

# Seeds: small meshes written by hexdual itself (never the development-set meshes) and fuzz/seeds/.
seed() {
  local t=$1 dir=$OUT/corpus/$1
  mkdir -p "$dir"
  local tmp=$OUT/seedtmp
  mkdir -p "$tmp"
  local cli=build/native/hexdual
  case $t in
    vtk) $cli grid 1x1x2 -o "$dir/g.vtk"; $cli grid 2x1x1 -o "$tmp/b.vtk" --binary; cp "$tmp/b.vtk" "$dir/b.vtk" ;;
    mesh) $cli ring 3x1x1 -o "$dir/r.mesh" ;;
    hxd) $cli grid 1x1x2 -o "$tmp/g.hxd"; $cli apply "$tmp/g.hxd" --ops 'v1;pillow h0f5' -o "$dir/p.hxd" >/dev/null ;;
    inflate) $cli grid 1x1x1 -o "$tmp/i.vtk"; gzip -c "$tmp/i.vtk" >"$dir/i.vtk.gz"; printf 'hexdual' | gzip -1 >"$dir/s.gz" ;;
    *) cp fuzz/seeds/"$t"/* "$dir/" ;;
  esac
}

# A fixed seed (printed) so that a run can be repeated; HEXDUAL_FUZZ_SEED picks another.
FUZZ_SEED=${HEXDUAL_FUZZ_SEED:-20261201}
echo "fuzz seed $FUZZ_SEED"
fail=0
for t in "${TARGETS[@]}"; do
  id=$(target_id "$t")
  bin=$OUT/fuzz_$t
  if [ ! -f "$bin" ] || [ fuzz/fuzz_readers.cpp -nt "$bin" ] || [ -n "$(find "${OBJS[@]}" -newer "$bin" 2>/dev/null | head -1)" ]; then
    "$CXX" "${FLAGS[@]}" -fsanitize=fuzzer -DHEXDUAL_FUZZ_TARGET="$id" fuzz/fuzz_readers.cpp "${OBJS[@]}" -o "$bin"
  fi
  [ -d "$OUT/corpus/$t" ] || seed "$t"
  mkdir -p "$OUT/findings/$t"
  if [ -n "${HEXDUAL_FUZZ_RUNS:-}" ]; then echo "== fuzz $t: $HEXDUAL_FUZZ_RUNS inputs"; else echo "== fuzz $t for ${SECONDS_EACH}s"; fi
  if [ -n "${HEXDUAL_FUZZ_RUNS:-}" ]; then LIMIT=(-runs="$HEXDUAL_FUZZ_RUNS"); else LIMIT=(-max_total_time="$SECONDS_EACH"); fi
  if ! "$bin" -seed="$FUZZ_SEED" "${LIMIT[@]}" -max_len=65536 -rss_limit_mb=1024 -timeout=5 -print_final_stats=0 \
      -artifact_prefix="$OUT/findings/$t/" "$OUT/corpus/$t" 2>"$OUT/fuzz_$t.log"; then
    echo "fuzz $t: FINDING (see $OUT/fuzz_$t.log and $OUT/findings/$t/)"; tail -30 "$OUT/fuzz_$t.log"; fail=1
  else
    grep -E "^#[0-9]+.*DONE|Done [0-9]+ runs" "$OUT/fuzz_$t.log" | tail -1 || true
  fi
done
exit $fail
