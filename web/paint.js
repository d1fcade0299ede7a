// Hex colours from the app state: the selected sheet or chord in its colour with the rest faint,
// the selected hex in the accent colour, hexes created by the last step in green, and optional
// colouring by scaled Jacobian (inverted hexes magenta). Shared by every 3D view.
import { sheetColor, chordColor } from './colors.js';

const BASE = [184, 196, 214];
const ACCENT = [255, 122, 0];
// Created hexes alternate two greens, so a pillow's pair (or a blind chord's) reads as two hexes.
const CREATED = [20, 200, 70];
const CREATED_DARK = [0, 110, 30];
const INVERTED = [214, 0, 170];

function cssToRgb(css) {
  const m = /^hsl\(([\d.]+),\s*([\d.]+)%,\s*([\d.]+)%\)$/.exec(css);
  if (!m) {
    const hex = /^#([0-9a-f]{6})$/i.exec(css);
    const n = hex ? parseInt(hex[1], 16) : 0x888888;
    return [n >> 16, (n >> 8) & 255, n & 255];
  }
  const h = Number(m[1]) / 360, s = Number(m[2]) / 100, l = Number(m[3]) / 100;
  const q = l < 0.5 ? l * (1 + s) : l + s - l * s, p = 2 * l - q;
  const ch = (t) => {
    t = (t + 1) % 1;
    const v = t < 1 / 6 ? p + (q - p) * 6 * t : t < 1 / 2 ? q : t < 2 / 3 ? p + (q - p) * (2 / 3 - t) * 6 : p;
    return Math.round(v * 255);
  };
  return [ch(h + 1 / 3), ch(h), ch(h - 1 / 3)];
}
export const rgbOf = cssToRgb;

/** Red (<= 0) through yellow (0.5) to green (1) for a scaled Jacobian. */
export function qualityRgb(sj) {
  const t = Math.max(0, Math.min(1, sj));
  return t < 0.5 ? [230, Math.round(60 + 380 * t), 50] : [Math.round(230 - 360 * (t - 0.5)), 210, 60];
}

/** A key that changes exactly when the colours change. */
export function paintKeyOf(s) {
  const sel = s.selection ? JSON.stringify(s.selection) : '';
  return [s.meshKey, sel, s.colorBy, s.report?.key ?? '', s.focus?.key ?? '', s.focusChanges].join('|');
}

/** Members of the selected sheet or chord. */
export function selectedHexes(s) {
  const sel = s.selection;
  if (!sel || !s.mesh) return null;
  try {
    if (sel.kind === 'sheet') return new Set(s.mesh.sheetHexes(sel.id));
    if (sel.kind === 'chord') return new Set(s.mesh.chordHexes(sel.id));
  } catch {
    return null;
  }
  return null;
}

/** colorOf(hexId) -> [r, g, b, a] (0..255) for the state. */
export function hexColors(s) {
  const members = selectedHexes(s);
  const focus = s.focus ? new Set(s.focus.hexes) : null;
  const created = s.report && s.report.key === s.meshKey ? new Map(s.report.created.map((h, i) => [h, i])) : null;
  const closed = s.mesh.counts.boundaryQuads === 0;
  const quality = s.colorBy === 'quality' ? s.quality : null;
  const selColor = members ? cssToRgb(s.selection.kind === 'sheet' ? sheetColor(s.selection.id) : chordColor(s.selection.id)) : null;
  const selHex = s.selection?.kind === 'hex' ? s.selection.hex : -1;
  const fresh = created && created.size > 0 && s.focusChanges && !members;
  const dim = members || focus || closed || fresh;
  const out = new Uint8Array(4);
  return (h) => {
    let c = BASE;
    if (quality) c = quality.scaledJacobian[h] <= 0 ? INVERTED : qualityRgb(quality.scaledJacobian[h]);
    let a = dim ? 46 : 255;
    if (closed && !members && !focus) a = 80;
    if (focus && focus.has(h)) (c = [90, 140, 230]), (a = 255);
    if (members && members.has(h)) (c = selColor), (a = 255);
    if (created && created.has(h)) (c = created.get(h) % 2 ? CREATED_DARK : CREATED), (a = 255);
    if (h === selHex) (c = ACCENT), (a = 255);
    out[0] = c[0], out[1] = c[1], out[2] = c[2], out[3] = a;
    return out;
  };
}
