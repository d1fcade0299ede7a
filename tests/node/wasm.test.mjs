// The built npm package in Node: same expectations as the native tests.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { init, Mesh, HexdualError, heapBytes, diagramToSVG, flips } from 'hexdual';

await init();

test('grid counts and dual match the formulas', () => {
  const m = Mesh.grid(3, 3, 3);
  assert.deepEqual(m.counts, { vertices: 64, edges: 144, quads: 108, hexes: 27, boundaryQuads: 54 });
  assert.equal(m.sheets.length, 9);
  assert.ok(m.sheets.every((s) => s.topology === 'disk' && s.boundaryLoops === 1));
  assert.equal(m.chords.length, 27);
  assert.ok(m.chords.every((c) => !c.closed && c.hexes === 3));
  m.delete();
});

test('ring mesh: closed circumferential chords, annuli', () => {
  const m = Mesh.ring(8, 2, 2);
  assert.equal(m.chords.filter((c) => c.closed).length, 4);
  assert.equal(m.sheets.filter((s) => s.topology === 'annulus').length, 4);
  assert.equal(m.sheets.filter((s) => s.topology === 'disk').length, 8);
  assert.deepEqual([...m.chordHexes(1)].length, 8);
  m.delete();
});

test('wasm info equals the native CLI info --json byte for byte', () => {
  const cli = new URL('../../build/native/hexdual', import.meta.url).pathname;
  for (const [kind, dims] of [['grid', '3x3x3'], ['ring', '8x2x2'], ['grid', '2x3x4']]) {
    const file = `/tmp/hexdual_node_${kind}_${dims}.vtk`;
    execFileSync(cli, [kind, dims, '-o', file]);
    const native = execFileSync(cli, ['info', file, '--json']).toString().trim();
    const [a, b, c] = dims.split('x').map(Number);
    const { file: report, ...counts } = JSON.parse(native);
    const m = kind === 'grid' ? Mesh.grid(a, b, c) : Mesh.ring(a, b, c);
    assert.deepEqual(m.info(), counts);
    m.delete();
    // The same file read by the package: counts, dual and what the reader found, all equal.
    const loaded = Mesh.load(readFileSync(file), file);
    assert.deepEqual(loaded.info(), { ...counts, file: report });
    assert.equal(report.format, 'vtk 3.0 ascii');
    loaded.delete();
  }
});

