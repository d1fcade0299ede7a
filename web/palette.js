// The operation palette: the steps the engine says apply at the selection (mesh.candidates with
// `near`), each with a one-line explanation and its Δ(V,E,F,H), then the cubical flips whose before
// side is there (mesh.flipPlaces); then the sheet operations on the sheet through a picked edge or
// the chord through a picked quad (mesh.select), each previewed (mesh.preview) under the pointer
// before a click applies it (on a touch screen: the first tap previews, the second applies). Typed
// steps work too; errors show next to it.
import { formatSelection } from './selection.js';
import { qualityText } from './stepText.js';

export const OPS = {
  pillow: ['minimal pillow: two hexes on the quad\'s 8 vertices, a new sphere sheet (TK03 §4.3)', '+4,+8,+6,+2'],
  unpillow: ['removes a pillow pair and re-glues its two free quads', '−4,−8,−6,−2'],
  chordpush: ['pushes a chord across the edge: a blind chord of 2 closes the two arcs (TK03 §4.1)', '+2,+6,+6,+2'],
  chordpull: ['removes a blind chord of 2 and re-glues its quads', '−2,−6,−6,−2'],
  hexpush: ['the 2–6 flip: pushes a hex through the quad (TK03 §4.2)', '+4,+12,+12,+4'],
  hexpull: ['the 6–2 flip: the inverse of a hex push', '−4,−12,−12,−4'],
  ringcollapse: ['collapses the ring chord along the edge (TK03 §4.4)', '−n,−3n,−3n,−n'],
  facecollapse: ['collapses two quads of an edge cycle into one (TK03 §4.4)', '−2,−2,0,0'],
  facesplit: ['splits two quads on the same 4 vertices apart', '+2,+2,0,0'],
};
// The sheet family (docs/operations.md#sheet-operations-a-separate-family): they change the
// boundary quad mesh; Δ comes from the preview.
export const SHEET_OPS = {
  'sheet-extract': 'removes the whole sheet: its hexes vanish and the quads on its two sides are glued (Borden et al. 2002)',
  'sheet-dice': 'splits the sheet into parallel sheets (refinement)',
  'column-collapse': 'collapses the chord\'s column of hexes along a quad diagonal (Merkley et al. 2007)',
};
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
  // A typed step or log that applied leaves the box (Enter again would apply it once more).
  const apply = () => {
    const before = window.hexdual.store.get().meshKey;
    actions.apply(input.value.trim());
    if (window.hexdual.store.get().meshKey !== before) input.value = '';
  };
  $('#op-apply').addEventListener('click', apply);
  input.addEventListener('keydown', (e) => e.key === 'Enter' && apply());
  const preview = $('#op-preview');
  list.addEventListener('pointerover', (e) => {
    const li = e.target.closest('li.sheet-op');
    if (li && li.dataset.step !== preview.dataset.step) showPreview(li);
    else if (li && previewFocus && window.hexdual.store.get().focus !== previewFocus) actions.set({ focus: previewFocus });
    else if (!li && e.target.closest('li')) endPreview(); // another kind of item: the preview is over
  });
  // A touch has no hover: its first tap on a sheet operation previews it, a second tap applies it.
  let pointerType = 'mouse';
  list.addEventListener('pointerdown', (e) => { pointerType = e.pointerType || 'mouse'; });
  list.addEventListener('click', (e) => {
    const li = e.target.closest('li[data-step], li[data-flip]');
    if (li?.classList.contains('sheet-op') && pointerType !== 'mouse' && preview.dataset.armed !== li.dataset.step) {
      showPreview(li, { touch: true });
      preview.dataset.armed = li.dataset.step;
      li.classList.add('armed');
      return;
    }
    if (li?.dataset.step) actions.apply(li.dataset.step);
    else if (li) actions.applyFlip(li.dataset.flip, li.dataset.hexes.split(',').map(Number));
  });
  let shownKey = null;

  /** What a sheet operation would change, from mesh.preview: shown before it is applied. */
  function showPreview(li, { touch = false } = {}) {
    const then = touch ? 'Tap again to apply.' : 'Click to apply.';
    const s = window.hexdual.store.get();
    preview.dataset.step = li.dataset.step;
    delete preview.dataset.armed;
    for (const x of list.querySelectorAll('li.armed')) x.classList.remove('armed');
    preview.classList.remove('warn');
    previewFocus = null;
    endFocus();
    let p;
    try {
      p = s.mesh.preview(li.dataset.step);
    } catch (e) {
      preview.textContent = `${li.dataset.step}: ${e.message}`;
      return;
    }
    li.classList.toggle('refused', !p.applies);
    if (!p.applies) {
      preview.textContent = `${p.step} is refused${p.rule ? ` (rule: ${p.rule})` : ''}: ${p.error}`;
      return;
    }
    const d = p.report.delta;
    const q = qualityText(p.report.quality);
    const inverted = p.report.quality?.inverted.length > 0;
    preview.classList.toggle('warn', inverted);
    preview.textContent = `${inverted ? '⚠ ' : ''}${p.step} would remove ${p.hexesRemoved} and create ${p.hexesCreated} hexes, Δ(${d.V},${d.E},${d.F},${d.H})` +
      (q ? `; ${q}` : '') + `. ${then}`;
    // In 3D, the hexes it would remove (or, for a dicing, which removes none, those of the sheet it
    // splits) are highlighted while the preview shows, the rest dimmed.
    const removed = p.report.removed.hexes.length ? [...p.report.removed.hexes] : operandHexes.get(p.step) ?? [];
    const what = p.report.removed.hexes.length ? `the ${removed.length} highlighted hexes would be removed` : `the highlighted sheet would be split`;
    previewFocus = removed.length
      ? { key: `preview:${p.step}:${s.meshKey}`, hexes: removed, label: `preview of ${p.step}: ${what} — ${touch ? 'tap it again in the list to apply' : 'click to apply'}` }
      : null;
    if (previewFocus) actions.set({ focus: previewFocus });
    // On a phone the 3D view is above the list, out of sight while tapping: a way up to it.
    if (previewFocus && touch && window.matchMedia('(max-width: 700px)').matches) {
      const see = document.createElement('button');
      see.type = 'button';
      see.className = 'see-3d';
      see.textContent = 'see it in 3D ↑';
      see.addEventListener('click', () => document.querySelector('#view3d').scrollIntoView({ block: 'start' }));
      preview.append(' ', see);
    }
  }
  let previewFocus = null;
  const operandHexes = new Map(); // sheet-family step -> the hexes of the sheet or chord it acts on
  function endFocus() {
    if (window.hexdual.store.get().focus?.key?.startsWith('preview:')) actions.set({ focus: null });
  }
  // The pointer left the list or moved to an item that is not a sheet operation.
  function endPreview() {
    endFocus();
    preview.textContent = '';
    preview.classList.remove('warn');
    delete preview.dataset.step;
  }
  // (A touch's pointer leaves after every tap: its preview stays until another item is tapped.)
  list.addEventListener('pointerleave', (e) => e.pointerType !== 'touch' && endPreview());

  /** The sheet through a picked edge or the chord through a picked quad, and its sheet-family steps. */
  function sheetSteps(s) {
    const sel = s.selection;
    if (!sel || (sel.kind !== 'edge' && sel.kind !== 'quad')) return { steps: [], what: '' };
    try {
      const pick = sel.kind === 'edge' ? { hex: sel.hex, edge: sel.edge } : { hex: sel.hex, face: sel.face };
      const x = s.mesh.select(pick);
      operandHexes.clear();
      for (const step of x.steps) operandHexes.set(step, [...x.hexes]);
      return { steps: x.steps, what: `${x.kind} ${x.id} (${x.hexes.length} hexes)` };
    } catch (e) {
      return { steps: [], what: '', error: `sheet operations at ${formatSelection(sel)}: ${e.message}` };
    }
  }

  function sheetItem(step, what) {
    const li = document.createElement('li');
    li.className = 'sheet-op';
    li.dataset.step = step;
    li.innerHTML = '<span class="step"></span><span class="delta">sheet family</span><span class="why"></span>';
    li.querySelector('.step').textContent = step;
    li.querySelector('.why').textContent = `${SHEET_OPS[step.split(' ')[0]] || ''} — on ${what}`;
    li.title = `apply ${step}`;
    return li;
  }

  /** Candidate steps at the selection from the engine: [{ step }], or a note saying why none. */
  function candidatesFor(s) {
    const sel = s.selection;
    const near = sel && nearOf(sel);
    if (!near) return { items: [], flips: [], note: 'Select a quad, an edge or a hex to see the operations that apply there.' };
    try {
      const items = s.mesh.candidates(undefined, { near }).map((step) => ({ step }));
      const flips = s.mesh.flipPlaces(near);
      return { items, flips };
    } catch (e) {
      return { items: [], flips: [], note: `candidates at ${formatSelection(sel)}: ${e.message}` };
    }
  }

  function flipItem(place) {
    const li = document.createElement('li');
    li.className = 'flip';
    li.dataset.flip = place.name;
    li.dataset.hexes = place.hexes.join(',');
    const at = place.hexes.map((h) => 'h' + h).join(' ');
    li.innerHTML = '<span class="step"></span><span class="delta"></span><span class="why"></span>';
    li.querySelector('.step').textContent = `flip ${place.name} at ${at}`;
    const f = actions.flips.find((x) => x.name === place.name);
    li.querySelector('.delta').textContent = f ? `${f.steps.length} step${f.steps.length === 1 ? '' : 's'}` : '';
    li.querySelector('.why').textContent = `cubical flip: replaces these ${place.hexes.length} hex${place.hexes.length > 1 ? 'es' : ''} by the other side of the 4-cube, as its verified atomic steps`;
    li.title = `apply flip ${place.name} at ${at}`;
    return li;
  }

  return {
    update(s) {
      if (!s.mesh) return;
      $('#op-error').textContent = s.opError && s.opError.key === s.meshKey ? s.opError.text : '';
      const key = `${s.meshKey}|${formatSelection(s.selection)}`;
      if (key === shownKey) return;
      shownKey = key;
      // An example step of the right form for the selection (pillow takes a quad, sheet-extract an edge).
      const example = { quad: 'pillow', edge: 'sheet-extract', hex: 'sheet-pillow' }[s.selection?.kind];
      input.placeholder = example ? `${example} ${formatSelection(s.selection)}` : 'pillow h13f5';
      const { items, flips, note } = candidatesFor(s);
      const sheet = sheetSteps(s);
      preview.textContent = '';
      delete preview.dataset.step;
      delete preview.dataset.armed;
      const empty = (text) => Object.assign(document.createElement('li'), { className: 'empty', textContent: text });
      const sheetNote = sheet.error ? [empty(sheet.error)] : [];
      if (!items.length && !flips.length && !sheet.steps.length) {
        list.replaceChildren(empty(note || `nothing applies at ${formatSelection(s.selection)}`), ...sheetNote);
        return;
      }
      list.replaceChildren(
        ...items.map((c) => {
          const op = c.step.split(' ')[0];
          const [why, delta] = OPS[op] || ['', ''];
          const li = document.createElement('li');
          li.dataset.step = c.step;
          const d = delta;
          li.innerHTML = `<span class="step"></span><span class="delta">Δ(${d})</span><span class="why"></span>`;
          li.querySelector('.step').textContent = c.step;
          li.querySelector('.why').textContent = why;
          li.title = `apply ${c.step}`;
          return li;
        }),
        ...flips.map(flipItem),
        ...sheet.steps.map((step) => sheetItem(step, sheet.what)),
        ...sheetNote,
      );
    },
  };
}
