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
