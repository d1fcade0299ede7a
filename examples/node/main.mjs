// hexdual from Node: build a grid, apply a pillow and a hex push (the 1-7 flip, TK03 Fig. 8),
// look at what changed, undo, save and reload. Run: npm install && node main.mjs
import { init, Mesh, HexdualError, diagramToSVG } from 'hexdual';
import { writeFileSync } from 'node:fs';

await init();
const mesh = Mesh.grid(3, 3, 3);
const pillow = mesh.apply('pillow h13f5');
console.log(`pillow: created hexes ${pillow.created.hexes}, delta ${JSON.stringify(pillow.delta)}, inverse '${pillow.inverse}'`);
const push = mesh.apply('hexpush h13f5');
console.log(`hexpush: sheets created ${push.changedSheets.created}, chords changed ${push.changedChords.changed}`);
console.log(`log ${mesh.log}  url ${mesh.logUrl}  hash ${mesh.canonicalHash()}`);

try {
  mesh.apply('hexpush h0f0');
} catch (e) {
  if (!(e instanceof HexdualError)) throw e;
  console.log(`rejected (${e.code}): ${e.message}`);
}

mesh.undo();
console.log(`after undo: ${mesh.counts.hexes} hexes, log ${mesh.log}`);

// .hxd keeps the gluings of degenerate states (the pillow's two hexes on the same 8 vertices);
// VTK stores hexes by their vertices only, so it refuses such a complex and names .hxd.
try {
  mesh.save('vtk', { binary: true });
} catch (e) {
  if (!(e instanceof HexdualError)) throw e;
  console.log(`VTK refused (${e.code}): ${e.message}`);
}
const grid = Mesh.grid(2, 2, 2);
const vtk = grid.save('vtk', { binary: true });  // binary VTK for other tools, where it can represent the mesh
grid.delete();
const copy = Mesh.load(mesh.save('hxd'), 'copy.hxd');
console.log(`binary VTK: ${vtk.length} bytes; .hxd reloaded isomorphic: ${Mesh.isomorphic(mesh, copy)}`);

const sheet = mesh.sheets.find((s) => s.hexes === 11);
const diagram = mesh.sheetDiagram(sheet.id);
writeFileSync('sheet.svg', diagramToSVG(diagram));
console.log(`sheet ${sheet.id}: ${diagram.crossings.hex.length} crossings, ${diagram.chords.id.length} chords -> sheet.svg`);
console.log(`candidates near hex 13: ${mesh.candidates('hexpush', { near: { hex: 13 } }).join(', ')}`);
copy.delete();
mesh.delete();
