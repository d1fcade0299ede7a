// A live tutorial figure: the engine's mesh after a sequence of stages, drawn in 3D and as a sheet
// diagram, with step buttons, a before/after toggle, counts with their change from the start, and
// an "open in explorer" link that reproduces the shown state. Keyboard: buttons, and ←/→ on the figure.
import { Mesh } from '../../wasm/index.js';
import { sheetColor, chordColor } from '../colors.js';
import { hexModel } from './hexGeometry.js';
import { createView } from './view.js';
import { createDiagram } from './diagram.js';

const COUNT_KEYS = ['vertices', 'edges', 'quads', 'hexes'];
const HOT = '#ffd400', NEW = '#ff9d5c', PICKED = '#e0245e';

/** Mesh spec -> Mesh (the explorer's `mesh=` forms: grid:AxBxC, ring:NxRxZ, fourcube). */
export function buildMesh(spec) {
  if (spec.kind === 'fourcube') return Mesh.fourCube();
  if (spec.kind === 'file') return Mesh.load(spec.text, spec.name);
  const [a, b, c] = spec.dims;
  return spec.kind === 'ring' ? Mesh.ring(a, b, c) : Mesh.grid(a, b, c);
}

export function meshParam(spec) {
  return spec.kind === 'fourcube' ? 'fourcube' : `${spec.kind}:${spec.dims.join('x')}`;
}

/** The explorer URL (relative to a tutorial page) for a mesh, applied steps and a sheet. */
export function explorerHash(spec, ops, sheet) {
  if (spec.kind === 'file') return null;
  const p = new URLSearchParams();
  p.set('mesh', meshParam(spec));
  if (ops.length) p.set('ops', ['v1', ...ops].join(';'));
  if (sheet !== null && sheet !== undefined) p.set('sheet', String(sheet));
  return '#' + p.toString();
}

/** Stages from a step list: stage k has the first k steps applied. */
export function stagesFromSteps(steps, labels = []) {
  return [{ ops: [], label: 'before' }, ...steps.map((s, k) => ({ ops: steps.slice(0, k + 1), label: labels[k] || s }))];
}

