// hexdual's Node entry (the "node" condition of the package's exports): the same API as
// index.js, with init() reading the .wasm from disk. Only this file imports Node modules.
import { readFile } from 'node:fs/promises';
import { init as initWith } from './index.js';

export * from './index.js';

/** Loads the WebAssembly module; with no options the .wasm is read from beside this file. */
export function init(options = {}) {
  return initWith(options, () => readFile(new URL('./dist/hexdual.wasm', import.meta.url)));
}
