// Step animation timing shared by the 3D views and the sheet diagrams: one duration, one easing,
// and prefers-reduced-motion (then every change is shown at once).
export const STEP_MS = 450;

/** Whether the user asked for less motion. */
export function prefersReducedMotion() {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}

const ease = (t) => (t < 0.5 ? 2 * t * t : 1 - (-2 * t + 2) ** 2 / 2);

/**
 * Calls `frame(t)` with t eased from 0 to 1 over `ms`, once per animation frame, then `done()`.
 * With reduced motion (or ms <= 0) it calls frame(1) and done() at once. Returns { cancel(), running }:
 * cancel jumps to the end.
 */
export function tween(ms, frame, done) {
  let finished = false;
  const finish = () => {
    if (finished) return;
    finished = true;
    frame(1);
    done?.();
  };
  const handle = {
    cancel: () => finish(),
    get running() {
      return !finished;
    },
  };
  if (ms <= 0 || prefersReducedMotion()) {
    finish();
    return handle;
  }
  const t0 = performance.now();
  const step = (now) => {
    if (finished) return;
    const f = Math.min(1, (now - t0) / ms);
    if (f >= 1) return finish();
    frame(ease(f));
    requestAnimationFrame(step);
  };
  frame(0);
  requestAnimationFrame(step);
  return handle;
}
