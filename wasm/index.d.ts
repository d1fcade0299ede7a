// Hand-written types for hexdual's JS API (wasm/index.js).
export interface InitOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  locateFile?: (path: string, prefix: string) => string;
}
export function init(options?: InitOptions): Promise<unknown>;
export function heapBytes(): number;
export interface FlipInfo {
  name: string;
  inverse: string;
  geometric: boolean;
  description: string;
  before: number[];
  steps: string[] | null;
}
export function flips(): FlipInfo[];

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
export interface Info extends Counts {
  sheets: SheetInfo[];
  chords: ChordInfo[];
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
}
export interface HexDual {
  sheetOf: Int32Array;
  chordOf: Int32Array;
}
export function hexTables(): { faceCorners: Int32Array; edgeCorners: Int32Array };
// ---- end of view data (explorer) ----
export type Format = 'vtk' | 'mesh' | 'hxd';
export type XY = [number, number];
export interface SheetDiagram {
  sheet: number;
  topology: SheetTopology;
  method: 'disk' | 'annulus' | 'sphere' | 'local';
  local: boolean;
  note: string;
  radius: number;
  openedHex: number | null;
  crossings: { hex: number; axis: number; x: number; y: number; chords: [number, number]; outside: boolean }[];
  boundary: { hex: number; face: number; x: number; y: number }[];
  chords: { id: number; otherSheet: number; closed: boolean; hexes: number[]; points: XY[] }[];
  loops: XY[][];
  cells: { edge: [number, number]; x: number; y: number }[];
}

export class Mesh {
  static grid(a: number, b: number, c: number): Mesh;
  static ring(around: number, radial: number, axial: number): Mesh;
  static fourCube(): Mesh;
  static load(bytes: Uint8Array | ArrayBuffer | string, name?: string): Mesh;
  info(): Info;
  readonly counts: Counts;
  readonly sheets: SheetInfo[];
  readonly chords: ChordInfo[];
  sheetHexes(id: number): Int32Array;
  chordHexes(id: number): Int32Array;
  dualSizes(): { sheets: number; chords: number };
  sheetDiagram(id: number): SheetDiagram;
  localSheetDiagram(id: number, hexes: number[], rings?: number): SheetDiagram;
  apply(step: string): string | null;
  memoryBytes(): number;
  validate(): void;
  save(format: Format, options?: { binary?: boolean }): string;
  // ---- view data (explorer) ----
  renderBuffers(options?: { shrink?: number; edges?: boolean }): RenderBuffers;
  hexCenters(): Float32Array;
  dualOverlay(): DualOverlay;
  quality(): Quality;
  hexDual(): HexDual;
  candidateSteps(op: string): string[];
  // ---- end of view data (explorer) ----
  delete(): void;
  [Symbol.dispose](): void;
}
