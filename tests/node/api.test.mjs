// The CLI-parity API of the package: step reports, exact undo/redo, logs, candidates, flips at
// any place, typed-array sheet diagrams and their SVG, hex centres, canonical hash.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { init, Mesh, HexdualError, diagramToSVG } from 'hexdual';

await init();
const cli = new URL('../../build/native/hexdual', import.meta.url).pathname;

test('apply returns the step report: ids, delta, changed sheets and chords, inverse', () => {
  const m = Mesh.grid(3, 3, 3);
  assert.deepEqual(m.apply('pillow h13f5'), {
    step: 'pillow h13f5', op: 'pillow', inverse: 'unpillow h27',
    created: { hexes: [27, 28], vertices: [64, 65, 66, 67] }, removed: { hexes: [], vertices: [] },
    delta: { V: 4, E: 8, F: 6, H: 2 },
    changedSheets: { created: [9], removed: [], changed: [3, 5] },
    changedChords: { created: [27, 28], removed: [], changed: [9] },  // the chords the pillow left as they were are not listed
    // The pillow's pair is degenerate by construction (left out of the smoothing and of afterRegular);
    // its 4 new vertices belong to the pair alone, so nothing moves.
    quality: {
      smoothed: true, before: 1, after: -0.577350269, afterRegular: 1, inverted: [], pinned: [], degenerate: [27, 28],
      moved: [], rings: 0, evaluations: 128, kept: false,
    },
  });
  const push = m.apply('hexpush  h13f5'.replace('  ', ' '));
  assert.equal(push.op, 'hexpush');
  assert.deepEqual(push.delta, { V: 4, E: 12, F: 12, H: 4 });
  m.delete();
});

test('undo and redo are exact (the engine journal) and sheet/chord ids stay stable', () => {
  const m = Mesh.grid(3, 3, 3);
  const start = m.save('hxd');
  const info0 = m.info();
  const r1 = m.apply('pillow h13f5');
  const r2 = m.apply('hexpush h13f5');
  const after = m.save('hxd');
  const info2 = m.info();
  // Sheets the steps left alone keep their ids (and sizes).
  for (const s of info0.sheets.filter((s) => !r1.changedSheets.changed.includes(s.id) && !r2.changedSheets.changed.includes(s.id))) {
    assert.deepEqual(info2.sheets.find((t) => t.id === s.id), s);
  }
  assert.equal(m.undo(), 'hexpush h13f5');
  assert.equal(m.undo(), 'pillow h13f5');
  assert.equal(m.canUndo, false);
  assert.deepEqual(m.save('hxd'), start);
  assert.deepEqual(m.info(), info0);
  assert.deepEqual(m.redo(), r1);
  assert.deepEqual(m.redo(), r2);
  assert.equal(m.canRedo, false);
  assert.deepEqual(m.save('hxd'), after);
  assert.deepEqual(m.info(), info2);
  m.undo();
  m.apply('pillow h0f1');  // a new step clears the redo list
  assert.equal(m.canRedo, false);
  assert.equal(m.log, 'v1;pillow h13f5;pillow h0f1');
  m.delete();
});

test('log in text and URL form; applyLog with stopAt, all or nothing', () => {
  const m = Mesh.grid(3, 3, 3);
  m.apply('pillow h13f5');
  m.apply('hexpush h13f5');
  assert.equal(m.log, 'v1;pillow h13f5;hexpush h13f5');
  const url = m.logUrl;
  const n = Mesh.grid(3, 3, 3);
  assert.equal(n.applyLog(url).length, 2);
  assert.equal(n.canonicalHash(), m.canonicalHash());
  const k = Mesh.grid(3, 3, 3);
  assert.deepEqual(k.applyLog(m.log, { stopAt: 1 }).map((r) => r.step), ['pillow h13f5']);
  const before = k.save('hxd');
  assert.throws(() => k.applyLog('v1;hexpush h13f5;hexpush h0f0'), (e) =>
    e instanceof HexdualError && e.code === 'PRECONDITION' &&
    e.message === 'step 2 (hexpush h0f0): hexpush: quad h0f0 is on the boundary; hex push needs an interior quad');
  assert.deepEqual(k.save('hxd'), before);  // step 1 was undone
  assert.equal(k.log, 'v1;pillow h13f5');
  assert.throws(() => k.applyLog('v2;pillow h1f1'), (e) => e.code === 'PARSE');
  for (const x of [m, n, k]) x.delete();
});

