// hexdual demo: wires the wasm module, the app state, the panel, the 3D view and the URL.
import { init, Mesh, flips } from '../wasm/index.js';
import wasmUrl from '../wasm/dist/hexdual.wasm?url';
import { createState } from './state.js';
import { createPanel } from './panel.js';
import { createView3d } from './view3d.js';
import { createSheetDiagram } from './sheetDiagram.js';
import { parseHash, formatHash } from './urlState.js';

const MAX_HEXES = 200000;

await init({ locateFile: (p) => (p.endsWith('.wasm') ? wasmUrl : p) });

const store = createState({
  mesh: null, meshSpec: null, meshKey: '', shrink: 0.15, selection: null, diagramSheet: null, ops: [], error: '',
  flipQueue: null,
});
let meshSerial = 0;

function replaceMesh(mesh, spec, selection = null, error = '', ops = []) {
  const old = store.get().mesh;
  const diagramSheet = selection && selection.kind === 'sheet' ? selection.id : null;
  store.set({ mesh, meshSpec: spec, meshKey: `${++meshSerial}`, selection, diagramSheet, ops, error, flipQueue: null });
  if (old) old.delete();
}

// Applies steps in order; returns the applied ones (with their inverses) and the first error.
function applySteps(mesh, steps) {
  const applied = [];
  for (const step of steps) {
    try {
      applied.push({ step, inverse: mesh.apply(step).inverse });
    } catch (e) {
      return { applied, error: `step ${applied.length + 1} (${step}): ${e.message}` };
    }
  }
  return { applied, error: '' };
}

function buildFromSpec(spec) {
  if (spec.kind === 'fourcube') return Mesh.fourCube();
  const [a, b, c] = spec.dims;
  if (a * b * c > MAX_HEXES) throw new Error(`${a}x${b}x${c} is more than ${MAX_HEXES} hexes; try a smaller mesh`);
  return spec.kind === 'ring' ? Mesh.ring(a, b, c) : Mesh.grid(a, b, c);
}

function validSelection(mesh, sel) {
  if (!sel) return null;
  const list = sel.kind === 'sheet' ? mesh.sheets : mesh.chords;
  return sel.id < list.length ? sel : null;
}

const actions = {
  flips: flips(),
  loadFlip(name) {
    const f = actions.flips.find((x) => x.name === name);
    if (!f || !f.steps) return store.set({ error: `no stored decomposition for ${name}` });
    const spec = { kind: 'fourcube', dims: [] };
    replaceMesh(buildFromSpec(spec), spec);
    store.set({ flipQueue: { name, steps: f.steps, done: 0 } });
  },
  stepFlip() {
    const s = store.get(), fq = s.flipQueue;
    if (!fq || fq.done >= fq.steps.length) return;
    actions.apply(fq.steps[fq.done]);
    if (!store.get().error) store.set({ flipQueue: { ...fq, done: fq.done + 1 } });
  },
  build(kind, dimsText) {
    if (kind === 'fourcube') {
      const spec = { kind, dims: [] };
      return replaceMesh(buildFromSpec(spec), spec);
    }
    const m = /^\s*(\d+)\s*x\s*(\d+)\s*x\s*(\d+)\s*$/.exec(dimsText);
    if (!m) return store.set({ error: `dimensions must look like 3x3x3, not '${dimsText}'` });
    const spec = { kind, dims: [Number(m[1]), Number(m[2]), Number(m[3])] };
    try {
      replaceMesh(buildFromSpec(spec), spec);
    } catch (e) {
      store.set({ error: e.message });
    }
  },
  open(bytes, name) {
    try {
      replaceMesh(Mesh.load(bytes, name), { kind: 'file', name });
    } catch (e) {
      store.set({ error: e.message });
    }
  },
  shrink(value) {
    store.set({ shrink: value });
  },
  select(selection, { keepDiagram = false } = {}) {
    const cur = store.get().selection;
    const same = cur && cur.kind === selection.kind && cur.id === selection.id;
    const next = same ? null : selection;
    const diagramSheet = keepDiagram ? store.get().diagramSheet : next && next.kind === 'sheet' ? next.id : null;
    store.set({ selection: next, diagramSheet });
  },
  apply(step) {
    const s = store.get();
    if (!step) return store.set({ error: 'type an operation step, e.g. pillow h13f5' });
    const { applied, error } = applySteps(s.mesh, [step]);
    store.set({ ops: [...s.ops, ...applied], error, selection: null, diagramSheet: null, meshKey: s.meshKey });
  },
  undo() {
    const s = store.get();
    const last = s.ops[s.ops.length - 1];
    if (!last) return;
    if (!last.inverse) return store.set({ error: `${last.step} has no inverse step` });
    const { error } = applySteps(s.mesh, [last.inverse]);
    store.set({ ops: error ? s.ops : s.ops.slice(0, -1), error, selection: null, diagramSheet: null });
  },
};

const panel = createPanel(document.getElementById('panel'), actions);
const view = createView3d(document.getElementById('view'));
const diagram = createSheetDiagram(document.getElementById('view'), actions);
store.subscribe((s) => {
  panel.update(s);
  view.update(s);
  diagram.update(s);
  const hash = formatHash({ mesh: s.meshSpec, selection: s.selection, ops: s.ops.map((o) => o.step) });
  if (s.meshSpec && s.meshSpec.kind !== 'file' && location.hash !== hash) history.replaceState(null, '', hash);
});

function loadFromUrl() {
  const parsed = parseHash(location.hash);
  let error = parsed.errors.join('; ');
  try {
    const mesh = buildFromSpec(parsed.mesh);
    const { applied, error: opError } = applySteps(mesh, parsed.ops);
    error = [error, opError].filter(Boolean).join('; ');
    replaceMesh(mesh, parsed.mesh, validSelection(mesh, parsed.selection), error, applied);
  } catch (e) {
    error = [error, e.message].filter(Boolean).join('; ');
    const spec = { kind: 'grid', dims: [3, 3, 3] };
    replaceMesh(buildFromSpec(spec), spec, null, error);
  }
}
window.addEventListener('hashchange', () => {
  const s = store.get();
  if (location.hash !== formatHash({ mesh: s.meshSpec, selection: s.selection, ops: s.ops.map((o) => o.step) })) loadFromUrl();
});
loadFromUrl();

// For tests and the console.
window.hexdual = { store, actions, view, ready: true };
