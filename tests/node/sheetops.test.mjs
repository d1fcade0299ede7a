// The sheet operations from the package: apply, undo and the log (v1, lower-case URL letters), the
// preview of a step (nothing changes), selection through a picked edge or quad, candidates by name,
// and the same reports as the CLI.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { init, Mesh, HexdualError } from 'hexdual';

await init();
const cli = new URL('../../build/native/hexdual', import.meta.url).pathname;

test('sheet-extract: the report (ids, delta, one sheet fewer, chords shorter), exact undo, the URL form', () => {
  const m = Mesh.grid(3, 3, 3);
  const hash = m.canonicalHash();
  const start = m.save('hxd');
  const sheets = m.dualSizes().sheets;
  const dualBefore = m.hexDual();
  const idsBefore = JSON.stringify([m.sheets.map((x) => [x.id, x.hexes]), m.chords.map((x) => [x.id, x.hexes])]);
  const r = m.apply('sheet-extract h13e0');
  assert.equal(r.op, 'sheet-extract');
  assert.deepEqual(r.removed.hexes, [1, 4, 7, 10, 13, 16, 19, 22, 25]);
  assert.deepEqual(r.delta, { V: -16, E: -40, F: -33, H: -9 });
  assert.deepEqual(r.changedSheets.removed, [3]);
  assert.equal(r.changedChords.removed.length, 6);  // the chords lying in the sheet
  assert.equal(r.inverse, 'sheet-insert h0f1 h3f1 h6f1 h9f1 h12f1 h15f1 h18f1 h21f1 h24f1');
  assert.equal(m.dualSizes().sheets, sheets - 1);
  assert.equal(m.counts.boundaryQuads, 54 - 12);  // the layer's 12 boundary quads are gone: a 2x3x3 grid
  m.validate();
  assert.equal(m.logUrl, '1.x13e0');
  assert.equal(m.log, 'v1;sheet-extract h13e0');
  assert.equal(m.undo(), 'sheet-extract h13e0');
  assert.deepEqual(m.save('hxd'), start);
  assert.equal(m.canonicalHash(), hash);
  // Exact undo includes the dual's ids: the extracted sheet and its chords come back with their own
  // ids (not fresh ones), so a URL's sel=/diag= written after an undo names what a replay names.
  assert.equal(JSON.stringify([m.sheets.map((x) => [x.id, x.hexes]), m.chords.map((x) => [x.id, x.hexes])]), idsBefore);
  const dualAfter = m.hexDual();
  assert.deepEqual([dualAfter.sheetOf, dualAfter.chordOf], [dualBefore.sheetOf, dualBefore.chordOf]);
  assert.deepEqual(m.dualSizes(), { sheets, chords: m.dualSizes().chords });
  m.delete();
});

test('the other sheet operations apply, and a log of them replays to the same state', () => {
  const m = Mesh.grid(3, 3, 3);
  assert.equal(m.apply('sheet-dice h13e0 3').delta.H, 18);
  assert.equal(m.apply('sheet-pillow h0').delta.H, 3);
  assert.equal(m.apply('column-collapse h13e8').removed.hexes.length, 3);
  const inserted = m.apply('sheet-insert h18f5 h19f5 h20f5');
  assert.equal(inserted.inverse.startsWith('sheet-extract h'), true);
  const again = Mesh.grid(3, 3, 3);
  again.applyLog(m.logUrl);
  assert.deepEqual(again.save('hxd'), m.save('hxd'));
  m.delete();
  again.delete();
});

test('refusals name their rule; the mesh is unchanged', () => {
  const m = Mesh.grid(3, 3, 1);
  const before = m.save('hxd');
  assert.throws(() => m.apply('sheet-extract h4e8'), (e) => e instanceof HexdualError && e.code === 'PRECONDITION' &&
    e.message === 'sheet-extract: no-sides: the chord through hex 0 runs from boundary to boundary inside the sheet (hexes 0); no hex would be left there');
  assert.throws(() => m.apply('sheet-dice h4e8 1'), /sheet-dice: bad-count: a sheet is diced into 2 to 64 sheets, not 1/);
  assert.throws(() => m.apply('sheet-dice h4e8 h1'), (e) => e.code === 'PARSE');
  assert.deepEqual(m.save('hxd'), before);
  m.delete();
});

test('preview: the report apply would give, or the refusal with its rule; nothing changes', () => {
  const m = Mesh.grid(3, 3, 3);
  m.apply('facecollapse h1e3 h1f3 h13f2');
  const before = m.save('hxd');
  const info = JSON.stringify(m.info());
  const p = m.preview('sheet-dice h13e0 2');
  assert.equal(p.applies, true);
  assert.equal(p.family, 'sheet');
  assert.equal(p.hexesCreated, 9);
  assert.deepEqual(m.save('hxd'), before);
  assert.equal(JSON.stringify(m.info()), info);
  assert.equal(m.log, 'v1;facecollapse h1e3 h1f3 h13f2');
  assert.deepEqual(m.apply('sheet-dice h13e0 2'), p.report);  // the same ids, delta, sheets and chords
  m.undo();
  const refused = m.preview('sheet-extract h0e0');
  assert.deepEqual(refused, {
    applies: false, family: 'sheet', step: 'sheet-extract h0e0', rule: 'self-touching',
    error: 'sheet-extract: self-touching: the sheet touches itself at vertex 5: its edges to 4 and to 36 would merge three vertices into one',
  });
  assert.equal(m.preview('hexpush h0f0').rule, null);
  assert.throws(() => m.preview('sheet-extract'), (e) => e.code === 'PARSE');
  assert.throws(() => m.preview(3), (e) => e.code === 'PRECONDITION');
  assert.deepEqual(m.save('hxd'), before);
  m.delete();
});

