// Page 3: incidences at the dual vertex of a picked hex (TK03 Theorems 1-2), before and after a pillow.
import { startPage, live } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { hexModel, incidences } from './hexGeometry.js';

const spec = { kind: 'grid', dims: [3, 3, 3] };
const PILLOW = 'pillow h13f5';

function chordsThrough(mesh, hex) {
  return mesh.chords
    .map((c) => ({ ...c, passes: [...mesh.chordHexes(c.id)].filter((h) => h === hex).length }))
    .filter((c) => c.passes > 0);
}

function showIncidences(f) {
  const hex = f.picked;
  const k = f.model.index.get(hex);
  live('picked', hex);
  if (k === undefined) {
    for (const name of ['quads', 'edges', 'vertices', 'sheet-passes', 'chord-passes', 'neighbours']) live(name, '—');
    return;
  }
  const inc = incidences(f.model, k);
  const sheets = f.dual.byHex.get(hex) || [];
  const chords = chordsThrough(f.mesh, hex);
  live('quads', inc.quads);
  live('edges', inc.edges);
  live('vertices', inc.vertices);
  live('sheet-passes', sheets.length);
  live('sheet-ids', sheets.join(', '));
  live('chord-passes', chords.reduce((n, c) => n + c.passes, 0));
  live('chord-list', chords.map((c) => `chord ${c.id}: ${c.hexes} hexes${c.closed ? ', closed' : ''}`).join('; '));
  live('neighbours', inc.neighbours);
  live('shared', `${inc.mostSharedWithOne}${inc.boundaryQuads ? ` (${inc.boundaryQuads} on the boundary)` : ''}`);
}

// The pillow's facts, from the engine: hex X's neighbours and the closed chords of length 2.
function pillowFacts() {
  const before = meshAfter(spec, []);
  const x = Math.max(...hexModel(before).ids) + 1;
  before.delete();
  const m = meshAfter(spec, [PILLOW]);
  const model = hexModel(m);
  const inc = incidences(model, model.index.get(x));
  live('pillow-x', x);
  live('pillow-neighbours', inc.neighbours);
  live('pillow-shared', inc.mostSharedWithOne);
  live('pillow-closed', m.chords.filter((c) => c.closed && c.hexes === 2).length);
  m.delete();
}

startPage(() => {
  pillowFacts();
  const fig = createFigure(document.getElementById('fig-simple'), {
    title: 'incidences at a dual vertex',
    mesh: spec,
    steps: [PILLOW],
    labels: ['pillow h13f5: hexes X and Y on the same 8 vertices'],
    pickable: true,
    picked: 13,
    sheet: (f) => (f.dual.byHex.get(f.picked) || [])[0],
    hint: 'Click a hex to count at its dual vertex; hover to see its sheets.',
    sheetChips: true,
    onUpdate: showIncidences,
    caption: 'A 3×3×3 grid; the picked hex in pink. After the step the pillow’s two new hexes (orange) are drawn pulled apart.',
  });
  const input = document.getElementById('hex-id');
  const pickTyped = () => fig.pick(Number(input.value));
  document.getElementById('hex-pick').addEventListener('click', pickTyped);
  input.addEventListener('keydown', (e) => e.key === 'Enter' && pickTyped());
});
