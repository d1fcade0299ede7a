// Wasm benchmark in Node: `node bench/bench_wasm.mjs build N [REPS]` prints one JSON line with the
// same fields as `hexdual_bench build N` (times are minima of the warm repetitions, as there). Times are CPU
// time of the process (user + system, `process.cpuUsage`), like the native bench's, so a loaded
// machine does not inflate one side of a wasm/native ratio.
import { init, Mesh } from 'hexdual';

const cpuMs = () => {
  const { user, system } = process.cpuUsage();
  return (user + system) / 1000;
};

const [, , what, nArg, repsArg] = process.argv;
if (!['build', 'layout', 'ops', 'throughput'].includes(what) || !nArg) {
  console.error('usage: node bench/bench_wasm.mjs build|layout|ops|throughput N [REPS|STEPS]');
  process.exit(2);
}
if (what === 'ops') {
  // The native `hexdual_bench ops N REPS` cases through the package: mesh.apply(step) (the step, the
  // tracker's dual update and the report crossing into JS) then mesh.undo(); minimum CPU time of
  // each (undoUs: mesh.undo, the exact undo with its dual update).
  await init();
  const n = Number(nArg), reps = Number(repsArg || 11);
  const m = Mesh.grid(n, n, n);
  m.smoothing = false;  // topology and dual only, as the native bench (the smoothing: bench_geometry)
  const id = (i, j, k) => i + n * (j + n * k);
  const c = Math.floor(n / 2), centre = id(c, c, c);
  const edge = `h${centre}e11`, f = `h${centre}f1`, g = `h${id(c, c + 1, c)}f1`;
  const cases = [
    ['pillow', null, () => `pillow h${centre}f5`],
    ['unpillow', `pillow h${centre}f5`, (r) => `unpillow h${r.created.hexes[0]}`],
    ['chordPush', null, () => `chordpush ${edge} ${f} ${g}`],
    ['chordPull', `chordpush ${edge} ${f} ${g}`, (r) => `chordpull h${r.created.hexes[0]}`],
    ['hexPush', null, () => `hexpush h${centre}f5`],
    ['hexPull', `hexpush h${centre}f5`, (r) => `hexpull h${r.created.hexes[0]}f5`],
    ['faceCollapse', null, () => `facecollapse ${edge} ${f} ${g}`],
    // The ring chord's axis in the first ring hex: the one of e0/e4/e8 that applies.
    ['ringCollapse', `hexpush h${centre}f5`, (r) => [0, 4, 8].map((e) => `ringcollapse h${r.created.hexes[2]}e${e}`)],
  ];
  for (const [name, setup, stepOf] of cases) {
    const r = setup ? m.apply(setup) : null;
    let steps = [stepOf(r)].flat(), step = steps[0];
    for (const s of steps) {
      try { m.apply(s); m.undo(); step = s; break; } catch { /* not this axis */ }
    }
    const times = [], undoTimes = [];
    for (let k = 0; k < reps; k++) {
      const t0 = cpuMs();
      m.apply(step);
      const t1 = cpuMs();
      m.undo();
      times.push(t1 - t0);
      undoTimes.push(cpuMs() - t1);
    }
    if (setup) m.undo();
    const us = (ts) => +(1000 * Math.min(...ts)).toFixed(2);
    console.log(JSON.stringify({ bench: 'op-wasm', n, op: name, stepUs: us(times), undoUs: us(undoTimes) }));
  }
  m.delete();
  process.exit(0);
}
if (what === 'throughput') {
  // Random pillow / hex push / chord push steps at random places through mesh.apply, as the native
  // `hexdual_bench throughput` (its own generator: the counts differ, the rate compares).
  await init();
  const n = Number(nArg), steps = Number(repsArg || 20000);
  const m = Mesh.grid(n, n, n);
  m.smoothing = false;  // topology and dual only, as the native bench (the smoothing: bench_geometry)
  let seed = 7;
  const rnd = (k) => { seed = (Math.imul(seed, 1103515245) + 12345) >>> 0; return (seed >>> 8) % k; };
  let applied = 0, attempted = 0, capacity = n ** 3;  // hex ids in use so far (ids are never reused here)
  const t0 = cpuMs();
  for (let s = 0; s < steps; s++) {
    const h = rnd(capacity);
    const op = ['pillow', 'hexpush', 'chordpush'][rnd(3)];
    const text = op === 'chordpush' ? `chordpush h${h}e${rnd(12)} h${h}f${rnd(6)} h${h}f${rnd(6)}` : `${op} h${h}f${rnd(6)}`;
    attempted++;
    try {
      const r = m.apply(text);
      for (const x of r.created.hexes) capacity = Math.max(capacity, x + 1);
      applied++;
    } catch { /* rejected: the mesh is unchanged */ }
  }
  const secs = (cpuMs() - t0) / 1000;
  console.log(JSON.stringify({ bench: 'throughput-wasm', n, attempted, applied, perSecond: Math.round(applied / secs), hexes: m.counts.hexes }));
  m.delete();
  process.exit(0);
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
const min = (a) => Math.min(...a);
const hexes = n ** 3;
console.log(JSON.stringify({
  bench: 'build-wasm', n, hexes, coldMs: +coldMs.toFixed(3), buildMs: +min(build).toFixed(3), dualMs: +min(dual).toFixed(3),
  totalMs: +(min(build) + min(dual)).toFixed(3), bytesPerHex: +(bytes / hexes).toFixed(1), ...sizes,
  peakRssMb: +(process.resourceUsage().maxRSS / 1024).toFixed(1),
}));
