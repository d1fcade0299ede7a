// The puzzles page played as a student plays it: every puzzle solved by pointer clicks on the 3D
// view or the sheet diagram (pick, point at an operation, click it), reaching its goal with the
// score shown against the shortest known; progress survives a reload and travels in the URL; the
// typed steps still work; the page fits a phone. Screenshots in build/screenshots/puzzles-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pageSession, screenshotDir } from './harness.mjs';

let server, context, page;
const { problems } = pageSession(before, after, (s) => ({ server, context, page } = s));
let viaDiagram = 0;

async function openPuzzle(id, width = 1280, { steps = '', motion = 'reduce' } = {}) {
  await page.emulateMedia({ reducedMotion: motion });
  await page.setViewportSize({ width, height: width < 600 ? 844 : 800 });
  await page.goto(`${server.url}tutorials/puzzles.html#p=${id}${steps}`);
  await page.waitForFunction(() => window.tutorial?.ready === true, null, { timeout: 30000 });
  await page.locator('#fig-puzzle').scrollIntoViewIfNeeded();
  await page.waitForFunction(() => window.tutorial.puzzle.figure.canvas !== null, null, { timeout: 10000 });
  await settle();
}

// Every step animation has ended and two frames are drawn.
const settle = () => page.evaluate(async () => {
  const frame = () => new Promise((r) => requestAnimationFrame(r));
  while (window.tutorial.puzzle.figure.animating) await frame();
  await frame();
  await frame();
});

const puzzle = () => page.evaluate(() => {
  const p = window.tutorial.puzzle;
  return { id: p.id, steps: p.steps, pick: p.pick, best: p.best, reference: p.reference };
});

/**
 * Where to click so that the pick offers `step`: samples the canvas around the step's first entity
 * (a quad's centre, a point near an edge, a hex's centre) and asks the page's own picker what is
 * there. Returns { x, y, mode } in page pixels, or null when it is hidden from this side.
 */
function findPick(step, exact) {
  return page.evaluate(([step, exact]) => {
    const fig = window.tutorial.puzzle.figure, view = fig.view, mesh = fig.mesh;
    const op = step.split(' ')[0];
    const m = /h(\d+)([fe]?)(\d*)/.exec(step.slice(op.length));
    const hex = Number(m[1]);
    // Whether a pick offers the step, or one of the same operation with the same result.
    const target = (mesh.apply(step), mesh.canonicalHash() + (mesh.undo(), ''));
    const offers = (p) => {
      if (!p) return false;
      const near = p.kind === 'hex' ? { hex: p.hex } : p.kind === 'quad' ? { hex: p.hex, face: p.face } : { hex: p.hex, edge: p.edge };
      const list = op === 'ringsplit' ? (p.kind === 'edge' ? mesh.ringSplits(near) : []) : mesh.candidates(op, { near });
      return list.includes(step) || (!exact && list.some((c) => (mesh.apply(c), mesh.canonicalHash() + (mesh.undo(), '')) === target));
    };
    // Every incidence of the entity (the same corner vertices, from the .hxd model), then page
    // points where a pick of it can land: over each side of the quad, along the edge on every face
    // that has it, or the hex's centre.
    const tables = view.tables, model = fig.model;
    const key = (h, corners) => corners.map((c) => model.corners[8 * model.index.get(h) + c]).sort((a, b) => a - b).join(',');
    const edgeKey = (h, e) => key(h, [tables.edgeCorners[2 * e], tables.edgeCorners[2 * e + 1]]);
    const faceKey = (h, f) => key(h, [0, 1, 2, 3].map((q) => tables.faceCorners[4 * f + q]));
    const edgesLike = (h, e) => model.ids.flatMap((g) => [...Array(12).keys()].filter((x) => edgeKey(g, x) === edgeKey(h, e)).map((x) => [g, x]));
    const points = [];
    const alongEdge = ([g, x]) => { for (let f = 0; f < 6; f++) points.push(...view.facePoints(g, f, x)); };
    if (op === 'ringsplit') {
      for (let e = 0; e < 12; e++) if (mesh.ringSplits({ hex, edge: e }).includes(step)) edgesLike(hex, e).forEach(alongEdge);
    } else if (m[2] === 'f') {
      const f0 = Number(m[3]);
      for (const g of model.ids) for (let f = 0; f < 6; f++) if (faceKey(g, f) === faceKey(hex, f0)) points.push(...view.facePoints(g, f));
    } else if (m[2] === 'e') edgesLike(hex, Number(m[3])).forEach(alongEdge);
    else for (const g of model.ids) points.push(view.project(g));
    const mode = op === 'ringsplit' || m[2] === 'e' ? 'edge' : m[2] === 'f' ? 'quad' : 'hex';
    const tried = new Map();
    const inView = ({ x, y }) => x >= 0 && y >= 0 && x < innerWidth && y < innerHeight;
    for (const { x, y } of points.filter(inView)) {
      const p = view.pickAt(x, y, mode);
      const key = JSON.stringify(p);
      if (!tried.has(key)) tried.set(key, offers(p));
      if (tried.get(key)) return { x, y, mode };
    }
    return null;
  }, [step, exact]);
}

