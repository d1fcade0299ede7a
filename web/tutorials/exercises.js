// The exercises of the "Try it yourself" page and their checks. No DOM: the checks run the engine on
// the reader's steps (also in Node, for the tests). A goal sees the state after every step.

export const EXERCISES = [
  {
    id: 'six-and-back',
    title: 'Two hexes into six, and back',
    goal: 'Start from a 2×1×1 block (hexes 0 and 1). Reach a mesh of exactly 6 hexes, then return to a mesh with the same counts, sheets and chords as the start.',
    mesh: { kind: 'grid', dims: [2, 1, 1] },
    hints: [
      'Page 5: which operation adds four hexes around two hexes that share one quad?',
      'Hex 0 and hex 1 share the quad h0f1 (hex 0, face x = 1).',
      'Every applied step reports its inverse; a hex push is undone by a hex pull of its inner quad.',
    ],
    answer: ['hexpush h0f1', 'hexpull h2f1'],
    check(history) {
      const start = history[0];
      const six = history.findIndex((s) => s.counts.hexes === 6);
      if (six < 0) return { ok: false, message: 'no step reached exactly 6 hexes yet' };
      const last = history[history.length - 1];
      if (history.length - 1 === six) return { ok: false, message: `6 hexes after step ${six}; now go back` };
      if (!sameState(start, last)) return { ok: false, message: `6 hexes after step ${six}, but the end state differs from the start (${describe(last)})` };
      return { ok: true, message: `solved: 6 hexes after step ${six}, and back to ${describe(last)} ✓` };
    },
  },
  {
    id: 'sphere',
    title: 'A sphere sheet of six hexes',
    goal: 'In a 3×3×3 grid, make a sheet that is a sphere (it never meets the boundary) made of exactly 6 hexes.',
    mesh: { kind: 'grid', dims: [3, 3, 3] },
    hints: [
      'A minimal pillow makes a sphere sheet — of how many hexes?',
      'Page 6: the traditional pillow surrounds a hex by a sphere sheet.',
      'The centre hex is 13; its top face is h13f5.',
    ],
    answer: ['pillow h13f5', 'hexpush h13f5'],
    check(history) {
      const last = history[history.length - 1];
      const spheres = last.sheets.filter((s) => s.topology === 'sphere');
      const six = spheres.find((s) => s.hexes === 6);
      if (six) return { ok: true, message: `solved: sheet ${six.id} is a sphere of 6 hexes ✓` };
      if (spheres.length) return { ok: false, message: `sphere sheets now: ${spheres.map((s) => `${s.hexes} hexes`).join(', ')} — not 6` };
      return { ok: false, message: 'no sphere sheet yet' };
    },
  },
  {
    id: 'face-collapse',
    title: 'Find a face collapse',
    goal: 'In a 4×4×4 grid, apply one face collapse (it must merge two sheets into one).',
    mesh: { kind: 'grid', dims: [4, 4, 4] },
    hints: [
      'The step is facecollapse E Qf Qg: an interior edge E and two quads f, g around it.',
      'In the 3×3×3 grid it is impossible (docs/operations.md): the quads must be opposite around E, and their far sides must not lie on the boundary.',
      'Try around an edge of hex 21 (x = 1, y = 1, z = 1).',
    ],
    answer: ['facecollapse h21e11 h21f1 h26f0'],
    check(history) {
      const k = history.findIndex((s) => s.step && s.step.startsWith('facecollapse'));
      if (k < 0) return { ok: false, message: 'no face collapse applied yet' };
      const merged = history[k - 1].dual.sheets - history[k].dual.sheets;
      if (merged !== 1) return { ok: false, message: `step ${k} changed the sheet count by ${-merged}, not −1` };
      return { ok: true, message: `solved: step ${k} merged two sheets into one (${history[k - 1].dual.sheets} → ${history[k].dual.sheets}) ✓` };
    },
  },
];

/** Splits typed text into steps (lines or ';'), dropping blanks and a leading "v1". */
export function parseSteps(text) {
  return text.split(/[;\n]/).map((s) => s.trim().replace(/\s+/g, ' ')).filter((s) => s && s !== 'v1');
}

function snapshot(mesh, step) {
  const sheets = mesh.sheets.map((s) => ({ id: s.id, hexes: s.hexes, topology: s.topology }));
  const hash = typeof mesh.canonicalHash === 'function' ? mesh.canonicalHash() : null;
  return { step, counts: mesh.counts, dual: mesh.dualSizes(), sheets, hash };
}

function sameState(a, b) {
  if (a.hash !== null && b.hash !== null) return a.hash === b.hash;
  const key = (s) => JSON.stringify([s.counts, s.dual, s.sheets.map((x) => [x.hexes, x.topology]).sort()]);
  return key(a) === key(b);
}

function describe(s) {
  return `${s.counts.hexes} hexes, ${s.dual.sheets} sheets, ${s.dual.chords} chords`;
}

/**
 * Applies `steps` to a fresh mesh from `build(ex.mesh)` and checks the goal.
 * Returns { ok, message, applied } (applied = how many steps the engine accepted).
 */
export function checkExercise(ex, steps, build) {
  const mesh = build(ex.mesh, []);
  try {
    const history = [snapshot(mesh, null)];
    for (const [k, step] of steps.entries()) {
      try {
        mesh.apply(step);
      } catch (e) {
        return { ok: false, message: `step ${k + 1} (${step}) was refused: ${e.message}`, applied: k };
      }
      history.push(snapshot(mesh, step));
    }
    if (steps.length === 0) return { ok: false, message: 'type at least one step', applied: 0 };
    return { ...ex.check(history), applied: steps.length };
  } finally {
    mesh.delete();
  }
}
