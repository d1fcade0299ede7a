// Hand-written types for hexdual's JS API (wasm/index.js, and wasm/index.node.js in Node).
// They need no particular `lib`: `Symbol.dispose` is used only where the lib declares it.

export interface InitOptions {
  /** The .wasm bytes, when the application loads them itself. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Maps 'hexdual.wasm' to the URL it is served from (e.g. a bundler's asset URL). */
  locateFile?: (path: string, prefix: string) => string;
}
/** Loads the WebAssembly module once; later calls return the same module. */
export function init(options?: InitOptions): Promise<unknown>;
/** Bytes currently allocated inside the wasm heap (for leak tests). */
export function heapBytes(): number;

/** PARSE: unreadable file or operation log. PRECONDITION: an argument or state the call needs is
 *  missing. INVALID_RESULT: the result (or the mesh) breaks an invariant. LIMIT: a size, memory or
 *  runtime limit. IO: the module or its .wasm could not be loaded. */
export type ErrorCode = 'PARSE' | 'PRECONDITION' | 'INVALID_RESULT' | 'LIMIT' | 'IO';
export class HexdualError extends Error {
  constructor(code: ErrorCode, message: string);
  readonly name: 'HexdualError';
  readonly code: ErrorCode;
}

export interface FlipInfo {
  name: string;
  inverse: string;
  geometric: boolean;
  description: string;
  before: number[];
  steps: string[] | null;
}
export function flips(): FlipInfo[];

/** One record of the decomposition search (core/flips/decompositions.txt, docs/flips.md). */
export interface DecompositionRecord {
  /** A flip name, 'tripleChordPush', or 'NAME/chord-only' (searched with chord push and pull only). */
  problem: string;
  found: boolean;
  /** The sequence found (op-log steps in the problem's complex), or null. */
  steps: string[] | null;
  maxDepth: number;
  /** Every sequence up to this many steps was examined. */
  depthSearched: number;
  states: number;
  seconds: number;
  /** 'all' or the operations searched, comma-separated. */
  ops: string;
}
export function decompositions(): DecompositionRecord[];

