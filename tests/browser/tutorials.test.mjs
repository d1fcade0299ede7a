// The tutorial pages in headless Chromium: every page loads without console errors, every live
// figure draws (pixels), every step button changes it, every "open in explorer" link reproduces the
// figure's state in the explorer, the live numbers are the engine's, and the exercises check.
// Screenshots at 1280 and 375 px land in build/screenshots/tutorials-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { writeFileSync } from 'node:fs';
import { pageSession, screenshotDir } from './harness.mjs';
import { init, Mesh, flips, decompositions } from 'hexdual';

await init();
const record = (problem) => decompositions().find((r) => r.problem === problem);

const PAGES = ['dual', 'diagrams', 'simple', 'pillow', 'push', 'collapse', 'flips', 'puzzles'];
let server, context, page;
const { problems } = pageSession(before, after, (s) => ({ server, context, page } = s));

async function open(name, width = 1280, motion = 'reduce') {
  await page.emulateMedia({ reducedMotion: motion });
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
    await open(name, 390);
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 1, `${name} fits 390 px (overflow ${overflow} px)`);
    for (let k = 0; k < (await figureCount()); k++) assert.ok((await inkOf(k)) > 1000, `${name} figure ${k} drew at 390 px`);
    await page.screenshot({ path: join(screenshotDir, `tutorials-${name}-390.png`), fullPage: true });
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
  // The chord-push figure (TK03 Fig. 2) draws a pushed sheet whole, with the blind chord: a closed
  // chord through exactly the two new hexes.
  const cpDiagram = page.locator('#fig-chordpush .diagram svg');
  assert.equal(await cpDiagram.getAttribute('data-method'), 'disk');
  assert.equal(await page.locator('#fig-chordpush .diagram-note').count(), 0, 'no note: the whole sheet is drawn');
  assert.deepEqual(await cpDiagram.locator('polyline[data-closed="1"]').evaluateAll((ls) => ls.map((l) => l.dataset.hexes.split(' ').map(Number).sort((a, b) => a - b).join(' '))), ['27 28']);
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
  // The merged annulus has a neck of 4 sides: drawn cut open along one seam, not squeezed round its hole.
  assert.match(await page.locator('#fig-face .diagram-note').textContent(), /^cut open along 1 seam: dashed sides with the same letter are the same seam/);
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

const liveText = (name) => page.locator(`[data-live="${name}"]`).first().textContent();

test('flips: every step count and bound on the page is the stored record\'s', async () => {
  await open('flips');
  const v44 = record('4-4v'), tcp = record('tripleChordPush');
  assert.equal(await liveText('v44-steps'), String(v44.steps.length));
  assert.equal(await liveText('v44-shorter'), String(v44.depthSearched - 1));
  assert.equal(await liveText('v44-states'), v44.states.toLocaleString('en'));
  assert.equal(await liveText('tcp-steps'), String(tcp.steps.length));
  assert.equal(await liveText('tcp-shorter'), String(tcp.depthSearched - 1));
  assert.equal(await liveText('tcp-states'), tcp.states.toLocaleString('en'));
  // The largest region along the 4-4v steps, replayed here in Node.
  const f = flips().find((x) => x.name === '4-4v');
  const m = Mesh.fourCube();
  let most = 0;
  for (const s of f.steps) (m.apply(s), (most = Math.max(most, m.counts.hexes - (8 - f.before.length))));
  m.delete();
  assert.equal(await liveText('v44-region'), String(most));
  // The explorer link replays the stored triple-chord push.
  const href = decodeURIComponent(await page.locator('#tcp-explorer').getAttribute('href'));
  assert.ok(href.includes(`steps=${['v1', ...tcp.steps].join(';')}&at=0`), href);
  // The flip table and the picker: the stored steps of every flip.
  const rows = await page.$$eval('#flip-table tbody tr', (trs) => trs.map((tr) => [...tr.cells].map((td) => td.textContent)));
  assert.deepEqual(rows.map((r) => [r[0], r[4]]), flips().map((x) => [x.name, x.steps ? x.steps.join('; ') : 'none found']));
  const options = await page.$$eval('#flip-name option', (os) => os.map((o) => o.textContent));
  assert.deepEqual(options, flips().filter((x) => x.steps).map((x) => `${x.name} (${x.steps.length} step${x.steps.length === 1 ? '' : 's'})`));
  assert.equal(await liveText('flip-names'), '1-7, 2-6, 3-5c, 3-5e, 4-4m, 4-4v');
  assert.match(await page.locator('main').textContent(), /six kinds \(and their inverses\)/);
  assert.equal(await liveText('chord-only-bound'), String(record('2-6/chord-only').depthSearched + 1));
});

