// hexdual explorer: wires the wasm package, the single app state, and the views that subscribe to it
// (3D view, sheet diagrams, timeline, palette, lists, flips view). The URL mirrors the state.
import { init, Mesh, flips } from '../wasm/index.js';
import wasmUrl from '../wasm/dist/hexdual.wasm?url';
import { createState } from './state.js';
import { createPanel } from './panel.js';
import { createView3d } from './view3d.js';
import { createDiagrams } from './sheetDiagram.js';
import { createTimeline } from './timeline.js';
import { createPalette } from './palette.js';
import { createFlipsView } from './flipsView.js';
import { createFiles } from './files.js';
import { parseHash, formatHash, parseStepLog } from './urlState.js';
import { formatSelection, sameSelection, dualThrough } from './selection.js';
import { createEngine } from './engine.js';

const timings = { start: performance.now() };
await init({ locateFile: (p) => (p.endsWith('.wasm') ? wasmUrl : p) });
timings.init = performance.now();

const store = createState({
  mesh: null, spec: null, meshKey: '', steps: [], at: 0, report: null, selection: null, diagrams: [],
  shrink: 0.15, overlay: false, singular: false, ghosts: true, focusChanges: true, colorBy: 'plain', quality: null, slice: null, camera: null,
  error: '', opError: null, waitingFor: null, notice: '', view: 'explore', flip: null, focus: null, busy: false,
});
const engine = createEngine(store);

// The live sheet and chord ids (the engine keeps ids stable, so they need not be 0..n-1).
function dualIds(mesh) {
  return { sheets: new Set(mesh.sheets.map((x) => x.id)), chords: new Set(mesh.chords.map((x) => x.id)) };
}

// Keeps the selection and diagrams whose hex / sheet still exist after the mesh changed.
function survivors(s, mesh) {
  const hd = engine.hexDual();
  const alive = (h) => h >= 0 && 3 * h < hd.sheetOf.length && hd.sheetOf[3 * h] >= 0;
  const ids = dualIds(mesh);
  let sel = s.selection;
  if (sel && 'hex' in sel && !alive(sel.hex)) sel = null;
  if (sel && sel.kind === 'sheet' && !ids.sheets.has(sel.id)) sel = null;
  if (sel && sel.kind === 'chord' && !ids.chords.has(sel.id)) sel = null;
  const diagrams = s.diagrams.filter((d) => ids.sheets.has(d.sheet) && (!d.local || alive(d.local.hex)));
  return { selection: sel, diagrams };
}

// Runs a step or a move in time as one state change, keeping what survives. Its error is shown
// once, under the step box (state.opError, for this mesh state only); the step's name is not repeated.
function changeMesh(change, errorPrefix) {
  try {
    store.batch(() => {
      change();
      const s = store.get();
      const focus = s.focus?.key?.startsWith('preview:') ? null : s.focus; // a preview's highlight ends with the step
      store.set({ ...survivors(s, s.mesh), error: '', opError: null, focus });
    });
  } catch (e) {
    // The engine's message starts with the operation's name (or 'oplog' for a log): said once.
    const op = /^operation log|\.txt\b/.test(errorPrefix) ? 'oplog' : errorPrefix.split(/[ :]/)[0];
    const message = op && e.message.startsWith(`${op}: `) ? e.message.slice(op.length + 2) : e.message;
    store.set({ opError: { key: store.get().meshKey, text: errorPrefix + message } });
  }
}

// A URL naming a local file (mesh=file:NAME), waiting for that file to be opened or dropped.
let pendingFile = null;
// While it waits, the 3x3x3 grid only stands in: a step there would replace the shared URL (its
// file and steps), so steps are refused until the file comes or another mesh is built.
function refuseOnStandIn() {
  if (!pendingFile) return false;
  store.set({ opError: { key: store.get().meshKey, text: `the URL's ${plural(pendingFile.steps.length, 'step')} are for ${pendingFile.mesh.name}: open or drop that file first (or build a mesh to work on another)` } });
  return true;
}