export type SheetTopology = 'disk' | 'annulus' | 'sphere' | 'torus' | 'other';
export interface SheetInfo {
  id: number;
  hexes: number;
  topology: SheetTopology;
  boundaryLoops: number;
  euler: number;
  selfIntersecting: boolean;
}
export interface ChordInfo {
  id: number;
  hexes: number;
  closed: boolean;
  selfIntersecting: boolean;
}
export interface Counts {
  vertices: number;
  edges: number;
  quads: number;
  hexes: number;
  boundaryQuads: number;
}
/** What the reader found in a loaded file (only on meshes made by Mesh.load). */
export interface FileReport {
  /** e.g. "vtk 5.1 binary", "gmsh 4.1 ascii", "medit ascii". */
  format: string;
  gzipped: boolean;
  /** Points in the file; `unusedVertices` of them are used by no hex and were dropped. */
  points: number;
  unusedVertices: number;
  /** Lower-dimensional cells skipped. */
  skipped: { vertices: number; lines: number; triangles: number; quads: number };
  /** Volume cells dropped by `hexesOnly`. */
  dropped: { tetrahedra: number; prisms: number; pyramids: number };
  /** Vertices whose link is neither a sphere nor a disk (the mesh opens; operations there are refused). */
  nonManifoldVertices: number[];
}
export interface Info extends Counts {
  sheets: SheetInfo[];
  chords: ChordInfo[];
  file?: FileReport;
}
// ---- view data (explorer) ----
export interface RenderBuffers {
  positions: Float32Array;
  normals: Float32Array;
  indices: Uint32Array;
  triangleHex: Int32Array;
  triangleFace: Uint8Array;
  edgePositions?: Float32Array;
  edgeHex?: Int32Array;
  edgeLocal?: Uint8Array;
}
export interface DualOverlay {
  sheetPositions: Float32Array;
  sheetIndices: Uint32Array;
  sheetTriangle: Int32Array;
  chordPositions: Float32Array;
  chordSegment: Int32Array;
  dualVertices: Float32Array;
  dualVertexHex: Int32Array;
}
export interface Quality {
  scaledJacobian: Float32Array;
  inverted: Int32Array;
  min: number;
  max: number;
  /** Live hexes, and the distribution as `hexdual quality --json` gives it. */
  hexes: number;
  mean: number;
  /** Hexes with scaled Jacobian <= 0. */
  nonPositive: number;
  /** 20 counts: bucket k holds [-1 + k/10, -1 + (k+1)/10), the last one includes 1. */
  buckets: number[];
}
/** What a step did to the geometry (docs/operations.md, "Geometry after every step"). */
export interface StepQuality {
  /** Whether the local untangling and smoothing placed the vertices around the step (Mesh.smoothing). */
  smoothed: boolean;
  /** Minimum scaled Jacobian of the measured hexes (touched by the step or reshaped by the smoothing) before and after (1 when none). */
  before: number;
  after: number;
  /** `after` without the hexes degenerate by construction. */
  afterRegular: number;
  /** Measured hexes with scaled Jacobian <= 0 that are not degenerate by construction. */
  inverted: number[];
  /** Those of `inverted` that no smoothing keeping the boundary fixed can make valid (a certified corner). */
  pinned: number[];
  /** Measured hexes no embedding makes valid: an interior edge of valence <= 2, or a corner frame mirrored by another hex. */
  degenerate: number[];
  /** Vertices the smoothing moved. */
  moved: number[];
  /** How many rings the smoothing's region was widened by (0, 1 or 2). */
  rings: number;
  /** Corner-energy evaluations: the smoothing's cost, independent of the mesh's size. */
  evaluations: number;
  /** The smoothing kept the operation's own placement (nothing moved): the smoothed one left more hexes newly inverted. */
  kept: boolean;
}
/** Irregular edges by valence and the rest of the singularity graph's size. */
export interface SingularityCounts {
  interiorEdges: number;
  boundaryEdges: number;
  interiorByValence: Record<string, number>;
  boundaryByValence: Record<string, number>;
  vertices: number;
  boundaryVertices: number;
  curves: number;
}
export interface SingularEdge {
  /** The edge's smallest (hex, local edge) incidence: pass it to edgeDual(). */
  hex: number;
  edge: number;
  vertices: [number, number];
  valence: number;
  boundary: boolean;
  /** Index into `curves`. */
  curve: number;
}
export interface SingularVertex {
  vertex: number;
  boundary: boolean;
  /** Singular edges at the vertex (1: a curve ends, 3 or more: curves branch, 2: of different kinds). */
  degree: number;
}
export interface SingularCurve {
  /** Indices into `edges`, in order along the curve. */
  edges: number[];
  valence: number;
  boundary: boolean;
  closed: boolean;
  /** The end vertices of an open curve; [] for a closed one. */
  ends: number[];
}
export interface Singularities {
  counts: SingularityCounts;
  edges: SingularEdge[];
  vertices: SingularVertex[];
  curves: SingularCurve[];
}
/** The dual through one edge. */
export interface EdgeDual {
  hex: number;
  edge: number;
  valence: number;
  boundary: boolean;
  /** The sheet crossing the edge. */
  sheet: number;
  /** Hexes around the edge in cycle (fan) order. */
  hexes: number[];
  /** Each quad containing the edge (canonical side) with the chord through it and that chord's other sheet. */
  quads: { hex: number; face: number; chord: number; sheet: number }[];
  chords: number[];
  sheets: number[];
}
export interface HexDual {
  sheetOf: Int32Array;
  chordOf: Int32Array;
}
export function hexTables(): { faceCorners: Int32Array; edgeCorners: Int32Array };
// ---- end of view data (explorer) ----
export type Format = 'vtk' | 'mesh' | 'hxd';
export type OpName =
  | 'pillow' | 'unpillow' | 'chordpush' | 'chordpull' | 'hexpush' | 'hexpull' | 'ringcollapse' | 'facecollapse' | 'facesplit';
