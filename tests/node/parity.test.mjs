// Native CLI and npm package agree: the operation logs in parity/logs.txt (sequences of the
// property test's random generator, fixed seeds; see parity/generate.sh) are replayed by
// `hexdual apply --json` and by mesh.applyLog; every step must report the same created and removed
// ids, Δ, changed sheets and chords and inverse, and the resulting files must be identical bytes
// with the same canonical hash.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { init, Mesh } from 'hexdual';

await init();
const root = new URL('../../', import.meta.url).pathname;
const cli = join(root, 'build/native/hexdual');
const lines = readFileSync(new URL('./parity/logs.txt', import.meta.url), 'utf8').trim().split('\n');

function build(spec) {
  const [kind, dims] = spec.split(' ');
  const [a, b, c] = dims.split('x').map(Number);
  return kind === 'ring' ? Mesh.ring(a, b, c) : Mesh.grid(a, b, c);
}

// The CLI's per-step JSON in the package's StepReport shape.
function fromCli(s) {
  const report = {
    step: s.text, op: s.op, inverse: s.inverse === '' ? null : s.inverse,
    created: { hexes: s.createdHexes, vertices: s.createdVertices },
    removed: { hexes: s.removedHexes, vertices: s.removedVertices },
    delta: s.delta, changedSheets: s.sheets, changedChords: s.chords, quality: s.quality,
  };
  if (s.inverse === '') report.noInverse = s.noInverse;
  return report;
}

test(`${lines.length} operation logs: CLI and package give the same ids, reports and canonical hash`, () => {
  assert.ok(lines.length >= 500, `${lines.length} logs`);
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-parity-'));
  let steps = 0;
  try {
    const starts = new Map();
    for (const line of lines) {
      const [spec, seed, log] = line.split('\t');
      if (!starts.has(spec)) {
        const file = join(dir, `${spec.replace(' ', '-')}.hxd`);
        execFileSync(cli, [...spec.split(' '), '-o', file]);
        starts.set(spec, file);
      }
      const out = join(dir, 'out.hxd');
      const native = JSON.parse(execFileSync(cli, ['apply', starts.get(spec), '--ops', log, '-o', out, '--json']).toString());
      const m = build(spec);
      try {
        const reports = m.applyLog(log);
        assert.deepEqual(reports, native.steps.map(fromCli), `seed ${seed}: ${log}`);
        const { vertices, edges, quads, hexes } = m.counts;
        assert.deepEqual({ vertices, edges, quads, hexes }, native.counts, `seed ${seed}`);
        const nativeBytes = readFileSync(out);
        assert.ok(Buffer.from(m.save('hxd')).equals(nativeBytes), `seed ${seed}: the .hxd files differ`);
        const reread = Mesh.load(nativeBytes, 'native.hxd');
        const mine = Mesh.load(m.save('hxd'), 'wasm.hxd');
        assert.equal(mine.canonicalHash(), reread.canonicalHash(), `seed ${seed}`);
        assert.ok(Mesh.isomorphic(mine, reread));
        reread.delete();
        mine.delete();
        steps += reports.length;
      } finally {
        m.delete();
      }
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  console.log(`parity: ${lines.length} logs, ${steps} steps`);
});
