// Words for what a step did or would do, shared by the palette's preview and the timeline's report.

const hexList = (ids, most = 8) => ids.slice(0, most).map((h) => 'h' + h).join(' ') + (ids.length > most ? ' …' : '');

/**
 * The step's geometry (StepQuality): the minimum scaled Jacobian of the hexes it touched before and
 * after, and the hexes it leaves inverted (those no smoothing with the boundary fixed can repair
 * named), as `hexdual apply` prints them.
 */
export function qualityText(q) {
  if (!q) return '';
  let text = `min scaled Jacobian ${q.before.toFixed(2)} → ${q.after.toFixed(2)}`;
  if (q.inverted.length) {
    text += ` · ${q.inverted.length} inverted: ${hexList(q.inverted)}`;
    if (q.pinned.length) text += ` (${q.pinned.length} pinned by the boundary: ${hexList(q.pinned, 4)})`;
  }
  return text;
}

/**
 * The step that undoes it, or why there is none. A long one (a sheet insertion names every quad of
 * its surface) shows its first places and how many there are, unless `full`.
 */
export function inverseText(r, { full = false } = {}) {
  if (!r.inverse) return r.noInverse ? `no inverse step (${r.noInverse}): undo restores it` : '';
  const [op, ...places] = r.inverse.split(' ');
  if (full || places.length <= 6) return `inverse: ${r.inverse}`;
  return `inverse: ${op} ${places.slice(0, 4).join(' ')} … (${places.length} places)`;
}
