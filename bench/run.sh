#!/usr/bin/env bash
# Runs the benchmarks (after `bash .ci/test` or `bash .ci/demo` has built everything) and prints
# markdown tables. Each size runs in its own process so peak RSS belongs to that size.
set -euo pipefail
cd "$(dirname "$0")/.."
SIZES=${SIZES:-"10 20 50 100"}
FLOOR_SIZES=${FLOOR_SIZES:-"10 50 100 150 200"}
REPS=${REPS:-5}
OP_REPS=${OP_REPS:-21}
# Every JSON result of this run, for the targets table at the end.
RESULTS=$(mktemp)
trap 'rm -f "$RESULTS"' EXIT

echo "### Dual extraction against the floor (CPU ms, minimum of interleaved repetitions on the same complex: 101 at 10³, 21 at 50³, $REPS at 100³, 2 from 150³)"
echo
echo "The floor (bench/floor.cpp) only labels sheets and chords: one union-find pass over glued quads."
echo
echo "| n³ hexes | floor ms | hexdual extractDual ms | ratio | floor ns/hex | hexdual ns/hex |"
echo "| --- | --- | --- | --- | --- | --- |"
for n in $FLOOR_SIZES; do
  reps=$REPS
  [ "$n" -ge 150 ] && reps=2
  # A 10³ extraction takes 0.1 ms and a 50³ one 11 ms: a minimum over 5 such short intervals
  # on a shared host is mostly the host's, so the small sizes take more repetitions (for free).
  [ "$n" -le 10 ] && reps=101
  [ "$n" -gt 10 ] && [ "$n" -le 50 ] && reps=21
  if ! f=$(build/native/hexdual_floor "$n" "$reps" 2>&1); then
    echo "| ${n}³ | — | — | — | not run: ${f//$'\n'/ } | |"
    continue
  fi
  echo "$f" >>"$RESULTS"
  node -e '
    const a = JSON.parse(process.argv[1]);
    console.log(`| ${a.n}³ = ${a.hexes} | ${a.floorMs.toFixed(1)} | ${a.dualMs.toFixed(1)} | ${a.ratio.toFixed(2)} | ${a.floorNsPerHex.toFixed(0)} | ${a.dualNsPerHex.toFixed(0)} |`);
  ' "$f"
done
echo

echo "### Build + dual extraction"
echo
# The package's Mesh keeps a DualTracker, so the wasm column's dual is the tracker's construction;
# wasm/native compares it with the native build + tracker (the same work), not with extractDual alone.
echo "| n³ hexes | native cold ms | native warm build+dual ms | native tracker ms | wasm cold ms | wasm warm build+tracker ms | wasm/native (warm, build+tracker) | bytes/hex | native peak RSS MB | node peak RSS MB |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for n in $SIZES; do
  nat=$(build/native/hexdual_bench build "$n" "$REPS")
  echo "$nat" >>"$RESULTS"
  # The wasm row comes from the package build (wasm/dist); marked when that build is absent or fails.
  was=$(node bench/bench_wasm.mjs build "$n" "$REPS" 2>/dev/null || echo '{"missing":true}')
  echo "$was" >>"$RESULTS"
  node -e '
    const a = JSON.parse(process.argv[1]), b0 = JSON.parse(process.argv[2]);
    const b = b0.missing ? { coldMs: NaN, buildMs: NaN, dualMs: NaN, totalMs: NaN, peakRssMb: NaN } : b0;
    const f = (x) => (Number.isNaN(x) ? "**no wasm build**" : x.toFixed(1));
    console.log(`| ${a.n}³ = ${a.hexes} | ${f(a.coldMs)} | ${f(a.buildMs)} + ${f(a.dualMs)} = ${f(a.totalMs)} | ${f(a.trackerMs)} | ${f(b.coldMs)} | ${f(b.buildMs)} + ${f(b.dualMs)} = ${f(b.totalMs)} | ${f(b.totalMs / (a.buildMs + a.trackerMs))} | ${f(a.bytesPerHex)} | ${f(a.peakRssMb)} | ${f(b.peakRssMb)} |`);
  ' "$nat" "$was"
done