test('load from bytes in all three formats, and save round trips (bytes out, binary VTK included)', () => {
  const m = Mesh.grid(2, 2, 2);
  for (const fmt of ['vtk', 'mesh', 'hxd']) {
    const bytes = m.save(fmt);
    assert.ok(bytes instanceof Uint8Array);
    const back = Mesh.load(bytes, `x.${fmt}`);
    assert.deepEqual(back.counts, m.counts);
    assert.ok(Mesh.isomorphic(back, m));
    back.delete();
  }
  const text = new TextDecoder().decode(m.save('vtk'));
  assert.match(text, /^# vtk DataFile Version/);
  const bin = m.save('vtk', { binary: true });
  assert.equal(new TextDecoder().decode(bin.slice(0, 200)).split('\n')[2], 'BINARY');
  const back = Mesh.load(bin.buffer, 'b.vtk');  // an ArrayBuffer works too
  assert.deepEqual(back.counts, m.counts);
  assert.equal(back.canonicalHash(), m.canonicalHash());
  back.delete();
  m.delete();
});

test('render buffers of a shell: the hexes seen from outside or from a cut, plus hexes asked for', () => {
  const m = Mesh.grid(3, 3, 3);
  const drawn = (rb) => [...new Set(rb.triangleHex)];
  assert.equal(drawn(m.renderBuffers({ shell: true })).length, 26);
  assert.ok(!drawn(m.renderBuffers({ shell: true })).includes(13));
  // Hiding the top layer (hexes 18..26) exposes the centre hex 13.
  const hidden = new Uint8Array(27).fill(1, 18);
  const cut = drawn(m.renderBuffers({ shell: true, hidden }));
  assert.equal(cut.length, 18);
  assert.ok(cut.includes(13));
  m.apply('pillow h13f5');
  assert.deepEqual(drawn(m.renderBuffers({ shell: true, always: [27, 28] })).slice(-2), [27, 28]);
  assert.throws(() => m.renderBuffers({ hidden: [1] }), { message: 'renderBuffers: hidden must be a Uint8Array (one byte per hex id)' });
  assert.throws(() => m.renderBuffers({ always: [1.5] }), { message: 'renderBuffers: always: hex id must be an integer, not 1.5' });
  m.delete();
  // The overlay of a part: hexes 0 and 1 of a 2x2x1 grid have 6 sheet quads and 9 chord segments.
  const g = Mesh.grid(2, 2, 1);
  const part = g.dualOverlay({ hexes: [0, 1] });
  assert.equal(part.sheetTriangle.length, 12);
  assert.equal(part.chordSegment.length, 9);
  assert.deepEqual([...part.dualVertexHex], [0, 1]);
  assert.equal(g.dualOverlay().chordSegment.length, 20);
  g.delete();
});

test('flip places: the flips whose before side is at a hex, a quad or an edge, each applicable', () => {
  const m = Mesh.grid(3, 3, 3);
  const key = (ps) => ps.map((p) => `${p.name}@${p.hexes.join(',')}`).sort();
  assert.deepEqual(key(m.flipPlaces({ hex: 13, face: 5 })), ['2-6@13,22']);
  assert.deepEqual(key(m.flipPlaces({ hex: 22 })), ['1-7@22', '2-6@13,22', '2-6@19,22', '2-6@21,22', '2-6@22,23', '2-6@22,25']);
  assert.deepEqual(key(m.flipPlaces({ hex: 13, edge: 0 })), ['2-6@1,10', '2-6@1,4', '2-6@10,13', '2-6@4,13']);
  const reports = m.flip('1-7', [22], { viaAtomic: true });
  assert.deepEqual(reports.map((r) => r.step), ['pillow h22f1', 'hexpush h22f1']);
  assert.equal(m.counts.hexes, 33);
  assert.throws(() => m.flipPlaces({ hex: 999 }), { message: 'flip places: hex 999 does not exist' });
  assert.throws(() => m.flipPlaces({ hex: 1, face: 6 }), { message: 'flip places: no local quad 6' });
  m.delete();
});

test('render buffers: 6 faces x 4 vertices per hex, a hex id per triangle', () => {
  const m = Mesh.grid(2, 1, 1);
  const rb = m.renderBuffers({ shrink: 0.2 });
  assert.equal(rb.positions.length, 2 * 24 * 3);
  assert.equal(rb.normals.length, 2 * 24 * 3);
  assert.equal(rb.indices.length, 2 * 36);
  assert.deepEqual([...new Set(rb.triangleHex)], [0, 1]);
  // Shrunk toward the centre (0.5,0.5,0.5) by 0.2: corner 0 at 0.1.
  // Hex 0, face 0, first corner is corner 0 at the origin, shrunk toward (0.5,0.5,0.5) by 0.2.
  assert.deepEqual([...rb.positions.slice(0, 3)].map((x) => Math.round(x * 1e6) / 1e6), [0.1, 0.1, 0.1]);
  assert.deepEqual([...rb.normals.slice(0, 3)].map((x) => x + 0), [-1, 0, 0]);
  m.delete();
});

test('errors arrive as HexdualError with a code and the C++ message', () => {
  const is = (code, message) => (e) => e instanceof HexdualError && e.name === 'HexdualError' && e.code === code && e.message === message;
  assert.throws(() => Mesh.grid(0, 1, 1), is('PRECONDITION', 'grid: every dimension must be at least 1'));
  assert.throws(() => Mesh.grid(10000, 10000, 10000), is('LIMIT', 'grid: more than 2^26 hexes'));
  assert.throws(() => Mesh.load('# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n', 'p.vtk'),
    is('PARSE', "p.vtk:4: dataset type 'POLYDATA' is not supported; only UNSTRUCTURED_GRID holds hexahedra"));
  assert.throws(() => Mesh.load('', 'empty.vtk'), is('PARSE', 'empty.vtk: the file is empty'));
  const m = Mesh.grid(1, 1, 1);
  assert.throws(() => m.sheetHexes(99), is('PRECONDITION', 'sheetHexes: sheet 99 does not exist'));
  assert.throws(() => m.chordHexes(-1), is('PRECONDITION', 'chordHexes: chord -1 does not exist'));
  assert.throws(() => m.save('obj'), is('PRECONDITION', "unknown format 'obj' (vtk, mesh or hxd)"));
  assert.throws(() => m.apply('frobnicate h1'), is('PARSE', "oplog: position 0: unknown operation at 'frobnicate'"));
  assert.throws(() => m.undo(), is('PRECONDITION', 'undo: nothing to undo'));
  const g = Mesh.grid(3, 3, 3);
  assert.throws(() => g.apply('facecollapse h1e3 h4f5 h13f2'), is('INVALID_RESULT',
    'facecollapse: the result would not be a valid complex (validate: hex 13 uses vertex 25 at corners 3 and 4)'));
  assert.equal(g.counts.hexes, 27);
  g.delete();
  assert.throws(() => m.redo(), is('PRECONDITION', 'redo: nothing to redo'));
  m.delete();
  assert.throws(() => m.counts, is('PRECONDITION', 'hexdual: this Mesh has been deleted'));
});

test('NaN, infinities and non-integers are rejected, not rounded', () => {
  const is = (message) => (e) => e instanceof HexdualError && e.code === 'PRECONDITION' && e.message === message;
  const m = Mesh.grid(2, 2, 2);
  assert.throws(() => m.chordHexes(NaN), is('chordHexes: id must be an integer, not NaN'));
  assert.throws(() => m.sheetHexes(1.5), is('sheetHexes: id must be an integer, not 1.5'));
  assert.throws(() => m.sheetHexes('0'), is("sheetHexes: id must be an integer, not '0'"));
  assert.throws(() => m.renderBuffers({ shrink: NaN }), is('renderBuffers: shrink must be a finite number, not NaN'));
  assert.throws(() => m.renderBuffers({ shrink: 1 }), is('renderBuffers: shrink must be in [0, 1), not 1'));
  assert.throws(() => Mesh.grid(Infinity, 1, 1), is('grid: a must be an integer, not Infinity'));
  assert.throws(() => m.sheetDiagram(0, { rings: -1 }), is('sheetDiagram: rings must be an integer >= 0, not -1'));
  assert.throws(() => m.flip('2-6', [0, NaN]), is('flip: hexes: hex id must be an integer, not NaN'));
  assert.throws(() => m.applyLog('v1', { stopAt: 0.5 }), is('applyLog: stopAt must be an integer >= 0, not 0.5'));
  m.delete();
});

test('10,000 failing calls do not grow the heap', () => {
  const bad = '# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 8 float\n0 0 0\n';
  const m = Mesh.grid(3, 3, 3);
  const failures = () => {
    assert.throws(() => Mesh.load(bad, 'bad.vtk'));
    assert.throws(() => Mesh.grid(-1, 2, 2));
    assert.throws(() => m.apply('hexpush h0f0'));
    assert.throws(() => m.applyLog('v1;pillow h13f5;hexpush h0f0'));
    assert.throws(() => m.sheetDiagram(99));
  };
  for (let i = 0; i < 200; i++) failures();
  const before = heapBytes();
  const jsBefore = process.memoryUsage().heapUsed;
  for (let i = 0; i < 2000; i++) failures();  // 10,000 throws
  // Capacities inside the mesh (undo lists, tracker scratch) move by a few bytes either way; a
  // leak of even one byte per throw would show as 10 kB.
  assert.ok(Math.abs(heapBytes() - before) < 1024, `wasm heap moved by ${heapBytes() - before} bytes`);
  globalThis.gc?.();
  const jsGrowth = process.memoryUsage().heapUsed - jsBefore;
  console.log(`10,000 throws: wasm heap ${heapBytes() - before} bytes, JS heapUsed ${jsGrowth} bytes`);
  assert.ok(jsGrowth < 8e6, `JS heap grew by ${jsGrowth} bytes`);
  assert.equal(m.counts.hexes, 27);
  m.delete();
});

test('meshes free their memory: 500 create/delete cycles do not grow the heap', () => {
  for (let i = 0; i < 50; i++) Mesh.grid(10, 10, 10).delete();
  const before = heapBytes();
  for (let i = 0; i < 500; i++) {
    const m = Mesh.grid(10, 10, 10);
    m.info();
    m.renderBuffers();
    m.delete();
  }
  assert.equal(heapBytes(), before);
});

test('sheet diagrams from wasm equal the native CLI JSON', () => {
  const cli = new URL('../../build/native/hexdual', import.meta.url).pathname;
  execFileSync(cli, ['grid', '3x3x3', '-o', '/tmp/hexdual_node_sd.hxd']);
  execFileSync('mkdir', ['-p', '/tmp/hexdual_node_sd']);
  execFileSync(cli, ['sheets', '/tmp/hexdual_node_sd.hxd', '--sheet', '2', '--json', '/tmp/hexdual_node_sd']);
  const native = JSON.parse(execFileSync('cat', ['/tmp/hexdual_node_sd/sheet-2.json']).toString());
  const m = Mesh.grid(3, 3, 3);
  const d = m.sheetDiagramJSON(2);
  assert.equal(d.crossings.length, 9);
  assert.equal(d.method, 'disk');
  assert.deepEqual(d.crossings.map((c) => c.hex), native.crossings.map((c) => c.hex));
  for (let i = 0; i < d.crossings.length; i++) {
    assert.ok(Math.abs(d.crossings[i].x - native.crossings[i].x) < 1e-6);
    assert.ok(Math.abs(d.crossings[i].y - native.crossings[i].y) < 1e-6);
  }
  const local = m.localSheetDiagram(2, [4], 1);  // hex 4 is the centre of the bottom layer
  assert.equal(local.local, true);
  assert.equal(local.crossings.length, 9);
  assert.throws(() => m.sheetDiagram(99), { message: 'sheet diagram: sheet 99 does not exist' });
  m.delete();
});

test('apply: operation steps from JS, with errors that leave the mesh unchanged', () => {
  const m = Mesh.grid(3, 3, 3);
  assert.equal(m.apply('pillow h13f5').inverse, 'unpillow h27');
  assert.equal(m.counts.hexes, 29);
  assert.throws(() => m.apply('hexpush h0f0'), { message: 'hexpush: quad h0f0 is on the boundary; hex push needs an interior quad' });
  assert.throws(() => m.apply('frobnicate h1'), { message: "oplog: position 0: unknown operation at 'frobnicate'" });
  assert.equal(m.counts.hexes, 29);
  assert.equal(m.apply('unpillow h27').inverse, 'pillow h13f5');
  assert.equal(m.counts.hexes, 27);
  m.delete();
});

test('flips: the 4-cube and the stored decompositions replay in wasm', async () => {
  const all = flips();
  assert.deepEqual(all.map((f) => f.name), ['1-7', '2-6', '3-5c', '3-5e', '4-4m', '4-4v', '5-3c', '5-3e', '6-2', '7-1']);
  // The 4-4 vertex flip (triple-hex push): 8 atomic steps, replayed below like the others.
  assert.equal(all.find((f) => f.name === '4-4v').steps.length, 8);
  assert.ok(all.every((f) => Array.isArray(f.steps)));
  assert.deepEqual(all.find((f) => f.name === '1-7').steps, ['pillow h0f1', 'hexpush h0f1']);
  for (const f of all.filter((x) => x.steps)) {
    const m = Mesh.fourCube();
    assert.equal(m.counts.hexes, 8);
    for (const step of f.steps) m.apply(step);
    m.validate();
    // The after side replaces the before side: hex count changes by (after - before) facets.
    assert.equal(m.counts.hexes, 8 - f.before.length + (8 - f.before.length), f.name);
    m.delete();
  }
});

test('mixed files: hexesOnly reads the hex part; without it the file is refused with its counts (PARSE)', () => {
  // 2 unit cubes stacked + 1 tetrahedron on top, VTK legacy ASCII.
  const vtk = [
    '# vtk DataFile Version 3.0', 'mixed', 'ASCII', 'DATASET UNSTRUCTURED_GRID', 'POINTS 13 float',
    '0 0 0', '1 0 0', '1 1 0', '0 1 0', '0 0 1', '1 0 1', '1 1 1', '0 1 1', '0 0 2', '1 0 2', '1 1 2', '0 1 2', '0.5 0.5 3',
    'CELLS 3 23', '8 0 1 2 3 4 5 6 7', '8 4 5 6 7 8 9 10 11', '4 8 9 10 12', 'CELL_TYPES 3', '12', '12', '10', '',
  ].join('\n');
  assert.throws(() => Mesh.load(vtk, 'mixed.vtk'), (e) => e instanceof HexdualError && e.code === 'PARSE' && /tetrahedr/.test(e.message) &&
    e.message.endsWith('(--hexes-only, or { hexesOnly: true } in the package, reads the hex part)'));
  const m = Mesh.load(vtk, 'mixed.vtk', { hexesOnly: true });
  const info = m.info();
  assert.equal(info.hexes, 2);
  assert.equal(info.file.dropped.tetrahedra, 1);
  assert.equal(info.file.unusedVertices, 1);
  m.delete();
});
