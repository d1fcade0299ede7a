// The puzzles of the puzzle page: each a start mesh, a goal the engine checks after every step,
// the shortest known number of steps (from the stored decomposition records where one exists), a
// known answer (for hints and tests) and hints. No DOM: the checks run the engine (also in Node).
// `eng` = { build(spec, ops) -> Mesh, flips() -> FlipInfo[], record(problem) -> DecompositionRecord }.

const G = (a, b, c) => ({ kind: 'grid', dims: [a, b, c] });
const FOURCUBE = { kind: 'fourcube', dims: [] };

/** What a goal looks at after each step: counts, dual sizes, sheets, closed chords, canonical hash. */
export function snapshot(mesh, step = null) {
  return {
    step,
    counts: mesh.counts,
    dual: mesh.dualSizes(),
    sheets: mesh.sheets.map((s) => ({ id: s.id, hexes: s.hexes, topology: s.topology })),
    closed2: mesh.chords.filter((c) => c.closed && c.hexes === 2).length,
    hash: mesh.canonicalHash(),
  };
}

// The canonical hash of the start after `steps` (the engine's, boundary fixed).
function hashAfter(eng, spec, steps) {
  const m = eng.build(spec, steps);
  try {
    return m.canonicalHash();
  } finally {
    m.delete();
  }
}

// The hash of the start with a flip applied directly (not by its atomic steps) at `hexes`.
function hashFlipped(eng, spec, pre, name, hexes) {
  const m = eng.build(spec, pre);
  try {
    m.flip(name, hexes);
    return m.canonicalHash();
  } finally {
    m.delete();
  }
}

// A goal reached when the complex is the target (same canonical hash).
const reach = (what) => (ctx) => {
  const last = ctx.history[ctx.history.length - 1];
  return ctx.targets.has(last.hash) ? { ok: true, message: `${what} ✓` } : { ok: false, message: `not yet: the complex is not ${what}` };
};

// A flip puzzle: reach the flip applied directly; shortest = the stored decomposition's length.
function flipPuzzle({ id, title, level, name, mesh, pre = [], before, goal, hints, layout, reference = null }) {
  return {
    id, title, level, mesh, pre, goal, hints, layout,
    flip: { name, before },
    focus: null,
    targets: (eng) => new Set([hashFlipped(eng, mesh, pre, name, before)]),
    check: reach(`the ${name} flip of hex${before.length === 1 ? '' : 'es'} ${before.join(', ')}`),
    reference: (eng) => {
      if (reference) return reference;
      if (mesh.kind === 'fourcube') return eng.flips().find((f) => f.name === name).steps;
      const m = eng.build(mesh, pre);
      try {
        return m.flip(name, before, { viaAtomic: true }).map((r) => r.step);
      } finally {
        m.delete();
      }
    },
    best: (eng) => ({ steps: eng.record(name).steps.length, source: `stored decomposition ${name}` }),
  };
}

