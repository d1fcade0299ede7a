// Wasm benchmark in Node: `node bench/bench_wasm.mjs build N [REPS]` prints one JSON line with the
// same fields as `hexdual_bench build N` (times are medians of the warm repetitions). Times are CPU
// time of the process (user + system, `process.cpuUsage`), like the native bench's, so a loaded
// machine does not inflate one side of a wasm/native ratio.
import { init, Mesh } from 'hexdual';

const cpuMs = () => {
  const { user, system } = process.cpuUsage();
  return (user + system) / 1000;
};

const [, , what, nArg, repsArg] = process.argv;
if ((what !== 'build' && what !== 'layout') || !nArg) {
  console.error('usage: node bench/bench_wasm.mjs build|layout N [REPS]');
  process.exit(2);
}
if (what === 'layout') {
  // Layout of the z-layer sheet of an N x N x 2 grid as typed arrays (what sheetDiagram returns),
  // and, for comparison, as the JSON object (sheetDiagramJSON: JSON text built and parsed).
  await init();
  const n = Number(nArg), reps = Number(repsArg || 5);
  const m = Mesh.grid(n, n, 2);
  const sheet = m.sheets.find((s) => s.hexes === n * n).id;
  const time = (f) => {
    const times = [];
    for (let r = 0; r < reps; r++) {
      const t0 = cpuMs();
      f();
      times.push(cpuMs() - t0);
    }
    times.sort((a, b) => a - b);
    return +times[Math.floor(times.length / 2)].toFixed(3);
  };
  const slots = m.sheetDiagram(sheet).crossings.hex.length;
  const ms = time(() => m.sheetDiagram(sheet));
  const jsonMs = time(() => m.sheetDiagramJSON(sheet));
  console.log(JSON.stringify({ bench: 'layout-wasm', n, slots, ms, jsonMs }));
  m.delete();
  process.exit(0);
}
const n = Number(nArg), reps = Number(repsArg || 5);
await init();
const build = [], dual = [];
let sizes, bytes;
for (let r = 0; r < reps; r++) {
  const t0 = cpuMs();
  const m = Mesh.grid(n, n, n);
  const t1 = cpuMs();
  sizes = m.dualSizes();
  const t2 = cpuMs();
  bytes = m.memoryBytes();
  m.delete();
  build.push(t1 - t0);
  dual.push(t2 - t1);
}
const coldMs = build[0] + dual[0];
if (reps > 1) {
  build.shift();
  dual.shift();
}
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
const hexes = n ** 3;
console.log(JSON.stringify({
  bench: 'build-wasm', n, hexes, coldMs: +coldMs.toFixed(3), buildMs: +median(build).toFixed(3), dualMs: +median(dual).toFixed(3),
  totalMs: +(median(build) + median(dual)).toFixed(3), bytesPerHex: +(bytes / hexes).toFixed(1), ...sizes,
  peakRssMb: +(process.resourceUsage().maxRSS / 1024).toFixed(1),
}));