/** The sheet operations: a family apart that changes the boundary quad mesh (docs/operations.md). */
export type SheetOpName = 'sheet-extract' | 'sheet-insert' | 'sheet-pillow' | 'column-collapse' | 'sheet-dice';
/** The sheet operations candidates() lists when named (sheet-insert and sheet-pillow take a surface or set you choose). */
export type SheetCandidateOp = 'sheet-extract' | 'column-collapse' | 'sheet-dice';
export type FlipName = '1-7' | '2-6' | '3-5c' | '3-5e' | '4-4m' | '4-4v' | '5-3c' | '5-3e' | '6-2' | '7-1';

export interface IdChanges {
  created: number[];
  removed: number[];
  /** Same id, different hexes. */
  changed: number[];
}
/** What one step did (the same facts as `hexdual apply --json`). */
export interface StepReport {
  /** The step as applied, normalised ('pillow h13f5'); a direct flip reads 'flip 2-6 [13,22]'. */
  step: string;
  /** The operation-log name: 'pillow', 'chordpush', ..., 'sheet-extract', ..., or 'flip' for a direct flip. */
  op: OpName | SheetOpName | 'flip';
  /** The step that undoes this one (up to ids), or null when there is none (use undo()). */
  inverse: string | null;
  /** Why there is no inverse step (only when `inverse` is null). */
  noInverse?: string;
  created: { hexes: number[]; vertices: number[] };
  removed: { hexes: number[]; vertices: number[] };
  delta: { V: number; E: number; F: number; H: number };
  changedSheets: IdChanges;
  changedChords: IdChanges;
  /** Scaled Jacobians of the touched hexes before and after, and what the smoothing did. */
  quality: StepQuality;
}
/** What applying a step would do (mesh.preview): the report apply would return, or the refusal. */
export type Preview =
  | {
      applies: true;
      family: 'atomic' | 'sheet';
      /** The step, normalised. */
      step: string;
      hexesRemoved: number;
      hexesCreated: number;
      report: StepReport;
    }
  | {
      applies: false;
      family: 'atomic' | 'sheet';
      step: string;
      /** The rule a sheet operation names ('self-touching', 'no-sides', ...); null for other refusals. */
      rule: string | null;
      error: string;
    };
/** A picked sheet (through an edge) or chord (through a quad), and the steps that act on it. */
export interface Selection {
  kind: 'sheet' | 'chord';
  id: number;
  /** The pick: 'h13e8' or 'h13f5'. */
  through: string;
  /** Sheets only. */
  topology?: SheetTopology;
  boundaryLoops?: number;
  /** Chords only. */
  closed?: boolean;
  selfIntersecting: boolean;
  /** One per slot (a self-intersecting one lists a hex twice); a chord's in order along it. */
  hexes: number[];
  /** Operation-log steps: 'sheet-extract h13e8', 'sheet-dice h13e8 2', or the chord's two 'column-collapse' diagonals. */
  steps: string[];
}
/** Where candidates() looks: a hex, a quad (hex + local face) or an edge (hex + local edge). */
export type Near = { hex: number } | { hex: number; face: number } | { hex: number; edge: number };

/** The JSON form of a sheet diagram (`hexdual sheets --json`). */
export type XY = [number, number];
/** What a sheet diagram shows and how it was laid out. */
export interface DiagramHeader {
  sheet: number;
  topology: SheetTopology;
  /** How the sheet was drawn: always whole ('local' only when a local diagram was asked for). */
  method: 'disk' | 'annulus' | 'holes' | 'sphere' | 'polygon' | 'local';
  local: boolean;
  note: string;
  radius: number;
  euler: number;
  openedHex: number | null;
}
export interface SheetDiagramJSON extends DiagramHeader {
  crossings: { hex: number; axis: number; x: number; y: number; chords: [number, number]; outside: boolean }[];
  boundary: { hex: number; face: number; x: number; y: number }[];
  chords: { id: number; otherSheet: number; closed: boolean; piece: number; hexes: number[]; points: XY[] }[];
  loops: XY[][];
  /** method 'polygon': the sides of the fundamental polygon; seams have labels a, a⁻¹, ..., the boundary ∂ (pair -1). */
  arcs: { label: string; pair: number; sign: 1 | -1; points: XY[] }[];
  cells: { edge: [number, number]; x: number; y: number }[];
}

