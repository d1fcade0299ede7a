// hexdual: idiomatic JS over the Embind module. `await init()` once, then use Mesh.
// This is the browser (and default) entry; Node resolves `hexdual` to index.node.js, which only
// changes how init() reads the .wasm. Nothing here imports a Node module.
import createHexdual from './dist/hexdual.mjs';

let modulePromise = null;
let M = null;

/** Every error hexdual throws: `code` says what kind, `message` is the engine's. */
export class HexdualError extends Error {
  constructor(code, message) {
    super(message);
    this.name = 'HexdualError';
    this.code = code;
  }
}

// A minimal module holding one `try` block: valid only where WebAssembly exception handling is.
const EH_PROBE = new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 4, 1, 96, 0, 0, 3, 2, 1, 0, 10, 7, 1, 5, 0, 6, 64, 11, 11]);

function requireWasmExceptions() {
  if (typeof WebAssembly !== 'object') throw new HexdualError('LIMIT', 'hexdual: this JavaScript runtime has no WebAssembly');
  if (!WebAssembly.validate(EH_PROBE)) {
    throw new HexdualError(
      'LIMIT',
      'hexdual: this runtime lacks WebAssembly exception handling, which hexdual needs ' +
        '(Node >= 17, Chromium/Chrome/Edge >= 95, Firefox >= 100, Safari >= 15.2)',
    );
  }
}

function isWasm(bytes) {
  return bytes.length >= 4 && bytes[0] === 0 && bytes[1] === 0x61 && bytes[2] === 0x73 && bytes[3] === 0x6d;
}

async function fetchWasm(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new HexdualError('IO', `hexdual: cannot fetch ${url}: ${e.message}`);
  }
  const bytes = response.ok ? new Uint8Array(await response.arrayBuffer()) : new Uint8Array(0);
  return isWasm(bytes) ? bytes : null;
}

// Where the .wasm lies relative to this file; bundlers see the literal and emit the file.
const wasmUrl = () => new URL('./dist/hexdual.wasm', import.meta.url);
// A dev server that pre-bundles dependencies (Vite) moves this file to node_modules/.vite/deps/
// but not the .wasm: look for it where the package is installed. (Not a literal on purpose.)
const PREBUNDLED_FALLBACK = '../../hexdual/wasm/dist/hexdual.wasm';

/** The .wasm bytes next to this module (the default when init() gets no location). */
export async function defaultWasmBinary() {
  const url = wasmUrl();
  if (url.protocol === 'file:') {
    throw new HexdualError('IO', "hexdual: in Node import 'hexdual' (its node entry reads the .wasm from disk) or pass init({ wasmBinary })");
  }
  const bytes = (await fetchWasm(url)) ?? (/\/\.vite\/deps\//.test(import.meta.url) ? await fetchWasm(new URL(PREBUNDLED_FALLBACK, import.meta.url)) : null);
  if (!bytes) {
    throw new HexdualError('IO', `hexdual: ${url} is not the WebAssembly module (is it served?); pass init({ locateFile }) or init({ wasmBinary })`);
  }
  return bytes;
}

/**
 * Loads the WebAssembly module once (later calls return the same promise). With no options the
 * .wasm is fetched from beside this file; `locateFile` or `wasmBinary` override that.
 */
export async function init(options = {}, loadDefault = defaultWasmBinary) {
  if (!modulePromise) {
    modulePromise = (async () => {
      requireWasmExceptions();
      const opts = { ...options };
      if (opts.wasmBinary) checkWasmBinary(opts.wasmBinary);  // before Emscripten, which prints its own noise
      if (!opts.wasmBinary && !opts.locateFile) opts.wasmBinary = await loadDefault();
      try {
        return await createHexdual(opts);
      } catch (e) {
        const why = String(e?.message ?? e).replace(/\s*Build with -s ASSERTIONS=1 for more info\.?/, '');
        throw e instanceof HexdualError ? e : new HexdualError('IO', `hexdual: the WebAssembly module did not load: ${why}`);
      }
    })();
    modulePromise.catch(() => {
      modulePromise = null;  // a failed init may be retried with other options
    });
  }
  M = await modulePromise;
  return M;
}

// init's wasmBinary: bytes of a WebAssembly module (it starts with \0asm), else an IO error.
function checkWasmBinary(bytes) {
  const view = bytes instanceof ArrayBuffer ? new Uint8Array(bytes) : ArrayBuffer.isView(bytes) ? new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength) : null;
  if (!view) throw new HexdualError('PRECONDITION', `init: wasmBinary must be the .wasm's bytes (an ArrayBuffer or Uint8Array), not ${describe(bytes)}`);
  if (!WebAssembly.validate(view)) {
    const head = [...view.subarray(0, 4)].map((b) => b.toString(16).padStart(2, '0')).join(' ');
    throw new HexdualError('IO', `init: wasmBinary is not a valid WebAssembly module (${view.length} bytes, starting ${head || 'with nothing'}; a .wasm starts 00 61 73 6d)`);
  }
}

