// What the tutorials read from the engine: the stored decomposition records (every step count
// and search bound on a page comes from them) and the ring splits through a picked edge.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { init, Mesh, flips, decompositions } from 'hexdual';

await init();

test('decompositions() holds every record of core/flips/decompositions.txt, field by field', () => {
  const text = readFileSync(new URL('../../core/flips/decompositions.txt', import.meta.url), 'utf8');
  const lines = text.split('\n').filter((l) => l && !l.startsWith('#'));
  const records = decompositions();
  assert.equal(records.length, lines.length);
  lines.forEach((line, k) => {
    const [problem, found, steps, maxDepth, depth, states, seconds, ops] = line.split('|');
    assert.deepEqual(records[k], {
      problem, found: found === 'found', steps: steps === '-' ? null : steps.split(';').slice(1),
      maxDepth: Number(maxDepth), depthSearched: Number(depth), states: Number(states), seconds: Number(seconds), ops,
    });
  });
  // The flips' steps are the found records' (flips() reads the same store).
  for (const f of flips()) assert.deepEqual(f.steps, records.find((r) => r.problem === f.name).steps);
  const chordOnly = records.find((r) => r.problem === '2-6/chord-only');
  assert.deepEqual([chordOnly.found, chordOnly.depthSearched, chordOnly.ops], [false, 8, 'chordpush,chordpull']);
});

test('ringSplits: the 4-4 vertex flip\'s three ring splits are offered at an edge of their loop, and apply', () => {
  const m = Mesh.fourCube();
  const steps = flips().find((f) => f.name === '4-4v').steps;
  // A split is offered at the edges of its loop that its first band's hex has (1 or 2 of its 12).
  const offeredAt = [];
  for (const step of steps) {
    if (step.startsWith('ringsplit')) {
      const hex = Number(/^ringsplit h(\d+)f/.exec(step)[1]);
      const edges = [...Array(12).keys()].filter((edge) => m.ringSplits({ hex, edge }).includes(step));
      offeredAt.push(edges.map((e) => `h${hex}e${e}`).join(' '));
    }
    m.apply(step);
  }
  assert.deepEqual(offeredAt, ['h1e0', 'h1e2', 'h1e0 h1e4']);
  assert.equal(m.counts.hexes, 8);
  assert.throws(() => m.ringSplits({ hex: 99, edge: 0 }), { code: 'PRECONDITION', message: 'ringsplit: no edge h99e0' });
  assert.throws(() => m.ringSplits({ hex: 0 }), { code: 'PRECONDITION' });
  m.delete();
});
