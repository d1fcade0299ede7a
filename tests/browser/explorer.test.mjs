// The explorer in headless Chromium, part 2: an interior change shows without slicing, a flip at a
// picked place in the user's own mesh, every export, and a big mesh drawn as its shell.
// Screenshots land in build/screenshots/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { screenshotDir } from './harness.mjs';
import { openBrowser, explorerPage, differing, cli } from './explorer_page.mjs';

let b, page, x, errors;

before(async () => {
  b = await openBrowser();
  ({ page, errors } = b);
  x = explorerPage(page, b.server);
});
after(() => b?.close());

// Whether the pixel at a page position shows one of the two greens of created hexes (lit and shaded).
async function greenAt(p) {
  const [r, g, b] = await x.pixels(p.x, p.y, 1, 1);
  return g > r + 40 && g > b + 20;
}
async function download(locator) {
  const [d] = await Promise.all([page.waitForEvent('download'), locator.click()]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
}
// Counts of a mesh file as the native CLI reads it.
function nativeHexes(bytes, name) {
  const file = `/tmp/hexdual_browser_export_${name}`;
  writeFileSync(file, bytes);
  return JSON.parse(cli('info', file, '--json')).hexes;
}

test('a pillow at the centre of a 3x3x3 grid shows without slicing: the other hexes fade, the two new ones are green and apart', async () => {
  await x.open('#mesh=grid:3x3x3&sel=h13f5');
  const pillow = page.locator('#candidates li[data-step="pillow h13f5"]');
  assert.equal(await pillow.count(), 1);
  const q = await x.project(13, 5);
  const region = [q.x - 50, q.y - 50, 100, 100];
  const before = await x.pixels(...region);
  await pillow.click();
  await x.settle();
  assert.deepEqual((await x.state()).report.created, [27, 28]);
  const after = await x.pixels(...region);
  assert.ok(differing(before, after) > 400, `only ${differing(before, after)} pixels changed around the quad`);
  const [a, b] = [await x.project(27), await x.project(28)];
  assert.ok(Math.hypot(a.x - b.x, a.y - b.y) > 8, `pillow hexes drawn at ${JSON.stringify([a, b])}`);
  assert.ok(await greenAt(a), 'hex 27 shows in the created colour');
  assert.ok(await greenAt(b), 'hex 28 shows in the created colour');
  await page.screenshot({ path: join(screenshotDir, 'explorer-interior-pillow.png') });
  assert.deepEqual(errors, []);
});

test('apply a flip at a picked place in my own mesh: the palette offers it, counts and URL follow, reload replays it', async () => {
  await x.open('#mesh=grid:3x3x3');
  await page.selectOption('#pick-mode', 'hex');
  const p = await x.project(22, 5);
  await page.mouse.click(p.x, p.y);
  assert.deepEqual((await x.state()).selection, { kind: 'hex', hex: 22 });
  const item = page.locator('#candidates li[data-flip="1-7"]');
  assert.equal(await item.count(), 1, 'the 1-7 flip is offered at a hex');
  assert.equal(await item.getAttribute('data-hexes'), '22');
  const nSteps = await page.evaluate(() => window.hexdual.actions.flips.find((f) => f.name === '1-7').steps.length);
  await item.click();
  await x.settle();
  const s = await x.state();
  assert.equal(s.error, '');
  assert.equal(s.steps.length, nSteps);
  assert.equal(s.at, nSteps);
  // The 1-7 flip replaces one hex by seven: 27 - 1 + 7.
  assert.equal((await x.shownCounts()).hexes, 33);
  assert.match(await page.locator('#tl-report').textContent(), /^flip 1-7 at h22 \(\d+ steps\)/);
  await page.screenshot({ path: join(screenshotDir, 'explorer-flip-in-mesh.png') });
  const url = page.url();
  await x.open(new URL(url).hash);
  assert.equal((await x.shownCounts()).hexes, 33);
  assert.deepEqual((await x.state()).steps, s.steps);
  // A quad between two hexes offers the flips whose before side is those two hexes.
  await x.open('#mesh=grid:3x3x3&sel=h13f5');
  const pairs = await page.locator('#candidates li[data-flip]').evaluateAll((lis) => lis.map((li) => `${li.dataset.flip}@${li.dataset.hexes}`));
  assert.ok(pairs.length >= 1 && pairs.every((t) => t.endsWith('@13,22')), pairs.join(' '));
  // A place that is not a before side is refused with the engine's message, the mesh unchanged.
  await page.evaluate(() => window.hexdual.actions.applyFlip('1-7', [4, 5]));
  assert.match(await page.locator('#op-error').textContent(), /^flip 1-7 at h4 h5: /);
  assert.equal((await x.shownCounts()).hexes, 27);
  assert.deepEqual(errors, []);
});

test('exports: PNG with the state URL, the SVG of a diagram, every writable mesh format, .hxd + steps of a dropped file', async () => {
  await x.open('#mesh=grid:3x3x3&steps=v1;pillow%20h13f5&diag=0');
  const exportButton = (label) => page.locator('#exports button', { hasText: label }).first();
  const png = (await download(exportButton('PNG'))).bytes;
  assert.deepEqual([...png.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  const text = png.toString('latin1');
  const at = text.indexOf('tEXthexdual-url\0');
  assert.ok(at > 0, 'a tEXt chunk named hexdual-url');
  assert.ok(text.slice(at + 16).startsWith(page.url()), 'the chunk holds the page URL');
  assert.match(x.hash(), /steps=v1;pillow h13f5/);

  const svg = await download(page.locator('.diagram[data-sheet="0"] button[data-act="svg"]'));
  assert.match(svg.name, /\.svg$/);
  const svgText = svg.bytes.toString('utf8');
  assert.match(svgText, /^<svg[^>]*xmlns="http:\/\/www.w3.org\/2000\/svg"/);
  assert.ok((svgText.match(/class="crossing/g) || []).length >= 9, 'the diagram has its crossings');

  // The pillowed mesh: only .hxd stores it (its gluings); VTK says why not, next to the page's errors.
  const formatButton = (label) => page.locator('#exports button', { hasText: new RegExp(`^${label.replace(/[.()]/g, '\\$&')}$`) });
  const hxdSaved = await download(formatButton('.hxd'));
  assert.equal(nativeHexes(hxdSaved.bytes, hxdSaved.name), 29);
  await formatButton('VTK').click();
  assert.match(await page.locator('#error').textContent(), /^VTK cannot represent this complex: .*write it as \.hxd/);
  // Back to the start mesh: every writable format, each read back natively with its 27 hexes.
  await page.click('#tl-back');
  for (const [label, head] of [['VTK (binary)', '# vtk DataFile'], ['VTK', '# vtk DataFile'], ['Medit .mesh', 'MeshVersionFormatted'], ['.hxd', 'hexdual 1']]) {
    const d = await download(formatButton(label));
    assert.ok(d.bytes.toString('latin1').startsWith(head), `${label} starts with ${head}`);
    assert.equal(nativeHexes(d.bytes, d.name), 27, `${label} read back`);
  }

  // A dropped file: the start mesh as .hxd plus the steps, which replay to the same state.
  const file = '/tmp/hexdual_browser_drop2.hxd';
  cli('grid', '2x2x2', '-o', file);
  await x.dropFile(readFileSync(file, 'utf8'), 'cube8.hxd');
  await page.waitForFunction(() => window.hexdual.store.get().mesh.counts.hexes === 8);
  await page.evaluate(() => window.hexdual.actions.apply('pillow h0f1'));
  assert.equal((await x.shownCounts()).hexes, 10);
  const [hxd, steps] = await Promise.all([
    page.waitForEvent('download').then(async (d) => ({ name: d.suggestedFilename(), bytes: readFileSync(await d.path()) })),
    (async () => {
      const second = page.waitForEvent('download', (d) => d.suggestedFilename().endsWith('.steps.txt'));
      await exportButton('download .hxd + steps').click();
      const d = await second;
      return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
    })(),
  ]);
  assert.equal(hxd.name, 'cube8.hxd');
  assert.equal(nativeHexes(hxd.bytes, 'start.hxd'), 8);
  assert.equal(steps.name, 'cube8.steps.txt');
  assert.equal(steps.bytes.toString('utf8'), 'v1;pillow h0f1\nat=1\n');

  // The recipient drops both files at once: the mesh opens, then its steps replay.
  const dropBoth = () => page.evaluate(([hxdText, stepsText]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([stepsText], 'cube8.steps.txt'));
    dt.items.add(new File([hxdText], 'cube8.hxd'));
    for (const type of ['dragenter', 'dragover', 'drop']) document.body.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true }));
  }, [hxd.bytes.toString('utf8'), steps.bytes.toString('utf8')]);
  const droppedState = async () => {
    await page.waitForFunction(() => window.hexdual.store.get().steps.length > 0 && window.hexdual.store.get().mesh.counts.hexes > 8);
    await x.settle();
    return ((s) => [s.hexes, s.steps, s.at, s.diagrams, s.error])(await x.state());
  };
  await x.open('#mesh=grid:3x3x3');
  await dropBoth();
  assert.deepEqual(await droppedState(), [10, ['pillow h0f1'], 1, [], '']);
  assert.match(x.hash(), /mesh=file:cube8\.hxd&steps=v1;pillow h0f1/);
  // In the page the sender's URL opens (their file was cube8.vtk): the steps apply once, and the
  // URL's diagrams come back with them.
  await x.open('#mesh=file:cube8.vtk&steps=v1;pillow%20h0f1&at=1&diag=0');
  await dropBoth();
  assert.deepEqual(await droppedState(), [10, ['pillow h0f1'], 1, [0], '']);
  // A URL naming the .hxd itself replays its steps when it comes: the log's same steps are not applied twice.
  await x.open('#mesh=file:cube8.hxd&steps=v1;pillow%20h0f1&at=1&diag=0');
  await dropBoth();
  assert.deepEqual(await droppedState(), [10, ['pillow h0f1'], 1, [0], '']);

  // Or pastes the log into the step box: all of it applies, or (a refused step in it) none of it.
  await page.click('#tl-start');
  await x.settle();
  const typeLog = async (text) => {
    await page.fill('#op-step', text);
    await page.press('#op-step', 'Enter');
    await x.settle();
  };
  await typeLog('v1;pillow h0f1;pillow h9999f0');
  assert.deepEqual(((s) => [s.hexes, s.at])(await x.state()), [8, 0], 'nothing of a refused log stays');
  assert.match(await page.locator('#op-error').textContent(), /^operation log: .*h9999/);
  assert.equal(await page.locator('#error').textContent(), '', 'the error is shown once, under the step box');
  await typeLog('v1;pillow h0f1 at=0'); // at=K: the log's step K is shown, the rest kept for redo
  assert.deepEqual(((s) => [s.hexes, s.steps, s.at])(await x.state()), [8, ['pillow h0f1'], 0]);
  await typeLog('v1;pillow h0f1 at=1');
  assert.deepEqual(((s) => [s.hexes, s.steps, s.at])(await x.state()), [10, ['pillow h0f1'], 1]);
  assert.equal(await page.locator('#op-error').textContent(), '');
  assert.equal(await page.inputValue('#op-step'), '', 'an applied log leaves the box');
  // A steps file dropped alone applies to the mesh on screen, and a refusal says it may be another's.
  await x.dropFile('v1;pillow h99f0\nat=1\n', 'other.steps.txt');
  await x.settle();
  assert.match(await page.locator('#op-error').textContent(), /^other\.steps\.txt \(applied to the mesh on screen: was it saved with another\?\): .*h99/);
  assert.equal((await x.state()).hexes, 10);
  assert.deepEqual(errors, []);
});

test('a big mesh: only its shell is drawn, a selection rebuilds no geometry, a slice shows the cut, past the memory limit a clear message', async () => {
  await x.open('#mesh=grid:30x30x30');
  const view = () => page.evaluate(() => ({ triangles: window.hexdual.view.triangleCount, builds: window.hexdual.view.builds }));
  const v0 = await view();
  // The shell of a 30^3 grid: 30^3 - 28^3 hexes, 12 triangles each.
  assert.equal(v0.triangles, 12 * (30 ** 3 - 28 ** 3));
  await page.locator('#sheets .row-item[data-id="3"]').click();
  await x.settle();
  assert.deepEqual((await x.state()).selection, { kind: 'sheet', id: 3 });
  assert.equal((await view()).builds, v0.builds, 'selecting a sheet rebuilt no geometry');
  // A change the 3D view does not show (a notice) draws no frame.
  const frames = () => page.evaluate(() => window.hexdual.view.frames);
  const f0 = await frames();
  await page.evaluate(() => window.hexdual.actions.set({ notice: 'nothing to draw' }));
  await x.settle();
  assert.equal(await frames(), f0);
  // Cutting at the middle of z draws the hexes on the cut as well (what the shell exposes).
  await page.evaluate(() => window.hexdual.actions.set({ slice: { axis: 2, at: 0.5 } }));
  await x.settle();
  const cut = (await view()).triangles;
  assert.ok(cut > 12 * 30 * 30 && cut < v0.triangles, `${cut} triangles with the slice`);
  // A pillow deep inside is drawn although it is not on the shell.
  await page.evaluate(() => window.hexdual.actions.set({ slice: null }));
  await page.evaluate(() => window.hexdual.actions.apply('pillow h13515f5'));
  await x.settle();
  assert.equal((await view()).triangles, v0.triangles + 2 * 12);
  await page.screenshot({ path: join(screenshotDir, 'explorer-big.png') });
  await x.open('#mesh=grid:200x200x200');
  assert.match(await page.locator('#error').textContent(), /ignored mesh: 200x200x200 is 8,000,000 hexes: about [\d.]+ GiB of wasm memory; the limit is 2 GiB \(about [\d,]+ hexes\)/);
  assert.equal((await x.shownCounts()).hexes, 27);
  assert.deepEqual(errors, []);
});

test('a step animates: hexes move and fade in 3D, crossings move in an open diagram; at once with reduced motion', async () => {
  for (const motion of ['no-preference', 'reduce']) {
    await page.emulateMedia({ reducedMotion: motion });
    await x.open('#mesh=grid:3x3x3&diag=5');
    const during = await page.evaluate(() => {
      window.hexdual.actions.apply('facecollapse h13e7 h13f5 h23f4');
      return { view: window.hexdual.view.animating, diagram: window.hexdual.diagrams.panels.get(5).animating };
    });
    assert.deepEqual(during, motion === 'reduce' ? { view: false, diagram: false } : { view: true, diagram: true }, motion);
    await x.settle();
    assert.equal(await page.evaluate(() => window.hexdual.view.animating), false);
    // The panel shows the new layout, the ghost of the old one is gone.
    assert.equal(await page.locator('.diagram[data-sheet="5"] .ghost').count(), 0);
  }
  await page.emulateMedia({ reducedMotion: 'no-preference' });
  assert.deepEqual(errors, []);
});
