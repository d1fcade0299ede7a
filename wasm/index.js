// hexdual: idiomatic JS over the Embind module. `await init()` once, then use Mesh.
import createHexdual from './dist/hexdual.mjs';

let modulePromise = null;
let M = null;

/**
 * Loads the WebAssembly module. In Node the .wasm is read from disk; in a browser pass
 * `locateFile` (or `wasmBinary`) when the bundler moves the file.
 */
export async function init(options = {}) {
  if (!modulePromise) {
    const opts = { ...options };
    if (!opts.wasmBinary && !opts.locateFile && typeof process !== 'undefined' && process.versions?.node) {
      const { readFile } = await import('node:fs/promises');
      opts.wasmBinary = await readFile(new URL('./dist/hexdual.wasm', import.meta.url));
    }
    modulePromise = createHexdual(opts);
  }
  M = await modulePromise;
  return M;
}

function module() {
  if (!M) throw new Error('hexdual: call `await init()` first');
  return M;
}

function check(result) {
  if (result === null || result === undefined || result === false) {
    throw new Error(module().lastError() || 'hexdual: unknown error');
  }
  return result;
}

// ---- view data (explorer) ----
function viewCall(result) {
  if (result.error !== undefined) throw new Error(result.error);
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
    this.#raw = raw;
  }

  /** An a x b x c grid of unit hexes. */
  static grid(a, b, c) {
    return new Mesh(check(module().WasmMesh.grid(a, b, c)));
  }
  /** An O-grid ring mesh: `around` hexes around, `radial` layers outward, `axial` along the axis. */
  static ring(around, radial, axial) {
    return new Mesh(check(module().WasmMesh.ring(around, radial, axial)));
  }
  /** The closed boundary of the 4-cube (8 cubes; hex id = facet 2*axis+side), where flips are built. */
  static fourCube() {
    return new Mesh(check(module().WasmMesh.fourCube()));
  }
  /** Reads a .vtk (ASCII or binary), .mesh or .hxd file from its bytes; the format is detected. */
  static load(bytes, name = 'mesh') {
    const data = typeof bytes === 'string' ? new TextEncoder().encode(bytes) : new Uint8Array(bytes);
    return new Mesh(check(module().WasmMesh.load(data, name)));
  }

  #live() {
    if (!this.#raw) throw new Error('hexdual: this Mesh has been deleted');
    return this.#raw;
  }

  /** Counts, sheets and chords (the same object as `hexdual info --json`). */
  info() {
    if (!this.#info) {
      const text = this.#live().infoJson();
      if (!text) check(null);
      this.#info = JSON.parse(text);
    }
    return this.#info;
  }
  get counts() {
    const { vertices, edges, quads, hexes, boundaryQuads } = this.info();
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
    return check(this.#live().sheetHexes(id));
  }
  /** Hex ids along a chord, in order. */
  chordHexes(id) {
    return check(this.#live().chordHexes(id));
  }
  /** The sheet diagram of a sheet: crossings, chords, boundary loops (docs/sheet-diagrams.md). */
  sheetDiagram(id) {
    const text = this.#live().sheetDiagramJson(id);
    if (!text) check(null);
    return JSON.parse(text);
  }
  /** A local sheet diagram: the sheet within `rings` rings of the given hexes, in a dotted circle. */
  localSheetDiagram(id, hexes, rings = 2) {
    const M = module();
    const v = new M.IntVector();
    try {
      for (const h of hexes) v.push_back(h);
      const text = this.#live().localSheetDiagramJson(id, v, rings);
      if (!text) check(null);
      return JSON.parse(text);
    } finally {
      v.delete();
    }
  }
  /**
   * Applies one operation-log step, e.g. 'pillow h13f5'; returns the inverse step
   * (or null when the operation has none). Throws, leaving the mesh unchanged, on a bad step.
   */
  apply(step) {
    const inv = this.#live().applyStep(step);
    if (!inv) check(null);
    this.#info = null;
    return inv === '-' ? null : inv;
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
  /** Throws an Error naming the first broken invariant. */
  validate() {
    check(this.#live().validate());
  }
  /** Writes the mesh as 'vtk', 'mesh' or 'hxd'; returns a string (binary VTK as a byte string). */
  save(format, { binary = false } = {}) {
    const text = this.#live().save(format, binary);
    if (!text) check(null);
    return text;
  }
  // ---- view data (explorer) ----
  // Geometry for drawing and picking (wasm/bindings_view.cpp). Every array is a copy.

  /**
   * Triangles of every hex shrunk toward its own dual point (a pillow pair draws apart), with the
   * hex id and local face of each triangle (face k of the buffer: triangles 2k, 2k+1, vertices
   * 4k..4k+3 in `faceCorners` order); with `edges`, line segments of every hex edge too.
   */
  renderBuffers({ shrink = 0.15, edges = false } = {}) {
    return viewCall(module().viewRenderBuffers(this.#live().complexAddress(), shrink, edges));
  }
  /** Each hex's dual point (3 floats per hex id; tombstones hold 0). */
  hexCenters() {
    return viewCall(module().viewDualPoints(this.#live().complexAddress())).points;
  }
  /** Sheet mid-surfaces (triangles with sheet ids), chord polylines (segments with chord ids), dual vertices. */
  dualOverlay() {
    const raw = this.#live();
    const dual = raw.dualAddress();
    if (!dual) check(null);
    return viewCall(module().viewDualOverlay(raw.complexAddress(), dual));
  }
  /** Scaled Jacobian per hex id, the inverted hexes (<= 0), and the range over live hexes. */
  quality() {
    return viewCall(module().viewQuality(this.#live().complexAddress()));
  }
  /** Sheet and chord ids through each hex: `sheetOf[3*h+axis]`, `chordOf[3*h+axis]` (-1 for removed hexes). */
  hexDual() {
    const dual = this.#live().dualAddress();
    if (!dual) check(null);
    return viewCall(module().viewHexDual(dual));
  }
  /** Every step of one operation that applies anywhere in the mesh (each tried on a copy). */
  candidateSteps(op) {
    return viewCall(module().viewCandidates(this.#live().complexAddress(), op)).steps;
  }
  // ---- end of view data (explorer) ----

  /** Frees the wasm memory of this mesh. */
  delete() {
    if (this.#raw) {
      this.#raw.delete();
      this.#raw = null;
    }
  }
  [Symbol.dispose]() {
    this.delete();
  }
}

/**
 * The cubical flips: name, inverse, whether geometric, the before side's facets in the 4-cube,
 * and the stored atomic decomposition (op-log steps on Mesh.fourCube()) or null.
 */
export function flips() {
  const text = module().flipsJson();
  if (!text) check(null);
  return JSON.parse(text);
}

/** Bytes currently allocated inside the wasm heap (for leak tests). */
export function heapBytes() {
  return module().heapUsed();
}