export const PUZZLES = [
  {
    id: 'sphere',
    title: 'A sphere sheet',
    level: 1,
    mesh: G(2, 2, 1),
    pre: [],
    goal: 'Make a sheet that is a sphere: a closed layer of hexes that never reaches the boundary.',
    hints: [
      'Every sheet of a grid is a disk: it ends on the boundary. A new sheet must come from an operation.',
      'The minimal pillow (page 4) wraps a new sheet around one interior quad.',
      'Pick a quad between two hexes (switch Pick to “quad” if edges get in the way) and choose “pillow”.',
    ],
    targets: () => null,
    check(ctx) {
      const sphere = ctx.history[ctx.history.length - 1].sheets.find((s) => s.topology === 'sphere');
      return sphere ? { ok: true, message: `sheet ${sphere.id} is a sphere of ${sphere.hexes} hexes ✓` } : { ok: false, message: 'not yet: every sheet still reaches the boundary' };
    },
    reference: () => ['pillow h0f1'],
    best: () => ({ steps: 1, source: 'one step: no sheet of the start is a sphere' }),
  },
  {
    id: 'pillow-back',
    title: 'A pillow and its removal',
    level: 2,
    mesh: G(2, 2, 1),
    pre: [],
    goal: 'Insert a pillow (a sphere sheet appears), then remove it again: end on the complex you started from.',
    hints: [
      'First make a sphere sheet, as in the first puzzle.',
      'Every step has an inverse. The pillow’s is “unpillow”: pick one of the two new hexes (in 3D with Pick “hex”, or its crossing in the diagram).',
      'The two new hexes are drawn in orange; their crossings sit on the sphere sheet’s diagram.',
    ],
    targets: (eng) => new Set([hashAfter(eng, G(2, 2, 1), [])]),
    check(ctx) {
      const k = ctx.history.findIndex((s) => s.sheets.some((x) => x.topology === 'sphere'));
      if (k < 0) return { ok: false, message: 'not yet: no sphere sheet so far' };
      const last = ctx.history[ctx.history.length - 1];
      if (!ctx.targets.has(last.hash)) return { ok: false, message: `a sphere sheet after step ${k}; now remove it` };
      return { ok: true, message: `a sphere after step ${k}, and back to the start ✓` };
    },
    reference: () => ['pillow h0f1', 'unpillow h4'],
    best: () => ({ steps: 2, source: 'two steps: one to make the sphere, one to undo it' }),
  },
  flipPuzzle({
    id: 'two-six',
    title: 'The 2–6 flip',
    level: 3,
    name: '2-6',
    mesh: G(2, 1, 1),
    before: [0, 1],
    goal: 'Replace the two hexes by six with the same outer faces (the 2–6 flip).',
    hints: [
      'Page 5: one atomic operation turns two hexes that share a quad into six.',
      'Pick the quad between hex 0 and hex 1.',
      'Choose “hex push”.',
    ],
  }),
  {
    id: 'blind-chord',
    title: 'A chord push makes a blind chord',
    level: 4,
    mesh: G(2, 2, 1),
    pre: [],
    goal: 'Make a blind chord: a closed chord of just 2 hexes, without adding a sheet.',
    hints: [
      'A pillow also makes closed chords of 2 hexes, but it adds a sheet: not that one.',
      'The chord push (page 5) opens two quads around an interior edge.',
      'Pick the edge where the four hexes meet (the vertical edge in the middle; Pick “edge” helps), then a chord push.',
    ],
    targets: () => null,
    check(ctx) {
      const [first, last] = [ctx.history[0], ctx.history[ctx.history.length - 1]];
      if (last.closed2 <= first.closed2) return { ok: false, message: 'not yet: no new closed chord of 2 hexes' };
      if (last.dual.sheets !== first.dual.sheets) return { ok: false, message: `a closed chord of 2, but the sheets changed (${first.dual.sheets} → ${last.dual.sheets})` };
      return { ok: true, message: `a blind chord of 2 hexes, sheets unchanged (${last.dual.sheets}) ✓` };
    },
    reference: () => ['chordpush h0e11 h0f1 h1f3'],
    best: () => ({ steps: 1, source: 'one step: the start has no closed chord' }),
  },
  flipPuzzle({
    id: 'six-two',
    title: 'Undo a hex push: the 6–2 flip',
    level: 5,
    name: '6-2',
    mesh: G(2, 1, 1),
    pre: ['hexpush h0f1'],
    before: [2, 3, 4, 5, 6, 7],
    goal: 'Six hexes came from a hex push. Turn them back into two.',
    hints: [
      'The inverse of a hex push is a hex pull.',
      'Pick the quad between the two middle hexes (the quad the push made).',
      'Choose “hex pull”.',
    ],
  }),
  {
    id: 'face-collapse',
    title: 'Merge two sheets by a face collapse',
    level: 6,
    mesh: G(3, 3, 2),
    pre: [],
    goal: 'Make two sheets one, without adding or removing a hex.',
    hints: [
      'A face collapse glues two quads around an interior edge: the two sheets through them become one.',
      'The edge must be interior and the two quads opposite around it; in this 3×3×2 grid that is an edge between the two layers at the centre hex 4.',
      'Pick an edge of the top face of hex 4 (Pick “edge” helps) and choose a face collapse.',
    ],
    targets: () => null,
    check(ctx) {
      const [first, last] = [ctx.history[0], ctx.history[ctx.history.length - 1]];
      if (last.counts.hexes !== first.counts.hexes) return { ok: false, message: `the hex count changed (${first.counts.hexes} → ${last.counts.hexes})` };
      if (last.dual.sheets !== first.dual.sheets - 1) return { ok: false, message: `not yet: ${last.dual.sheets} sheets (start ${first.dual.sheets})` };
      return { ok: true, message: `${first.dual.sheets} sheets became ${last.dual.sheets}, still ${last.counts.hexes} hexes ✓` };
    },
    reference: () => ['facecollapse h4e7 h4f5 h14f4'],
    best: () => ({ steps: 1, source: 'one step' }),
  },
  flipPuzzle({
    id: 'one-seven',
    title: 'The 1–7 flip (traditional pillow)',
    level: 7,
    name: '1-7',
    mesh: G(1, 1, 2),
    before: [0],
    // The stored 1-7 steps placed here would pillow a boundary quad of hex 0: its one interior quad instead.
    reference: ['pillow h0f5', 'hexpush h0f5'],
    goal: 'Replace hex 0 (the lower one) by seven hexes: a hex wrapped in a layer of six.',
    hints: [
      'No single operation adds six hexes. Page 6: a minimal pillow, then a hex push.',
      'Pillow the quad between hex 0 and hex 1.',
      'Then hex push through the quad between hex 0 and the pillow hex next to it.',
    ],
  }),
  flipPuzzle({
    id: 'seven-one',
    title: 'The 7–1 flip',
    level: 8,
    name: '7-1',
    mesh: G(1, 1, 2),
    pre: ['pillow h0f5', 'hexpush h0f5'],
    before: [1, 3, 4, 5, 6, 7, 8, 9].filter((h) => h !== 1),
    goal: 'Seven hexes came from a 1–7 flip of the lower hex. Make them one hex again.',
    hints: [
      'Undo the two steps of the 1–7 flip in reverse order.',
      'First a hex pull (the inverse of the hex push): pick the inner quad of the central hex.',
      'Then remove the pillow pair.',
    ],
  }),
  {
    id: 'ring-collapse',
    title: 'Cut a chord: the (2,1)–(1,2) flip',
    level: 9,
    mesh: G(3, 3, 3),
    pre: [],
    focus: [4, 13, 22],
    goal: 'Change the centre column (hexes 4, 13, 22, in blue): two hex pushes make a ring of hexes; collapse it.',
    hints: [
      'TK03 §4.4: two hex pushes, then a ring collapse of a closed chord they made.',
      'Hex push the quad between hexes 13 and 22, then the quad between hexes 4 and 13 (now a new hex).',
      'A ring collapse is picked at an edge of a hex of the ring (the green ring around the column).',
    ],
    // A ring collapse of the ring the first push made (hex 29 is on it), along either diagonal; the
    // second push's ring would only undo that push.
    targets: (eng) => new Set(['e4', 'e5'].map((e) => hashAfter(eng, G(3, 3, 3), ['hexpush h13f5', 'hexpush h4f5', `ringcollapse h29${e}`]))),
    check: reach('a (2,1)–(1,2) flip of the column'),
    reference: () => ['hexpush h13f5', 'hexpush h4f5', 'ringcollapse h29e4'],
    best: () => ({ steps: 3, source: 'TK03 §4.4’s recipe (no stored search)' }),
  },
  flipPuzzle({
    id: 'three-five-e',
    title: 'The 3–5 flip, edge type',
    level: 10,
    name: '3-5e',
    mesh: FOURCUBE,
    before: [0, 2, 4],
    goal: 'In the 4-cube: replace cubes 0, 2, 4 (blue, around one edge) by five hexes shaped like the other side.',
    hints: [
      'It starts with a hex push between two of the blue cubes.',
      'Then a face collapse, a face split, and a chord pull.',
      'Ask for the next step below if you are stuck; the figure marks where to pick.',
    ],
  }),
  flipPuzzle({
    id: 'three-five-c',
    title: 'The 3–5 flip, column type',
    level: 11,
    name: '3-5c',
    mesh: FOURCUBE,
    before: [0, 1, 2],
    goal: 'In the 4-cube: replace cubes 0, 1, 2 (blue) by five hexes shaped like the other side.',
    hints: [
      'Like the (2,1)–(1,2) flip: two hex pushes and a ring collapse …',
      '… and then remove the pillow that is left.',
      'Ask for the next step below if you are stuck.',
    ],
  }),
  flipPuzzle({
    id: 'four-four-m',
    title: 'The 4–4 flip, mixed type',
    level: 12,
    name: '4-4m',
    mesh: FOURCUBE,
    before: [0, 1, 2, 4],
    goal: 'In the 4-cube: replace cubes 0, 1, 2, 4 (blue) by four hexes shaped like the other side.',
    hints: [
      'The 3–5 column flip’s steps appear here too.',
      'Two hex pushes, a ring collapse, a face split, a chord pull, an unpillow.',
      'Ask for the next step below if you are stuck.',
    ],
  }),
  flipPuzzle({
    id: 'four-four-v',
    title: 'The 4–4 vertex flip in 8 steps',
    level: 13,
    name: '4-4v',
    mesh: FOURCUBE,
    before: [0, 2, 4, 6],
    goal: 'In the 4-cube: replace the four cubes around a vertex (0, 2, 4 and the outer cube 6) by four hexes shaped like the other side — TK03’s open “triple-hex push”.',
    hints: [
      'The paper guessed “hex push and some form of ring collapse”. Start with a hex push.',
      'Then three ring splits (pick an edge: the ring splits through it are offered), two ring collapses and two hex pulls.',
      'Ask for the next step below if you are stuck: each step is marked in the figure.',
    ],
  }),
  {
    id: 'triple-chord',
    title: 'The triple-chord push',
    level: 14,
    mesh: G(3, 3, 3),
    pre: [],
    focus: [0, 1, 3, 4, 9, 10, 12, 13],
    goal: 'Around the vertex shared by the eight blue hexes, push the three chords through it past each other (TK03 §4.5.1).',
    hints: [
      'The paper guessed three hex pushes and a “node separate”; the shortest known way is different.',
      'It starts with two hex pushes, then face collapses and splits around a ring collapse, and a chord pull.',
      'Ask for the next step below if you are stuck.',
    ],
    targets: (eng) => new Set([hashAfter(eng, G(3, 3, 3), eng.record('tripleChordPush').steps)]),
    check: reach('the triple-chord push'),
    reference: (eng) => eng.record('tripleChordPush').steps,
    best: (eng) => ({ steps: eng.record('tripleChordPush').steps.length, source: 'stored decomposition tripleChordPush' }),
  },
];