test('push: the chord-only sentence is the stored record with the parity argument, from the engine', async () => {
  await open('push');
  const r = record('2-6/chord-only');
  assert.equal(r.found, false);
  assert.equal(await liveText('co-searched'), String(r.depthSearched));
  assert.equal(await liveText('co-states'), r.states.toLocaleString('en'));
  // A chord push adds 2 hexes, a hex push 4: sequences are even, so depth 8 searched rules out 9.
  assert.deepEqual([await liveText('co-push'), await liveText('co-hexpush'), await liveText('co-parity')], ['2', '4', 'even']);
  assert.equal(await liveText('co-bound'), String(r.depthSearched + 1));
  assert.doesNotMatch(await page.locator('main').textContent(), /at most 6/);
  // Prose numbers: X and Y of the chord push share four quads; the hex push replaces hexes 13, 22 by six.
  assert.match(await page.locator('main').textContent(), /X and Y share four quads/);
  const g = Mesh.grid(3, 3, 3);
  const cp = g.apply('chordpush h13e3 h13f3 h16f5');
  const [x] = cp.created.hexes;
  const shared = new TextDecoder().decode(g.save('hxd')).split('gluings')[1].trim().split('\n').slice(1)
    .map((l) => l.split(/\s+/).map(Number)).filter(([a, , b]) => (a === x && b === x + 1) || (a === x + 1 && b === x)).length;
  g.delete();
  assert.equal(shared, 4, 'the chord push\'s two hexes are glued across 4 quads');
  const h = Mesh.grid(3, 3, 3).apply('hexpush h13f5');
  assert.deepEqual([h.removed.hexes, h.created.hexes.length], [[13, 22], 6]);
  assert.match(await page.locator('#fig-hexpush .caption').textContent(), /hexes 13 and 22 are replaced by a swapped pair; four new hexes surround them \(all six in orange\)/);
});

test('the 4-cube on the flips page: eight labelled cubes apart, the two sides in two colours, at desktop and phone size', async () => {
  for (const width of [1280, 390]) {
    await open('flips', width);
    await page.locator('#fig-flip').scrollIntoViewIfNeeded();
    await drawn(0);
    const cubes = await page.evaluate(() => {
      const f = window.tutorial.figures[0];
      const at = [...Array(8).keys()].map((h) => f.view.project(h));
      const labels = [...f.root.querySelectorAll('.hex-labels span')].map((s) => [s.textContent, s.className]);
      let closest = Infinity;
      for (let a = 0; a < 8; a++) for (let b = a + 1; b < 8; b++) if (a !== 6 && b !== 6) closest = Math.min(closest, Math.hypot(at[a].x - at[b].x, at[a].y - at[b].y));
      return { labels, closest };
    });
    assert.deepEqual(cubes.labels.map(([t]) => t), ['0', '1', '2', '3', '4', '5', '6 (outer)', '7']);
    assert.deepEqual(cubes.labels.map(([, c]) => c), ['before', 'after', 'after', 'after', 'after', 'after', 'after', 'after']);
    assert.ok(cubes.closest > (width > 600 ? 40 : 20), `cube centres at least ${cubes.closest.toFixed(0)} px apart`);
    // Blue (before) and orange (after) pixels on the canvas.
    const colours = await page.evaluate(() => {
      const src = window.tutorial.figures[0].canvas;
      const c = document.createElement('canvas');
      [c.width, c.height] = [src.width, src.height];
      c.getContext('2d').drawImage(src, 0, 0);
      const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let blue = 0, orange = 0;
      for (let i = 0; i < px.length; i += 4) {
        if (px[i + 2] > px[i] + 40) blue++;
        if (px[i] > px[i + 2] + 60 && px[i + 1] > px[i + 2]) orange++;
      }
      return { blue, orange };
    });
    assert.ok(colours.blue > 300 && colours.orange > 300, JSON.stringify(colours));
    await page.locator('#fig-flip').screenshot({ path: join(screenshotDir, `tutorials-fourcube-${width}.png`) });
  }
  assert.deepEqual(problems, []);
});