test('select: the sheet through a picked edge, the chord through a picked quad', () => {
  const m = Mesh.grid(3, 3, 3);
  const s = m.select({ hex: 13, edge: 0 });
  assert.deepEqual(s, {
    kind: 'sheet', id: 3, through: 'h13e0', topology: 'disk', boundaryLoops: 1, selfIntersecting: false,
    hexes: [1, 4, 7, 10, 13, 16, 19, 22, 25], steps: ['sheet-extract h13e0', 'sheet-dice h13e0 2'],
  });
  const c = m.select({ hex: 13, face: 1 });
  assert.equal(c.kind, 'chord');
  assert.deepEqual(c.hexes, [12, 13, 14]);
  assert.deepEqual(c.steps, ['column-collapse h13e0', 'column-collapse h13e1']);
  assert.deepEqual([...m.chordHexes(c.id)], c.hexes);
  assert.throws(() => m.select({ hex: 99, edge: 0 }), /select: hex 99 does not exist/);
  assert.throws(() => m.select({ hex: 1, edge: 0, face: 1 }), (e) => e.code === 'PRECONDITION');
  // After an extraction the ids follow the tracker: the picked sheet is the one the mesh shows.
  m.apply('sheet-extract h13e0');
  assert.equal(m.select({ hex: 0, edge: 0 }).id, m.hexDual().sheetOf[0]);
  m.delete();
});

test('candidates by name list the sheet operations; without a name, the atomic ones only', () => {
  const m = Mesh.grid(2, 2, 2);
  assert.deepEqual(m.candidates('sheet-extract'), ['sheet-extract h0e0', 'sheet-extract h0e4', 'sheet-extract h0e8',
    'sheet-extract h1e0', 'sheet-extract h2e4', 'sheet-extract h4e8']);
  assert.equal(m.candidates().some((s) => s.startsWith('sheet-') || s.startsWith('column-')), false);
  m.delete();
});

test('the package and the CLI give the same reports for a log of sheet operations', () => {
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-sheetops-'));
  try {
    const file = join(dir, 'g.hxd');
    execFileSync(cli, ['grid', '4x4x4', '-o', file]);
    const log = 'v1;sheet-pillow h21 h22;sheet-extract h0e0;sheet-dice h5e8 2;column-collapse h26e4';
    const native = JSON.parse(execFileSync(cli, ['apply', file, '--ops', log, '--dry-run', '--json']).toString());
    const m = Mesh.grid(4, 4, 4);
    const reports = m.applyLog(log);
    assert.equal(reports.length, native.steps.length);
    reports.forEach((r, k) => {
      assert.deepEqual(r.created.hexes, native.steps[k].createdHexes);
      assert.deepEqual(r.removed.vertices, native.steps[k].removedVertices);
      assert.deepEqual(r.delta, native.steps[k].delta);
      assert.deepEqual(r.changedSheets, native.steps[k].sheets);
      assert.deepEqual(r.changedChords, native.steps[k].chords);
    });
    m.delete();
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('counts in constant time agree with info() after every kind of step, undo and redo (fixed seed)', () => {
  const seed = 20261204;
  console.log(`counts test seed ${seed}`);
  let state = seed;
  const pick = (k) => { state = (Math.imul(state, 1103515245) + 12345) >>> 0; return (state >>> 8) % k; };
  const exact = (m) => {
    const { vertices, edges, quads, hexes, boundaryQuads } = m.info();
    return { vertices, edges, quads, hexes, boundaryQuads };
  };
  const ops = ['pillow', 'chordpush', 'hexpush', 'facecollapse', 'sheet-extract', 'sheet-pillow', 'column-collapse', 'sheet-dice', undefined];
  let applied = 0;
  for (const m of [Mesh.grid(4, 4, 4), Mesh.ring(8, 2, 2)]) {
    m.smoothing = false;
    const start = m.counts;  // the Euler characteristic is counted here, once
    assert.deepEqual(start, exact(m));
    for (let s = 0; s < 30; s++) {
      const op = ops[pick(ops.length)];
      // sheet-pillow has no candidate list: pillow the hex of a random pillow candidate (both
      // apply there when the hex is away from self-touching; a refusal leaves the mesh as it was).
      const steps = op === 'sheet-pillow'
        ? m.candidates('pillow').map((st) => `sheet-pillow ${st.split(' ')[1].replace(/f\d$/, '')}`)
        : op ? m.candidates(op) : [];
      if (op && steps.length) {
        try {
          m.apply(steps[pick(steps.length)]);
          applied++;
        } catch (e) {
          assert.ok(e instanceof HexdualError && op === 'sheet-pillow', String(e));
        }
      } else if (m.canUndo) {
        m.undo();
        if (pick(2)) m.redo();
      }
      const cheap = m.counts;  // before info() is built again
      assert.deepEqual(cheap, exact(m), `seed ${seed}, step ${s}: ${m.log}`);
    }
    while (m.canUndo) m.undo();
    assert.deepEqual(m.counts, start);
    m.delete();
  }
  assert.ok(applied >= 30, `${applied} steps applied`);
});
