// `using` disposes the mesh where the lib declares Symbol.dispose (esnext).
import { init, Mesh } from 'hexdual';

export async function withUsing(): Promise<number> {
  await init();
  using mesh = Mesh.grid(2, 2, 2);
  return mesh.counts.hexes;
}