function module() {
  if (!M) throw new HexdualError('PRECONDITION', 'hexdual: call `await init()` first');
  return M;
}

// Turns the engine's stored error into a HexdualError when a call failed.
function check(result) {
  if (result === null || result === undefined || result === false || result === '' || result === -1) {
    const Mod = module();
    throw new HexdualError(Mod.lastErrorCode() || 'PRECONDITION', Mod.lastError() || 'hexdual: unknown error');
  }
  return result;
}

function integer(what, x, min = -2147483648) {
  if (typeof x !== 'number' || !Number.isInteger(x) || x < min || x > 2147483647) {
    throw new HexdualError('PRECONDITION', `${what} must be an integer${min > -2147483648 ? ` >= ${min}` : ''}, not ${describe(x)}`);
  }
  return x;
}
function finite(what, x) {
  if (typeof x !== 'number' || !Number.isFinite(x)) throw new HexdualError('PRECONDITION', `${what} must be a finite number, not ${describe(x)}`);
  return x;
}
function describe(x) {
  return typeof x === 'string' ? `'${x}'` : String(x);
}
function toBytes(what, data) {
  if (typeof data === 'string') return new TextEncoder().encode(data);
  if (data instanceof Uint8Array) return data;
  if (data instanceof ArrayBuffer || ArrayBuffer.isView(data)) return new Uint8Array(data.buffer ?? data, data.byteOffset ?? 0, data.byteLength);
  throw new HexdualError('PRECONDITION', `${what} must be a string, a Uint8Array (or another typed array or DataView) or an ArrayBuffer, not ${describe(data)}`);
}
// { boundary: 'kept' | 'free' } of isomorphic() and canonicalHash(): true for 'free'.
function boundaryFree(what, options) {
  const boundary = options?.boundary ?? 'kept';
  if (boundary !== 'kept' && boundary !== 'free') {
    throw new HexdualError('PRECONDITION', `${what}: boundary must be 'kept' or 'free', not ${describe(boundary)}`);
  }
  return boundary === 'free';
}
function intVector(what, list) {
  if (!list || typeof list[Symbol.iterator] !== 'function') throw new HexdualError('PRECONDITION', `${what} must be a list of hex ids`);
  const v = new (module().IntVector)();
  try {
    for (const h of list) v.push_back(integer(`${what}: hex id`, h));
  } catch (e) {
    v.delete();
    throw e;
  }
  return v;
}
// The engine's step report (as `hexdual apply --json`) under the names of StepReport in index.d.ts.
function toReport({ flip, report: r }) {
  const report = {
    step: flip ? `flip ${flip}` : r.text,
    op: flip ? 'flip' : r.op,
    inverse: r.inverse === '' ? null : r.inverse,
    created: { hexes: r.createdHexes, vertices: r.createdVertices },
    removed: { hexes: r.removedHexes, vertices: r.removedVertices },
    delta: r.delta,
    changedSheets: r.sheets,
    changedChords: r.chords,
    quality: r.quality,
  };
  if (report.inverse === null) report.noInverse = flip ? 'a flip applied directly has no inverse step; use undo()' : r.noInverse;
  return report;
}
const OPS = ['pillow', 'unpillow', 'chordpush', 'chordpull', 'hexpush', 'hexpull', 'ringcollapse', 'facecollapse', 'facesplit',
  'sheet-extract', 'column-collapse', 'sheet-dice'];  // the sheet operations candidates() enumerates when named