echo
echo "### Operation latency at the centre of an n³ grid (CPU µs, minimum of $OP_REPS; op alone / op + incremental dual update)"
echo
lines=""
for n in $SIZES; do lines+=$(build/native/hexdual_bench ops "$n" "$OP_REPS")$'\n'; done
printf '%s' "$lines" >>"$RESULTS"
node -e '
  const rows = process.argv[1].trim().split("\n").map((l) => JSON.parse(l));
  const sizes = [...new Set(rows.map((r) => r.n))], ops = [...new Set(rows.map((r) => r.op))];
  const first = sizes[0], last = sizes[sizes.length - 1];
  console.log(`| operation | ${sizes.map((n) => `${n}³`).join(" | ")} | ratio ${last}³/${first}³ (op / op+dual) |`);
  console.log(`| --- | ${sizes.map(() => "---").join(" | ")} | --- |`);
  for (const op of ops) {
    const get = (n) => rows.find((r) => r.n === n && r.op === op);
    const cells = sizes.map((n) => `${get(n).opUs.toFixed(0)} / ${get(n).opPlusDualUs.toFixed(0)}`);
    const ra = get(last).opUs / get(first).opUs, rb = get(last).opPlusDualUs / get(first).opPlusDualUs;
    console.log(`| ${op} | ${cells.join(" | ")} | ${ra.toFixed(2)} / ${rb.toFixed(2)} |`);
  }
' "$lines"

echo
# The same fixed-seed sequence THROUGHPUT_REPS times, the fastest reported (like the minimum of
# repetitions elsewhere: one 0.3-second run on a shared host can lose a third to a neighbour).
THROUGHPUT_REPS=${THROUGHPUT_REPS:-3}
echo "### Random sequences (pillow, hex push, chord push at random places, with dual updates; CPU time, best of $THROUGHPUT_REPS runs)"
echo
echo "| grid | attempted | applied | applied per second | hexes at the end |"
echo "| --- | --- | --- | --- | --- |"
for n in 10 100; do
  t=""
  for _ in $(seq "$THROUGHPUT_REPS"); do
    u=$(build/native/hexdual_bench throughput "$n" 20000)
    t=$(node -e 'const [a, b] = process.argv.slice(1).map((x) => (x ? JSON.parse(x) : null)); console.log(JSON.stringify(!a || b.appliedPerSec > a.appliedPerSec ? b : a));' "$t" "$u")
  done
  echo "$t" >>"$RESULTS"
  node -e 'const t = JSON.parse(process.argv[1]); console.log(`| ${t.n}³ | ${t.attempted} | ${t.applied} | ${t.appliedPerSec} | ${t.hexesAfter} |`);' "$t"
done

echo
echo "### The same steps through the npm package (wasm): mesh.apply(step) with its dual update and report, then mesh.undo() (CPU µs, minimum of $OP_REPS)"
echo
echo "The package's step does more than the native op + dual column: it journals the step for undo/redo, builds the"
echo "report (created/removed ids, Euler delta, changed sheet and chord ids) and hands it to JavaScript."
echo
wlines=""
for n in $SIZES; do wlines+=$(node bench/bench_wasm.mjs ops "$n" "$OP_REPS" 2>/dev/null || echo '{"missing":true}')$'\n'; done
node -e '
  const rows = process.argv[1].trim().split("\n").map((l) => JSON.parse(l)).filter((r) => !r.missing);
  if (!rows.length) { console.log("**no wasm build**"); process.exit(0); }
  const sizes = [...new Set(rows.map((r) => r.n))], ops = [...new Set(rows.map((r) => r.op))];
  const first = sizes[0], last = sizes[sizes.length - 1];
  console.log(`| operation | ${sizes.map((n) => `${n}³`).join(" | ")} | ratio ${last}³/${first}³ |`);
  console.log(`| --- | ${sizes.map(() => "---").join(" | ")} | --- |`);
  for (const op of ops) {
    const get = (n) => rows.find((r) => r.n === n && r.op === op).stepUs;
    console.log(`| ${op} | ${sizes.map((n) => get(n).toFixed(0)).join(" | ")} | ${(get(last) / get(first)).toFixed(2)} |`);
  }
' "$wlines"
echo
echo "| grid | wasm: attempted | applied | applied per second | hexes at the end |"
echo "| --- | --- | --- | --- | --- |"
for n in 10 100; do
  t=$(node bench/bench_wasm.mjs throughput "$n" 20000 2>/dev/null || echo '{"missing":true}')
  node -e 'const t = JSON.parse(process.argv[1]); console.log(t.missing ? `| ${process.argv[2]}³ | **no wasm build** | | | |` : `| ${t.n}³ | ${t.attempted} | ${t.applied} | ${t.perSecond} | ${t.hexes} |`);' "$t" "$n"
done

