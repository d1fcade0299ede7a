#!/usr/bin/env bash
# Runs the benchmarks (after `bash .ci/test` or `bash .ci/demo` has built everything) and prints
# a markdown table. Each size runs in its own process so peak RSS belongs to that size.
set -euo pipefail
cd "$(dirname "$0")/.."
SIZES=${SIZES:-"10 20 50 100"}
REPS=${REPS:-5}
echo "| n³ hexes | native cold ms | native warm build+dual ms | wasm cold ms | wasm warm build+dual ms | wasm/native (warm) | bytes/hex | native peak RSS MB | node peak RSS MB |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for n in $SIZES; do
  nat=$(build/native/hexdual_bench build "$n" "$REPS")
  was=$(node bench/bench_wasm.mjs build "$n" "$REPS")
  node -e '
    const a = JSON.parse(process.argv[1]), b = JSON.parse(process.argv[2]);
    const f = (x) => x.toFixed(1);
    console.log(`| ${a.n}³ = ${a.hexes} | ${f(a.coldMs)} | ${f(a.buildMs)} + ${f(a.dualMs)} = ${f(a.totalMs)} | ${f(b.coldMs)} | ${f(b.buildMs)} + ${f(b.dualMs)} = ${f(b.totalMs)} | ${(b.totalMs / a.totalMs).toFixed(2)} | ${f(a.bytesPerHex)} | ${f(a.peakRssMb)} | ${f(b.peakRssMb)} |`);
  ' "$nat" "$was"
done
