// hexdual in a Vite app: `npm run dev` or `npm run build && npm run preview`.
import { init, Mesh, diagramToSVG } from 'hexdual';

// No top-level await: Vite's default build target predates it.
async function main() {
  await init();
  const mesh = Mesh.grid(3, 3, 3);
  const report = mesh.apply('pillow h13f5');
  document.getElementById('diagram').innerHTML = diagramToSVG(mesh.sheetDiagram(2));
  out.textContent = JSON.stringify({
    hexes: mesh.counts.hexes,
    created: report.created.hexes,
    inverse: report.inverse,
    hash: mesh.canonicalHash(),
  });
  out.dataset.status = 'ok';
  mesh.delete();
}

const out = document.getElementById('out');
main().catch((e) => {
  out.textContent = `${e.name}: ${e.message}`;
  out.dataset.status = 'error';
});
