// The package's geometry and singularity calls: mesh.singularities(), mesh.edgeDual(),
// mesh.quality()'s distribution, step reports' quality, mesh.smoothing, and positionsHash equal to
// the CLI's after the same logs (the parity logs, smoothing on), so native and wasm place vertices
// bit for bit alike.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { init, Mesh } from 'hexdual';

await init();
const root = new URL('../../', import.meta.url).pathname;
const cli = join(root, 'build/native/hexdual');

test('singularities of a grid: the 12 box edges, valence 1 on the boundary; same counts as info()', () => {
  const m = Mesh.grid(3, 4, 5);
  const s = m.singularities();
  assert.deepEqual(s.counts, { interiorEdges: 0, boundaryEdges: 48, interiorByValence: {}, boundaryByValence: { 1: 48 }, vertices: 8, boundaryVertices: 8, curves: 12 });
  assert.equal(s.edges.length, 48);
  assert.equal(s.curves.length, 12);
  assert.ok(s.edges.every((e) => e.boundary && e.valence === 1 && e.curve >= 0 && e.vertices.length === 2));
  assert.deepEqual(m.info().singularities, s.counts);
  m.delete();
});

test('a hex push makes 16 valence-3 and 16 valence-5 edges (as natively); edgeDual names the sheet and 3 chords around one', () => {
  const m = Mesh.grid(4, 4, 4);
  const r = m.apply('hexpush h21f1');
  assert.equal(r.quality.smoothed, true);
  assert.deepEqual(r.quality.inverted, []);
  assert.deepEqual(r.quality.degenerate, []);
  // A flat hex push moves the 16 vertices of its 6 hexes: the 4 new ones and q's own among them.
  assert.equal(r.quality.moved.length, 16);
  assert.ok(r.created.vertices.every((v) => r.quality.moved.includes(v)));
  assert.deepEqual(r.quality.pinned, []);
  assert.equal(r.quality.rings, 0);
  assert.ok(r.quality.evaluations > 0);
  assert.equal(r.quality.kept, false, 'the smoothed placement is the better one here');
  assert.equal(r.quality.before, 1);
  assert.ok(r.quality.after > 0.3);
  const s = m.singularities();
  assert.deepEqual(s.counts.interiorByValence, { 3: 16, 5: 16 });  // tests/test_singularity.cpp checks them by vertex pairs
  const e = s.edges.find((x) => !x.boundary && x.valence === 3);
  const d = m.edgeDual(e.hex, e.edge);
  assert.equal(d.valence, 3);
  assert.equal(d.hexes.length, 3);
  assert.equal(d.quads.length, 3);
  assert.equal(d.chords.length, 3);
  assert.ok(d.sheets.includes(d.sheet));
  assert.throws(() => m.edgeDual(999, 0), /edgedual: hex 999 does not exist/);
  m.delete();
});

test('a pillow reports its two hexes as degenerate by construction; smoothing off keeps the offsets', () => {
  const m = Mesh.grid(3, 3, 3);
  const r = m.apply('pillow h13f1');
  assert.deepEqual(r.quality.degenerate, r.created.hexes);
  assert.deepEqual(r.quality.inverted, []);
  m.undo();
  m.smoothing = false;
  assert.equal(m.smoothing, false);
  const before = m.positionsHash();
  const p = m.apply('hexpush h13f1');
  assert.equal(p.quality.smoothed, false);
  assert.deepEqual(p.quality.moved, []);
  m.undo();
  assert.equal(m.positionsHash(), before);
  assert.throws(() => { m.smoothing = 1; }, /smoothing must be true or false/);
  m.delete();
});