/**
 * Where a step is picked, as a pick { kind: 'quad' | 'edge' | 'hex', hex, face | edge }: the first
 * entity it names; for a ring split (named by quad pairs) an edge of its loop on the first quad's
 * hex, found by asking `mesh` which of that hex's edges offer it.
 */
export function placeOf(step, mesh) {
  const m = /^\w+ h(\d+)(?:([fe])(\d+))?/.exec(step);
  const hex = Number(m[1]);
  if (step.startsWith('ringsplit ')) {
    const edge = [...Array(12).keys()].find((e) => mesh.ringSplits({ hex, edge: e }).includes(step));
    return { kind: 'edge', hex, edge: edge ?? 0 };
  }
  if (!m[2]) return { kind: 'hex', hex };
  return m[2] === 'f' ? { kind: 'quad', hex, face: Number(m[3]) } : { kind: 'edge', hex, edge: Number(m[3]) };
}

/**
 * The known answer as the page offers it: each step as listed at its first entity
 * (`eng.stepsAt(mesh, pick)`), or, where the stored text names the same operation from other
 * sides (a face split's quads), the offered step with the same result (canonical hash).
 */
export function offeredPath(p, reference, eng) {
  const m = eng.build(p.mesh, p.pre);
  try {
    return reference.map((step) => {
      const offered = eng.stepsAt(m, placeOf(step, m));
      let use = step;
      if (!offered.includes(step)) {
        m.apply(step);
        const want = m.canonicalHash();
        m.undo();
        use = offered.find((c) => {
          m.apply(c);
          const same = m.canonicalHash() === want;
          m.undo();
          return same;
        }) ?? step;
      }
      m.apply(use);
      return use;
    });
  } finally {
    m.delete();
  }
}

