// The explorer in headless Chromium, used as a student would: click in 3D, apply from the palette,
// step through time, share the URL, drop a file, zoom a diagram, step through a flip.
// Screenshots land in build/screenshots/ (desktop 1200 px and phone 375 px wide).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { screenshotDir } from './harness.mjs';
import { openBrowser, explorerPage, differing, cli } from './explorer_page.mjs';
import { init, decompositions } from 'hexdual';

await init();

let b, page, errors;
let open, settle, shownCounts, state, project, hash, pixels, dropFile;

before(async () => {
  b = await openBrowser();
  ({ page, errors } = b);
  ({ open, settle, shownCounts, state, project, hash, pixels, dropFile } = explorerPage(page, b.server));
});
after(() => b?.close());

function nativeInfo(kind, dims) {
  const file = `/tmp/hexdual_browser_${kind}_${dims}.hxd`;
  cli(kind, dims, '-o', file);
  return JSON.parse(cli('info', file, '--json'));
}

test('default page: the 3x3x3 grid with the native counts, lists and a hover id', async () => {
  await open('');
  const native = nativeInfo('grid', '3x3x3');
  const { vertices, edges, quads, hexes, boundaryQuads } = native;
  assert.deepEqual(await shownCounts(), { vertices, edges, quads, hexes, boundaryQuads });
  assert.equal(await page.locator('#sheet-count').textContent(), `(${native.sheets.length})`);
  assert.equal(await page.locator('#chord-count').textContent(), `(${native.chords.length})`);
  assert.equal(await page.evaluate(() => window.hexdual.view.triangleCount), 27 * 12);
  // The chord list is virtualized: fewer rows in the DOM than chords.
  assert.ok((await page.locator('#chords .row-item').count()) < native.chords.length);
  await page.fill('#chord-filter', '26');
  assert.equal(await page.locator('#chords .row-item').count(), 1);
  // Hovering hex 20's front face shows its quad id and the sheets and chords through it.
  const p = await project(20, 2);
  await page.mouse.move(p.x, p.y);
  await page.waitForSelector('#tip:not([hidden])');
  assert.match(await page.locator('#tip').textContent(), /^quad h20f2 · sheets \d, \d · chords \d+$/);
  await page.screenshot({ path: join(screenshotDir, 'explorer-grid.png') });
});

test('click a hex on the canvas, pillow it from the palette: two hexes appear apart; URL reloads to the same state; back and forward', async () => {
  await open('#mesh=grid:3x3x3');
  await page.selectOption('#pick-mode', 'hex');
  const p = await project(20);
  await page.mouse.click(p.x, p.y);
  assert.deepEqual((await state()).selection, { kind: 'hex', hex: 20 });
  assert.match(hash(), /sel=h20(&|$)/);
  assert.match(await page.locator('#selection-info').textContent(), /^hex h20 · sheets/);
  // The palette lists what applies at hex 20 (from the engine), each with Δ.
  const pillow = page.locator('#candidates li[data-step^="pillow"]').first();
  const step = await pillow.getAttribute('data-step');
  assert.match(step, /^pillow h(20f\d|\d+f\d)$/);
  assert.match(await pillow.textContent(), /Δ\(\+4,\+8,\+6,\+2\)/);
  const [, qh, qf] = /h(\d+)f(\d)/.exec(step).map(Number);
  await page.selectOption('#pick-mode', 'auto');
  await settle();
  const q = await project(qh, qf);
  const region = [q.x - 40, q.y - 40, 80, 80];
  const beforePixels = await pixels(...region);
  await page.screenshot({ path: join(screenshotDir, 'explorer-before-pillow.png') });
  await pillow.click();
  await settle();
  assert.equal((await shownCounts()).hexes, 29);
  const s1 = await state();
  assert.deepEqual(s1.steps, [step]);
  assert.deepEqual(s1.report.created, [27, 28]);
  assert.deepEqual(s1.report.removed, []);
  assert.ok(s1.report.changedSheets.length >= 1);
  // The new sphere sheet is marked as changed in the list.
  assert.ok((await page.locator('#sheets .row-item.changed').count()) >= 1);
  // The two new hexes are drawn apart: different drawn centres, and the picture changed there.
  const [x, y] = [await project(27), await project(28)];
  assert.ok(Math.hypot(x.x - y.x, x.y - y.y) > 3, `pillow hexes drawn at ${JSON.stringify([x, y])}`);
  const afterPixels = await pixels(...region);
  assert.ok(differing(beforePixels, afterPixels) > 50, 'the pillow changed the picture around its quad');
  await page.screenshot({ path: join(screenshotDir, 'explorer-after-pillow.png') });
  assert.match(hash(), new RegExp(`steps=v1;${step}`));
  // Reload: the same state.
  const url = page.url();
  await page.goto('about:blank');
  await page.goto(url);
  await page.waitForFunction(() => window.hexdual?.ready === true);
  assert.equal((await shownCounts()).hexes, 29);
  assert.deepEqual((await state()).steps, [step]);
  // Back (the timeline button) and forward (→): exact, and the URL keeps the steps with at=K.
  await page.click('#tl-back');
  assert.equal((await shownCounts()).hexes, 27);
  assert.equal((await state()).at, 0);
  // Going back removed the pillow: its hexes are reported and drawn as fading ghosts.
  assert.deepEqual((await state()).report.removed, [27, 28]);
  assert.equal(await page.evaluate(() => window.hexdual.view.ghostCount), 1);
  assert.match(hash(), /at=0/);
  await page.keyboard.press('ArrowRight');
  assert.equal((await shownCounts()).hexes, 29);
  assert.deepEqual((await state()).report.created, [27, 28]);
  assert.doesNotMatch(hash(), /at=/);
  // Undo, then a different step: the URL's steps are the remaining ones and replay to the same ids.
  await page.click('#tl-back');
  await page.evaluate(() => window.hexdual.actions.apply('pillow h13f5'));
  assert.deepEqual((await state()).steps, ['pillow h13f5']);
  assert.deepEqual((await state()).report.created, [27, 28]);
  const url2 = page.url();
  await page.goto('about:blank');
  await page.goto(url2);
  await page.waitForFunction(() => window.hexdual?.ready === true);
  assert.deepEqual((await state()).steps, ['pillow h13f5']);
  assert.deepEqual(errors, []);
});

