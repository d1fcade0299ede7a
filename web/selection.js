// Selection ids as the operation log writes them: h13 (hex), h13f5 (quad by a side), h13e4
// (edge by an incidence), s4 (sheet), c7 (chord).
const FORMS = [
  [/^h(\d+)f([0-5])$/, (m) => ({ kind: 'quad', hex: +m[1], face: +m[2] })],
  [/^h(\d+)e(\d|1[01])$/, (m) => ({ kind: 'edge', hex: +m[1], edge: +m[2] })],
  [/^h(\d+)$/, (m) => ({ kind: 'hex', hex: +m[1] })],
  [/^s(\d+)$/, (m) => ({ kind: 'sheet', id: +m[1] })],
  [/^c(\d+)$/, (m) => ({ kind: 'chord', id: +m[1] })],
];

export function parseSelection(text) {
  for (const [re, make] of FORMS) {
    const m = re.exec(text);
    if (m) return make(m);
  }
  return null;
}

export function formatSelection(s) {
  if (!s) return '';
  switch (s.kind) {
    case 'quad': return `h${s.hex}f${s.face}`;
    case 'edge': return `h${s.hex}e${s.edge}`;
    case 'hex': return `h${s.hex}`;
    case 'sheet': return `s${s.id}`;
    case 'chord': return `c${s.id}`;
  }
  return '';
}

export function sameSelection(a, b) {
  return formatSelection(a) === formatSelection(b);
}

/** The sheets and chords through a hex, quad or edge, from mesh.hexDual() arrays. */
export function dualThrough(sel, hd) {
  if (!sel || !('hex' in sel) || !hd) return { sheets: [], chords: [] };
  const h = sel.hex;
  const sheetOf = (a) => hd.sheetOf[3 * h + a], chordOf = (a) => hd.chordOf[3 * h + a];
  const uniq = (xs) => [...new Set(xs.filter((x) => x >= 0))];
  if (sel.kind === 'hex') return { sheets: uniq([0, 1, 2].map(sheetOf)), chords: uniq([0, 1, 2].map(chordOf)) };
  // A quad normal to axis a carries the chord along a and is crossed by the sheets of the other axes;
  // an edge along axis a is crossed by the sheet of axis a (TK03 §1.1).
  const a = sel.kind === 'quad' ? sel.face >> 1 : sel.edge >> 2;
  const others = [0, 1, 2].filter((b) => b !== a);
  if (sel.kind === 'quad') return { sheets: uniq(others.map(sheetOf)), chords: uniq([chordOf(a)]) };
  return { sheets: uniq([sheetOf(a)]), chords: uniq(others.map(chordOf)) };
}
