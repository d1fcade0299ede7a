// The operations that apply at a pick, as the engine lists them (mesh.candidates near the pick, and
// mesh.ringSplits at an edge), grouped by operation: pointing at one previews it, a click applies it.
import { OPS } from '../palette.js';
import { stepText, pickText } from './stepText.js';

const ORDER = ['pillow', 'unpillow', 'chordpush', 'chordpull', 'hexpush', 'hexpull', 'ringcollapse', 'ringsplit', 'facecollapse', 'facesplit'];
const NAMES = {
  pillow: 'Pillow', unpillow: 'Unpillow', chordpush: 'Chord push', chordpull: 'Chord pull', hexpush: 'Hex push', hexpull: 'Hex pull',
  ringcollapse: 'Ring collapse', ringsplit: 'Ring split', facecollapse: 'Face collapse', facesplit: 'Face split',
};
const WHY = { ...Object.fromEntries(Object.entries(OPS).map(([k, v]) => [k, v[0]])), ringsplit: 'the inverse of a ring collapse: a ring of new hexes along a loop of edges (TK03 §4.4)' };

function nearOf(p) {
  return p.kind === 'hex' ? { hex: p.hex } : p.kind === 'quad' ? { hex: p.hex, face: p.face } : { hex: p.hex, edge: p.edge };
}

/** The steps that apply at a pick, from the engine. */
export function stepsAt(mesh, pick) {
  const near = nearOf(pick);
  const steps = mesh.candidates(undefined, { near });
  if (pick.kind === 'edge') steps.push(...mesh.ringSplits(near));
  return steps;
}

export function createCandidates(root, { onPreview, onApply }) {
  root.classList.add('candidates');
  const head = Object.assign(document.createElement('p'), { className: 'cand-head' });
  const list = Object.assign(document.createElement('div'), { className: 'cand-list' });
  root.append(head, list);
  let previewing = null;
  // The list is redrawn under a resting pointer after every step: the browser then reports the
  // pointer entering the new item under it. A preview starts only once the pointer really moved.
  let pointer = { x: NaN, y: NaN }, restingAt = null;
  document.addEventListener('pointermove', (e) => (pointer = { x: e.clientX, y: e.clientY }), { passive: true });
  const moved = (e) => !restingAt || e.clientX !== restingAt.x || e.clientY !== restingAt.y;
  const preview = (step) => {
    if (step === previewing) return;
    previewing = step;
    onPreview(step);
  };
  list.addEventListener('pointerleave', () => preview(null));
  list.addEventListener('focusout', (e) => !list.contains(e.relatedTarget) && preview(null));

  function item(step) {
    const b = Object.assign(document.createElement('button'), { type: 'button', className: 'cand' });
    b.dataset.step = step;
    b.innerHTML = '<span class="cand-text"></span><code></code>';
    b.querySelector('.cand-text').textContent = stepText(step);
    b.querySelector('code').textContent = step;
    b.title = WHY[step.split(' ')[0]] || '';
    b.addEventListener('pointerenter', (e) => moved(e) && preview(step));
    b.addEventListener('focus', () => preview(step));
    b.addEventListener('click', () => {
      previewing = null;
      onApply(step);
    });
    return b;
  }

  return {
    /** Lists what applies at `pick` in `mesh`; returns the steps. */
    show(mesh, pick) {
      list.replaceChildren();
      previewing = null;
      restingAt = pointer;
      if (!pick) {
        head.textContent = 'Pick a quad, an edge or a hex in the figure (or a crossing in the sheet diagram): the operations that apply there appear here.';
        return [];
      }
      let steps;
      try {
        steps = stepsAt(mesh, pick);
      } catch (e) {
        head.textContent = `${pickText(pick)}: ${e.message}`;
        return [];
      }
      head.textContent = steps.length ? `At ${pickText(pick)} — point at one to preview it, click to apply:` : `Nothing applies at ${pickText(pick)}. Pick another place.`;
      for (const op of ORDER) {
        const group = steps.filter((s) => s.startsWith(op + ' '));
        if (!group.length) continue;
        const box = Object.assign(document.createElement('div'), { className: 'cand-group' });
        const h = Object.assign(document.createElement('h3'), { textContent: `${NAMES[op]} (${group.length})` });
        h.title = WHY[op] || '';
        box.append(h, ...group.map(item));
        list.append(box);
      }
      return steps;
    },
    get previewing() {
      return previewing;
    },
  };
}
