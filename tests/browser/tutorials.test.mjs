// The tutorial pages in headless Chromium: every page loads without console errors, every live
// figure draws (pixels), every step button changes it, every "open in explorer" link reproduces the
// figure's state in the explorer, the live numbers are the engine's, and the exercises check.
// Screenshots at 1280 and 375 px land in build/screenshots/tutorials-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { startServer, startBrowser, screenshotDir } from './harness.mjs';

const PAGES = ['dual', 'diagrams', 'simple', 'pillow', 'push', 'collapse', 'flips', 'puzzles'];
let server, context, page;
const problems = [];

before(async () => {
  server = await startServer();
  context = await startBrowser();
  page = await context.newPage();
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
});
after(async () => {
  await context?.close();
  server?.stop();
});

async function open(name, width = 1280) {
  await page.setViewportSize({ width, height: 900 });
  const started = Date.now();
  await page.goto(`${server.url}tutorials/${name}.html`);
  await page.waitForFunction(() => window.tutorial?.ready === true, null, { timeout: 30000 });
  return Date.now() - started;
}

// Non-white pixels of a figure's WebGL canvas (drawn with preserveDrawingBuffer).
async function inkOf(k) {
  await drawn(k);
  return page.evaluate(async (k) => {
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const src = window.tutorial.figures[k].canvas;
    const c = document.createElement('canvas');
    c.width = src.width;
    c.height = src.height;
    const g = c.getContext('2d');
    g.drawImage(src, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    for (let i = 0; i < px.length; i += 4) if (px[i] < 245 || px[i + 1] < 245 || px[i + 2] < 245) ink++;
    return ink;
  }, k);
}

// What a figure shows: stage, counts, the diagram's markup and a pixel digest of the canvas.
async function signature(k) {
  await drawn(k);
  return page.evaluate(async (k) => {
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const f = window.tutorial.figures[k];
    const c = document.createElement('canvas');
    c.width = 64;
    c.height = 64;
    c.getContext('2d').drawImage(f.canvas, 0, 0, 64, 64);
    const px = c.getContext('2d').getImageData(0, 0, 64, 64).data;
    let digest = 0;
    for (let i = 0; i < px.length; i++) digest = (digest * 31 + px[i]) >>> 0;
    return JSON.stringify({ stage: f.stage, counts: f.counts(), svg: f.root.querySelector('.diagram')?.innerHTML.length, digest });
  }, k);
}

// A figure makes its WebGL view when it first scrolls into sight.
async function drawn(k) {
  await page.locator('.figure').nth(k).scrollIntoViewIfNeeded();
  await page.waitForFunction((k) => window.tutorial.figures[k].canvas !== null, k, { timeout: 10000 });
}

async function figureCount() {
  return page.evaluate(() => window.tutorial.figures.length);
}

test('the index links every page, and the explorer links the tutorials', async () => {
  await page.setViewportSize({ width: 1280, height: 900 });
  await page.goto(`${server.url}tutorials/index.html`);
  const hrefs = await page.$$eval('.toc a', (as) => as.map((a) => a.getAttribute('href')));
  assert.deepEqual(hrefs, PAGES.map((p) => `${p}.html`));
  await page.screenshot({ path: join(screenshotDir, 'tutorials-index-1280.png'), fullPage: true });
  await page.goto(server.url);
  await page.waitForFunction(() => window.hexdual?.ready === true, null, { timeout: 20000 });
  await page.locator('a[href="./tutorials/index.html"]').click();
  await page.waitForURL(/tutorials\/index\.html$/);
});

for (const name of PAGES) {
  test(`${name}: loads, draws every figure, no console errors, screenshots`, async () => {
    problems.length = 0;
    const ms = await open(name);
    const t = await page.evaluate(() => window.tutorial.timings);
    console.log(`${name}: ready ${t.sinceNavigationMs} ms after navigation (engine ${t.engineMs} ms, page ${t.pageMs} ms; ${ms} ms in the test incl. loading); headless Chromium, software GL, shared machine`);
    const n = await figureCount();
    assert.ok(n >= 1, `${name} has a live figure`);
    for (let k = 0; k < n; k++) assert.ok((await inkOf(k)) > 2000, `${name} figure ${k} drew something`);
    await page.screenshot({ path: join(screenshotDir, `tutorials-${name}-1280.png`), fullPage: true });
    await open(name, 375);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 1, `${name} fits 375 px (overflow ${overflow} px)`);
    for (let k = 0; k < (await figureCount()); k++) assert.ok((await inkOf(k)) > 1000, `${name} figure ${k} drew at 375 px`);
    await page.screenshot({ path: join(screenshotDir, `tutorials-${name}-375.png`), fullPage: true });
    assert.deepEqual(problems, []);
  });

  test(`${name}: every step button and the before/after toggle change the figure`, async () => {
    await open(name);
    const n = await figureCount();
    for (let k = 0; k < n; k++) {
      const fig = page.locator('.figure').nth(k);
      const stages = await page.evaluate((k) => window.tutorial.figures[k].stages.length, k);
      if (stages < 2) continue;
      await page.evaluate((k) => window.tutorial.figures[k].go(0), k);
      let seen = await signature(k);
      for (let s = 1; s < stages; s++) {
        await fig.locator('[data-action=forward]').click();
        const now = await signature(k);
        assert.notEqual(now, seen, `${name} figure ${k}: step ▶ to stage ${s} changed nothing`);
        seen = now;
      }
      assert.equal(await fig.locator('[data-action=forward]').isDisabled(), true);
      await fig.locator('[data-action=back]').click();
      assert.notEqual(await signature(k), seen, `${name} figure ${k}: ◀ changed nothing`);
      await fig.locator('[data-action=toggle]').click();
      assert.equal(await fig.getAttribute('data-stage'), String(stages - 1));
      await fig.locator('[data-action=toggle]').click();
      assert.equal(await fig.getAttribute('data-stage'), '0');
      // Keyboard: → on the focused figure steps forward.
      await fig.focus();
      await page.keyboard.press('ArrowRight');
      assert.equal(await fig.getAttribute('data-stage'), '1');
    }
  });

  test(`${name}: every "open in explorer" link reproduces the figure's state`, async () => {
    await open(name);
    const n = await figureCount();
    const explorer = await context.newPage();
    try {
      for (let k = 0; k < n; k++) {
        const stages = await page.evaluate((k) => window.tutorial.figures[k].stages.length, k);
        for (const stage of new Set([0, stages - 1])) {
          const want = await page.evaluate(
            ({ k, stage }) => {
              const f = window.tutorial.figures[k];
              f.go(stage);
              const link = f.root.querySelector('.explorer-link');
              return { href: link.hidden ? null : link.href, counts: f.counts(), ops: f.stages[stage].ops, hash: f.canonicalHash() };
            },
            { k, stage },
          );
          if (want.href === null) continue; // a mesh built in the page from a file: no explorer link
          await explorer.goto(want.href);
          await explorer.waitForFunction(() => window.hexdual?.ready === true, null, { timeout: 20000 });
          const got = await explorer.evaluate(() => {
            const s = window.hexdual.store.get();
            return { counts: { ...s.mesh.counts, ...s.mesh.dualSizes() }, ops: s.steps.slice(0, s.at), error: s.error ?? "", hash: s.mesh.canonicalHash() };
          });
          assert.equal(got.error, '', `${name} figure ${k} stage ${stage}: explorer error`);
          assert.deepEqual(got.ops, want.ops, `${name} figure ${k} stage ${stage}: steps`);
          assert.deepEqual(got.counts, want.counts, `${name} figure ${k} stage ${stage}: counts`);
          assert.equal(got.hash, want.hash, `${name} figure ${k} stage ${stage}: canonical hash`);
        }
      }
    } finally {
      await explorer.close();
    }
  });
}