/** The puzzle's facts computed by the engine once: target hashes, the known answer, shortest known. */
export function preparePuzzle(p, eng) {
  const targets = p.targets(eng);
  const stored = p.reference(eng);
  const reference = eng.stepsAt ? offeredPath(p, stored, eng) : stored;
  return { targets, reference, stored, best: p.best(eng) };
}

/**
 * Applies `steps` after the puzzle's start and checks the goal after the last one. Returns
 * { ok, message, applied, history } (applied = how many steps the engine accepted).
 */
export function checkPuzzle(p, prepared, steps, eng) {
  const mesh = eng.build(p.mesh, p.pre);
  try {
    const history = [snapshot(mesh)];
    for (const [k, step] of steps.entries()) {
      try {
        mesh.apply(step);
      } catch (e) {
        return { ok: false, message: `step ${k + 1} (${step}) was refused: ${e.message}`, applied: k, history };
      }
      history.push(snapshot(mesh, step));
    }
    if (steps.length === 0) return { ok: false, message: 'no step yet', applied: 0, history };
    return { ...p.check({ history, targets: prepared.targets }), applied: steps.length, history };
  } finally {
    mesh.delete();
  }
}

/** Stars for a solution: 3 at the shortest known (or better), 2 within two more steps, else 1. */
export function stars(used, best) {
  return used <= best ? 3 : used <= best + 2 ? 2 : 1;
}