const actions = {
  flips: flips(),
  engine,
  /** Builds a grid, ring or the 4-cube boundary (`dims` like 3x3x3). */
  build(kind, dimsText) {
    pendingFile = null;
    store.set({ waitingFor: null });
    let spec = { kind: 'fourcube', dims: [] };
    if (kind !== 'fourcube') {
      const m = /^\s*(\d+)\s*x\s*(\d+)\s*x\s*(\d+)\s*$/.exec(dimsText);
      if (!m) return store.set({ error: `dimensions must look like 3x3x3, not '${dimsText}'` });
      spec = { kind, dims: [+m[1], +m[2], +m[3]] };
    }
    try {
      store.batch(() => {
        engine.start(spec);
        store.set({ selection: null, diagrams: [], camera: null, error: '', notice: '', focus: null });
      });
    } catch (e) {
      store.set({ error: e.message });
    }
  },
  /**
   * Opens a mesh file (Open or a drop). When the URL named this file (mesh=file:NAME), its steps
   * replay and its selection, diagrams and view come back, as for a generated mesh's URL.
   */
  open(bytes, name) {
    const pending = pendingFile;
    try {
      store.batch(() => engine.start({ kind: 'file', name }, bytes));
    } catch (e) {
      return store.set({ error: e.message.startsWith(name) ? e.message : `${name}: ${e.message}` });
    }
    pendingFile = null;
    store.set({ waitingFor: null });
    const notice = `${name} is a local file: the URL cannot carry it. Share it with "download .hxd + steps".`;
    if (pending && pending.mesh.name === name) {
      store.batch(() => {
        const errors = [...pending.errors];
        const stepError = engine.replay(pending.steps, pending.at);
        if (stepError) errors.push(stepError);
        showUrlState(pending, errors, notice);
      });
      if (pending.camera) view.setCamera(pending.camera);
      return;
    }
    const other = pending ? `the URL's steps were for ${pending.mesh.name}, not ${name}: not replayed` : '';
    store.set({ selection: null, diagrams: [], camera: null, error: other, focus: null, notice });
  },
  /**
   * Opens what was dropped or chosen: a mesh file, a steps file (.txt: the log of "download .hxd +
   * steps"), or both at once. The mesh opens first, then the log applies to it.
   */
  async openFiles(files) {
    const isLog = (f) => /\.txt$/i.test(f.name);
    const mesh = files.find((f) => !isLog(f));
    const log = files.find(isLog);
    const pending = pendingFile; // a shared URL waiting for its file, if any
    const parsed = log ? parseStepLog(await log.text()) : null;
    const logSteps = parsed && parsed.log.startsWith('v1') ? parsed.log.split(';').slice(1).filter(Boolean) : null;
    const sameSteps = (a, b) => !!a && !!b && a.length === b.length && a.every((x, i) => x === b[i]);
    if (mesh) {
      const replays = pending && pending.mesh.name === mesh.name;
      actions.open(new Uint8Array(await mesh.arrayBuffer()), mesh.name);
      // The URL named this file and its steps replayed: the same steps in the log are not applied twice.
      if (replays && log && sameSteps(logSteps, pending.steps)) return;
    }
    if (!log) return;
    // Alone, a steps file applies to the mesh on screen, which may not be the one it was saved with.
    const prefix = mesh ? `${log.name}: ` : `${log.name} (applied to the mesh on screen: was it saved with another?): `;
    if (!parsed) return store.set({ opError: { key: store.get().meshKey, text: `${log.name}: not an operation log (it starts with v1; or 1.)` } });
    actions.applyLog(parsed.log, parsed.at, prefix);
    // The sender's .hxd + steps dropped in the page their URL opened (whose file had another name,
    // e.g. part.vtk.gz): the same steps, so the URL's selection, diagrams and view come back too.
    const s = store.get();
    if (mesh && pending && !pendingFile && sameSteps(s.steps, pending.steps)) {
      store.batch(() => showUrlState({ ...pending, at: parsed.at ?? pending.at }, [], s.notice));
      if (pending.camera) view.setCamera(pending.camera);
    }
  },
  /** Applies a typed or palette step at the current position (later undone steps are dropped). */
  apply(step) {
    if (refuseOnStandIn()) return;
    if (!step) return store.set({ opError: { key: store.get().meshKey, text: 'type an operation step, e.g. pillow h13f5' } });
    const log = parseStepLog(step);
    if (log) return actions.applyLog(log.log, log.at);
    changeMesh(() => engine.applyStep(step), `${step}: `);
  },
  /**
   * Applies an operation log (typed, pasted, or a dropped steps.txt of "download .hxd + steps") at
   * the current position, all or nothing; `at` = K then shows the log's step K (0: before it).
   */
  applyLog(log, at = null, errorPrefix = 'operation log: ') {
    if (refuseOnStandIn()) return;
    const start = store.get().at;
    changeMesh(() => {
      engine.applyLog(log);
      const end = store.get().at;
      if (at !== null && start + at < end) engine.goTo(start + at); // at=K: step K of the log
    }, errorPrefix);
  },
  /** Applies a cubical flip at a place (hex ids of its before side) as its atomic steps. */
  applyFlip(name, hexes) {
    if (refuseOnStandIn()) return;
    changeMesh(() => engine.applyFlip(name, hexes), `flip ${name} at ${hexes.map((h) => 'h' + h).join(' ')}: `);
  },
  goTo(k) {
    const s = store.get();
    if (k < 0 || k > s.steps.length || k === s.at) return;
    changeMesh(() => engine.goTo(k), '');
  },
  back() {
    actions.goTo(store.get().at - 1);
  },
  forward() {
    actions.goTo(store.get().at + 1);
  },
  select(sel) {
    const cur = store.get().selection;
    store.set({ selection: sel && !sameSelection(sel, cur) ? sel : null });
  },
  /** Opens (or closes) the diagram of a sheet; `local` = { hex, rings } draws k rings around a hex. */
  toggleDiagram(sheet, local = null) {
    const ds = store.get().diagrams;
    const open = ds.find((d) => d.sheet === sheet);
    if (open && !local) return store.set({ diagrams: ds.filter((d) => d !== open) });
    store.set({ diagrams: [...ds.filter((d) => d.sheet !== sheet), { sheet, local }].slice(-4) });
  },
  closeDiagram(sheet) {
    store.set({ diagrams: store.get().diagrams.filter((d) => d.sheet !== sheet) });
  },
  /** Opens the diagrams of the sheets through the selection (e.g. the two sheets of a chord's quad). */
  openSheetsOfSelection() {
    const s = store.get();
    let sheets = [];
    if (s.selection?.kind === 'sheet') sheets = [s.selection.id];
    else if (s.selection?.kind === 'chord') {
      const hexes = s.mesh.chordHexes(s.selection.id);
      const hd = engine.hexDual();
      const h = hexes[0];
      const axis = [0, 1, 2].find((a) => hd.chordOf[3 * h + a] === s.selection.id);
      sheets = [0, 1, 2].filter((a) => a !== axis).map((a) => hd.sheetOf[3 * h + a]);
    } else if (s.selection) sheets = dualThrough(s.selection, engine.hexDual()).sheets;
    const ds = s.diagrams.filter((d) => !sheets.includes(d.sheet));
    store.set({ diagrams: [...ds, ...[...new Set(sheets)].map((sheet) => ({ sheet, local: null }))].slice(-4) });
  },
  set(patch) {
    store.set(patch);
  },
};