test('live numbers: the paper\'s counts match the engine', async () => {
  await open('push');
  assert.deepEqual(await page.$$eval('[data-live^="cp-"]', (e) => e.map((x) => x.textContent)).then((t) => t.slice(0, 5)),
    ['+2', '+6', '+6', '+2', 'the engine agrees with the paper ✓']);
  assert.equal(await page.locator('[data-live="hp-check"]').textContent(), 'the engine agrees with the paper ✓');
  assert.equal(await page.locator('[data-live="cp-blind"]').textContent(), '1');
  await open('pillow');
  assert.equal(await page.locator('[data-live="delta"]').first().textContent(), '(+4, +8, +6, +2)');
  // The README's picture (docs/images/tutorial.png is a copy of this file).
  await page.locator('.figure').first().screenshot({ path: join(screenshotDir, 'tutorials-pillow-figure.png') });
  assert.equal(await page.locator('[data-live="new-sheet"]').textContent(), 'sheet 9, a sphere of 2 hexes');
  assert.equal(await page.locator('[data-live="back"]').textContent(), 'yes, all six counts equal');
  await open('collapse');
  assert.equal(await page.locator('[data-live="trad-delta"]').textContent(), '(+8, +20, +18, +6)');
  assert.equal(await page.locator('[data-live="ring-region"]').textContent(), '7');
  assert.equal(await page.locator('[data-live="face-delta"]').textContent(), '(−2, −2, 0, 0)');
  await open('simple');
  assert.deepEqual(
    await page.$$eval('#incidences [data-live="quads"], #incidences [data-live="edges"], #incidences [data-live="vertices"]', (e) => e.map((x) => x.textContent)),
    ['6', '12', '8'],
  );
  assert.equal(await page.locator('[data-live="pillow-shared"]').textContent(), '5');
  assert.equal(await page.locator('[data-live="pillow-neighbours"]').textContent(), '2');
  await open('diagrams');
  // The twisted ring: one sheet with 16 slots on 8 hexes; its diagram shows each hex twice or says why not.
  const self = await page.locator('[data-live="self-sheets"]').textContent();
  assert.match(self, /^sheet 0 has 16 slots on 8 hexes; its diagram shows (\d+) crossings, (\d+) hexes twice$/);
  const [, crossings, twice] = /shows (\d+) crossings, (\d+) hexes twice/.exec(self).map(Number);
  assert.ok(crossings >= 15 && twice >= 7, self);
});

test('picking a hex on the Theorems page counts at its dual vertex', async () => {
  await open('simple');
  await page.locator('[data-action=forward]').click();
  await page.fill('#hex-id', '27');
  await page.locator('#hex-pick').click();
  assert.equal(await page.locator('#incidences [data-live="picked"]').textContent(), '27');
  assert.equal(await page.locator('#incidences [data-live="shared"]').textContent(), '5');
  assert.equal(await page.locator('#incidences [data-live="quads"]').textContent(), '6');
});