test('picking a quad and an edge on the canvas; the selection is in the URL and survives a step', async () => {
  await open('#mesh=grid:3x3x3');
  const p = await project(20, 2);
  await page.mouse.click(p.x, p.y);
  assert.deepEqual((await state()).selection, { kind: 'quad', hex: 20, face: 2 });
  assert.match(hash(), /sel=h20f2/);
  // Near a side of the face: an edge.
  const edgePick = await page.evaluate(([x, y]) => {
    const v = window.hexdual.view;
    for (let dx = 0; dx < 60; dx++) {
      const pick = v.pickAt(x + dx, y);
      if (pick && pick.kind === 'edge') return { pick, x: x + dx, y };
    }
    return null;
  }, [p.x, p.y]);
  assert.ok(edgePick, 'an edge is pickable near the side of a face');
  await page.mouse.click(edgePick.x, edgePick.y);
  const sel = (await state()).selection;
  assert.equal(sel.kind, 'edge');
  assert.match(hash(), new RegExp(`sel=h${sel.hex}e${sel.edge}`));
  await page.evaluate(() => window.hexdual.actions.apply('pillow h13f5'));
  assert.deepEqual((await state()).selection, sel);
});

test('a malformed URL says what it ignored, parameter by parameter', async () => {
  await open('#mesh=grid:3x3x3&sheet=999&at=x&foo=1&cam=1,2&steps=v1;pillow%20h13f5;hexpush%20h0f0&diag=77&sing=banana');
  const err = await page.locator('#error').textContent();
  assert.match(err, /ignored sheet=999: there are 10 sheets \(0\.\.9\)/);
  assert.match(err, /ignored at=x: expected a step number/);
  assert.match(err, /ignored foo=1: unknown parameter/);
  assert.match(err, /ignored cam=1,2: expected six numbers/);
  assert.match(err, /ignored steps from step 2 \(hexpush h0f0\): hexpush: quad h0f0 is on the boundary/i);
  assert.match(err, /ignored diag=77: there are \d+ sheets/);
  assert.match(err, /ignored sing=banana: expected 0 or 1/);
  assert.equal((await shownCounts()).hexes, 29);
  // The step that replayed is reported in the timeline, as a step applied here would be; the 3D view
  // shows the mesh as a fresh load does (the report is text only: no ghosts, no dimming).
  assert.match(await page.locator('#tl-report').textContent(), /^replayed 1 step from the link: \+2 \/ −0 hexes · sheets [0-9, ]+ · chords /);
  assert.equal(await page.evaluate(() => window.hexdual.store.get().report.textOnly), true);
  await open('#mesh=grid:2x2x2&steps=v1;pillow%20h0f1&at=5');
  assert.match(await page.locator('#error').textContent(), /ignored at=5: there is only 1 step$/);
  await open('#mesh=cube:zz&sel=h999');
  assert.match(await page.locator('#error').textContent(), /ignored mesh=cube:zz/);
  assert.match(await page.locator('#error').textContent(), /ignored sel=h999: hex 999 does not exist/);
});