const view = createView3d(document.getElementById('view3d'), {
  onPick: (pick) => actions.select(pick),
  onHover: (pick, e) => panel.hover(pick, e),
  onCamera: () => store.set({ camera: view.getCamera() }),
});
const panel = createPanel(document.getElementById('panel'), actions, view);
const diagrams = createDiagrams(document.getElementById('diagrams'), actions, { onHover: (pick) => panel.hover(pick, null) });
const timeline = createTimeline(document.getElementById('timeline'), actions);
const palette = createPalette(document.getElementById('palette'), actions);
const flipsView = createFlipsView(document.getElementById('flips'), actions, store);
const files = createFiles(document.body, actions, store, view);

let urlTimer = 0;
function writeUrl(s) {
  if (pendingFile) return; // the URL keeps naming the file and its steps until the file comes
  const hash = formatHash(s);
  if (location.hash !== hash) history.replaceState(null, '', hash);
}
store.subscribe((s) => {
  document.body.dataset.view = s.view;
  for (const [name, v] of [['view', view], ['panel', panel], ['diagrams', diagrams], ['timeline', timeline], ['palette', palette], ['flips', flipsView], ['files', files]]) {
    const t = performance.now();
    v.update(s);
    timings[name] = (timings[name] || 0) + performance.now() - t;
  }
  clearTimeout(urlTimer);
  writeUrl(s);
});

