// Puzzle progress: which puzzles are solved and in how many steps, and the steps of each puzzle
// in play, kept in localStorage; the puzzle and its steps are also in the URL (shareable):
// puzzles.html#p=sphere&steps=v1;pillow%20h0f1
const KEY = 'hexdual-puzzles-v1';

function load() {
  try {
    const v = JSON.parse(localStorage.getItem(KEY) || '{}');
    return { solved: v.solved || {}, steps: v.steps || {}, current: v.current || null };
  } catch {
    return { solved: {}, steps: {}, current: null };
  }
}

export function createProgress() {
  const data = load();
  const save = () => {
    try {
      localStorage.setItem(KEY, JSON.stringify(data));
    } catch {
      // Private mode or a full quota: progress then lives in the URL only.
    }
  };
  return {
    solved: (id) => data.solved[id] ?? null,
    steps: (id) => data.steps[id] ?? [],
    get current() {
      return data.current;
    },
    /** Records the steps in play (and the puzzle as the current one). */
    play(id, steps) {
      data.current = id;
      data.steps[id] = steps;
      save();
    },
    /** Records a solution; keeps the fewest steps. */
    solve(id, used) {
      data.solved[id] = Math.min(used, data.solved[id] ?? Infinity);
      save();
    },
    reset() {
      data.solved = {};
      data.steps = {};
      data.current = null;
      save();
    },
  };
}

/** { id, steps } from a URL hash (steps null when absent). */
export function parsePuzzleHash(hash) {
  const p = new URLSearchParams(hash.replace(/^#/, ''));
  const log = p.get('steps');
  const steps = log && log.startsWith('v1') ? log.split(';').slice(1).filter(Boolean) : null;
  return { id: p.get('p'), steps };
}

export function puzzleHash(id, steps) {
  const log = ['v1', ...steps].join(';');
  return `#p=${encodeURIComponent(id)}${steps.length ? `&steps=${encodeURIComponent(log).replace(/%3B/g, ';').replace(/%20/g, '%20')}` : ''}`;
}
