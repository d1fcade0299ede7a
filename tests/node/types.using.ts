// Compiled with lib esnext only: `using` disposes a Mesh where Symbol.dispose exists.
import { init, Mesh } from '../../wasm/index.js';

async function disposes(): Promise<number> {
  await init();
  using m = Mesh.grid(2, 2, 2);
  return m.counts.hexes;
}
void disposes;
