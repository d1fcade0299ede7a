// The operation palette: the steps the engine says apply at the selection (candidates), each with
// a one-line explanation and its Δ(V,E,F,H); one click applies. Typed steps work too; errors show
// next to the palette.
import { formatSelection } from './selection.js';

const OPS = {
  pillow: ['minimal pillow: two hexes on the quad\'s 8 vertices, a new sphere sheet (TK03 §4.3)', '+4,+8,+6,+2'],
  unpillow: ['removes a pillow pair and re-glues its two free quads', '−4,−8,−6,−2'],
  chordpush: ['pushes a chord across the edge: a blind chord of 2 closes the two arcs (TK03 §4.4)', '+2,+6,+6,+2'],
  chordpull: ['removes a blind chord of 2 and re-glues its quads', '−2,−6,−6,−2'],
  hexpush: ['the 2–6 flip: pushes a hex through the quad (TK03 §4.5)', '+4,+12,+12,+4'],
  hexpull: ['the 6–2 flip: the inverse of a hex push', '−4,−12,−12,−4'],
  ringcollapse: ['collapses the ring chord along the edge (TK03 §4.2)', '−n,−3n,−3n,−n'],
  facecollapse: ['collapses two quads of an edge cycle into one (TK03 §4.1)', '−2,−2,0,0'],
  facesplit: ['splits two quads on the same 4 vertices apart', '+2,+2,0,0'],
};
const ALL_OPS = Object.keys(OPS);
// Without the package's candidates(op, {near}), every op is enumerated over the whole mesh: only
// affordable on small meshes.
const ENUMERATE_MAX_HEXES = 3000;

function nearOf(sel) {
  if (sel.kind === 'hex') return { hex: sel.hex };
  if (sel.kind === 'quad') return { hex: sel.hex, face: sel.face };
  if (sel.kind === 'edge') return { hex: sel.hex, edge: sel.edge };
  return null;
}

export function createPalette(root, actions) {
  const $ = (s) => root.querySelector(s);
  const list = $('#candidates');
  const input = $('#op-step');
  const apply = () => actions.apply(input.value.trim());
  $('#op-apply').addEventListener('click', apply);
  input.addEventListener('keydown', (e) => e.key === 'Enter' && apply());
  list.addEventListener('click', (e) => {
    const li = e.target.closest('li[data-step]');
    if (li) actions.apply(li.dataset.step);
  });
  let allKey = null, all = [];
  let shownKey = null;

  function enumerate(mesh) {
    const out = [];
    for (const op of ALL_OPS) {
      try {
        out.push(...mesh.candidateSteps(op));
      } catch {
        // an operation the engine does not enumerate: nothing to offer for it
      }
    }
    return out;
  }

  /** Candidate steps at the selection: [{ step, why, delta }]. */
  function candidatesFor(s) {
    const sel = s.selection;
    const near = sel && nearOf(sel);
    if (!near) return { items: [], note: 'Select a quad, an edge or a hex to see the operations that apply there.' };
    const m = s.mesh;
    if (typeof m.candidates === 'function') {
      try {
        const found = m.candidates(undefined, { near });
        return { items: found.map((c) => (typeof c === 'string' ? { step: c } : c)) };
      } catch {
        // fall through to enumeration
      }
    }
    if (m.counts.hexes > ENUMERATE_MAX_HEXES) return { items: [], note: `${m.counts.hexes} hexes: type a step (e.g. pillow ${formatSelection(sel)})` };
    if (allKey !== s.meshKey) {
      allKey = s.meshKey;
      all = enumerate(m);
    }
    const exact = formatSelection(sel);
    const re = new RegExp(`\\bh${sel.hex}(?![0-9])`);
    const items = all.filter((step) => re.test(step)).map((step) => ({ step, exact: step.split(' ').includes(exact) }));
    items.sort((a, b) => Number(b.exact) - Number(a.exact));
    return { items };
  }

  return {
    update(s) {
      if (!s.mesh) return;
      $('#op-error').textContent = s.error && /^[a-z]+ h\d/.test(s.error) ? s.error : '';
      const key = `${s.meshKey}|${formatSelection(s.selection)}`;
      if (key === shownKey) return;
      shownKey = key;
      if (s.selection && 'hex' in s.selection && !input.value) input.placeholder = `pillow ${formatSelection(s.selection)}`;
      const { items, note } = candidatesFor(s);
      if (!items.length) {
        list.replaceChildren(Object.assign(document.createElement('li'), { className: 'empty', textContent: note || `nothing applies at ${formatSelection(s.selection)}` }));
        return;
      }
      list.replaceChildren(
        ...items.map((c) => {
          const op = c.step.split(' ')[0];
          const [why, delta] = OPS[op] || ['', ''];
          const li = document.createElement('li');
          li.dataset.step = c.step;
          const d = c.delta ? (Array.isArray(c.delta) ? c.delta.join(',') : String(c.delta)) : delta;
          li.innerHTML = `<span class="step"></span><span class="delta">Δ(${d})</span><span class="why"></span>`;
          li.querySelector('.step').textContent = c.step;
          li.querySelector('.why').textContent = c.why || c.explanation || why;
          li.title = `apply ${c.step}`;
          return li;
        }),
      );
    },
  };
}