// Turns the figure by dragging on its canvas (as a student does when a place is hidden): a fifth
// of a turn around the vertical per call, tilted after a whole turn.
async function turn(k) {
  const box = await page.locator('#fig-puzzle canvas').boundingBox();
  const [x, y] = [box.x + box.width / 2, box.y + box.height * 0.85];
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + box.height * 0.2, y + (k === 4 ? -box.height * 0.12 : 0), { steps: 5 });
  await page.mouse.up();
  await settle();
}

/** Plays one step by pointer: a crossing in the diagram for a hex step where it shows, else the 3D view. */
async function play(step, { preview = false } = {}) {
  const hexOnly = /^(unpillow|chordpull) h(\d+)$/.exec(step);
  let picked = false;
  if (hexOnly) {
    // The hex's crossing in the sheet diagram, where no other crossing covers it.
    const at = await page.evaluate((hex) => {
      const c = window.tutorial.puzzle.figure.diagramView.crossingAt(hex);
      const top = c && document.elementFromPoint(c.x, c.y);
      return top && top.dataset?.hex === String(hex) ? c : null;
    }, Number(hexOnly[2]));
    if (at) {
      await page.mouse.click(at.x, at.y);
      picked = true;
      viaDiagram++;
    }
  }
  // The pick mode for the step's first entity (the radio is clicked first: it may scroll the page).
  const mode = step.startsWith('ringsplit') || /^\w+ h\d+e/.test(step) ? 'edge' : /^\w+ h\d+f/.test(step) ? 'quad' : 'hex';
  if (!picked) {
    await page.locator(`input[name=pick][value=${mode}]`).check();
    await page.locator('#fig-puzzle canvas').scrollIntoViewIfNeeded();
  }
  // The step as written where it shows (its ids keep the rest of the answer valid), else an equal one.
  for (let attempt = 0; !picked && attempt < 12; attempt++) {
    const at = await findPick(step, attempt < 8);
    if (!at) {
      await turn(attempt);
      continue;
    }
    await page.mouse.click(at.x, at.y);
    picked = true;
  }
  assert.ok(picked, `${step}: no place on the canvas offers it`);
  // The step itself, or the one of the same operation with the same result (the other half of a
  // blind chord, a face split named from the other sides).
  const choice = await page.evaluate((step) => {
    const p = window.tutorial.puzzle, mesh = p.figure.mesh;
    if (p.candidates.includes(step)) return step;
    const hash = (s) => (mesh.apply(s), mesh.canonicalHash() + (mesh.undo(), ''));
    const want = hash(step);
    return p.candidates.find((c) => c.split(' ')[0] === step.split(' ')[0] && hash(c) === want) ?? null;
  }, step);
  assert.ok(choice, `${step} (or an equal step) is offered at ${JSON.stringify((await puzzle()).pick)}`);
  const item = page.locator(`#candidates button.cand[data-step="${choice}"]`);
  if (preview) {
    await item.hover();
    await settle();
    assert.equal(await page.evaluate(() => window.tutorial.puzzle.figure.previewing), true, 'pointing at an operation previews it');
  }
  await item.click();
  await settle();
  return choice;
}

