// Operation-log steps read out for a student: "pillow h0f1" -> "Pillow the +x face of hex 0", with
// what the step did (from the engine's step report). Faces are 2*axis + side (docs/oplog.md).

// A hex's local axes (x, y, z of its corner numbering) are the grid's axes in a grid; elsewhere
// (the 4-cube) they are only local, hence "local".
const FACE = ['−x', '+x', '−y', '+y', '−z', '+z'];
const AXIS = ['x', 'y', 'z'];

/** "face 1 (local +x) of hex 0" for h0f1. */
export function quadText(hex, face) {
  return `face ${face} (local ${FACE[face]}) of hex ${hex}`;
}
/** "edge 11 (local z) of hex 0" for h0e11. */
export function edgeText(hex, edge) {
  return `edge ${edge} (local ${AXIS[edge >> 2]}) of hex ${hex}`;
}

/** A pick ({ kind, hex, face | edge }) in words. */
export function pickText(p) {
  if (!p) return '';
  if (p.kind === 'quad') return `quad h${p.hex}f${p.face}: ${quadText(p.hex, p.face)}`;
  if (p.kind === 'edge') return `edge h${p.hex}e${p.edge}: ${edgeText(p.hex, p.edge)}`;
  return `hex ${p.hex}`;
}

// The entities of a step: [{ kind, hex, face | edge }] in argument order (pairs give both quads).
export function stepEntities(step) {
  const out = [];
  for (const m of step.matchAll(/h(\d+)([fe])(\d+)|h(\d+)(?![\dfe])/g)) {
    if (m[4] !== undefined) out.push({ kind: 'hex', hex: Number(m[4]) });
    else out.push(m[2] === 'f' ? { kind: 'quad', hex: Number(m[1]), face: Number(m[3]) } : { kind: 'edge', hex: Number(m[1]), edge: Number(m[3]) });
  }
  return out;
}

/** The step as a sentence. */
export function stepText(step) {
  const op = step.split(' ')[0];
  const e = stepEntities(step);
  const q = (i) => (e[i] ? quadText(e[i].hex, e[i].face) : '?');
  switch (op) {
    case 'pillow': return `Pillow ${q(0)}: two new hexes and a sphere sheet around it`;
    case 'unpillow': return `Remove the pillow pair of hex ${e[0]?.hex}`;
    case 'chordpush': return `Chord push around ${edgeText(e[0].hex, e[0].edge)}, opening ${q(1)} and ${q(2)}`;
    case 'chordpull': return `Pull out the blind chord through hex ${e[0]?.hex}`;
    case 'hexpush': return `Hex push through ${q(0)} (the 2–6 flip)`;
    case 'hexpull': return `Hex pull through ${q(0)} (the 6–2 flip)`;
    case 'ringcollapse': return `Collapse the ring of hexes through ${edgeText(e[0].hex, e[0].edge)}`;
    case 'facecollapse': return `Face collapse around ${edgeText(e[0].hex, e[0].edge)}: ${q(1)} meets ${q(2)}`;
    case 'facesplit': return `Face split: cut ${q(0)} apart from ${q(1)}`;
    case 'ringsplit': return `Ring split along a loop of ${e.length / 2} edges (a ring of ${e.length / 2} new hexes)`;
    default: return step;
  }
}

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;

/** What a step report says happened, briefly: "+2 hexes (4, 5); sheets: new 5". */
export function effectText(r) {
  const parts = [];
  if (r.created.hexes.length) parts.push(`+${plural(r.created.hexes.length, 'hex').replace('hexs', 'hexes')} (${r.created.hexes.join(', ')})`);
  if (r.removed.hexes.length) parts.push(`−${plural(r.removed.hexes.length, 'hex').replace('hexs', 'hexes')} (${r.removed.hexes.join(', ')})`);
  const s = r.changedSheets;
  const sheets = [s.created.length ? `new ${s.created.join(', ')}` : '', s.removed.length ? `gone ${s.removed.join(', ')}` : ''].filter(Boolean);
  if (sheets.length) parts.push(`sheets: ${sheets.join('; ')}`);
  return parts.join('; ') || 'no hex created or removed';
}
