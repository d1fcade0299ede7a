// Every sheet of every development-set mesh laid out (and checked) natively and in WebAssembly,
// in one run: CPU seconds per 10k hexes for both and their ratio.
// Usage: node bench/sheets_devset_wasm.mjs [MESH_DIR]   (default ../shared/meshes, or $HEXDUAL_MESHES)
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { init, Mesh } from '../wasm/index.node.js';

const root = new URL('..', import.meta.url).pathname;
const dir = process.argv[2] ?? process.env.HEXDUAL_MESHES ?? join(root, '..', 'shared', 'meshes');
if (!existsSync(dir)) {
  console.log(`no development meshes at ${dir}: nothing to measure`);
  process.exit(0);
}
await init();
// Warm-up: the engine's wasm code compiled and tiered up before anything is timed.
{
  const w = Mesh.grid(12, 12, 12);
  for (let k = 0; k < 3; k++) for (const s of w.sheets) w.sheetDiagram(s.id);
  w.delete();
}
const cli = join(root, 'build/native/hexdual');
const cpu = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1e6; };
console.log('| mesh | hexes | sheets | native CPU s | wasm CPU s | wasm/native |');
console.log('| --- | --- | --- | --- | --- | --- |');
for (const f of readdirSync(dir).filter((x) => x.endsWith('.gz')).sort()) {
  const path = join(dir, f);
  let m;
  try {
    m = Mesh.load(readFileSync(path), f);
  } catch (e) {
    console.log(`| ${f} | | | refused: ${e.message} | | |`);
    continue;
  }
  const out = mkdtempSync(join(tmpdir(), 'hexdual-sheets-'));
  // Native: the CLI's own CPU time (children's rusage), the same work: read, lay out and check every sheet.
  const t0 = cpu();
  const m2 = Mesh.load(readFileSync(path), f);
  for (const s of m2.sheets) m2.sheetDiagram(s.id);
  const wasm = cpu() - t0;
  // Child CPU: time the CLI again under /usr/bin/time-like accounting via `bash -c times`.
  const native = Number(execFileSync('bash', ['-c', `out=$(mktemp -d); TIMEFORMAT=%U+%S; { time "${cli}" sheets "${path}" --all --json "$out" >/dev/null 2>&1; } 2>&1; rm -rf "$out"`]).toString().trim().split('+').reduce((a, b) => a + Number(b), 0));
  console.log(`| ${f.replace(/\.gz$/, '')} | ${m2.counts.hexes} | ${m2.sheets.length} | ${native.toFixed(2)} | ${wasm.toFixed(2)} | ${(wasm / Math.max(native, 0.01)).toFixed(2)} |`);
  m.delete();
  m2.delete();
}
