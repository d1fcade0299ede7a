// Page 2: a disk and a sphere (before/after a pillow), an annulus (O-grid), a self-crossing sheet
// (a twisted ring); every count is read from the engine.
import { startPage, live } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { sheetWith, sheetOf } from './select.js';
import { twistedRingVtk } from './twisted.js';

const TWISTED = { kind: 'file', name: 'twisted-ring.vtk', text: twistedRingVtk(8) };

function sheetSizes() {
  const grid = meshAfter({ kind: 'grid', dims: [3, 3, 3] }, []);
  live('disk-hexes', grid.sheets.find((s) => s.id === sheetWith(grid, [13, 4])).hexes);
  grid.delete();
  const pillowed = meshAfter({ kind: 'grid', dims: [3, 3, 3] }, ['pillow h13f5']);
  live('sphere-hexes', pillowed.sheets.find((s) => s.topology === 'sphere').hexes);
  pillowed.delete();
}

startPage(() => {
  sheetSizes();
  createFigure(document.getElementById('fig-sphere'), {
    title: 'a disk sheet, then the sphere sheet of a pillow',
    mesh: { kind: 'grid', dims: [3, 3, 3] },
    stages: [
      { ops: [], label: 'a disk sheet through hex 13', sheet: (f) => sheetWith(f.mesh, [13, 4]), forceSheet: true },
      { ops: ['pillow h13f5'], label: 'pillow h13f5: the new sphere sheet', sheet: (f) => sheetOf(f.mesh, (s) => s.topology === 'sphere'), forceSheet: true },
    ],
    sheetChips: true,
    caption: 'Disk: TK03 Fig. 1. Sphere: the dual of a minimal pillow, TK03 Fig. 6.',
  });

  createFigure(document.getElementById('fig-annulus'), {
    title: 'annulus sheets of an O-grid',
    mesh: { kind: 'ring', dims: [8, 2, 2] },
    stages: [
      { ops: [], label: 'an annulus sheet', sheet: (f) => sheetOf(f.mesh, (s) => s.topology === 'annulus'), forceSheet: true },
      { ops: [], label: 'another annulus sheet', sheet: (f) => sheetOf(f.mesh, (s) => s.topology === 'annulus', 1), forceSheet: true },
      { ops: [], label: 'a disk sheet across the ring', sheet: (f) => sheetOf(f.mesh, (s) => s.topology === 'disk'), forceSheet: true },
    ],
    sheetChips: true,
    caption: 'An 8×2×2 O-grid: annulus sheets (two loops) and the disk sheets across the ring.',
    onUpdate(f) {
      live('annuli', f.mesh.sheets.filter((s) => s.topology === 'annulus').length);
      live('closed-chords', f.mesh.chords.filter((c) => c.closed).length);
    },
  });

  createFigure(document.getElementById('fig-self'), {
    title: 'a self-crossing sheet: the twisted ring',
    mesh: TWISTED,
    stages: [
      { ops: [], label: 'the self-crossing sheet', sheet: (f) => sheetOf(f.mesh, (s) => s.selfIntersecting), forceSheet: true },
      { ops: [], label: 'a sheet across the ring', sheet: (f) => sheetOf(f.mesh, (s) => !s.selfIntersecting), forceSheet: true },
    ],
    sheetChips: true,
    caption: 'A twisted O-grid (the mesh of docs/sheet-diagrams.md): one sheet through every hex twice.',
    onUpdate(f) {
      live('twisted-hexes', f.mesh.counts.hexes);
      const self = f.mesh.sheets.find((s) => s.selfIntersecting);
      if (!self) return live('self-sheets', 'no self-crossing sheet');
      const m = meshAfter(TWISTED, []);
      const d = m.sheetDiagramJSON(self.id);
      const distinct = new Set(m.sheetHexes(self.id)).size;
      m.delete();
      const labels = d.crossings.map((c) => c.hex);
      const twice = new Set(labels.filter((h, k) => labels.indexOf(h) !== k)).size;
      live('self-sheets', `sheet ${self.id} has ${self.hexes} slots on ${distinct} hexes; its diagram shows ${labels.length} crossings, ${twice} hexes twice`);
      live('self-topology', self.topology);
      live('self-method', d.method);
    },
  });
});