echo
echo "### Sheet diagram layout (the z-layer sheet of an n x n x 2 grid; median of 5)"
echo
echo "| sheet hexes | native ms (layout) | wasm ms (typed arrays to JS) | wasm/native | wasm ms (JSON object to JS) |"
echo "| --- | --- | --- | --- | --- |"
for n in 10 30 100; do
  a=$(build/native/hexdual_bench layout "$n" 5)
  b=$(node bench/bench_wasm.mjs layout "$n" 5)
  node -e 'const a = JSON.parse(process.argv[1]), b = JSON.parse(process.argv[2]); console.log(`| ${a.slots} | ${a.ms.toFixed(1)} | ${b.ms.toFixed(1)} | ${(b.ms / a.ms).toFixed(2)} | ${b.jsonMs.toFixed(1)} |`);' "$a" "$b"
done

echo
MESHES=${HEXDUAL_MESHES:-../shared/meshes}
if [ -d "$MESHES" ]; then
  echo "### Sheet diagram layout per sheet on the development set (every sheet of each mesh; CPU ms, minimum of 3)"
  echo
  echo "| mesh | sheets | crossings | layout ms | µs per sheet |"
  echo "| --- | --- | --- | --- | --- |"
  tmpm=$(mktemp -d)
  for gz in "$MESHES"/*.gz; do
    name=$(basename "$gz" .gz)
    gzip -dc "$gz" > "$tmpm/$name"
    if r=$(build/native/hexdual_bench layout-file "$tmpm/$name" 3 2>/dev/null); then
      echo "$r" >>"$RESULTS"
      node -e 'const a = JSON.parse(process.argv[1]); console.log(`| ${a.mesh} | ${a.sheets} | ${a.slots} | ${a.ms.toFixed(1)} | ${a.usPerSheet.toFixed(0)} |`);' "$r"
    fi
    rm -f "$tmpm/$name"
  done
  rm -rf "$tmpm"
  echo
fi
echo "### The npm package's size"
echo
wasm=wasm/dist/hexdual.wasm
[ -f "$wasm" ] && echo "{\"bench\":\"size\",\"wasmGzBytes\":$(gzip -9c $wasm | wc -c)}" >>"$RESULTS"
echo "hexdual.wasm $(stat -c %s $wasm) bytes, $(gzip -9c $wasm | wc -c) gzipped; loader hexdual.mjs $(stat -c %s wasm/dist/hexdual.mjs) bytes, $(gzip -9c wasm/dist/hexdual.mjs | wc -c) gzipped"
echo
echo "### Peers, for context (quoted from the performance issue: CPU time on this kind of machine, not rerun here)"
echo
echo "| tool | task | 10³ | 22³ | 46³ | 100³ |"
echo "| --- | --- | --- | --- | --- | --- |"
echo "| MOAB 5.1.1 DualTool::construct_hex_dual | dual extraction | 529 ms | 4.8 s | 52.9 s | 886 s |"
echo "| MOAB 5.1.1 face_shrink (= hex push) + dual update | one operation | | | 3.7 s | |"
echo "| gmds sheet selector | sheets (some wrong) | | | 15.8 s | |"

echo
echo "### Cold build with glibc's transparent huge pages for all of malloc (an environment setting, for comparison)"
echo
echo "hexdual advises huge pages for its large arrays itself (core/complex/huge_pages.hpp); glibc can do it for every"
echo "allocation when the process starts with GLIBC_TUNABLES=glibc.malloc.hugetlb=1."
echo
echo "| n³ | cold ms | warm build+dual ms | cold/warm |"
echo "| --- | --- | --- | --- |"
t=$(GLIBC_TUNABLES=glibc.malloc.hugetlb=1 build/native/hexdual_bench build 100 "$REPS")
node -e 'const a = JSON.parse(process.argv[1]); console.log(`| ${a.n}³ | ${a.coldMs.toFixed(1)} | ${a.totalMs.toFixed(1)} | ${(a.coldMs / a.totalMs).toFixed(2)} |`);' "$t"

echo
echo "### Sheet extraction of the middle layer of a 100³ grid (issue 22; CPU ms, minimum of $REPS applications and undos)"
echo
echo "Floor: the step's own edits (unglue, remove, renumber, glue; journaled for undo) replayed in a transaction"
echo "with no planning, no checks and no dual update."
echo
echo "| step | op ms | op + dual update ms | floor (its edits alone) ms | exact undo's ids (idMemo + restoreIds) ms | slots the update visits |"
echo "| --- | --- | --- | --- | --- | --- |"
se=$(build/native/hexdual_bench sheetops 100 "$REPS" sheetExtract)
echo "$se" >>"$RESULTS"
node -e 'const a = JSON.parse(process.argv[1]); console.log(`| ${a.op} (10,000 hexes) | ${a.opMs.toFixed(1)} | ${a.opPlusDualMs.toFixed(1)} | ${a.editsMs.toFixed(1)} | ${a.undoIdsMs.toFixed(1)} | ${a.slotsTouched} |`);' "$se"

echo
echo "### Against the performance targets (this run)"
echo
node -e '
  const rows = require("fs").readFileSync(process.argv[1], "utf8").trim().split("\n").filter(Boolean).map((l) => JSON.parse(l));
  const builds = rows.filter((r) => r.bench === "build"), floors = rows.filter((r) => r.floorMs !== undefined);
  const ops = rows.filter((r) => r.op !== undefined && r.bench !== "sheetop"), thr = rows.filter((r) => r.bench === "throughput" || r.appliedPerSec !== undefined);
  const verdict = (ok) => (ok ? "met" : "**not met**");
  console.log("| target | this run | verdict |");
  console.log("| --- | --- | --- |");
  const b100 = builds.find((r) => r.n === 100);
  if (b100) {
    console.log(`| build + dual at 100³ ≤ 100 ms warm | ${b100.totalMs.toFixed(1)} ms | ${verdict(b100.totalMs <= 100)} |`);
    console.log(`| cold ≤ 1.5× warm at 100³ | ${(b100.coldMs / b100.totalMs).toFixed(2)}× | ${verdict(b100.coldMs <= 1.5 * b100.totalMs)} |`);
  }
  if (floors.length > 1) {
    const ns = floors.map((f) => f.dualNsPerHex), spread = Math.max(...ns) / Math.min(...ns);
    const sizes = floors.map((f) => f.n + "³").join(", ");
    console.log(`| per-hex cost flat (${sizes}) | ${ns.map((x) => x.toFixed(0)).join(" / ")} ns/hex, max/min ${spread.toFixed(2)} | ${verdict(spread <= 1.5)} |`);
    const ratios = floors.map((f) => f.ratio);
    console.log(`| extractDual / floor | ${ratios.map((x) => x.toFixed(2)).join(" / ")} | (≈2 needed for 100 ms) |`);
  }
  const sizes = [...new Set(ops.map((r) => r.n))];
  if (sizes.length > 1) {
    const lo = Math.min(...sizes), hi = Math.max(...sizes);
    for (const op of [...new Set(ops.map((r) => r.op))]) {
      const a = ops.find((r) => r.n === lo && r.op === op), b = ops.find((r) => r.n === hi && r.op === op);
      const ratio = b.opPlusDualUs / a.opPlusDualUs;
      console.log(`| ${op} + dual update, ${hi}³/${lo}³ ≤ 1.5 | ${ratio.toFixed(2)} | ${verdict(ratio <= 1.5)} |`);
    }
  }
  for (const t of thr) console.log(`| throughput at ${t.n}³ ≥ 50,000 applied/s | ${t.appliedPerSec} | ${verdict(t.appliedPerSec >= 50000)} |`);
  const w100 = rows.find((r) => r.bench === "build-wasm" && r.n === 100);
  if (b100 && w100) {
    const ratio = w100.totalMs / (b100.buildMs + b100.trackerMs);
    console.log(`| wasm ≤ 1.2× native, build + tracker at 100³ | ${w100.totalMs.toFixed(1)} / ${(b100.buildMs + b100.trackerMs).toFixed(1)} ms = ${ratio.toFixed(2)} | ${verdict(ratio <= 1.2)} |`);
  }
  const size = rows.find((r) => r.bench === "size");
  if (size) console.log(`| .wasm ≤ 250 kB gzipped (gzip -9) | ${size.wasmGzBytes} bytes | ${verdict(size.wasmGzBytes <= 250000)} |`);
  const se = rows.find((r) => r.bench === "sheetop" && r.op === "sheetExtract");
  if (se) console.log(`| sheet extraction at 100³ ≤ 5 ms natively (issue 22; op + dual update) | ${se.opMs.toFixed(1)} + ${(se.opPlusDualMs - se.opMs).toFixed(1)} = ${se.opPlusDualMs.toFixed(1)} ms (its edits alone: ${se.editsMs.toFixed(1)} ms) | ${verdict(se.opPlusDualMs <= 5)} |`);
' "$RESULTS"
