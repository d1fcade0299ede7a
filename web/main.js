// hexdual demo: wires the wasm module, the app state, the panel, the 3D view and the URL.
import { init, Mesh } from '../wasm/index.js';
import wasmUrl from '../wasm/dist/hexdual.wasm?url';
import { createState } from './state.js';
import { createPanel } from './panel.js';
import { createView3d } from './view3d.js';
import { parseHash, formatHash } from './urlState.js';

const MAX_HEXES = 200000;

await init({ locateFile: (p) => (p.endsWith('.wasm') ? wasmUrl : p) });

const store = createState({ mesh: null, meshSpec: null, meshKey: '', shrink: 0.15, selection: null, error: '' });
let meshSerial = 0;

function replaceMesh(mesh, spec, selection = null, error = '') {
  const old = store.get().mesh;
  store.set({ mesh, meshSpec: spec, meshKey: `${++meshSerial}`, selection, error });
  if (old) old.delete();
}

function buildFromSpec(spec) {
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
  build(kind, dimsText) {
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
  select(selection) {
    const cur = store.get().selection;
    const same = cur && cur.kind === selection.kind && cur.id === selection.id;
    store.set({ selection: same ? null : selection });
  },
};

const panel = createPanel(document.getElementById('panel'), actions);
const view = createView3d(document.getElementById('view'));
store.subscribe((s) => {
  panel.update(s);
  view.update(s);
  const hash = formatHash({ mesh: s.meshSpec, selection: s.selection });
  if (s.meshSpec && s.meshSpec.kind !== 'file' && location.hash !== hash) history.replaceState(null, '', hash);
});

function loadFromUrl() {
  const parsed = parseHash(location.hash);
  let error = parsed.errors.join('; ');
  try {
    const mesh = buildFromSpec(parsed.mesh);
    replaceMesh(mesh, parsed.mesh, validSelection(mesh, parsed.selection), error);
  } catch (e) {
    error = [error, e.message].filter(Boolean).join('; ');
    const spec = { kind: 'grid', dims: [3, 3, 3] };
    replaceMesh(buildFromSpec(spec), spec, null, error);
  }
}
window.addEventListener('hashchange', () => {
  if (location.hash !== formatHash({ mesh: store.get().meshSpec, selection: store.get().selection })) loadFromUrl();
});
loadFromUrl();

// For tests and the console.
window.hexdual = { store, actions, view, ready: true };