const FORMATS = ['vtk', 'mesh', 'hxd'];

// ---- view data (explorer) ----
// A geometry call's {json} or {error, code} (bindings_geometry.cpp).
function jsonCall(result) {
  if (result.error !== undefined) throw new HexdualError(result.code ?? 'PRECONDITION', result.error);
  return JSON.parse(result.json);
}
function viewCall(result) {
  if (result.error !== undefined) throw new HexdualError(result.code ?? 'PRECONDITION', result.error);
  return result;
}
/** Local numbering: the 4 corners of each face (buffer order) and the 2 of each edge, flattened. */
export function hexTables() {
  return module().viewTables();
}
// ---- end of view data (explorer) ----

export class Mesh {
  #raw;
  #info = null;
  constructor(raw) {
    if (!raw || typeof raw.infoJson !== 'function') {
      throw new HexdualError('PRECONDITION', 'hexdual: make meshes with Mesh.grid, Mesh.ring, Mesh.fourCube or Mesh.load');
    }
    this.#raw = raw;
  }

  /** An a x b x c grid of unit hexes. */
  static grid(a, b, c) {
    return new Mesh(check(module().WasmMesh.grid(integer('grid: a', a), integer('grid: b', b), integer('grid: c', c))));
  }
  /** An O-grid ring mesh: `around` hexes around, `radial` layers outward, `axial` along the axis. */
  static ring(around, radial, axial) {
    return new Mesh(check(module().WasmMesh.ring(integer('ring: around', around), integer('ring: radial', radial), integer('ring: axial', axial))));
  }
  /** The closed boundary of the 4-cube (8 cubes; hex id = facet 2*axis+side), where flips are built. */
  static fourCube() {
    return new Mesh(check(module().WasmMesh.fourCube()));
  }
  /**
   * Reads a mesh file from its bytes; the format is detected (VTK legacy 2.0–5.1, .vtu, Gmsh .msh,
   * Medit .mesh/.meshb, .hxd; gzipped or not). `hexesOnly` reads the hex part of a mixed file.
   */
  static load(bytes, name = 'mesh', options = {}) {
    const data = toBytes('load: bytes', bytes);
    if (typeof name !== 'string') throw new HexdualError('PRECONDITION', 'load: name must be a string');
    return new Mesh(check(module().WasmMesh.load(data, name, !!options.hexesOnly)));
  }
  /**
   * Whether two meshes are the same complex up to renumbering. boundary 'kept' (the default): only
   * interior vertex ids may differ; 'free': any renumbering (after save and load, or steps that
   * renumber the boundary).
   */
  static isomorphic(a, b, options = {}) {
    const free = boundaryFree('isomorphic', options);
    return check(module().isomorphic(a.#live(), b.#live(), free)) === 1;
  }

  #live() {
    if (!this.#raw) throw new HexdualError('PRECONDITION', 'hexdual: this Mesh has been deleted');
    return this.#raw;
  }
  #changed() {
    this.#info = null;
  }

  /** Counts, sheets and chords (the same object as `hexdual info --json`). */
  info() {
    if (!this.#info) this.#info = JSON.parse(check(this.#live().infoJson()));
    return this.#info;
  }
  /** V, E, F, H and boundary quads, in constant time after the first (no need to build info()). */
  get counts() {
    const { vertices, edges, quads, hexes, boundaryQuads } = this.#info ?? JSON.parse(check(this.#live().countsJson()));
    return { vertices, edges, quads, hexes, boundaryQuads };
  }
  get sheets() {
    return this.info().sheets;
  }
  get chords() {
    return this.info().chords;
  }
  /** Hex ids on a sheet, one per slot. */
  sheetHexes(id) {
    return check(this.#live().sheetHexes(integer('sheetHexes: id', id)));
  }
  /** Hex ids along a chord, in order. */
  chordHexes(id) {
    return check(this.#live().chordHexes(integer('chordHexes: id', id)));
  }
  /** Centroid of every hex: x, y, z per hex id (NaN for ids an operation removed). */
  hexCenters() {
    return this.#live().hexCenters();
  }
  /**
   * The sheet diagram of a sheet as typed arrays (docs/api.md); with `local`, only the part of the
   * sheet within `rings` rings of the hexes in `local`, in a dotted circle.
   */
  sheetDiagram(id, { local, rings = 2 } = {}) {
    integer('sheetDiagram: id', id);
    integer('sheetDiagram: rings', rings, 0);
    const v = intVector('sheetDiagram: local', local ?? []);
    try {
      return check(this.#live().sheetDiagram(id, local !== undefined, v, rings));
    } finally {
      v.delete();
    }
  }
  /** The sheet diagram as the JSON object of `hexdual sheets --json` (crossings, chords, loops, ...). */
  sheetDiagramJSON(id, { local, rings = 2 } = {}) {
    integer('sheetDiagram: id', id);
    if (local === undefined) return JSON.parse(check(this.#live().sheetDiagramJson(id)));
    return this.localSheetDiagram(id, local, rings);
  }
  /** A local sheet diagram as a JSON object: the sheet within `rings` rings of the given hexes. */
  localSheetDiagram(id, hexes, rings = 2) {
    integer('localSheetDiagram: id', id);
    integer('localSheetDiagram: rings', rings, 0);
    const v = intVector('localSheetDiagram: hexes', hexes);
    try {
      return JSON.parse(check(this.#live().localSheetDiagramJson(id, v, rings)));
    } finally {
      v.delete();
    }
  }
  /**
   * Applies one operation-log step, e.g. 'pillow h13f5'; returns its report (ids created and
   * removed, the change of counts and of the dual, the inverse step). Throws HexdualError, leaving
   * the mesh unchanged, on a bad step.
   */
  apply(step) {
    if (typeof step !== 'string') throw new HexdualError('PRECONDITION', 'apply: step must be a string such as "pillow h13f5"');
    if (step.includes(';')) {
      throw new HexdualError('PARSE', `apply: takes one step, and ${describe(step)} holds ${step.split(';').length} parts; applyLog applies a log of several ('v1;pillow h13f5;hexpush h13f5')`);
    }
    const report = toReport(JSON.parse(check(this.#live().applyReport(step))));
    this.#changed();
    return report;
  }
  /**
   * Applies an operation log (text 'v1;pillow h13f5;...' or its URL form '1.P13f5...'), at most
   * `stopAt` steps. All or nothing: on an error no step of the log stays applied.
   */
  applyLog(log, { stopAt } = {}) {
    if (typeof log !== 'string') throw new HexdualError('PRECONDITION', 'applyLog: log must be a string');
    const n = stopAt === undefined ? -1 : integer('applyLog: stopAt', stopAt, 0);
    const reports = JSON.parse(check(this.#live().applyLog(log, n))).map(toReport);
    this.#changed();
    return reports;
  }
  /**
   * What applying `step` would do, without doing it: `{ applies: true, report }` (the report apply
   * would return, with the same ids) or `{ applies: false, rule, error }` (the refusal and, for a
   * sheet operation, its rule). The mesh, its dual and the undo list are not changed.
   */
  preview(step) {
    if (typeof step !== 'string') throw new HexdualError('PRECONDITION', 'preview: step must be a string such as "sheet-extract h13e8"');
    const raw = this.#live();
    const tracker = raw.trackerAddress();
    if (!tracker) check(null);
    const out = JSON.parse(module().sheetopsPreview(raw.complexAddress(), tracker, step, raw.smoothing()));
    if (out.code !== undefined) throw new HexdualError(out.code, out.error);  // the binding's failure, not a refusal
    const base = { applies: out.applies, family: out.family, step: out.text };
    if (!out.applies) return { ...base, rule: out.rule, error: out.error };
    return { ...base, hexesRemoved: out.hexesRemoved, hexesCreated: out.hexesCreated, report: toReport({ flip: null, report: out.report }) };
  }
  /**
   * The sheet through a picked edge ({ hex, edge }) or the chord through a picked quad ({ hex, face }):
   * its id, hexes, topology, and the operation-log steps of the sheet operations that act on it.
   */
  select(pick) {
    const hex = integer('select: pick.hex', pick?.hex);
    if ((pick.edge === undefined) === (pick.face === undefined)) throw new HexdualError('PRECONDITION', 'select: pick an edge ({ hex, edge }) or a quad ({ hex, face })');
    const kind = pick.edge !== undefined ? 'edge' : 'face';
    const local = integer(`select: pick.${kind}`, pick[kind]);
    const raw = this.#live();
    const dual = raw.dualAddress();
    if (!dual) check(null);
    const out = JSON.parse(module().sheetopsSelect(raw.complexAddress(), dual, hex, kind, local));
    if (out.code !== undefined) throw new HexdualError(out.code, out.error);  // the binding's failure, not a refusal
    return out;
  }
  /** Undoes the last applied step exactly (ids included); returns that step's text. */
  undo() {
    const step = check(this.#live().undo());
    this.#changed();
    return step;
  }
  /** Re-applies the last undone step; returns its report. */
  redo() {
    const report = toReport(JSON.parse(check(this.#live().redo())));
    this.#changed();
    return report;
  }
  get canUndo() {
    return this.#live().undoDepth() > 0;
  }
  get canRedo() {
    return this.#live().redoDepth() > 0;
  }
  /** The applied steps as an operation log, 'v1;pillow h13f5;...'. */
  get log() {
    return check(this.#live().log(false));
  }
  /** The applied steps in the URL-safe form, '1.P13f5...'. */
  get logUrl() {
    return check(this.#live().log(true));
  }
  /**
   * Steps that apply, as operation-log text: of one operation or of all the atomic ones (a sheet
   * operation is listed when named: 'sheet-extract', 'column-collapse', 'sheet-dice'); with `near` only those
   * naming a hex ({ hex: 13 }), a quad ({ hex: 13, face: 5 }) or an edge ({ hex: 13, edge: 2 }).
   */
  candidates(op, { near } = {}) {
    if (op !== undefined && !OPS.includes(op)) {
      throw new HexdualError('PRECONDITION', `candidates: unknown operation ${describe(op)} (${OPS.join(', ')})`);
    }
    let kind = '', hex = -1, local = -1;
    if (near !== undefined) {
      hex = integer('candidates: near.hex', near?.hex);
      if (near.face !== undefined && near.edge !== undefined) throw new HexdualError('PRECONDITION', 'candidates: near names a face or an edge, not both');
      kind = near.face !== undefined ? 'quad' : near.edge !== undefined ? 'edge' : 'hex';
      if (kind === 'quad') local = integer('candidates: near.face', near.face);
      if (kind === 'edge') local = integer('candidates: near.edge', near.edge);
    }
    return JSON.parse(check(this.#live().candidates(op ?? '', kind, hex, local)));
  }
  /**
   * Applies cubical flip `name` to the hexes forming its before side (like `hexdual flip NAME
   * --at ...`); with viaAtomic, as its stored atomic steps (which then appear in `log`). Returns
   * one report per step.
   */
  flip(name, hexes, { viaAtomic = false } = {}) {
    if (typeof name !== 'string') throw new HexdualError('PRECONDITION', 'flip: name must be a string such as "2-6"');
    const v = intVector('flip: hexes', hexes);
    try {
      const reports = JSON.parse(check(this.#live().flip(name, v, !!viaAtomic))).map(toReport);
      this.#changed();
      return reports;
    } finally {
      v.delete();
    }
  }
  /** 64-bit hash (16 hex digits) of the canonical form: equal for isomorphic meshes (see isomorphic's boundary option). */
  canonicalHash(options = {}) {
    return check(this.#live().canonicalHash(boundaryFree('canonicalHash', options)));
  }
  /** Number of sheets and chords, without building the JSON description (cheap after the first call). */
  dualSizes() {
    const raw = this.#live();
    return { sheets: raw.numSheets(), chords: raw.numChords() };
  }
  /** Bytes held by the complex (topology and positions) inside the wasm heap. */
  memoryBytes() {
    return this.#live().memoryBytes();
  }
  /** Throws a HexdualError naming the first broken invariant. */
  validate() {
    check(this.#live().validate());
  }
  /** The mesh as a file: 'vtk' (ASCII, or binary with { binary: true }), 'mesh' or 'hxd'. */
  save(format, { binary = false } = {}) {
    if (!FORMATS.includes(format)) throw new HexdualError('PRECONDITION', `unknown format ${describe(format)} (vtk, mesh or hxd)`);
    if (binary && format !== 'vtk') throw new HexdualError('PRECONDITION', `save: binary applies to 'vtk' only, not ${describe(format)}`);
    return check(this.#live().saveBytes(format, !!binary));
  }
  // ---- view data (explorer) ----
  // Geometry for drawing and picking (wasm/bindings_view.cpp). Every array is a copy.

  /**
   * Triangles of every hex shrunk toward its own dual point (a pillow pair draws apart), with the
   * hex id and local face of each triangle (face k of the buffer: triangles 2k, 2k+1, vertices
   * 4k..4k+3 in `faceCorners` order); with `edges`, line segments of every hex edge too.
   * Which hexes: all; with `shell` only those with a face on the boundary or next to a hidden hex;
   * `hidden[h]` != 0 leaves hex h out; `always` (hex ids) are drawn regardless.
   */
  renderBuffers({ shrink = 0.15, edges = false, shell = false, hidden = null, always = null } = {}) {
    finite('renderBuffers: shrink', shrink);
    if (shrink < 0 || shrink >= 1) throw new HexdualError('PRECONDITION', `renderBuffers: shrink must be in [0, 1), not ${shrink}`);
    if (hidden !== null && !(hidden instanceof Uint8Array)) throw new HexdualError('PRECONDITION', 'renderBuffers: hidden must be a Uint8Array (one byte per hex id)');
    const ids = always === null ? null : Int32Array.from(always, (h) => integer('renderBuffers: always: hex id', h));
    return viewCall(module().viewRenderBuffers(this.#live().complexAddress(), shrink, edges, !!shell, hidden, ids));
  }
  /** Each hex's dual point (3 floats per hex id; tombstones hold 0): where the explorer shrinks it to. */
  dualPoints() {
    return viewCall(module().viewDualPoints(this.#live().complexAddress())).points;
  }
  /**
   * Sheet mid-surfaces (triangles with sheet ids), chord polylines (segments with chord ids), dual
   * vertices; with `hexes`, only their part (the chord segments between two of them).
   */
  dualOverlay({ hexes = null } = {}) {
    const raw = this.#live();
    const ids = hexes === null ? null : Int32Array.from(hexes, (h) => integer('dualOverlay: hexes: hex id', h));
    const dual = raw.dualAddress();
    if (!dual) check(null);
    return viewCall(module().viewDualOverlay(raw.complexAddress(), dual, ids));
  }
  /**
   * Scaled Jacobian per hex id, the inverted hexes (<= 0), the range over live hexes, and the
   * distribution as `hexdual quality --json` gives it (hexes, mean, nonPositive, 20 buckets).
   */
  quality() {
    const address = this.#live().complexAddress();
    return { ...jsonCall(module().geometryQualityStats(address)), ...viewCall(module().viewQuality(address)) };
  }
  /** Sheet and chord ids through each hex: `sheetOf[3*h+axis]`, `chordOf[3*h+axis]` (-1 for removed hexes). */
  hexDual() {
    const dual = this.#live().dualAddress();
    if (!dual) check(null);
    return viewCall(module().viewHexDual(dual));
  }
  /**
   * Flips with a stored atomic decomposition that apply near a hex, a quad ({ hex, face }) or an
   * edge ({ hex, edge }): [{ name, hexes }], each ready for flip(name, hexes, { viaAtomic: true }).
   */
  flipPlaces(near) {
    const hex = integer('flipPlaces: near.hex', near?.hex);
    const kind = near.face !== undefined ? 'quad' : near.edge !== undefined ? 'edge' : 'hex';
    const local = kind === 'quad' ? integer('flipPlaces: near.face', near.face) : kind === 'edge' ? integer('flipPlaces: near.edge', near.edge) : -1;
    return viewCall(module().viewFlipPlaces(this.#live().complexAddress(), hex, kind, local)).places.map((p) => ({ name: p.name, hexes: [...p.hexes] }));
  }
  // ---- end of view data (explorer) ----

  /**
   * The ring splits whose loop of edges passes through an edge ({ hex, edge }), loops of at most
   * `maxEdges` (default 8) edges, each one that applies: op-log steps (candidates() does not
   * enumerate ring splits). Written as the decomposition search writes them.
   */
  ringSplits(near, { maxEdges = 8 } = {}) {
    const hex = integer('ringSplits: near.hex', near?.hex);
    const edge = integer('ringSplits: near.edge', near?.edge);
    const max = integer('ringSplits: maxEdges', maxEdges);
    return viewCall(module().tutorialRingSplits(this.#live().complexAddress(), hex, edge, max)).steps;
  }

  // ---- geometry and singularities ----
  /** The singularity graph: irregular edges (with their curve), irregular vertices, curves, counts. */
  singularities() {
    return jsonCall(module().geometrySingularities(this.#live().complexAddress()));
  }
  /** The sheet crossing an edge and the chords (with their other sheets) through the quads around it. */
  edgeDual(hex, edge) {
    const raw = this.#live();
    const h = integer('edgeDual: hex', hex), e = integer('edgeDual: edge', edge);
    const dual = raw.dualAddress();
    if (!dual) check(null);
    return jsonCall(module().geometryEdgeDual(raw.complexAddress(), dual, h, e));
  }
  /** Positions of vertices: x, y, z of each id in `ids`, in order (3 numbers per vertex). */
  vertexPositions(ids) {
    if (!Array.isArray(ids) || !ids.every((v) => Number.isInteger(v))) throw new HexdualError('PRECONDITION', 'vertexPositions: ids must be an array of integers');
    const out = module().geometryVertexPositions(this.#live().complexAddress(), ids);
    if (out.error !== undefined) throw new HexdualError(out.code, out.error);
    return out.xyz;
  }
  /** FNV-1a hash of every live vertex's id and position bits (as `hexdual apply --json` prints). */
  positionsHash() {
    return module().geometryPositionsHash(this.#live().complexAddress());
  }
  /** Whether steps and flips untangle and smooth the vertices around them (default true; false: the operations' own placement, still measured). */
  get smoothing() {
    return this.#live().smoothing();
  }
  set smoothing(on) {
    if (typeof on !== 'boolean') throw new HexdualError('PRECONDITION', 'smoothing must be true or false');
    this.#live().setSmoothing(on);
  }

  /** Frees the wasm memory of this mesh. */
  delete() {
    if (this.#raw) {
      this.#raw.delete();
      this.#raw = null;
    }
  }
}
// `using m = Mesh.grid(...)` where the runtime has explicit resource management.
if (typeof Symbol.dispose === 'symbol') {
  Mesh.prototype[Symbol.dispose] = function dispose() {
    this.delete();
  };
}

/** A sheet diagram (from mesh.sheetDiagram) drawn as an SVG document. */
export function diagramToSVG(d) {
  if (!d || typeof d !== 'object' || !d.crossings) throw new HexdualError('PRECONDITION', 'diagramToSVG: pass a diagram from mesh.sheetDiagram()');
  return check(module().diagramToSvg(d));
}

/**
 * The cubical flips: name, inverse, whether geometric, the before side's facets in the 4-cube,
 * and the stored atomic decomposition (op-log steps on Mesh.fourCube()) or null.
 */
export function flips() {
  return JSON.parse(check(module().flipsJson()));
}

/**
 * Every stored decomposition search record (core/flips/decompositions.txt): problem, found, steps
 * (op-log steps in the problem's complex, or null), maxDepth, depthSearched, states, seconds, ops.
 */
export function decompositions() {
  return viewCall(module().tutorialRecords()).records;
}

/** Bytes currently allocated inside the wasm heap (for leak tests). */
export function heapBytes() {
  return module().heapUsed();
}
