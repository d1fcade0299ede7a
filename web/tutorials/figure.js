// A live tutorial figure: the engine's mesh after a sequence of stages, drawn in 3D and as a sheet
// diagram, with step buttons, a before/after toggle, counts with their change from the start, and
// an "open in explorer" link that reproduces the shown state. Every change of stage is animated in
// both views. Keyboard: buttons, and ←/→ on the figure. Pages can pick hexes, quads and edges
// (opts.onPick), mark picks, and preview a state (the puzzles).
import { Mesh } from '../../wasm/index.js';
import { sheetColor, chordColor } from '../colors.js';
import { hexModel } from './hexGeometry.js';
import { createView } from './view.js';
import { createDiagram } from './diagram.js';

const COUNT_KEYS = ['vertices', 'edges', 'quads', 'hexes'];
const HOT = '#ffd400', NEW = '#ff9d5c', PICKED = '#e0245e';

/**
 * Mesh spec -> Mesh (the explorer's `mesh=` forms: grid:AxBxC, ring:NxRxZ, fourcube). The tutorials
 * keep the operations' own vertex placement (no smoothing): each figure then has the shape the
 * pages describe (a pushed hex halfway to the quad's centre, a blind chord 0.3 along two edges),
 * the same in every play of a puzzle.
 */
