// The primal pictures of docs/operations.md are drawn by docs/primal-figures.mjs from the package:
// they must show what each step does (created / removed hexes) and be current.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const root = new URL('../../', import.meta.url).pathname;
const out = mkdtempSync(join(tmpdir(), 'hexdual-figures-'));
execFileSync('node', [join(root, 'docs/primal-figures.mjs'), out]);
const polygons = (svg, colour) => (svg.match(/<polygon [^>]*>/g) ?? []).filter((p) => p.includes(`fill="${colour}"`)).length;
const CREATED = '#f28e2b', REMOVED = '#d62728';

// Six quads per hex drawn: created hexes in the after panel, removed ones in the before panel.
const expected = {
  pillow: { created: 2, removed: 0 },
  chordpush: { created: 2, removed: 0 },
  hexpush: { created: 6, removed: 2 },
  ringcollapse: { created: 0, removed: 8 },
  facecollapse: { created: 0, removed: 0 },
};

for (const [name, { created, removed }] of Object.entries(expected)) {
  test(`primal figure of ${name}: ${created} hexes created, ${removed} removed, committed copy current`, () => {
    const svg = readFileSync(join(out, `op-${name}-primal.svg`), 'utf8');
    assert.equal(polygons(svg, CREATED), 6 * created);
    assert.equal(polygons(svg, REMOVED), 6 * removed);
    const committed = readFileSync(join(root, `docs/images/op-${name}-primal.svg`), 'utf8');
    assert.equal(svg, committed, `docs/images/op-${name}-primal.svg is stale: run node docs/primal-figures.mjs`);
  });
}

test.after(() => rmSync(out, { recursive: true, force: true }));
