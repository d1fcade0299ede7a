// Page 1: a three-hex mesh (TK03 Fig. 1), one stage per sheet; counts checked over every sheet diagram.
import { startPage, live } from './page.js';
import { createFigure, buildMesh } from './figure.js';

const spec = { kind: 'grid', dims: [3, 1, 1] };

function dualFacts(mesh) {
  let chordAppearances = 0, crossings = 0;
  for (const s of mesh.sheets) {
    const d = mesh.sheetDiagramJSON(s.id);
    chordAppearances += d.chords.length;
    crossings += d.crossings.length;
  }
  const perHex = new Map();
  for (const s of mesh.sheets) for (const h of mesh.sheetHexes(s.id)) perHex.set(h, (perHex.get(h) || 0) + 1);
  const allThree = [...perHex.values()].every((n) => n === 3) && perHex.size === mesh.counts.hexes;
  return { chordAppearances, crossings, allThree };
}

startPage(() => {
  const m = buildMesh(spec);
  const sheets = [...m.sheets].sort((a, b) => b.hexes - a.hexes || a.id - b.id);
  const facts = dualFacts(m);
  live('hexes', m.counts.hexes);
  live('sheets', sheets.length);
  live('chords', m.chords.length);
  live('chord-appearances', facts.chordAppearances);
  live('crossings', facts.crossings);
  live('three-sheets', facts.allThree ? 'true for every hex' : 'NOT true here');
  m.delete();
  createFigure(document.getElementById('fig-dual'), {
    title: 'a three-hex mesh and its sheets',
    mesh: spec,
    stages: sheets.map((s) => ({ ops: [], sheet: s.id, forceSheet: true, label: `sheet ${s.id} (${s.hexes} hex${s.hexes === 1 ? '' : 'es'}, ${s.topology})` })),
    sheetChips: true,
    dualVertices: true,
    caption: 'Like TK03 Fig. 1: hexes in 3D with the chosen sheet coloured, its chords as lines through dual vertices; right, its sheet diagram.',
  });
});