test('every puzzle is solved by pointer clicks, reaching its goal and the shortest known score', async () => {
  await openPuzzle('sphere');
  const all = await page.evaluate(() => window.tutorial.puzzle.puzzles);
  assert.ok(all.length >= 12, `${all.length} puzzles`);
  const timings = [];
  for (const id of all) {
    const t0 = Date.now();
    await openPuzzle(id);
    const p = await puzzle();
    assert.deepEqual(p.steps, [], `${id} starts with no steps`);
    const played = [];
    for (const [k, step] of p.reference.entries()) {
      try {
        played.push(await play(step, { preview: k === 0 }));
      } catch (e) {
        e.message = `${id}, step ${k + 1} of ${p.reference.join('; ')} (played ${played.join('; ')}): ${e.message}`;
        throw e;
      }
    }
    const done = await puzzle();
    assert.deepEqual(done.steps, played, `${id}: the steps played`);
    assert.equal(await page.locator('#puzzle').getAttribute('data-solved'), 'true', `${id}: ${await page.locator('#puzzle-check').textContent()}`);
    const score = await page.locator('#puzzle-score').textContent();
    const n = p.reference.length;
    assert.match(score, new RegExp(`^Solved in ${n} steps?\\. Shortest known: ${p.best.steps} steps? \\(`), `${id}: ${score}`);
    assert.equal(await page.locator('#puzzle-score .stars').textContent(), '★★★');
    assert.equal(await page.locator('#puzzle-log li').count(), n);
    assert.match(decodeURIComponent(new URL(page.url()).hash), new RegExp(`p=${id}&steps=v1;`));
    timings.push(`${id} ${n} steps ${((Date.now() - t0) / 1000).toFixed(1)} s`);
    if (['sphere', 'four-four-v'].includes(id)) await page.screenshot({ path: join(screenshotDir, `puzzles-${id}-solved-1280.png`), fullPage: true });
  }
  console.log(timings.join('\n'));
  assert.ok(viaDiagram >= 1, 'some hex was picked as a crossing in the sheet diagram');
  // Solved puzzles are marked in the list, with the steps used.
  assert.equal(await page.locator('.puzzle-chip', { hasText: '✓' }).count(), all.length);
  assert.deepEqual(problems, []);
});