test('an animated step: hexes move and fade in 3D and crossings move in the diagram, not with reduced motion', async () => {
  await open('pillow', 1280, 'no-preference');
  const fig = page.locator('.figure').first();
  await fig.scrollIntoViewIfNeeded();
  await drawn(0);
  await page.evaluate(() => window.tutorial.figures[0].go(0));
  await page.evaluate(() => new Promise((r) => setTimeout(r, 600)));
  const mid = await page.evaluate(async () => {
    const f = window.tutorial.figures[0];
    f.root.querySelector('[data-action=forward]').click();
    await new Promise((r) => setTimeout(r, 120));
    return { view: f.view.animating, any: f.animating };
  });
  assert.deepEqual(mid, { view: true, any: true });
  await fig.screenshot({ path: join(screenshotDir, 'tutorials-animated-step.png') });
  await page.evaluate(() => new Promise((r) => setTimeout(r, 700)));
  assert.equal(await page.evaluate(() => window.tutorial.figures[0].animating), false);
  // The flips page steps through a decomposition: the 3-5e flip's face collapse (step 2) reshapes
  // hexes in 3D and moves crossings on the same sheet. A filmstrip of the step for docs/tutorials.md.
  await open('flips', 1280, 'no-preference');
  await page.selectOption('#flip-name', '3-5e');
  await drawn(0);
  const strip = await page.evaluate(async () => {
    const f = window.tutorial.figures[0];
    f.go(1);
    f.selectSheet(f.sheet);
    await new Promise((r) => setTimeout(r, 700));
    const svgImage = async (svg) => {
      const text = new XMLSerializer().serializeToString(svg);
      const img = new Image();
      img.src = URL.createObjectURL(new Blob([text], { type: 'image/svg+xml' }));
      await img.decode();
      return img;
    };
    const frames = [];
    f.go(2);
    const animating = [f.view.animating, f.diagramView.animating];
    const t0 = performance.now();
    for (const at of [0, 120, 240, 360, 600]) {
      while (performance.now() - t0 < at) await new Promise((r) => requestAnimationFrame(r));
      frames.push({ gl: f.canvas.toDataURL(), svg: await svgImage(f.root.querySelector('.diagram svg')) });
    }
    // Five frames side by side: 3D above, the sheet diagram below.
    const w = 300, out = document.createElement('canvas');
    [out.width, out.height] = [5 * w, 2 * w];
    const g = out.getContext('2d');
    g.fillStyle = 'white';
    g.fillRect(0, 0, out.width, out.height);
    for (const [k, fr] of frames.entries()) {
      const gl = new Image();
      gl.src = fr.gl;
      await gl.decode();
      const s = Math.min(w / gl.width, w / gl.height);
      g.drawImage(gl, k * w + (w - gl.width * s) / 2, (w - gl.height * s) / 2, gl.width * s, gl.height * s);
      g.drawImage(fr.svg, k * w + 10, w + 10, w - 20, w - 20);
      g.fillStyle = '#555';
      g.font = '14px sans-serif';
      g.fillText(`${[0, 120, 240, 360, 600][k]} ms`, k * w + 8, 18);
    }
    return { animating, png: out.toDataURL('image/png') };
  });
  assert.deepEqual(strip.animating, [true, true], 'the 3D view and the diagram of the same sheet animate the step');
  writeFileSync(join(screenshotDir, 'tutorials-animated-step-strip.png'), Buffer.from(strip.png.split(',')[1], 'base64'));
  await open('pillow', 1280, 'reduce');
  await drawn(0);
  const reduced = await page.evaluate(() => {
    const f = window.tutorial.figures[0];
    f.go(0);
    f.go(1);
    return f.animating;
  });
  assert.equal(reduced, false);
  assert.deepEqual(problems, []);
});