test('quality(): the distribution as `hexdual quality --json` prints it', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-geometry-'));
  try {
    const file = join(dir, 'ring.hxd');
    execFileSync(cli, ['ring', '8x2x2', '-o', file]);
    const native = JSON.parse(execFileSync(cli, ['quality', file, '--json']).toString());
    const m = Mesh.load(readFileSync(file), 'ring.hxd');
    const q = m.quality();
    assert.equal(q.hexes, native.hexes);
    assert.equal(q.nonPositive, native.nonPositive);
    assert.deepEqual(q.buckets, native.buckets);
    assert.equal(q.buckets.reduce((a, b) => a + b, 0), 32);
    assert.ok(Math.abs(q.mean - native.mean) < 1e-8);
    assert.ok(q.scaledJacobian instanceof Float32Array);
    m.delete();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('the parity logs: CLI and package reach the same positionsHash and step qualities, smoothing on (every log) and off (every 5th)', () => {
  const lines = readFileSync(new URL('./parity/logs.txt', import.meta.url), 'utf8').trim().split('\n');
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-geometry-'));
  let compared = 0;
  try {
    const starts = new Map();
    for (const [k, line] of lines.entries()) {
      const [spec, seed, log] = line.split('\t');
      if (!starts.has(spec)) {
        const file = join(dir, `${spec.replace(' ', '-')}.hxd`);
        execFileSync(cli, [...spec.split(' '), '-o', file]);
        starts.set(spec, file);
      }
      for (const smooth of k % 5 === 0 ? [true, false] : [true]) {
        const args = ['apply', starts.get(spec), '--ops', log, '-o', join(dir, 'out.hxd'), '--json'];
        const native = JSON.parse(execFileSync(cli, smooth ? args : [...args, '--no-smooth']).toString());
        const [kind, dims] = spec.split(' ');
        const [a, b, c] = dims.split('x').map(Number);
        const m = kind === 'ring' ? Mesh.ring(a, b, c) : Mesh.grid(a, b, c);
        m.smoothing = smooth;
        const reports = m.applyLog(log);
        assert.equal(m.positionsHash(), native.positionsHash, `seed ${seed} smoothing ${smooth}`);
        assert.deepEqual(reports.map((r) => r.quality), native.steps.map((s) => s.quality), `seed ${seed}`);
        m.delete();
        ++compared;
      }
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  assert.ok(compared >= lines.length * 6 / 5, `${compared} replays of ${lines.length} logs`);
});

test('a flip applied directly is smoothed and measured like a step; smoothing off leaves its hexes inverted', () => {
  const m = Mesh.grid(4, 4, 4);
  const [r] = m.flip('2-6', [21, 22]);
  assert.equal(r.quality.smoothed, true);
  assert.deepEqual(r.quality.inverted, []);
  assert.equal(r.quality.moved.length, 16);
  assert.ok(r.quality.after > 0.5);
  m.undo();
  m.smoothing = false;
  const [off] = m.flip('2-6', [21, 22]);
  assert.equal(off.quality.smoothed, false);
  assert.deepEqual(off.quality.inverted, [64, 66, 67, 68, 69]);  // as `hexdual flip 2-6 --at 21,22 --no-smooth` prints
  m.delete();
});

test('vertexPositions: the positions of the ids asked for, in order; a dead id or a non-array is a PRECONDITION', () => {
  const m = Mesh.grid(1, 1, 1);
  assert.deepEqual([...m.vertexPositions([0, 7])], [0, 0, 0, 1, 1, 1]);
  assert.deepEqual([...m.vertexPositions([])], []);
  assert.throws(() => m.vertexPositions([99]), { code: 'PRECONDITION', message: 'vertexPositions: vertex 99 does not exist' });
  assert.throws(() => m.vertexPositions('0'), { code: 'PRECONDITION', message: /array of integers/ });
  // The ends of every singular edge: a 2x2x2 grid's boundary edges of valence 1 (its 12 cube edges, 2 each).
  const g = Mesh.grid(2, 2, 2);
  const sing = g.singularities();
  assert.equal(sing.edges.length, 24);
  const xyz = g.vertexPositions(sing.edges.flatMap((e) => e.vertices));
  assert.equal(xyz.length, 6 * 24);
  for (let i = 0; i < 24; i++) assert.equal(Math.hypot(xyz[6 * i] - xyz[6 * i + 3], xyz[6 * i + 1] - xyz[6 * i + 4], xyz[6 * i + 2] - xyz[6 * i + 5]), 1);
  m.delete();
  g.delete();
});
