// The primal before/after pictures of docs/operations.md, drawn by the explorer: hexes shrunk hard
// toward their dual points so that the interior shows; before, the operation's entity is selected;
// after, one hex the step created (or, for the collapses, a hex next to it) is selected.
// Run after `bash .ci/setup.sh`: node docs/primal-figures.mjs
import { join } from 'node:path';
import { startServer, startBrowser, root } from '../tests/browser/harness.mjs';

// [name, mesh, step, selection before, selection after]
const figures = [
  ['pillow', 'grid:3x3x3', 'pillow h13f5', 'h13f5', 'h28'],
  ['chordpush', 'grid:3x3x3', 'chordpush h13e3 h13f3 h16f5', 'h13e3', 'h28'],
  ['hexpush', 'grid:3x3x3', 'hexpush h13f5', 'h13f5', 'h27'],
  ['facecollapse', 'grid:4x4x4', 'facecollapse h21e11 h21f1 h25f1', 'h21e11', 'h21'],
];

const server = await startServer();
const context = await startBrowser();
const page = await context.newPage();
await page.setViewportSize({ width: 1000, height: 720 });
async function shoot(hash, file) {
  await page.goto('about:blank'); // a new page load each time (a hash change alone keeps the state)
  await page.goto(`${server.url}index.html${hash}`);
  await page.waitForFunction(() => window.hexdual?.ready === true, null, { timeout: 30000 });
  await page.waitForTimeout(800);
  const err = await page.locator('#error').textContent();
  if (err && err.trim()) throw new Error(`${hash}: ${err}`);
  await page.locator('#view canvas').screenshot({ path: join(root, 'docs', 'images', file) });
  console.log(`docs/images/${file}`);
}
try {
  for (const [name, mesh, step, before, after] of figures) {
    const enc = (s) => encodeURIComponent(s);
    await shoot(`#mesh=${enc(mesh)}&sel=${enc(before)}&shrink=0.55`, `op-${name}-primal-before.png`);
    await shoot(`#mesh=${enc(mesh)}&steps=${enc(`v1;${step}`)}&sel=${enc(after)}&shrink=0.55`, `op-${name}-primal-after.png`);
  }
} finally {
  await context.close();
  server.stop();
}
