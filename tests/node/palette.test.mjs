// One colour rule: the C++ SVG writer (core/layout/palette.hpp) and the demo (web/colors.js) agree.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { GOLDEN_ANGLE, SATURATION, LIGHTNESS, CHORD_ID_OFFSET, sheetColor, chordColor } from '../../web/colors.js';

const root = new URL('../..', import.meta.url).pathname;

test('palette constants are the same in palette.hpp and colors.js', () => {
  const hpp = readFileSync(join(root, 'core/layout/palette.hpp'), 'utf8');
  const constant = (name) => Number(hpp.match(new RegExp(`${name} = ([0-9.]+);`))[1]);
  assert.equal(constant('kGoldenAngle'), GOLDEN_ANGLE);
  assert.equal(constant('kSaturation'), SATURATION);
  assert.equal(constant('kLightness'), LIGHTNESS);
  assert.equal(constant('kChordIdOffset'), CHORD_ID_OFFSET);
  assert.equal(sheetColor(1), 'hsl(137.5, 65%, 50%)');
  assert.equal(chordColor(0), 'hsl(348.0, 65%, 50%)'); // 1000 * 137.508 = 381 turns + 348 degrees
});

test('every chord in a native SVG diagram has the colour colors.js gives it', (t) => {
  const cli = join(root, 'build/native/hexdual');
  if (!existsSync(cli)) return t.skip('native CLI not built');
  const dir = mkdtempSync(join(tmpdir(), 'hexdual-palette-'));
  try {
    execFileSync(cli, ['grid', '4x3x2', '-o', join(dir, 'g.hxd')]);
    let chords = 0;
    for (const sheet of [0, 3, 5]) {
      execFileSync(cli, ['sheets', join(dir, 'g.hxd'), '--sheet', String(sheet), '--svg', dir]);
      const svg = readFileSync(join(dir, `sheet-${sheet}.svg`), 'utf8');
      for (const m of svg.matchAll(/stroke="(hsl\([^"]*\))" stroke-width="[0-9.]+"><title>chord (\d+) /g)) {
        assert.equal(m[1], chordColor(Number(m[2])), `chord ${m[2]}`);
        ++chords;
      }
    }
    assert.equal(chords, 15); // three sheets of a 4x3x2 grid crossed by 5 chords each
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