test('a sheet diagram: opens from the list, zooms with the wheel, labels appear, a crossing selects its hex in 3D', async () => {
  await open('#mesh=grid:6x6x3');
  await page.locator('#sheets .row-item[data-id="0"]').click();
  const svg = page.locator('.diagram[data-sheet="0"] svg');
  await svg.waitFor();
  const n = await svg.locator('.crossing').count();
  assert.ok(n >= 18);
  const zoom0 = Number(await page.locator('.diagram[data-sheet="0"]').getAttribute('data-zoom'));
  const box = await svg.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let i = 0; i < 6; i++) await page.mouse.wheel(0, -200);
  await settle();
  const zoom1 = Number(await page.locator('.diagram[data-sheet="0"]').getAttribute('data-zoom'));
  assert.ok(zoom1 > 2 * zoom0, `zoomed from ${zoom0} to ${zoom1}`);
  assert.equal(await page.locator('.diagram[data-sheet="0"]').getAttribute('data-labels'), 'shown');
  // The crossing nearest the panel's centre (the wheel zoomed in there).
  const { hex, x, y } = await page.evaluate(() => {
    const svg = document.querySelector('.diagram[data-sheet="0"] svg').getBoundingClientRect();
    let best = null;
    for (const c of document.querySelectorAll('.diagram[data-sheet="0"] .crossing')) {
      const r = c.getBoundingClientRect();
      const x = r.x + r.width / 2, y = r.y + r.height / 2;
      const d = Math.hypot(x - (svg.x + svg.width / 2), y - (svg.y + svg.height / 2));
      if (!best || d < best.d) best = { d, x, y, hex: Number(c.dataset.hex) };
    }
    return best;
  });
  // Hovering a crossing shows its hex in 3D too (a hover mark, nothing selected yet).
  const marks = () => page.evaluate(() => window.hexdual.view.marksShown);
  await page.mouse.move(box.x + 2, box.y + 2);
  await page.evaluate(() => window.hexdual.actions.select(null));  // the list's click selected the sheet
  await settle();
  assert.equal(await marks(), 0);
  await page.mouse.move(x, y, { steps: 3 });
  await page.waitForFunction(() => window.hexdual.view.marksShown > 0);
  await settle();
  await page.screenshot({ path: join(screenshotDir, 'explorer-diagram-hover.png') });
  await page.mouse.move(box.x + 2, box.y + 2);
  await page.waitForFunction(() => window.hexdual.view.marksShown === 0);
  await page.mouse.click(x, y);
  assert.deepEqual((await state()).selection, { kind: 'hex', hex });
  assert.match(hash(), new RegExp(`sel=h${hex}&diag=0`));
  await page.screenshot({ path: join(screenshotDir, 'explorer-diagram.png') });
  // Two diagrams side by side: the sheets through the selected hex.
  await page.click('#open-sheets');
  assert.ok((await page.locator('.diagram').count()) >= 2);
  await page.screenshot({ path: join(screenshotDir, 'explorer-diagrams.png') });
});