/**
 * A sheet diagram as typed arrays. Points are (x, y) pairs in `xy` arrays, inside the circle of
 * `radius` around the origin. Polylines (chords, loops) are runs of points: item k spans points
 * offsets[k] .. offsets[k+1]-1.
 */
export interface SheetDiagram extends DiagramHeader {
  /** One per (hex, axis) slot of the sheet: where two chords cross; labelled by hex id. */
  crossings: { hex: Int32Array; axis: Int8Array; xy: Float64Array; chords: Int32Array; outside: Uint8Array };
  /** Where chords meet the boundary loop: a boundary quad (hex, local face). */
  boundary: { hex: Int32Array; face: Int8Array; xy: Float64Array };
  chords: {
    id: Int32Array;
    otherSheet: Int32Array;
    closed: Uint8Array;
    /** A chord crossing the seams of a cut-open sheet is drawn in pieces 0, 1, ... */
    piece: Int32Array;
    offsets: Uint32Array;
    xy: Float64Array;
    hexOffsets: Uint32Array;
    hexes: Int32Array;
  };
  /**
   * Method 'polygon' (a sheet of genus > 0, non-orientable, or cut open): the polygon's sides in
   * order. Both sides of a seam share `pair`; `sign` -1 marks the side glued in the opposite
   * direction; `label` is 'a', 'a⁻¹', ... or '∂' for the sheet's own boundary.
   */
  arcs: { label: string[]; pair: Int32Array; sign: Int8Array; offsets: Uint32Array; xy: Float64Array };
  /** Boundary loops (outer first), or the dotted circle of a local diagram. */
  loops: { offsets: Uint32Array; xy: Float64Array };
  /** Mid-surface vertices: one per primal edge (hex, local edge) crossing the sheet. */
  cells: { hex: Int32Array; edge: Int8Array; xy: Float64Array };
  /** Mid-surface quads, 4 cell indices per crossing. */
  quads: Int32Array;
}
export interface DiagramOptions {
  /** Hex ids: draw only the part of the sheet around them, in a dotted circle. */
  local?: Iterable<number>;
  /** How many rings of hexes around `local` (default 2). */
  rings?: number;
}
/** The diagram drawn as an SVG document (as `hexdual sheets --svg`). */
export function diagramToSVG(d: SheetDiagram): string;

// `[Symbol.dispose]` appears on Mesh only where the lib declares Symbol.dispose (esnext, es2025
// or esnext.disposable), so `using m = Mesh.grid(...)` works there and plain es2022 still compiles.
type DisposeKey = SymbolConstructor extends { readonly dispose: infer K extends symbol } ? K : never;
type MaybeDisposable = { [K in DisposeKey]: () => void };

export interface LoadOptions {
  /**
   * Read the hexahedra of a file that also holds tetrahedra, prisms or pyramids (their faces become
   * boundary). Without it such a file is refused (PARSE) with the counts of each kind.
   */
  hexesOnly?: boolean;
}

export interface IsomorphismOptions {
  /**
   * 'kept' (the default): an isomorphism must keep every boundary vertex id (what the flips need:
   * the same boundary). 'free': any renumbering of vertices and hexes, e.g. a mesh and its copy
   * after `save` and `load`, which number the ids densely again.
   */
  boundary?: 'kept' | 'free';
}

