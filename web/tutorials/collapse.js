// Page 6: traditional pillow (TK03 Fig. 8), the (2,1)-(1,2) flip by ring collapse and a face
// collapse (§4.4); Δ and dual changes computed by the engine.
import { startPage, live, deltaText, signed } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { sheetWith, sheetOf } from './select.js';

const GRID3 = { kind: 'grid', dims: [3, 3, 3] };
const GRID5 = { kind: 'grid', dims: [5, 5, 5] };
const GRID4 = { kind: 'grid', dims: [4, 4, 4] };
const TRADITIONAL = ['pillow h13f5', 'hexpush h13f5'];
const RING = ['hexpush h62f5', 'hexpush h37f5', 'ringcollapse h127e4'];
export const FACE = 'facecollapse h21e11 h21f1 h26f0';

function change(spec, ops) {
  const m = meshAfter(spec, []);
  const before = { ...m.counts, ...m.dualSizes(), closed: m.chords.filter((c) => c.closed).length, ids: m.counts.hexes };
  for (const s of ops) m.apply(s);
  const after = { ...m.counts, ...m.dualSizes(), closed: m.chords.filter((c) => c.closed).length };
  const delta = Object.fromEntries(Object.keys(after).map((k) => [k, after[k] - before[k]]));
  return { m, delta };
}

const merged = { removed: [], into: null };

startPage(() => {
  {
    const { m, delta } = change(GRID3, TRADITIONAL);
    const sphere = m.sheets.find((s) => s.topology === 'sphere');
    live('trad-delta', deltaText(delta));
    live('trad-sheet', sphere ? `a ${sphere.topology} of ${sphere.hexes} hexes` : 'not a sphere');
    live('trad-chords', delta.closed);
    live('trad-region', 1 + delta.hexes);
    m.delete();
  }
  {
    const { m, delta } = change(GRID5, RING);
    live('ring-ops', RING.join('; '));
    live('ring-delta', deltaText(delta));
    live('ring-region', 3 + delta.hexes);
    live('ring-boundary', signed(delta.boundaryQuads));
    m.delete();
  }
  {
    const { m, delta } = change(GRID4, [FACE]);
    live('face-step', FACE);
    live('face-delta', deltaText(delta));
    live('face-sheets', `${signed(delta.sheets)} (${m.dualSizes().sheets - delta.sheets} → ${m.dualSizes().sheets})`);
    const before = meshAfter(GRID4, []);
    const alive = new Set(m.sheets.map((s) => s.id));
    merged.removed = before.sheets.filter((s) => !alive.has(s.id));
    merged.into = m.sheets.find((s) => s.topology !== 'disk');
    live('face-merge', `${merged.removed.map((s) => `sheet ${s.id} (${s.topology}, ${s.hexes} hexes)`).join(', ')} joined sheet ${merged.into?.id}: now an ${merged.into?.topology} of ${merged.into?.hexes} hexes`);
    before.delete();
    m.delete();
  }
  createFigure(document.getElementById('fig-traditional'), {
    title: 'traditional pillow',
    mesh: GRID3,
    steps: TRADITIONAL,
    startAfter: true,
    labels: ['pillow h13f5 (i)', 'hexpush h13f5 (ii)'],
    sheet: (f) => sheetOf(f.mesh, (s) => s.topology === 'sphere') ?? sheetWith(f.mesh, [13, 22, 4]),
    sheetChips: true,
    caption: 'TK03 Fig. 8: start, (i) minimal pillow, (ii) hex push. The new sphere sheet is shown when there is one.',
  });
  createFigure(document.getElementById('fig-ring'), {
    title: 'the (2,1)-(1,2) flip',
    mesh: GRID5,
    steps: RING,
    startAfter: true,
    sheet: (f) => sheetWith(f.mesh, [7, 12, 17, 112]), // the x = 2 sheet, through the column
    sheetChips: true,
    emphasis: (f, id) => (f.stage === 0 && [37, 62, 87].includes(id) ? '#7aa6ff' : null),
    caption: 'TK03 §4.4: two hex pushes, then a ring collapse of a closed chord they made. Orange: hexes the steps created; at the start (show before), the column of hexes 37, 62, 87 in blue.',
  });
  createFigure(document.getElementById('fig-face'), {
    title: 'face collapse',
    mesh: GRID4,
    steps: [FACE],
    startAfter: true,
    sheet: (f) => (f.stage === 0 ? merged.removed[0]?.id : merged.into?.id),
    sheetChips: true,
    caption: 'TK03 §4.4: face collapse in a 4×4×4 grid. Before: one of the two sheets that merge; after: the merged sheet, an annulus whose two halves meet at a neck of 4 sides, so it is drawn cut open along one seam (the sides marked a and a⁻¹ are glued): between two circles one half would be squeezed inside the neck.',
  });
});