function el(tag, attrs = {}, parent, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

function signed(n) {
  return n > 0 ? `+${n}` : n < 0 ? `−${-n}` : '0';
}

/** Applies `ops` to a fresh mesh; throws naming the step that failed. */
export function meshAfter(spec, ops) {
  const mesh = buildMesh(spec);
  ops.forEach((step, k) => {
    try {
      mesh.apply(step);
    } catch (e) {
      mesh.delete();
      throw new Error(`step ${k + 1} (${step}): ${e.message}`);
    }
  });
  return mesh;
}

function hexSheets(mesh) {
  const bySheet = new Map(), byHex = new Map();
  for (const s of mesh.sheets) {
    const hexes = [...mesh.sheetHexes(s.id)];
    bySheet.set(s.id, hexes);
    for (const h of hexes) byHex.set(h, [...(byHex.get(h) || []), s.id]);
  }
  return { bySheet, byHex };
}

export function createFigure(root, opts) {
  const spec = opts.mesh;
  let stages = opts.stages || stagesFromSteps(opts.steps || [], opts.labels);
  root.classList.add('figure');
  root.tabIndex = 0;
  root.setAttribute('role', 'group');
  root.setAttribute('aria-label', opts.title || 'live figure');
  const panes = el('div', { class: 'panes' }, root);
  const view3d = el('div', { class: 'view3d' }, panes);
  const side = el('div', { class: 'side' }, panes);
  const chips = el('div', { class: 'chips', role: 'group', 'aria-label': 'sheets' }, side);
  const diagramBox = el('div', { class: 'diagram-box' }, side);
  const status = el('p', { class: 'status', 'aria-live': 'polite' }, root);
  const controls = el('div', { class: 'controls' }, root);
  const back = el('button', { type: 'button', 'data-action': 'back', 'aria-label': 'previous step' }, controls, '◀ step');
  const fwd = el('button', { type: 'button', 'data-action': 'forward', 'aria-label': 'next step' }, controls, 'step ▶');
  const toggle = el('button', { type: 'button', 'data-action': 'toggle', 'aria-pressed': 'false' }, controls, 'show after');
  const stageLabel = el('span', { class: 'stage-label' }, controls);
  const link = el('a', { class: 'explorer-link', target: '_blank', rel: 'noopener' }, controls, 'open in explorer ↗');
  const table = el('table', { class: 'counts' }, root);
  if (opts.caption) el('p', { class: 'caption' }, root, opts.caption);

  const state = { stage: opts.startAfter ? stages.length - 1 : opts.start || 0, sheet: null, hot: -1, picked: opts.picked ?? null, mesh: null, model: null };
  let startCounts = null, startMaxId = -1, dual = null;

  // The 3D view (a WebGL context) is made when the figure first scrolls into sight: pages with
  // several figures become interactive sooner.
  let view = null;
  const seen = new IntersectionObserver((entries) => {
    if (!entries.some((e) => e.isIntersecting) || view) return;
    seen.disconnect();
    view = createView(view3d, {
      onHover: (h) => hover(h >= 0 ? state.model.ids[h] : -1),
      onPick: (h) => opts.pickable && pick(state.model.ids[h]),
    });
    if (state.model) draw3d();
  });
  seen.observe(view3d);
  const diagram = createDiagram(diagramBox, { onHover: (id) => hover(id) });

  function created(id) {
    return startMaxId >= 0 && id > startMaxId;
  }

  function chooseSheet() {
    const st = stages[state.stage];
    const pick = st.sheet ?? opts.sheet;
    const want = typeof pick === 'function' ? pick(api) : pick;
    const ids = state.mesh.sheets.map((s) => s.id);
    if (state.userSheet !== undefined && ids.includes(state.userSheet) && !st.forceSheet) return state.userSheet;
    return ids.includes(want) ? want : ids[0] ?? null;
  }

  function load() {
    const st = stages[state.stage];
    const old = state.mesh;
    state.mesh = meshAfter(spec, st.ops);
    if (old) old.delete();
    dual = hexSheets(state.mesh);
    // Every hex lies on a sheet, so the sheets name every live hex.
    state.model = hexModel(state.mesh, [...dual.byHex.keys()].sort((a, b) => a - b));
    if (!startCounts) {
      const first = state.stage !== 0 ? meshAfter(spec, stages[0].ops) : null;
      const m0 = first || state.mesh;
      startCounts = { ...m0.counts, ...m0.dualSizes() };
      startMaxId = Math.max(...(first ? hexSheets(m0) : dual).byHex.keys());
      if (first) first.delete();
    }
    state.sheet = chooseSheet();
  }

  function colorOf(h) {
    const id = state.model.ids[h];
    if (id === state.hot) return HOT;
    if (id === state.picked) return PICKED;
    const extra = opts.emphasis?.(api, id);
    if (extra) return extra;
    if (opts.sheetIn3d !== false && state.sheet !== null && dual.bySheet.get(state.sheet)?.includes(id)) return sheetColor(state.sheet);
    if (created(id)) return NEW;
    return null;
  }

  function sheetChords(d) {
    if (!d) return [];
    const index = state.model.index;
    return d.chords.map((c) => ({
      hexes: [...state.mesh.chordHexes(c.id)].map((h) => index.get(h)),
      color: chordColor(c.id),
      closed: state.mesh.chords.find((x) => x.id === c.id)?.closed,
    }));
  }

  let lastDiagram = null;
  function drawDiagram() {
    lastDiagram = null;
    if (state.sheet === null) return diagram.message('no sheet to draw');
    try {
      const local = opts.local?.(api);
      lastDiagram = local ? state.mesh.localSheetDiagram(state.sheet, local.hexes, local.rings) : state.mesh.sheetDiagramJSON(state.sheet);
      const info = state.mesh.sheets.find((s) => s.id === state.sheet);
      const createdSet = new Set(lastDiagram.crossings.map((c) => c.hex).filter(created));
      diagram.draw(lastDiagram, { created: createdSet, title: `sheet ${state.sheet}: ${info.topology}, ${info.hexes} hexes` });
      diagram.mark(state.hot);
    } catch (e) {
      diagram.message(e.message);
    }
  }

  function draw3d() {
    if (!view) return;
    view.draw(state.model, {
      colorOf,
      chords: opts.sheetIn3d === false ? [] : sheetChords(lastDiagram),
      dualVertices: !!opts.dualVertices,
      fitKey: spec.kind === 'file' ? spec.name : meshParam(spec),
    });
  }

  function drawChips() {
    chips.replaceChildren();
    if (!opts.sheetChips) return;
    for (const s of state.mesh.sheets) {
      const b = el('button', { type: 'button', class: 'chip', 'data-sheet': s.id, 'aria-pressed': String(s.id === state.sheet) }, chips);
      el('span', { class: 'swatch', style: `background:${sheetColor(s.id)}` }, b);
      b.append(`sheet ${s.id} · ${s.hexes} hex${s.hexes === 1 ? '' : 'es'}`);
      b.addEventListener('click', () => selectSheet(s.id));
      b.addEventListener('pointerenter', () => hoverSheet(s.id));
      b.addEventListener('pointerleave', () => hoverSheet(null));
    }
  }

  function hoverSheet(id) {
    const keep = state.sheet;
    if (id !== null) state.sheet = id;
    draw3d();
    state.sheet = keep;
  }

  function drawCounts() {
    const c = { ...state.mesh.counts, ...state.mesh.dualSizes() };
    table.replaceChildren();
    const head = el('tr', {}, table), row = el('tr', {}, table);
    for (const k of [...COUNT_KEYS, 'sheets', 'chords']) {
      el('th', {}, head, k);
      const d = c[k] - startCounts[k];
      const td = el('td', { 'data-count': k, 'data-delta': d }, row, String(c[k]));
      if (state.stage > 0 && d !== 0) el('small', {}, td, ` (${signed(d)})`);
    }
  }

  function update() {
    const last = stages.length - 1;
    back.disabled = state.stage === 0;
    fwd.disabled = state.stage === last;
    toggle.hidden = last === 0;
    toggle.textContent = state.stage === last ? 'show before' : 'show after';
    toggle.setAttribute('aria-pressed', String(state.stage === last));
    const st = stages[state.stage];
    stageLabel.textContent = last > 0 ? `${state.stage}/${last}: ${st.label}` : st.label || '';
    const hash = api.hash();
    link.hidden = hash === null;
    if (hash !== null) link.href = `../index.html${hash}`;
    drawChips();
    drawDiagram();
    draw3d();
    drawCounts();
    describeHot();
    root.dataset.stage = String(state.stage);
    opts.onUpdate?.(api);
  }

  function describeHot() {
    if (state.hot < 0) {
      status.textContent = opts.hint || 'Hover a hex (3D) or a crossing (diagram) to see it in both.';
      return;
    }
    const sheets = dual.byHex.get(state.hot) || [];
    status.textContent = `hex ${state.hot}: on sheet${sheets.length === 1 ? '' : 's'} ${sheets.join(', ')}`;
  }

  function hover(id) {
    if (id === state.hot) return;
    state.hot = id;
    diagram.mark(id);
    draw3d();
    describeHot();
  }

  function pick(id) {
    state.picked = id;
    update();
  }

  function selectSheet(id) {
    state.userSheet = id;
    state.sheet = id;
    update();
  }

  function go(k) {
    const next = Math.max(0, Math.min(stages.length - 1, k));
    if (next === state.stage && state.mesh) return;
    state.stage = next;
    try {
      load();
    } catch (e) {
      status.textContent = e.message;
      throw e;
    }
    update();
  }

  back.addEventListener('click', () => go(state.stage - 1));
  fwd.addEventListener('click', () => go(state.stage + 1));
  toggle.addEventListener('click', () => go(state.stage === stages.length - 1 ? 0 : stages.length - 1));
  root.addEventListener('keydown', (e) => {
    if (e.target.closest('input, textarea, select')) return;
    if (e.key === 'ArrowRight') go(state.stage + 1);
    else if (e.key === 'ArrowLeft') go(state.stage - 1);
    else return;
    e.preventDefault();
  });

  const api = {
    root,
    spec,
    get stages() { return stages; },
    get stage() { return state.stage; },
    get mesh() { return state.mesh; },
    get model() { return state.model; },
    get sheet() { return state.sheet; },
    get picked() { return state.picked; },
    get dual() { return dual; },
    get startCounts() { return startCounts; },
    get diagram() { return lastDiagram; },
    get canvas() { return view?.canvas ?? null; },
    isCreated: created,
    counts() { return { ...state.mesh.counts, ...state.mesh.dualSizes() }; },
    /** The engine's canonical hash of the shown complex (isomorphism with the boundary fixed). */
    canonicalHash() { return state.mesh.canonicalHash(); },
    delta() {
      const c = api.counts();
      return Object.fromEntries(Object.keys(c).map((k) => [k, c[k] - startCounts[k]]));
    },
    hash() { return explorerHash(spec, stages[state.stage].ops, state.sheet); },
    go,
    pick,
    selectSheet,
    /** Replaces the stages (e.g. steps a reader typed) and shows the last one. */
    setStages(next) {
      stages = next;
      startCounts = null;
      state.stage = next.length - 1;
      load();
      update();
    },
    destroy() {
      seen.disconnect();
      view?.destroy();
      state.mesh?.delete();
      state.mesh = null;
      const list = window.tutorial.figures;
      list.splice(list.indexOf(api), 1);
      root.replaceChildren();
    },
  };
  state.stage = Math.max(0, Math.min(stages.length - 1, state.stage));
  load();
  update();
  (window.tutorial ||= { figures: [] }).figures.push(api);
  return api;
}