export function buildMesh(spec) {
  const mesh = buildUnsmoothed(spec);
  mesh.smoothing = false;
  return mesh;
}
function buildUnsmoothed(spec) {
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

/** The live hex ids of a mesh, ascending (ids stay stable across operations). */
export function liveHexIds(mesh) {
  const of = mesh.hexDual().sheetOf;
  const ids = [];
  for (let h = 0; 3 * h < of.length; h++) if (of[3 * h] >= 0) ids.push(h);
  return ids;
}

function hexSheets(mesh) {
  const bySheet = new Map(), byHex = new Map();
  for (const s of mesh.sheets) {
    const hexes = [...mesh.sheetHexes(s.id)];
    bySheet.set(s.id, new Set(hexes));
    for (const h of hexes) byHex.set(h, [...(byHex.get(h) || []), s.id]);
  }
  return { bySheet, byHex };
}

// The hexes created and removed going from one set of live ids to another.
function idChange(before, after) {
  const a = new Set(before), b = new Set(after);
  return { created: after.filter((h) => !a.has(h)), removed: before.filter((h) => !b.has(h)) };
}

function figureDom(root, opts) {
  root.classList.add('figure');
  root.tabIndex = 0;
  root.setAttribute('role', 'group');
  root.setAttribute('aria-label', opts.title || 'live figure');
  const panes = el('div', { class: 'panes' }, root);
  const dom = { view3d: el('div', { class: 'view3d' }, panes) };
  const side = el('div', { class: 'side' }, panes);
  if (opts.sideTop) side.appendChild(opts.sideTop); // e.g. the puzzle's operations, next to the 3D view
  dom.chips = el('div', { class: 'chips', role: 'group', 'aria-label': 'sheets' }, side);
  dom.diagramBox = el('div', { class: 'diagram-box' }, side);
  dom.status = el('p', { class: 'status', 'aria-live': 'polite' }, root);
  const controls = el('div', { class: 'controls' }, root);
  dom.back = el('button', { type: 'button', 'data-action': 'back', 'aria-label': 'previous step' }, controls, '◀ step');
  dom.fwd = el('button', { type: 'button', 'data-action': 'forward', 'aria-label': 'next step' }, controls, 'step ▶');
  dom.toggle = el('button', { type: 'button', 'data-action': 'toggle', 'aria-pressed': 'false' }, controls, 'show after');
  dom.stageLabel = el('span', { class: 'stage-label' }, controls);
  dom.link = el('a', { class: 'explorer-link', target: '_blank', rel: 'noopener' }, controls, 'open in explorer ↗');
  if (opts.controls === false) controls.hidden = true;
  dom.table = el('table', { class: 'counts' }, root);
  if (opts.caption) el('p', { class: 'caption' }, root, opts.caption);
  return dom;
}

export function createFigure(root, opts) {
  const spec = opts.mesh;
  let stages = opts.stages || stagesFromSteps(opts.steps || [], opts.labels);
  const dom = figureDom(root, opts);
  const state = { stage: opts.startAfter ? stages.length - 1 : opts.start || 0, sheet: null, hot: -1, picked: opts.picked ?? null, mesh: null, preview: null, ids: [] };
  let startCounts = null, startMaxId = -1, dual = null, model = null, change = null, marks = [], drawnKey = 0;

  // The 3D view (a WebGL context) is made when the figure first scrolls into sight: pages with
  // several figures become interactive sooner.
  let view = null;
  const seen = new IntersectionObserver((entries) => {
    if (!entries.some((e) => e.isIntersecting) || view) return;
    seen.disconnect();
    view = createView(dom.view3d, {
      onHover: (p) => (opts.onHover ? opts.onHover(p, api) : hover(p ? p.hex : -1)),
      onPick: (p, e) => picked3d(p, e),
      pickMode: () => opts.pickMode?.(api) ?? 'hex',
    });
    if (state.mesh) draw3d(false);
  });
  seen.observe(dom.view3d);
  const diagram = createDiagram(dom.diagramBox, {
    onHover: (id) => (opts.onHover ? opts.onHover(id >= 0 ? { kind: 'hex', hex: id } : null, api) : hover(id)),
    onPick: (id, e) => (opts.onPick ? opts.onPick({ kind: 'hex', hex: id }, api, e, 'diagram') : opts.pickable && pick(id)),
  });

  function picked3d(p, e) {
    if (opts.onPick) return opts.onPick(p, api, e, '3d');
    if (opts.pickable && p) pick(p.hex);
  }

  function created(id) {
    return startMaxId >= 0 && id > startMaxId;
  }

  function chooseSheet() {
    const st = stages[state.stage];
    const pickSheet = st.sheet ?? opts.sheet;
    const want = typeof pickSheet === 'function' ? pickSheet(api) : pickSheet;
    const ids = state.mesh.sheets.map((s) => s.id);
    if (state.userSheet !== undefined && ids.includes(state.userSheet) && !st.forceSheet) return state.userSheet;
    return ids.includes(want) ? want : ids[0] ?? null;
  }

  // Builds the shown mesh (the stage's, or a preview's ops) and notes what changed since the last.
  function load() {
    const ops = state.preview ?? stages[state.stage].ops;
    const old = state.mesh;
    state.mesh = meshAfter(spec, ops);
    const ids = liveHexIds(state.mesh);
    change = old ? idChange(state.ids, ids) : null;
    drawnKey++; // a new mesh: the 3D view rebuilds (animated or not)
    state.ids = ids;
    if (old) old.delete();
    dual = hexSheets(state.mesh);
    model = null;
    if (!startCounts) {
      const first = state.stage !== 0 || state.preview ? meshAfter(spec, stages[0].ops) : null;
      const m0 = first || state.mesh;
      startCounts = { ...m0.counts, ...m0.dualSizes() };
      startMaxId = Math.max(...liveHexIds(m0));
      if (first) first.delete();
    }
    state.sheet = chooseSheet();
  }

  function colorOf(id) {
    if (id === state.hot) return HOT;
    if (id === state.picked) return PICKED;
    const extra = opts.emphasis?.(api, id);
    if (extra) return extra;
    // New hexes are orange even on the chosen sheet (every caption says so); the rest of the sheet
    // keeps its colour.
    if (created(id)) return NEW;
    if (opts.sheetIn3d !== false && state.sheet !== null && dual.bySheet.get(state.sheet)?.has(id)) return sheetColor(state.sheet);
    return null;
  }

  function sheetChords(d) {
    if (!d || opts.sheetIn3d === false) return [];
    return d.chords.map((c) => ({
      hexes: [...state.mesh.chordHexes(c.id)],
      color: chordColor(c.id),
      closed: state.mesh.chords.find((x) => x.id === c.id)?.closed,
    }));
  }

  let lastDiagram = null;
  function drawDiagram(animate) {
    lastDiagram = null;
    if (state.sheet === null) return diagram.message('no sheet to draw');
    try {
      const local = opts.local?.(api);
      lastDiagram = local ? state.mesh.localSheetDiagram(state.sheet, local.hexes, local.rings) : state.mesh.sheetDiagramJSON(state.sheet);
      const info = state.mesh.sheets.find((s) => s.id === state.sheet);
      const createdSet = new Set(lastDiagram.crossings.map((c) => c.hex).filter(created));
      diagram.draw(lastDiagram, { created: createdSet, title: `sheet ${state.sheet}: ${info.topology}, ${info.hexes} hexes`, animate });
      diagram.mark(state.hot);
      diagram.select(marks.map(([p]) => p?.hex).filter((h) => h !== undefined));
    } catch (e) {
      diagram.message(e.message);
    }
  }

  function draw3d(animate) {
    if (!view) return;
    view.draw(state.mesh, {
      key: drawnKey,
      colorOf,
      chords: sheetChords(lastDiagram),
      dualVertices: !!opts.dualVertices,
      fitKey: spec.kind === 'file' ? spec.name : meshParam(spec),
      layout: opts.layout,
      shrink: opts.shrink,
      animate: animate && change ? change : null,
      marks,
      labels: opts.hexLabels ? () => opts.hexLabels(api) : null, // after the layout is made
    });
    opts.onDraw3d?.(api);
  }

  function drawChips() {
    dom.chips.replaceChildren();
    if (!opts.sheetChips) return;
    for (const s of state.mesh.sheets) {
      const b = el('button', { type: 'button', class: 'chip', 'data-sheet': s.id, 'aria-pressed': String(s.id === state.sheet) }, dom.chips);
      el('span', { class: 'swatch', style: `background:${sheetColor(s.id)}` }, b);
      b.append(`sheet ${s.id} · ${s.hexes} hex${s.hexes === 1 ? '' : 'es'}`);
      b.addEventListener('click', () => selectSheet(s.id));
    }
  }

  function drawCounts() {
    const c = { ...state.mesh.counts, ...state.mesh.dualSizes() };
    dom.table.replaceChildren();
    const head = el('tr', {}, dom.table), row = el('tr', {}, dom.table);
    for (const k of [...COUNT_KEYS, 'sheets', 'chords']) {
      el('th', {}, head, k);
      const d = c[k] - startCounts[k];
      const td = el('td', { 'data-count': k, 'data-delta': d }, row, String(c[k]));
      if ((state.stage > 0 || state.preview) && d !== 0) el('small', {}, td, ` (${signed(d)})`);
    }
  }

  // Redraws everything; `animate`: from the previous mesh (a change of stage or a preview).
  function update(animate = false) {
    const last = stages.length - 1;
    dom.back.disabled = state.stage === 0;
    dom.fwd.disabled = state.stage === last;
    dom.toggle.hidden = last === 0;
    dom.toggle.textContent = state.stage === last ? 'show before' : 'show after';
    dom.toggle.setAttribute('aria-pressed', String(state.stage === last));
    const st = stages[state.stage];
    const label = last > 0 ? `${state.stage}/${last}: ${st.label}` : st.label || '';
    dom.stageLabel.textContent = state.preview ? `preview: ${state.preview[state.preview.length - 1]}` : label;
    const hash = api.hash();
    dom.link.hidden = hash === null;
    if (hash !== null) dom.link.href = `../index.html${hash}`;
    drawChips();
    drawDiagram(animate);
    draw3d(animate);
    drawCounts();
    describeHot();
    root.dataset.stage = String(state.stage);
    root.classList.toggle('previewing', state.preview !== null);
    opts.onUpdate?.(api);
  }

  function describeHot() {
    if (state.hot < 0) {
      dom.status.textContent = opts.hint || 'Hover a hex (3D) or a crossing (diagram) to see it in both.';
      return;
    }
    const sheets = dual.byHex.get(state.hot) || [];
    dom.status.textContent = `hex ${state.hot}: on sheet${sheets.length === 1 ? '' : 's'} ${sheets.join(', ')}`;
  }

  function hover(id) {
    if (id === state.hot) return;
    state.hot = id;
    diagram.mark(id);
    draw3d(false);
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
    if (next === state.stage && state.mesh && !state.preview) return;
    state.stage = next;
    state.preview = null;
    try {
      load();
    } catch (e) {
      dom.status.textContent = e.message;
      throw e;
    }
    update(true);
  }

  dom.back.addEventListener('click', () => go(state.stage - 1));
  dom.fwd.addEventListener('click', () => go(state.stage + 1));
  dom.toggle.addEventListener('click', () => go(state.stage === stages.length - 1 ? 0 : stages.length - 1));
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
    /** Per-hex corners, gluings and dual points parsed from .hxd (hexGeometry.js), made on demand. */
    get model() { return (model ??= hexModel(state.mesh, state.ids)); },
    get sheet() { return state.sheet; },
    get picked() { return state.picked; },
    get dual() { return dual; },
    get startCounts() { return startCounts; },
    get diagram() { return lastDiagram; },
    get diagramView() { return diagram; },
    get canvas() { return view?.canvas ?? null; },
    get view() { return view; },
    get previewing() { return state.preview !== null; },
    /** Whether a step animation is running in 3D or in the diagram. */
    get animating() { return !!view?.animating || diagram.animating; },
    liveIds: () => state.ids,
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
    /** Replaces the stages (e.g. steps a reader typed or clicked) and shows the last one, animated. */
    setStages(next, { animate = true } = {}) {
      stages = next;
      startCounts = null;
      state.stage = next.length - 1;
      state.preview = null;
      load();
      update(animate);
    },
    /** Shows the mesh after `ops` (a candidate step, animated) without changing the stage; null ends it. */
    preview(ops) {
      if (ops === null && state.preview === null) return;
      state.preview = ops;
      load();
      update(true);
    },
    /** Quad, edge or hex marks in 3D ([pick, colour, opacity]); their hexes are ringed in the diagram. */
    setMarks(items) {
      marks = items;
      view?.setMarks(items);
      diagram.select(items.map(([p]) => p?.hex).filter((h) => h !== undefined));
    },
    /** Redraws colours (e.g. after the page's emphasis changed). */
    repaint() { draw3d(false); },
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
