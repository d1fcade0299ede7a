#!/usr/bin/env bash
# Regenerates the sheet-diagram figures of docs/sheet-diagrams.md and the before/after figures of
# docs/operations.md (needs the native and wasm builds, and
# rsvg-convert from Debian's librsvg2-bin). Usage: bash docs/figures.sh
set -euo pipefail
cd "$(dirname "$0")/.."
H=build/native/hexdual
T=$(mktemp -d)
OUT=docs/images
mkdir -p "$OUT"
fig() {  # fig NAME MESH SHEET [--local HEXES --rings K]
  local name=$1 mesh=$2 sheet=$3; shift 3
  rm -rf "$T/svg" && mkdir -p "$T/svg"
  $H sheets "$mesh" --sheet "$sheet" --svg "$T/svg" "$@" >/dev/null
  rsvg-convert "$T"/svg/*.svg -o "$OUT/$name.png"
  echo "$OUT/$name.png"
}
$H grid 3x3x3 -o "$T/g3.hxd"
$H grid 5x5x5 -o "$T/g5.hxd"
$H ring 8x3x3 -o "$T/ring.hxd"
$H apply "$T/g3.hxd" --ops 'v1;pillow h13f5' -o "$T/pillow.hxd" >/dev/null
$H apply "$T/g3.hxd" --ops 'v1;chordpush h13e3 h13f3 h16f5' -o "$T/chordpush.hxd" >/dev/null
$H apply "$T/g3.hxd" --ops 'v1;hexpush h13f5' -o "$T/hexpush.hxd" >/dev/null
$H flip 1-7 --at 62 "$T/g5.hxd" -o "$T/flip17.hxd" >/dev/null
fig grid-sheet "$T/g3.hxd" 0                                   # Fig. 1: a sheet of a 3x3x3 grid
fig ring-annulus "$T/ring.hxd" 0                               # an annulus sheet of an O-grid
fig pillow-sphere "$T/pillow.hxd" 9                            # Fig. 6: the new sphere sheet
fig pillow-crossed "$T/pillow.hxd" 5                           # Fig. 6: a sheet the pillow crosses, whole
fig chordpush-blind "$T/chordpush.hxd" 7                       # Fig. 2: the blind chord on a pushed sheet, whole
fig chordpush-pushed "$T/chordpush.hxd" 3                      # Fig. 2: e's sheet, two chords crossing twice
fig hexpush-sheet "$T/hexpush.hxd" 7                           # Fig. 4: the new closed chord of 4, whole
fig flip17-sphere "$T/flip17.hxd" 15                           # Fig. 8: the traditional pillow's sphere
# docs/operations.md: the same sheet before and after each operation.
$H grid 4x4x4 -o "$T/g4.hxd"
$H apply "$T/g4.hxd" --ops 'v1;facecollapse h21e11 h21f1 h25f1' -o "$T/facecollapse.hxd" >/dev/null
$H apply "$T/ring.hxd" --ops 'v1;ringcollapse h25e4' -o "$T/ringcollapse.hxd" >/dev/null
fig op-pillow-before "$T/g3.hxd" 5 --local 13,22 --rings 1        # after: pillow-crossed, pillow-sphere
fig op-chordpush-before "$T/g3.hxd" 3                           # after: chordpush-pushed
fig op-hexpush-before "$T/g3.hxd" 7                             # after: hexpush-sheet
fig op-ringcollapse-before "$T/ring.hxd" 3                         # an annulus of 24 hexes the ring crosses
fig op-ringcollapse-after "$T/ringcollapse.hxd" 3                  # the same annulus, 16 hexes
fig op-facecollapse-before-a "$T/g4.hxd" 6                         # two disks through f and g ...
fig op-facecollapse-before-b "$T/g4.hxd" 7
fig op-facecollapse-after "$T/facecollapse.hxd" 6                  # ... merge into one annulus
fig torus-polygon docs/examples/torus-shell.hxd 0              # a torus sheet cut open: a b a^-1 b^-1
fig klein-polygon docs/examples/klein-shell.hxd 0              # a Klein-bottle sheet: three seams, two twisted
fig mobius-polygon docs/examples/twisted-ring.hxd 0            # a Moebius-band sheet: a boundary a boundary
# docs/operations.md, sheet operations: a sheet they cross or cut, before and after (ids as `hexdual select` reads them).
$H apply "$T/g4.hxd" --ops 'v1;sheet-extract h21e0' -o "$T/sheetextract.hxd" >/dev/null
$H apply "$T/g3.hxd" --ops 'v1;sheet-pillow h0' -o "$T/sheetpillow.hxd" >/dev/null
$H apply "$T/g3.hxd" --ops 'v1;column-collapse h13e0' -o "$T/columncollapse.hxd" >/dev/null
$H apply "$T/g3.hxd" --ops 'v1;sheet-dice h13e0 2' -o "$T/sheetdice.hxd" >/dev/null
fig op-sheetextract-before "$T/g4.hxd" 9                           # the z=1 layer, crossed by the x=1 layer's chords
fig op-sheetextract-after "$T/sheetextract.hxd" 8                  # ... one chord fewer each way: 12 hexes
fig op-sheetpillow-new "$T/sheetpillow.hxd" 9                      # the new disk round the corner hex
fig op-sheetpillow-crossed "$T/sheetpillow.hxd" 0                  # the x=0 layer, 2 hexes more
fig op-columncollapse-before "$T/g3.hxd" 5                         # the y=1 layer holding the chord
fig op-columncollapse-after "$T/columncollapse.hxd" 5              # ... without it
fig op-sheetdice-before "$T/g3.hxd" 7                              # the z=1 layer crossing the diced sheet
fig op-sheetdice-after "$T/sheetdice.hxd" 7                        # ... one more chord across it
node docs/primal-figures.mjs                                   # primal before/after of each operation
rm -rf "$T"