test('progress: solved marks and the steps in play survive a reload; a shared link opens the same steps; start again', async () => {
  await openPuzzle('blind-chord');
  // The previous test solved every puzzle: the list says so after a reload (localStorage).
  await page.reload();
  await page.waitForFunction(() => window.tutorial?.ready === true);
  assert.equal(await page.locator('.puzzle-chip', { hasText: '✓' }).count(), (await page.evaluate(() => window.tutorial.puzzle.puzzles.length)));
  // Steps in play are kept per puzzle (here: the sphere's, from the previous test) …
  await page.locator('.puzzle-chip[data-puzzle="sphere"]').click();
  assert.deepEqual((await puzzle()).steps, ['pillow h0f1']);
  assert.equal(await page.locator('#puzzle').getAttribute('data-solved'), 'true');
  // … and the link carries them: another tab opens the same state.
  const link = await page.locator('#puzzle-share').getAttribute('href');
  assert.equal(decodeURIComponent(link), '#p=sphere&steps=v1;pillow h0f1');
  const other = await context.newPage();
  await other.goto(`${server.url}tutorials/puzzles.html${link}`);
  await other.waitForFunction(() => window.tutorial?.ready === true);
  assert.deepEqual(await other.evaluate(() => window.tutorial.puzzle.steps), ['pillow h0f1']);
  assert.equal(await other.locator('#puzzle-log li').count(), 1);
  assert.match(await other.locator('#puzzle-log li').textContent(), /^Pillow face 1 \(local \+x\) of hex 0: two new hexes and a sphere sheet around it — \+2 hexes \(4, 5\); sheets: new 5$/);
  await other.close();
  // Undo and start again, by their buttons.
  await page.locator('#puzzle-undo').click();
  assert.deepEqual((await puzzle()).steps, []);
  assert.equal(await page.locator('#puzzle').getAttribute('data-solved'), 'false');
  assert.match(decodeURIComponent(new URL(page.url()).hash), /^#p=sphere$/);
  assert.deepEqual(problems, []);
});

test('hints and the next step: the figure marks where to pick; typed steps still work and refused ones say why', async () => {
  await openPuzzle('one-seven', 1280, { steps: '&steps=v1' });
  await page.locator('#puzzle-hint').click();
  await page.locator('#puzzle-hint').click();
  assert.equal(await page.locator('#puzzle-hints li').count(), 2);
  await page.locator('#puzzle-next').click();
  assert.match(await page.locator('#puzzle-next-text').textContent(), /^Next: Pillow face 5 \(local \+z\) of hex 0: .* \(pillow h0f5\)\.$/);
  await page.locator('.typing summary').click();
  await page.locator('#puzzle-typed').fill('pillow h0f5\nhexpush h0f9');
  await page.locator('#puzzle-apply-typed').click();
  assert.match(await page.locator('#puzzle-typed-result').textContent(), /^applied 1; hexpush h0f9: /);
  assert.deepEqual((await puzzle()).steps, ['pillow h0f5']);
  await page.locator('#puzzle-typed').fill('hexpush h0f5');
  await page.locator('#puzzle-apply-typed').click();
  await settle();
  assert.equal(await page.locator('#puzzle').getAttribute('data-solved'), 'true');
  // Off the known answer: the hint says where it left it.
  await page.locator('#puzzle-reset').click();
  await page.locator('#puzzle-typed').fill('hexpush h0f5');
  await page.locator('#puzzle-apply-typed').click();
  await page.locator('#puzzle-next').click();
  assert.equal(await page.locator('#puzzle-next-text').textContent(), 'Your steps leave the known answer at step 1: undo back to the start to follow it.');
  assert.deepEqual(problems, []);
});

test('a step animates in 3D and in the diagram, and not with prefers-reduced-motion', async () => {
  for (const motion of ['no-preference', 'reduce']) {
    await openPuzzle('sphere', 1280, { steps: '&steps=v1', motion });
    const seen = await page.evaluate(() => {
      const fig = window.tutorial.puzzle.figure;
      fig.setStages([...fig.stages, { ops: ['pillow h0f1'], label: 'pillow h0f1' }]);
      return { view: fig.view.animating, diagram: fig.diagramView.animating };
    });
    await settle();
    const after = await page.evaluate(() => window.tutorial.puzzle.figure.animating);
    if (motion === 'reduce') assert.deepEqual(seen, { view: false, diagram: false });
    else assert.equal(seen.view, true, 'the 3D view animates the step');
    assert.equal(after, false);
  }
});

test('phone and desktop: no sideways scroll, screenshots of a puzzle in play', async () => {
  for (const width of [1280, 390]) {
    await openPuzzle('ring-collapse', width, { steps: '&steps=v1;hexpush%20h13f5' });
    const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 1, `puzzles fits ${width} px (overflow ${overflow} px)`);
    await page.locator('input[name=pick][value=quad]').check();
    const at = await findPick('hexpush h4f5', true);
    assert.ok(at, 'the second push is pickable');
    await page.mouse.click(at.x, at.y);
    // Point at the second push (hovering may scroll the list under the pointer: point again then).
    const label = page.locator('#fig-puzzle .stage-label');
    for (let k = 0; k < 3 && (await label.textContent()) !== 'preview: hexpush h4f5'; k++) {
      await page.locator('#candidates button.cand[data-step="hexpush h4f5"]').hover();
      await settle();
    }
    assert.equal(await label.textContent(), 'preview: hexpush h4f5');
    await page.screenshot({ path: join(screenshotDir, `puzzles-play-${width}.png`), fullPage: true });
    await page.locator('#fig-puzzle').screenshot({ path: join(screenshotDir, `puzzles-board-${width}.png`) });
  }
  await openPuzzle('four-four-v', 390, { steps: '&steps=v1;hexpush%20h0f0' });
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth) <= 1);
  await page.screenshot({ path: join(screenshotDir, 'puzzles-four-four-v-390.png'), fullPage: true });
  assert.deepEqual(problems, []);
});
