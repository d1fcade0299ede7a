// The demo page in headless Chromium: counts equal the native CLI's, a sheet can be picked,
// garbage URLs fall back with a message. Screenshots land in build/screenshots/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { startServer, startBrowser, root, screenshotDir } from './harness.mjs';

let server, context, page;
const errors = [];

before(async () => {
  server = await startServer();
  context = await startBrowser();
  page = await context.newPage();
  page.on('pageerror', (e) => errors.push(e.message));
});
after(async () => {
  await context?.close();
  server?.stop();
});

function nativeInfo(kind, dims) {
  const cli = join(root, 'build/native/hexdual');
  const file = `/tmp/hexdual_browser_${kind}_${dims}.hxd`;
  execFileSync(cli, [kind, dims, '-o', file]);
  return JSON.parse(execFileSync(cli, ['info', file, '--json']).toString());
}

async function open(hash) {
  await page.goto(server.url + hash);
  await page.waitForFunction(() => window.hexdual?.ready === true, null, { timeout: 20000 });
}

async function shownCounts() {
  return page.$$eval('[data-count]', (tds) => Object.fromEntries(tds.map((td) => [td.dataset.count, Number(td.textContent)])));
}

test('default page shows the 3x3x3 grid with the native counts', async () => {
  await open('');
  const native = nativeInfo('grid', '3x3x3');
  const { vertices, edges, quads, hexes, boundaryQuads } = native;
  assert.deepEqual(await shownCounts(), { vertices, edges, quads, hexes, boundaryQuads });
  assert.equal(await page.locator('#sheets li').count(), native.sheets.length);
  assert.equal(await page.locator('#chords li').count(), native.chords.length);
  assert.equal(await page.evaluate(() => window.hexdual.view.triangleCount), 27 * 12);
  await page.screenshot({ path: join(screenshotDir, 'demo-grid.png') });
});

