// Page 5: chord push and hex push, each with the paper's Δ checked against the engine's.
import { startPage, live, signed, chordOnlyBound } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { sheetWith } from './select.js';

const spec = { kind: 'grid', dims: [3, 3, 3] };
export const CHORD_PUSH = 'chordpush h13e3 h13f3 h16f5';
export const HEX_PUSH = 'hexpush h13f5';
const PAPER = { cp: [2, 6, 6, 2], hp: [4, 12, 12, 4] };

// The chord-only search of the hex push, with the parity argument from the engine's own Δ(hexes).
function chordOnly(push, hexPush) {
  const b = chordOnlyBound({ push, hexPush });
  live('co-searched', b.searched);
  live('co-states', b.states.toLocaleString('en'));
  live('co-push', push);
  live('co-hexpush', hexPush);
  live('co-parity', b.parity ? 'odd' : 'even');
  live('co-bound', b.bound);
}

function summary(prefix, step, paper) {
  const m = meshAfter(spec, []);
  const before = { ...m.counts, ...m.dualSizes() };
  const closed = (mesh, n) => mesh.chords.filter((c) => c.closed && (n === undefined || c.hexes === n)).length;
  const closedBefore = [closed(m), closed(m, 2)];
  m.apply(step);
  const after = { ...m.counts, ...m.dualSizes() };
  const d = ['vertices', 'edges', 'quads', 'hexes'].map((k) => after[k] - before[k]);
  ['v', 'e', 'f', 'h'].forEach((k, i) => live(`${prefix}-${k}`, signed(d[i])));
  const ok = d.every((x, i) => x === paper[i]);
  for (const e of document.querySelectorAll(`[data-live="${prefix}-check"]`)) e.className = ok ? 'check-ok' : 'check-no';
  live(`${prefix}-check`, ok ? 'the engine agrees with the paper ✓' : 'the engine differs from the paper ✗');
  live(`${prefix}-sheets`, after.sheets - before.sheets);
  live(`${prefix}-blind`, closed(m, 2) - closedBefore[1]);
  live(`${prefix}-closed`, closed(m) - closedBefore[0]);
  m.delete();
  return d[3];
}

startPage(() => {
  live('chordpush-step', CHORD_PUSH);
  live('hexpush-step', HEX_PUSH);
  chordOnly(summary('cp', CHORD_PUSH, PAPER.cp), summary('hp', HEX_PUSH, PAPER.hp));
  createFigure(document.getElementById('fig-chordpush'), {
    title: 'chord push',
    mesh: spec,
    steps: [CHORD_PUSH],
    startAfter: true,
    sheet: (f) => sheetWith(f.mesh, [6, 7, 8, 15]), // a pushed sheet (the y = 2 layer): it gets the blind chord
    sheetChips: true,
    caption: 'TK03 Figs. 2–3. New hexes in orange. The diagram shows one of the two sheets pushed through each other: after the push, the blind chord is the small loop through the two new crossings. Pick the sheet of the edge e (the x = 1 layer) above to see its two chords now cross twice, at the same two hexes.',
  });
  createFigure(document.getElementById('fig-hexpush'), {
    title: 'hex push',
    mesh: spec,
    steps: [HEX_PUSH],
    startAfter: true,
    sheet: (f) => sheetWith(f.mesh, [10, 12, 14, 16]), // a pushed sheet (the z = 1 layer): it gets the new closed chord
    sheetChips: true,
    caption: 'TK03 Figs. 4–5: hexes 13 and 22 are replaced by a swapped pair; four new hexes surround them (all six in orange).',
  });
});