test('a long disk fills a wide panel lying down; on a phone two fingers pinch-zoom a diagram and labels appear', async () => {
  await open('#mesh=grid:20x3x2&diag=2');
  const panel = page.locator('.diagram[data-sheet="2"]');
  await panel.locator('svg .crossing').first().waitFor();
  assert.equal(await panel.locator('svg .crossing').count(), 60);
  const extentOf = () => page.evaluate(() => {
    const svg = document.querySelector('.diagram[data-sheet="2"] svg').getBoundingClientRect();
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const c of document.querySelectorAll('.diagram[data-sheet="2"] .crossing')) {
      const r = c.getBoundingClientRect();
      x0 = Math.min(x0, r.x); x1 = Math.max(x1, r.right); y0 = Math.min(y0, r.y); y1 = Math.max(y1, r.bottom);
    }
    return { w: x1 - x0, h: y1 - y0, panel: svg.width };
  });
  const e = await extentOf();
  assert.ok(e.w > 4 * e.h, `the 20 x 3 layer lies down: ${JSON.stringify(e)}`);
  assert.ok(e.w > 0.7 * e.panel, `and fills the panel's width: ${JSON.stringify(e)}`);
  // Its panel opens in the drawing's shape (wide), so its labels fit without a resize.
  const pb = await panel.boundingBox();
  assert.ok(pb.width > 1.6 * pb.height, `a wide panel: ${pb.width} x ${pb.height}`);
  assert.ok(await panel.evaluate((p) => [...p.querySelectorAll('.labels text')].filter((t) => t.style.display !== 'none').length) >= 40, 'most crossings labelled');
  const overlaps = await panel.evaluate((p) => {
    const r = [...p.querySelectorAll('.labels text')].filter((t) => t.style.display !== 'none').map((t) => t.getBoundingClientRect());
    let n = 0;
    for (let i = 0; i < r.length; i++)
      for (let j = i + 1; j < r.length; j++)
        if (r[i].left < r[j].right - 1 && r[j].left < r[i].right - 1 && r[i].top < r[j].bottom - 1 && r[j].top < r[i].bottom - 1) n++;
    return n;
  });
  assert.equal(overlaps, 0, 'no two labels overlap');
  await page.screenshot({ path: join(screenshotDir, 'explorer-diagram-long.png') });

  await page.setViewportSize({ width: 390, height: 844 });
  await open('#mesh=grid:6x6x3&diag=13');
  const svg = page.locator('.diagram[data-sheet="13"] svg');
  await svg.locator('.crossing').first().waitFor();
  await svg.scrollIntoViewIfNeeded();
  const zoom0 = Number(await page.locator('.diagram[data-sheet="13"]').getAttribute('data-zoom'));
  const labelsShown = () => page.evaluate(() => [...document.querySelectorAll('.diagram[data-sheet="13"] .labels text')].filter((t) => t.style.display !== 'none').length);
  const before = await labelsShown();
  const selection = (await state()).selection;
  // Two touch pointers move apart from the panel's centre (synthetic events, as a phone sends them).
  await svg.evaluate((el) => {
    const r = el.getBoundingClientRect(), cx = r.x + r.width / 2, cy = r.y + r.height / 2;
    const ev = (type, id, x) => el.dispatchEvent(new PointerEvent(type, { pointerId: id, pointerType: 'touch', isPrimary: id === 1, clientX: x, clientY: cy, bubbles: true }));
    ev('pointerdown', 1, cx - 20);
    ev('pointerdown', 2, cx + 20);
    for (let k = 1; k <= 10; k++) ev('pointermove', 1, cx - 20 - 8 * k), ev('pointermove', 2, cx + 20 + 8 * k);
    ev('pointerup', 2, cx + 100);
    ev('pointerup', 1, cx - 100);
  });
  const zoom1 = Number(await page.locator('.diagram[data-sheet="13"]').getAttribute('data-zoom'));
  assert.ok(zoom1 > 4 * zoom0, `pinched from ${zoom0} to ${zoom1}`);
  assert.ok((await labelsShown()) >= before, 'labels stay or appear as the crossings spread');
  assert.deepEqual((await state()).selection, selection, 'a pinch selects nothing');
  await page.screenshot({ path: join(screenshotDir, 'explorer-diagram-pinched-phone.png') });
  await page.setViewportSize({ width: 1200, height: 760 });
  assert.deepEqual(errors, []);
});

test('dual overlay, quality colouring with a histogram, slicing plane', async () => {
  await open('#mesh=grid:3x3x3&steps=v1;pillow%20h13f5&overlay=1&color=quality&slice=y:0.5');
  assert.equal(await page.evaluate(() => window.hexdual.view.overlayShown), true);
  assert.match(await page.locator('#quality-summary').textContent(), /29 hexes · 1 inverted: h28/);
  await page.screenshot({ path: join(screenshotDir, 'explorer-overlay.png') });
});

test('drop a file on the page: it loads, the URL says it is local, and .hxd + steps is offered', async () => {
  await open('#mesh=grid:3x3x3');
  const file = '/tmp/hexdual_browser_drop.hxd';
  cli('grid', '2x2x2', '-o', file);
  await dropFile(readFileSync(file, 'utf8'), 'cube8.hxd');
  await page.waitForFunction(() => window.hexdual.store.get().mesh.counts.hexes === 8);
  assert.match(hash(), /mesh=file:cube8\.hxd/);
  assert.match(await page.locator('#notice').textContent(), /cube8\.hxd is a local file/);
  assert.ok(await page.locator('#exports button', { hasText: 'download .hxd + steps' }).isVisible());
  // The exports themselves (PNG with the URL, every format, .hxd + steps): explorer.test.mjs.
});

