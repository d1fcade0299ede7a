// init() before and after a failure, in a process of its own (a successful init is kept for good):
// calls before init, bad wasmBinary bytes refused with a clear error before Emscripten sees them,
// and a retry with the right bytes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { init, Mesh, HexdualError } from 'hexdual';

test('init: calls before it, wrong wasmBinary, then a retry that works', async () => {
  assert.throws(() => Mesh.grid(2, 2, 2), { code: 'PRECONDITION', message: 'hexdual: call `await init()` first' });
  await assert.rejects(init({ wasmBinary: new Uint8Array([1, 2, 3, 4, 5]) }), (e) => e instanceof HexdualError && e.code === 'IO' &&
    e.message === 'init: wasmBinary is not a valid WebAssembly module (5 bytes, starting 01 02 03 04; a .wasm starts 00 61 73 6d)');
  await assert.rejects(init({ wasmBinary: 'hexdual.wasm' }), {
    code: 'PRECONDITION', message: "init: wasmBinary must be the .wasm's bytes (an ArrayBuffer or Uint8Array), not 'hexdual.wasm'",
  });
  await assert.rejects(init({ wasmBinary: new ArrayBuffer(0) }), { code: 'IO', message: /^init: wasmBinary is not a valid WebAssembly module \(0 bytes, starting with nothing/ });
  await init({ wasmBinary: readFileSync(new URL('../../wasm/dist/hexdual.wasm', import.meta.url)) });
  assert.equal(Mesh.grid(2, 2, 2).counts.hexes, 8);
});