export interface Mesh extends MaybeDisposable {}
export class Mesh {
  private constructor(raw: never);
  static grid(a: number, b: number, c: number): Mesh;
  static ring(around: number, radial: number, axial: number): Mesh;
  static fourCube(): Mesh;
  static load(bytes: Uint8Array | ArrayBuffer | ArrayBufferView | string, name?: string, options?: LoadOptions): Mesh;
  /** Same complex up to renumbering: boundary 'kept' (default) lets only interior vertex ids differ, 'free' any. */
  static isomorphic(a: Mesh, b: Mesh, options?: IsomorphismOptions): boolean;
  info(): Info;
  /** Constant time after the first read (info() is O(mesh) after every step). */
  readonly counts: Counts;
  readonly sheets: SheetInfo[];
  readonly chords: ChordInfo[];
  sheetHexes(id: number): Int32Array;
  chordHexes(id: number): Int32Array;
  hexCenters(): Float64Array;
  /** How many live sheets and chords (ids stay stable across operations, so they need not be 0..n-1). */
  dualSizes(): { sheets: number; chords: number };
  sheetDiagram(id: number, options?: DiagramOptions): SheetDiagram;
  sheetDiagramJSON(id: number, options?: DiagramOptions): SheetDiagramJSON;
  localSheetDiagram(id: number, hexes: Iterable<number>, rings?: number): SheetDiagramJSON;
  apply(step: string): StepReport;
  applyLog(log: string, options?: { stopAt?: number }): StepReport[];
  undo(): string;
  redo(): StepReport;
  readonly canUndo: boolean;
  readonly canRedo: boolean;
  readonly log: string;
  readonly logUrl: string;
  candidates(op?: OpName | SheetCandidateOp, options?: { near?: Near }): string[];
  /** What applying `step` would do, without doing it (the mesh, its dual and the undo list are not changed). */
  preview(step: string): Preview;
  /** The sheet through a picked edge or the chord through a picked quad. */
  select(pick: { hex: number; edge: number } | { hex: number; face: number }): Selection;
  flip(name: FlipName, hexes: Iterable<number>, options?: { viaAtomic?: boolean }): StepReport[];
  canonicalHash(options?: IsomorphismOptions): string;
  memoryBytes(): number;
  validate(): void;
  save(format: Format, options?: { binary?: boolean }): Uint8Array;
  // ---- view data (explorer) ----
  /**
   * Which hexes: all; with `shell` only those with a face on the boundary or next to a hidden hex;
   * `hidden[h]` != 0 leaves hex h out (one byte per hex id); `always` are drawn regardless.
   */
  renderBuffers(options?: { shrink?: number; edges?: boolean; shell?: boolean; hidden?: Uint8Array | null; always?: Iterable<number> | null }): RenderBuffers;
  dualPoints(): Float32Array;
  /** With `hexes`, only their sheet quads, dual points and the chord segments between two of them. */
  dualOverlay(options?: { hexes?: Iterable<number> | null }): DualOverlay;
  quality(): Quality;
  hexDual(): HexDual;
  /** Flips with a stored atomic decomposition that apply near the pick, for flip(name, hexes, { viaAtomic: true }). */
  flipPlaces(near: Near): { name: FlipName; hexes: number[] }[];
  // ---- end of view data (explorer) ----
  /** Ring splits whose loop passes through the edge (loops of at most maxEdges edges, default 8). */
  ringSplits(near: { hex: number; edge: number }, options?: { maxEdges?: number }): string[];
  // ---- geometry and singularities ----
  singularities(): Singularities;
  /** The dual through an edge (any incidence of it); throws for a hex or edge that does not exist. */
  edgeDual(hex: number, edge: number): EdgeDual;
  /** Hash of every live vertex's id and position bits (equal to `hexdual apply --json`'s positionsHash). */
  positionsHash(): string;
  /** x, y, z of each vertex id, in order (3 numbers per vertex); throws PRECONDITION for an id that is not a live vertex. */
  vertexPositions(ids: number[]): Float64Array;
  /** Whether steps (and flips) untangle and smooth the vertices around them (default true); false keeps the operations' own placement (still measured). */
  smoothing: boolean;
  delete(): void;
}
