// Page 4: minimal pillow and its inverse (TK03 §4.3, Figs. 6-7); Δ, the sphere sheet and the
// round trip are computed by the engine.
import { startPage, live, deltaText } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { sheetWith, sheetOf } from './select.js';

const spec = { kind: 'grid', dims: [3, 3, 3] };
const PILLOW = 'pillow h13f5';

function counts(mesh) {
  return { ...mesh.counts, ...mesh.dualSizes() };
}

function diff(a, b) {
  return Object.fromEntries(Object.keys(a).map((k) => [k, b[k] - a[k]]));
}

startPage(() => {
  const m = meshAfter(spec, []);
  const start = counts(m);
  const closedBefore = m.chords.filter((c) => c.closed).length;
  const inverse = m.apply(PILLOW).inverse;
  const after = counts(m);
  const sphere = m.sheets.find((s) => s.topology === 'sphere');
  live('delta', deltaText(diff(start, after)));
  live('new-sheet', sphere ? `sheet ${sphere.id}, a ${sphere.topology} of ${sphere.hexes} hexes` : 'none');
  live('new-chords', m.chords.filter((c) => c.closed && c.hexes === 2).length - closedBefore);
  live('inverse', inverse);
  m.apply(inverse);
  const same = JSON.stringify(counts(m)) === JSON.stringify(start);
  live('back', same ? 'yes, all six counts equal' : 'NO');
  m.delete();

  createFigure(document.getElementById('fig-pillow'), {
    title: 'minimal pillow and its inverse',
    mesh: spec,
    steps: [PILLOW, inverse],
    start: 1,
    labels: [`${PILLOW}: a new sphere sheet`, `${inverse}: the inverse`],
    sheet: (f) => sheetOf(f.mesh, (s) => s.topology === 'sphere') ?? sheetWith(f.mesh, [13, 22, 4]),
    sheetChips: true,
    caption: 'Before: a sheet through the quad’s dual edge. After: the pillow’s sphere sheet of its two new hexes (both orange; the face of the first is opened and drawn as the outside). Pick any sheet to compare.',
  });
});
