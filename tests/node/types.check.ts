// Compiled by `tsc --noEmit` only: checks that wasm/index.d.ts describes the API as used.
import { init, Mesh, heapBytes, type Info, type RenderBuffers, type SheetTopology } from '../../wasm/index.js';

async function example(): Promise<number> {
  await init();
  const m: Mesh = Mesh.grid(3, 3, 3);
  const info: Info = m.info();
  const topo: SheetTopology = info.sheets[0].topology;
  const rb: RenderBuffers = m.renderBuffers({ shrink: 0.1 });
  const hexes: Int32Array = m.sheetHexes(0);
  const text: string = m.save('hxd');
  m.validate();
  m.delete();
  // @ts-expect-error: only the three formats are accepted
  m.save('obj');
  return info.hexes + rb.indices.length + hexes.length + text.length + heapBytes() + (topo === 'disk' ? 1 : 0);
}
void example;
