// A TypeScript user of the installed package: compiled with `tsc --strict` (lib es2022 and esnext).
import { init, Mesh, HexdualError, diagramToSVG, flips, type StepReport, type SheetDiagram, type ErrorCode } from 'hexdual';

export async function main(): Promise<string> {
  await init();
  const mesh: Mesh = Mesh.grid(3, 3, 3);
  const report: StepReport = mesh.apply('pillow h13f5');
  const inverse: string | null = report.inverse;
  const created: number[] = report.created.hexes;
  const diagram: SheetDiagram = mesh.sheetDiagram(2, { local: created, rings: 1 });
  const xy: Float64Array = diagram.crossings.xy;
  const bytes: Uint8Array = mesh.save('vtk', { binary: true });
  const copy = Mesh.load(bytes, 'copy.vtk');
  const same: boolean = Mesh.isomorphic(mesh, copy);
  const steps: string[] = mesh.candidates('hexpush', { near: { hex: 13, face: 5 } });
  const flipReports: StepReport[] = mesh.flip('2-6', [0, 1], { viaAtomic: true });
  let code: ErrorCode | '' = '';
  try {
    mesh.apply('frobnicate h1');
  } catch (e) {
    if (e instanceof HexdualError) code = e.code;
  }
  const names: string[] = flips().map((f) => f.name);
  copy.delete();
  mesh.delete();
  // @ts-expect-error: only vtk, mesh and hxd are formats
  mesh.save('obj');
  return `${inverse}${xy.length}${same}${steps.length}${flipReports.length}${code}${names.length}${diagramToSVG(diagram).length}`;
}
