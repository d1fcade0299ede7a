// The tutorial puzzles (web/tutorials/puzzles.js) against the engine: every puzzle's known answer
// reaches its goal in the shortest known number of steps, the start does not, and the shortest
// known comes from the stored decomposition record where the puzzle names one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { init, Mesh, flips, decompositions } from 'hexdual';
import { PUZZLES, preparePuzzle, checkPuzzle, stars, placeOf } from '../../web/tutorials/puzzles.js';
import { stepsAt } from '../../web/tutorials/candidates.js';

await init();
const eng = {
  build(spec, ops) {
    const m = spec.kind === 'fourcube' ? Mesh.fourCube() : Mesh.grid(...spec.dims);
    for (const s of ops) m.apply(s);
    return m;
  },
  flips,
  record: (problem) => decompositions().find((r) => r.problem === problem),
  stepsAt,
};

test('at least 12 puzzles, rising in level, with distinct ids', () => {
  assert.ok(PUZZLES.length >= 12, `${PUZZLES.length} puzzles`);
  assert.deepEqual(PUZZLES.map((p) => p.level), PUZZLES.map((_, k) => k + 1));
  assert.equal(new Set(PUZZLES.map((p) => p.id)).size, PUZZLES.length);
  for (const need of ['sphere', 'pillow-back', 'two-six', 'one-seven', 'blind-chord', 'face-collapse', 'three-five-e', 'three-five-c', 'four-four-v']) {
    assert.ok(PUZZLES.some((p) => p.id === need), need);
  }
});

for (const p of PUZZLES) {
  test(`${p.id}: the known answer solves it in the shortest known number of steps; the start does not`, () => {
    const prepared = preparePuzzle(p, eng);
    const verdict = checkPuzzle(p, prepared, prepared.reference, eng);
    assert.equal(verdict.ok, true, verdict.message);
    assert.equal(prepared.reference.length, prepared.best.steps, `${prepared.best.source}`);
    assert.equal(stars(prepared.reference.length, prepared.best.steps), 3);
    // The goal is not met before the last step.
    for (let k = 0; k < prepared.reference.length; k++) {
      assert.equal(checkPuzzle(p, prepared, prepared.reference.slice(0, k), eng).ok, false, `solved after ${k} steps`);
    }
    // Every step of the answer is offered by the page at the first place it names.
    const m = eng.build(p.mesh, p.pre);
    for (const step of prepared.reference) {
      assert.ok(stepsAt(m, placeOf(step, m)).includes(step), `${step} offered at ${JSON.stringify(placeOf(step, m))}`);
      m.apply(step);
    }
    m.delete();
    if (p.flip) {
      const r = eng.record(p.flip.name);
      assert.equal(prepared.best.steps, r.steps.length);
      assert.equal(prepared.best.source, `stored decomposition ${p.flip.name}`);
    }
  });
}

test('a refused step names the step and the engine\'s rule', () => {
  const p = PUZZLES.find((x) => x.id === 'sphere');
  const v = checkPuzzle(p, preparePuzzle(p, eng), ['pillow h0f0'], eng);
  assert.equal(v.ok, false);
  assert.match(v.message, /^step 1 \(pillow h0f0\) was refused: pillow: /);
});

test('the numbers in the goals are the engine\'s: hexes a flip makes, the blue hexes named', () => {
  const words = { two: 2, four: 4, five: 5, six: 6, seven: 7, eight: 8, one: 1 };
  for (const p of PUZZLES.filter((x) => x.flip)) {
    // "… by N hexes" / "… into two" / "… back into two": the hexes where the before side was.
    const m = /(?:by|into|Make them) (one|two|four|five|six|seven)\b/.exec(p.goal);
    assert.ok(m, `${p.id}: ${p.goal}`);
    const start = eng.build(p.mesh, p.pre);
    const host = start.counts.hexes - p.flip.before.length;
    start.flip(p.flip.name, p.flip.before);
    assert.equal(start.counts.hexes - host, words[m[1]], `${p.id}: ${p.goal}`);
    start.delete();
  }
  const tcp = PUZZLES.find((x) => x.id === 'triple-chord');
  assert.match(tcp.goal, /the eight blue hexes/);
  assert.equal(tcp.focus.length, 8);
  const col = PUZZLES.find((x) => x.id === 'ring-collapse');
  assert.match(col.goal, new RegExp(`hexes ${col.focus.join(', ')}`));
  assert.match(PUZZLES.find((x) => x.id === 'blind-chord').goal, /a closed chord of just 2 hexes/);
});