test('picking a sheet highlights its hexes and goes into the URL', async () => {
  await open('');
  await page.locator('#sheets li[data-id="4"]').click();
  assert.equal(await page.locator('#selection-label').textContent(), 'sheet 4: 9 hexes');
  assert.equal(await page.locator('#sheets li.selected').getAttribute('data-id'), '4');
  assert.match(page.url(), /#mesh=grid%3A3x3x3&sheet=4$/);
  await page.waitForTimeout(300);
  // Pixels: the highlighted sheet is drawn in colour (not only the faint grey-blue).
  const png = await page.locator('#view canvas').screenshot({ path: join(screenshotDir, 'demo-grid-sheet.png') });
  assert.ok(png.length > 10000);
});

test('ring mesh from the URL: closed chords and annuli, counts equal the native CLI', async () => {
  await open('#mesh=ring:8x2x2&chord=1');
  const native = nativeInfo('ring', '8x2x2');
  assert.equal((await shownCounts()).hexes, native.hexes);
  assert.equal((await shownCounts()).edges, native.edges);
  const text = await page.locator('#chords li[data-id="1"]').textContent();
  assert.match(text, /chord 1 8 hexes · closed/);
  const sheetText = await page.locator('#sheets').textContent();
  assert.equal((sheetText.match(/annulus/g) || []).length, 4);
  assert.equal(await page.locator('#selection-label').textContent(), 'chord 1: 8 hexes');
  await page.waitForTimeout(300);
  await page.screenshot({ path: join(screenshotDir, 'demo-ring-chord.png') });
});

test('a garbage URL falls back to the default mesh with a message', async () => {
  await open('#mesh=cube:zz&sheet=abc');
  assert.equal((await shownCounts()).hexes, 27);
  const err = await page.locator('#error').textContent();
  assert.match(err, /ignored mesh=cube:zz/);
  assert.match(err, /ignored sheet=abc/);
});

test('a bad file upload shows the reader error and keeps the mesh', async () => {
  await open('#mesh=grid:2x2x2');
  await page.setInputFiles('#mesh-file', { name: 'bad.vtk', mimeType: 'text/plain', buffer: Buffer.from('# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n0 0 0\n') });
  await page.waitForFunction(() => document.querySelector('#error').textContent.length > 0);
  assert.match(await page.locator('#error').textContent(), /bad\.vtk:\d+: unexpected end of file/);
  assert.equal((await shownCounts()).hexes, 8);
  assert.deepEqual(errors, []);
});

test('picking a sheet shows its diagram; clicking a chord there selects it in 3D', async () => {
  await open('');
  await page.locator('#sheets li[data-id="2"]').click();
  await page.waitForSelector('#diagram svg[data-sheet="2"]');
  assert.equal(await page.locator('#diagram svg circle[data-hex]').count(), 9);
  assert.equal(await page.locator('#diagram svg .chord').count(), 6);
  assert.match(await page.locator('#diagram .diagram-title').textContent(), /sheet 2 · disk/);
  const chord = page.locator('#diagram svg .chord').first();
  const id = await chord.getAttribute('data-chord');
  await chord.dispatchEvent('click');
  assert.equal(await page.locator('#selection-label').textContent(), `chord ${id}: 3 hexes`);
  assert.equal(await page.locator('#diagram svg[data-sheet="2"]').count(), 1);  // the diagram stays
  await page.waitForTimeout(300);
  await page.screenshot({ path: join(screenshotDir, 'demo-diagram.png') });
});

test('operations: apply a step, see the counts change, share it in the URL, undo', async () => {
  await open('');
  await page.fill('#op-step', 'pillow h13f5');
  await page.click('#op-apply');
  assert.equal((await shownCounts()).hexes, 29);
  assert.equal((await shownCounts()).vertices, 68);
  assert.equal(await page.locator('#ops-log li').count(), 1);
  assert.match(decodeURIComponent(page.url()), /ops=v1;pillow[+ ]h13f5/);
  assert.match(await page.locator('#sheets').textContent(), /sphere/);
  // A rejected step leaves the mesh as it was and says why.
  await page.fill('#op-step', 'hexpush h0f0');
  await page.click('#op-apply');
  assert.match(await page.locator('#error').textContent(), /hexpush: quad h0f0 is on the boundary/);
  assert.equal((await shownCounts()).hexes, 29);
  // The shared URL rebuilds the same state.
  const url = page.url();
  await page.goto('about:blank');
  await page.goto(url);
  await page.waitForFunction(() => window.hexdual?.ready === true);
  assert.equal((await shownCounts()).hexes, 29);
  await page.click('#op-undo');
  assert.equal((await shownCounts()).hexes, 27);
  assert.equal(await page.locator('#ops-log li').count(), 0);
  // A log that cannot apply is reported, and the steps before it are kept.
  await open('#mesh=grid:3x3x3&ops=v1;pillow%20h13f5;hexpush%20h0f0');
  assert.equal((await shownCounts()).hexes, 29);
  assert.match(await page.locator('#error').textContent(), /step 2 \(hexpush h0f0\)/);
});

test('flips: load the 4-cube and step through the 1-7 decomposition', async () => {
  await open('');
  await page.selectOption('#flip-name', '1-7');
  await page.click('#flip-load');
  assert.equal((await shownCounts()).hexes, 8);
  assert.equal((await shownCounts()).boundaryQuads, 0);
  assert.match(await page.locator('#flip-status').textContent(), /1-7: 0 of 2 steps applied — next: pillow h0f1/);
  await page.click('#flip-step');
  assert.equal((await shownCounts()).hexes, 10);
  await page.click('#flip-step');
  assert.equal((await shownCounts()).hexes, 14);  // 7 host cubes + the 7 that replace cube 0
  assert.match(await page.locator('#flip-status').textContent(), /2 of 2 steps applied — the after side/);
  assert.ok(await page.locator('#flip-step').isDisabled());
  assert.match(decodeURIComponent(page.url()), /mesh=fourcube&ops=v1;pillow[+ ]h0f1;hexpush[+ ]h0f1/);
  assert.ok(await page.locator('#flip-name option[value="4-4v"]').isDisabled());
  await page.waitForTimeout(300);
  await page.screenshot({ path: join(screenshotDir, 'demo-flip.png') });
});
