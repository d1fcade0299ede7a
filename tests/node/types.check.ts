// Compiled by `tsc --noEmit` only (lib es2022 and esnext): checks that wasm/index.d.ts describes the API as used.
import {
  init, Mesh, HexdualError, heapBytes, diagramToSVG, flips, decompositions,
  type DecompositionRecord,
  type Info, type RenderBuffers, type SheetTopology, type StepReport, type SheetDiagram, type ErrorCode, type Preview, type Selection,
} from '../../wasm/index.js';

async function example(): Promise<number> {
  await init();
  const m: Mesh = Mesh.grid(3, 3, 3);
  const info: Info = m.info();
  const topo: SheetTopology = info.sheets[0].topology;
  const rb: RenderBuffers = m.renderBuffers({ shrink: 0.1 });
  const hexes: Int32Array = m.sheetHexes(0);
  const bytes: Uint8Array = m.save('hxd');
  const report: StepReport = m.apply('pillow h13f5');
  const inverse: string | null = report.inverse;
  const reports: StepReport[] = m.applyLog('v1;hexpush h13f5', { stopAt: 1 });
  const undone: string = m.undo();
  const redone: StepReport = m.redo();
  const log: string = m.log + m.logUrl;
  const cands: string[] = m.candidates('pillow', { near: { hex: 13, face: 5 } }).concat(m.candidates());
  const flipped: StepReport[] = m.flip('2-6', [0, 1], { viaAtomic: true });
  const d: SheetDiagram = m.sheetDiagram(0, { local: new Set([13]), rings: 1 });
  const svg: string = diagramToSVG(d);
  const centres: Float64Array = m.hexCenters();
  const same: boolean = Mesh.isomorphic(m, Mesh.load(bytes, 'x.hxd'));
  const hash: string = m.canonicalHash() + m.canonicalHash({ boundary: 'free' });
  const sameFree: boolean = Mesh.isomorphic(m, m, { boundary: 'free' });
  // @ts-expect-error: boundary is 'kept' or 'free'
  Mesh.isomorphic(m, m, { boundary: 'loose' });
  const splits: string[] = m.ringSplits({ hex: 0, edge: 0 }, { maxEdges: 6 });
  const records: DecompositionRecord[] = decompositions();
  const p: Preview = m.preview('sheet-extract h13e0');
  const previewed: number = p.applies ? p.report.delta.H + p.hexesRemoved : (p.rule ?? p.error).length;
  const sel: Selection = m.select({ hex: 13, edge: 0 });
  const ends: Float64Array = m.vertexPositions(m.singularities().edges.flatMap((e) => e.vertices));
  const chordSel: Selection = m.select({ hex: 13, face: 1 });
  const sheetOp: StepReport['op'] = 'sheet-dice';
  const sheetCands: string[] = m.candidates('column-collapse');
  // @ts-expect-error: sheet-insert takes a surface you choose: not listed by candidates()
  m.candidates('sheet-insert');
  let code: ErrorCode | undefined;
  try {
    m.validate();
  } catch (e) {
    if (e instanceof HexdualError) code = e.code;
  }
  m.delete();
  // @ts-expect-error: only the three formats are accepted
  m.save('obj');
  // @ts-expect-error: near needs a hex
  m.candidates('pillow', { near: { face: 5 } });
  // @ts-expect-error: Mesh is made by its static builders
  new Mesh(null);
  return info.hexes + rb.indices.length + hexes.length + bytes.length + heapBytes() + (topo === 'disk' ? 1 : 0) +
    (inverse ?? '').length + reports.length + undone.length + redone.delta.H + log.length + cands.length + flipped.length +
    svg.length + centres.length + (same ? 1 : 0) + (sameFree ? 1 : 0) + hash.length + (code ? 1 : 0) + flips().length +
    splits.length + records.filter((r) => r.found && r.steps !== null).length + previewed +
    sel.hexes.length + ends.length + chordSel.steps.length + sheetOp.length + sheetCands.length;
}
void example;