test('candidates: per operation, all, and near a hex, a quad or an edge', () => {
  const m = Mesh.grid(3, 3, 3);
  const file = '/tmp/hexdual_node_cand.hxd';
  execFileSync(cli, ['grid', '3x3x3', '-o', file]);
  const native = execFileSync(cli, ['candidates', file, 'hexpush']).toString().trim().split('\n');
  assert.deepEqual(m.candidates('hexpush'), native);
  assert.deepEqual(m.candidates('hexpush', { near: { hex: 13, face: 5 } }), ['hexpush h13f5']);
  assert.deepEqual(m.candidates('hexpush', { near: { hex: 22, face: 4 } }), ['hexpush h13f5']);  // the other side
  assert.deepEqual(m.candidates('hexpush', { near: { hex: 13 } }).length, 6);
  assert.deepEqual(m.candidates('unpillow'), []);
  const all = m.candidates();
  assert.ok(all.includes('pillow h13f5') && all.includes('hexpush h13f5') && all.some((s) => s.startsWith('chordpush')));
  assert.ok(m.candidates('chordpush', { near: { hex: 13, edge: 0 } }).every((s) => s.startsWith('chordpush h')));
  assert.throws(() => m.candidates('frob'), (e) => e.code === 'PRECONDITION' && /unknown operation 'frob'/.test(e.message));
  assert.throws(() => m.candidates('pillow', { near: { hex: 99 } }), { message: 'candidates: hex 99 does not exist' });
  m.delete();
});

