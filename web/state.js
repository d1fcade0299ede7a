// The single app state; views subscribe and redraw what changed. `batch` groups several sets into
// one notification (loading a URL builds the mesh, replays steps and sets the selection at once).
export function createState(initial) {
  let state = { ...initial };
  const listeners = new Set();
  let depth = 0, dirty = false;
  function notify() {
    if (depth > 0) return void (dirty = true);
    dirty = false;
    for (const fn of listeners) fn(state);
  }
  return {
    get: () => state,
    set(patch) {
      state = { ...state, ...patch };
      notify();
    },
    batch(fn) {
      depth++;
      try {
        return fn();
      } finally {
        depth--;
        if (depth === 0 && dirty) notify();
      }
    },
    subscribe(fn) {
      listeners.add(fn);
      return () => listeners.delete(fn);
    },
  };
}