function loadFromUrl() {
  store.batch(loadFromUrlNow);
}
function loadFromUrlNow() {
  const t0 = performance.now();
  timings.urlStart = t0;
  const p = parseHash(location.hash);
  const errors = [...p.errors];
  pendingFile = null;
  store.set({ waitingFor: null });
  if (p.mesh.kind === 'file') {
    // The file itself cannot come with the URL: a 3x3x3 grid stands in, and the URL keeps naming the
    // file and its steps until the file is opened or dropped (then they replay, see actions.open).
    pendingFile = p;
    engine.start({ kind: 'grid', dims: [3, 3, 3] });
    store.set({
      waitingFor: p.mesh.name,
      selection: null, diagrams: [], camera: null, shrink: p.shrink ?? 0.15, view: p.view, notice: '', quality: null,
      error: [...errors, `mesh=file:${p.mesh.name} is a local file that the URL cannot carry: open or drop it on the page (its ${plural(p.steps.length, 'step')} will replay)`].join('\n'),
    });
    return;
  }
  try {
    engine.start(p.mesh);
  } catch (e) {
    errors.push(`ignored mesh: ${e.message}`);
    engine.start({ kind: 'grid', dims: [3, 3, 3] });
    p.steps = [];
  }
  const stepError = engine.replay(p.steps, p.at);
  if (stepError) errors.push(stepError);
  showUrlState(p, errors, '');
  if (p.camera) view.setCamera(p.camera);
}

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;

// After a URL's steps replayed: its selection, diagrams and view settings, those naming missing
// hexes, sheets or chords dropped with a message.
function showUrlState(p, errors, notice) {
  if (p.at !== null && p.at > p.steps.length) errors.push(`ignored at=${p.at}: there ${p.steps.length === 1 ? 'is' : 'are'} only ${plural(p.steps.length, 'step')}`);
  const s = store.get();
  const ids = dualIds(s.mesh);
  const range = (set) => (set.size ? `0..${Math.max(...set)}` : 'none');
  const hd = engine.hexDual();
  let sel = p.selection;
  if (sel && 'hex' in sel && !(3 * sel.hex < hd.sheetOf.length && hd.sheetOf[3 * sel.hex] >= 0)) {
    errors.push(`ignored sel=${formatSelection(sel)}: hex ${sel.hex} does not exist`);
    sel = null;
  }
  for (const kind of ['sheet', 'chord']) {
    const set = kind === 'sheet' ? ids.sheets : ids.chords;
    if (sel && sel.kind === kind && !set.has(sel.id)) {
      errors.push(`ignored ${kind}=${sel.id}: there are ${plural(set.size, kind)} (${range(set)})`);
      sel = null;
    }
  }
  const diags = [];
  for (const d of p.diagrams) {
    if (ids.sheets.has(d)) diags.push({ sheet: d, local: null });
    else errors.push(`ignored diag=${d}: there are ${plural(ids.sheets.size, 'sheet')} (${range(ids.sheets)})`);
  }
  store.set({
    selection: sel, diagrams: diags, camera: p.camera, overlay: p.overlay, singular: p.singular, colorBy: p.colorBy, ghosts: p.ghosts,
    shrink: p.shrink ?? 0.15, slice: p.slice, view: p.view, flip: p.flip, error: errors.join('\n'), notice,
    quality: p.colorBy === 'quality' ? s.mesh.quality() : null,
  });
}

window.addEventListener('hashchange', () => {
  if (location.hash !== formatHash(store.get())) loadFromUrl();
});
window.addEventListener('keydown', (e) => {
  if (e.target.closest('input, textarea, select')) return;
  if (e.key === 'ArrowLeft') actions.back();
  if (e.key === 'ArrowRight') actions.forward();
  if (e.key === 'Escape') actions.select(null);
});
loadFromUrl();
timings.loaded = performance.now();

// For tests and the console.
window.hexdual = { store, actions, view, diagrams, engine, pkg: { Mesh }, timings, ready: true };
