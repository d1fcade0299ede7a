// A sheet diagram redrawn after a step, animated: crossings that stay (same hex and axis) move from
// their old place to their new one, new crossings and the new chords fade in, and the old drawing
// (its chords, loops and the crossings that went away) fades out underneath. Used by the explorer's
// diagram panels and the tutorial figures; timing and reduced motion from motion.js.
import { tween, STEP_MS } from './motion.js';

// Above this many crossings a redraw is shown at once (moving thousands of SVG nodes is not smooth).
const MAX_ANIMATED = 600;

/** A crossing's key: a hex crosses a sheet once per axis (twice on a self-crossing sheet). */
export const crossingKey = (c) => `${c.hex}:${c.axis}`;

/** Where each crossing of a diagram JSON is drawn, by key. */
export function crossingPlaces(d) {
  return new Map(d.crossings.map((c) => [crossingKey(c), [c.x, c.y]]));
}

/**
 * Animates a redraw. `old`: crossingPlaces of the previous drawing (null: nothing to animate);
 * `ghost`: the previous drawing's element, already placed under the new one, whose crossings carry
 * data-key; `items`: the new crossings as { key, x, y, place(x, y), els } (els fade in when the
 * crossing is new); `fadeIn`: other new elements (chords). Returns { cancel() } or null.
 */
export function animateDiagram({ old, ghost, items, fadeIn = [], ms = STEP_MS }) {
  if (!old || items.length > MAX_ANIMATED) {
    ghost?.remove();
    return null;
  }
  const keys = new Set(items.map((i) => i.key));
  for (const e of ghost?.querySelectorAll('[data-key]') ?? []) if (keys.has(e.dataset.key)) e.remove();
  const moving = items.filter((i) => old.has(i.key)), appearing = items.filter((i) => !old.has(i.key));
  const faded = [...appearing.flatMap((i) => i.els), ...fadeIn];
  return tween(ms, (t) => {
    for (const i of moving) {
      const [x0, y0] = old.get(i.key);
      i.place(x0 + (i.x - x0) * t, y0 + (i.y - y0) * t);
    }
    for (const e of faded) e.style.opacity = String(t);
    if (ghost) ghost.style.opacity = String(1 - t);
  }, () => {
    ghost?.remove();
    for (const e of faded) e.style.opacity = '';
  });
}