test('flip at any place, directly (undoable) or via its atomic steps (logged)', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-flip-'));
  try {
    execFileSync(cli, ['grid', '3x3x3', '-o', join(dir, 'g.hxd')]);
    execFileSync(cli, ['flip', '2-6', '--at', '13,22', join(dir, 'g.hxd'), '-o', join(dir, 'f.hxd')]);
    const m = Mesh.grid(3, 3, 3);
    const [r] = m.flip('2-6', [13, 22]);
    assert.equal(r.step, 'flip 2-6 [13,22]');
    assert.equal(r.op, 'flip');
    assert.deepEqual(r.delta, { V: 4, E: 12, F: 12, H: 4 });
    assert.deepEqual(m.save('hxd'), new Uint8Array(readFileSync(join(dir, 'f.hxd'))));
    assert.throws(() => m.log, (e) => e.code === 'PRECONDITION' && /flip applied directly/.test(e.message));
    m.undo();
    assert.equal(m.counts.hexes, 27);
    const steps = m.flip('1-7', [13], { viaAtomic: true }).map((x) => x.step);
    const native = execFileSync(cli, ['flip', '1-7', '--at', '13', join(dir, 'g.hxd'), '-o', join(dir, 'a.hxd'), '--via-atomic']).toString().trim();
    assert.equal(`v1;${steps.join(';')}`, native);
    assert.equal(m.log, native);
    assert.deepEqual(m.save('hxd'), new Uint8Array(readFileSync(join(dir, 'a.hxd'))));
    assert.throws(() => m.flip('2-6', [0, 26]), (e) => e.code === 'PRECONDITION');
    assert.throws(() => m.flip('9-9', [0]), (e) => e.code === 'PRECONDITION');
    assert.equal(m.log, native);  // failed flips change nothing
    m.delete();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

// The JSON form rounds coordinates; typed arrays carry full doubles.
function close(actual, expected) {
  assert.equal(actual.length, expected.length);
  for (let i = 0; i < actual.length; i++) assert.ok(Math.abs(actual[i] - expected[i]) < 1e-6, `${i}: ${actual[i]} vs ${expected[i]}`);
}

test('sheet diagram as typed arrays equals the JSON form, and its SVG equals the CLI SVG', () => {
  const m = Mesh.grid(3, 3, 3);
  m.apply('pillow h13f5');
  for (const opts of [undefined, { local: [13], rings: 1 }]) {
    for (const s of m.sheets.filter((x) => !opts || m.sheetHexes(x.id).includes(13))) {
      const d = m.sheetDiagram(s.id, opts);
      const j = m.sheetDiagramJSON(s.id, opts);
      assert.deepEqual([...d.crossings.hex], j.crossings.map((c) => c.hex));
      close(d.crossings.xy, j.crossings.flatMap((c) => [c.x, c.y]));
      assert.deepEqual([...d.crossings.chords], j.crossings.flatMap((c) => c.chords));
      assert.deepEqual([...d.chords.id], j.chords.map((c) => c.id));
      close(d.chords.xy, j.chords.flatMap((c) => c.points.flat()));
      assert.deepEqual([...d.chords.hexes], j.chords.flatMap((c) => c.hexes));
      assert.equal(d.chords.offsets.at(-1), d.chords.xy.length / 2);
      close(d.loops.xy, j.loops.flat(2));
      assert.deepEqual([...d.boundary.hex], j.boundary.map((b) => b.hex));
      assert.equal(d.cells.hex.length, j.cells.length);
      assert.equal(d.quads.length, 4 * d.crossings.hex.length);
      assert.equal(d.method, j.method);
      assert.equal(d.openedHex, j.openedHex);
    }
  }
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-svg-'));
  try {
    execFileSync(cli, ['grid', '3x3x3', '-o', join(dir, 'g.hxd')]);
    execFileSync(cli, ['sheets', join(dir, 'g.hxd'), '--sheet', '2', '--svg', dir]);
    const g = Mesh.grid(3, 3, 3);
    assert.equal(diagramToSVG(g.sheetDiagram(2)), readFileSync(join(dir, 'sheet-2.svg'), 'utf8'));
    execFileSync(cli, ['sheets', join(dir, 'g.hxd'), '--sheet', '2', '--local', '4', '--rings', '1', '--svg', dir]);
    assert.equal(diagramToSVG(g.sheetDiagram(2, { local: [4], rings: 1 })), readFileSync(join(dir, 'sheet-2-local.svg'), 'utf8'));
    g.delete();
    // A torus sheet cut open into a polygon: its seams (a b a⁻¹ b⁻¹) and chord pieces survive the typed arrays.
    const torusFile = new URL('../../docs/examples/torus-shell.hxd', import.meta.url).pathname;
    execFileSync(cli, ['sheets', torusFile, '--sheet', '0', '--svg', dir]);
    const t = Mesh.load(readFileSync(torusFile), 'torus-shell.hxd');
    const td = t.sheetDiagram(0);
    assert.equal(td.method, 'polygon');
    assert.deepEqual(td.arcs.label, ['a', 'b', 'a⁻¹', 'b⁻¹']);
    assert.equal(td.euler, 0);
    assert.equal(diagramToSVG(td), readFileSync(join(dir, 'sheet-0.svg'), 'utf8'));
    t.delete();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  assert.throws(() => diagramToSVG({}), (e) => e.code === 'PRECONDITION');
  m.delete();
});

test('hexCenters: centroids by hex id, NaN for removed ids', () => {
  const m = Mesh.grid(2, 1, 1);
  assert.deepEqual([...m.hexCenters()], [0.5, 0.5, 0.5, 1.5, 0.5, 0.5]);
  const g = Mesh.grid(3, 3, 3);
  g.apply('pillow h13f5');
  g.apply('unpillow h27');
  const c = g.hexCenters();
  assert.equal(c.length, 29 * 3);
  assert.ok(Number.isNaN(c[27 * 3]) && Number.isNaN(c[28 * 3 + 2]));
  assert.deepEqual([...c.slice(13 * 3, 13 * 3 + 3)], [1.5, 1.5, 1.5]);
  m.delete();
  g.delete();
});

test('canonicalHash and isomorphic: renumbering-invariant, change-sensitive', () => {
  const a = Mesh.grid(3, 3, 3);
  const b = Mesh.load(a.save('vtk'), 'a.vtk');
  assert.match(a.canonicalHash(), /^[0-9a-f]{16}$/);
  assert.equal(a.canonicalHash(), b.canonicalHash());
  assert.ok(Mesh.isomorphic(a, b));
  b.apply('pillow h13f5');
  assert.notEqual(a.canonicalHash(), b.canonicalHash());
  assert.equal(Mesh.isomorphic(a, b), false);
  b.undo();
  assert.ok(Mesh.isomorphic(a, b));
  a.delete();
  b.delete();
});

test("isomorphic and canonicalHash with { boundary: 'free' }: a copy saved after a sheet extraction, and extraction then its inverse", () => {
  const m = Mesh.grid(3, 3, 3);
  const report = m.apply('sheet-extract h13e0');
  const copy = Mesh.load(m.save('hxd'), 'copy.hxd');  // ids numbered densely again, boundary ones too
  assert.equal(Mesh.isomorphic(m, copy), false);      // boundary kept: its vertex ids moved
  assert.ok(Mesh.isomorphic(m, copy, { boundary: 'free' }));
  assert.equal(m.canonicalHash({ boundary: 'free' }), copy.canonicalHash({ boundary: 'free' }));
  assert.notEqual(m.canonicalHash({ boundary: 'free' }), m.canonicalHash());
  m.apply(report.inverse);
  const grid = Mesh.grid(3, 3, 3);
  assert.ok(Mesh.isomorphic(m, grid, { boundary: 'free' }));
  assert.ok(Mesh.isomorphic(Mesh.grid(3, 3, 4), Mesh.grid(4, 3, 3), { boundary: 'free' }));
  assert.equal(Mesh.isomorphic(Mesh.grid(3, 3, 4), Mesh.grid(3, 3, 3), { boundary: 'free' }), false);
  grid.apply('pillow h13f5');
  assert.equal(Mesh.isomorphic(m, grid, { boundary: 'free' }), false);
  assert.throws(() => Mesh.isomorphic(m, grid, { boundary: 'loose' }), { code: 'PRECONDITION', message: "isomorphic: boundary must be 'kept' or 'free', not 'loose'" });
  assert.throws(() => m.canonicalHash({ boundary: 1 }), { code: 'PRECONDITION', message: "canonicalHash: boundary must be 'kept' or 'free', not 1" });
  for (const x of [m, copy, grid]) x.delete();
});

test('dualSizes counts live sheets and chords: after pillow then its inverse, the start counts again', () => {
  const m = Mesh.grid(3, 3, 3);
  const start = m.dualSizes();
  assert.deepEqual(start, { sheets: 9, chords: 27 });
  const r = m.apply('pillow h13f5');
  assert.deepEqual(m.dualSizes(), { sheets: 10, chords: 29 });
  m.apply(r.inverse);
  assert.deepEqual(m.dualSizes(), start);
  assert.equal(m.sheets.length, start.sheets);
  m.delete();
});

test('apply takes one step (a log with ; is refused and points to applyLog); save refuses binary for formats without it', () => {
  const m = Mesh.grid(3, 3, 3);
  const hash = m.canonicalHash();
  assert.throws(() => m.apply('pillow h13f5;hexpush h13f5'), {
    code: 'PARSE',
    message: "apply: takes one step, and 'pillow h13f5;hexpush h13f5' holds 2 parts; applyLog applies a log of several ('v1;pillow h13f5;hexpush h13f5')",
  });
  assert.equal(m.canonicalHash(), hash);
  assert.equal(m.log, 'v1');
  assert.throws(() => m.save('mesh', { binary: true }), { code: 'PRECONDITION', message: "save: binary applies to 'vtk' only, not 'mesh'" });
  assert.throws(() => m.save('hxd', { binary: true }), { code: 'PRECONDITION', message: "save: binary applies to 'vtk' only, not 'hxd'" });
  assert.ok(m.save('vtk', { binary: true }).length > 0);
  m.delete();
});