test('flips view: step through the 3-5e decomposition with before and after', async () => {
  await open('#view=flips');
  const flips = await page.evaluate(() => window.hexdual.actions.flips.filter((f) => f.steps).map((f) => f.name));
  const name = flips.includes('3-5e') ? '3-5e' : flips[0];
  await page.selectOption('#flip-name', name);
  await page.click('#flip-load');
  const total = (await state()).steps.length;
  assert.ok(total >= 1);
  assert.match(await page.locator('#flip-status').textContent(), new RegExp(`before side; ${total} steps`));
  await page.screenshot({ path: join(screenshotDir, 'explorer-flip-before.png') });
  for (let i = 1; i <= total; i++) {
    await page.keyboard.press('ArrowRight');
    assert.equal((await state()).at, i);
    assert.match(await page.locator('#flip-status').textContent(), new RegExp(`step ${i} of ${total}`));
  }
  assert.match(await page.locator('#flip-status').textContent(), /the after side/);
  await settle();
  await page.screenshot({ path: join(screenshotDir, 'explorer-flip-after.png') });
  await page.keyboard.press('ArrowLeft');
  assert.equal((await state()).at, total - 1);
});

test('flips view: the 4-4 vertex flip (triple-hex push) steps through its 8 atomic steps', async () => {
  await open('#view=flips');
  await page.selectOption('#flip-name', '4-4v');
  await page.click('#flip-load');
  assert.equal((await state()).steps.length, 8);
  assert.match(await page.locator('#flip-status').textContent(), /before side; 8 steps/);
  for (let i = 1; i <= 8; i++) {
    await page.keyboard.press('ArrowRight');
    assert.equal((await state()).at, i);
    if (i === 4) {
      await settle();
      await page.screenshot({ path: join(screenshotDir, 'explorer-flip-44v-step4.png') });
    }
  }
  assert.match(await page.locator('#flip-status').textContent(), /step 8 of 8/);
  assert.match(await page.locator('#flip-status').textContent(), /the after side/);
  assert.equal(await page.evaluate(() => window.hexdual.store.get().mesh.counts.hexes), 8);
  await settle();
  await page.screenshot({ path: join(screenshotDir, 'explorer-flip-44v-after.png') });
});

test('the triple-chord push decomposition: the tutorial link replays its 8 steps in the explorer', async () => {
  // The link the flips tutorial writes from the stored record (tutorials.test.mjs checks the page's).
  const { steps } = decompositions().find((r) => r.problem === 'tripleChordPush');
  const href = `#mesh=grid:3x3x3&steps=${['v1', ...steps].join(';').replace(/ /g, '%20')}&at=0&slice=z:0.4`;
  await open(href);
  const s = await state();
  assert.ok(!s.error, s.error);
  assert.deepEqual(s.steps, ['hexpush h4f5', 'hexpush h29f2', 'facecollapse h1e11 h5f0 h34f2', 'ringcollapse h30e4',
    'facesplit h28f4 h36f4', 'facecollapse h7e2 h27f5 h35f5', 'facesplit h27f1 h5f0', 'chordpull h35']);
  // The link opens before the first step, so a student steps forward and sees each step's change.
  assert.equal(s.at, 0);
  assert.equal((await shownCounts()).hexes, 27);
  const hexesAfter = [31, 35, 35, 31, 31, 31, 31, 29];
  for (let i = 1; i <= 8; i++) {
    await page.keyboard.press('ArrowRight');
    assert.equal((await state()).at, i);
    assert.equal((await shownCounts()).hexes, hexesAfter[i - 1], `hexes after step ${i}`);
    if (i === 2) {
      await settle();
      await page.screenshot({ path: join(screenshotDir, 'explorer-triple-chord-push-step2.png') });
    }
  }
  // 27 hexes + the triple-chord push's 2; (V, E, F, H) change by (+2, +6, +6, +2).
  assert.deepEqual(await shownCounts(), { ...(await shownCounts()), vertices: 66, edges: 150, quads: 114, hexes: 29 });
  await settle();
  await page.screenshot({ path: join(screenshotDir, 'explorer-triple-chord-push.png') });
});

test('phone width: the page stacks and still shows the mesh', async () => {
  await page.setViewportSize({ width: 375, height: 812 });
  await open('#mesh=grid:3x3x3&steps=v1;pillow%20h13f5&sel=s9&diag=9');
  await page.screenshot({ path: join(screenshotDir, 'explorer-phone.png'), fullPage: true });
  assert.equal((await shownCounts()).hexes, 29);
  await page.setViewportSize({ width: 1200, height: 760 });
  assert.deepEqual(errors, []);
});
