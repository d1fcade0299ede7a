#!/usr/bin/env bash
# Regenerates the sheet-diagram figures of docs/sheet-diagrams.md (needs the native build and
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
$H apply "$T/g5.hxd" --ops 'v1;chordpush h62e11 h62f1 h67f1' -o "$T/chordpush.hxd" >/dev/null
$H apply "$T/g5.hxd" --ops 'v1;hexpush h62f5' -o "$T/hexpush.hxd" >/dev/null
$H flip 1-7 --at 62 "$T/g5.hxd" -o "$T/flip17.hxd" >/dev/null
fig grid-sheet "$T/g3.hxd" 0                                   # Fig. 1: a sheet of a 3x3x3 grid
fig ring-annulus "$T/ring.hxd" 0                               # an annulus sheet of an O-grid
fig pillow-sphere "$T/pillow.hxd" 9                            # Fig. 6: the new sphere sheet
fig pillow-crossed "$T/pillow.hxd" 5 --local 27,28 --rings 1    # Fig. 6: a sheet the pillow crosses
fig chordpush-pushed "$T/chordpush.hxd" 12 --local 125,126 --rings 1   # Fig. 2: two pushed sheets now meet
fig chordpush-blind "$T/chordpush.hxd" 8 --local 125,126 --rings 1     # Fig. 2: the blind chord on e's sheet
fig hexpush-sheet "$T/hexpush.hxd" 12 --local 125,126,127,128 --rings 1  # Fig. 4: the new closed chord of 4
fig flip17-sphere "$T/flip17.hxd" 15                           # Fig. 8: the traditional pillow's sphere
fig torus-polygon docs/examples/torus-shell.hxd 0              # a torus sheet cut open: a b a^-1 b^-1
fig klein-polygon docs/examples/klein-shell.hxd 0              # a Klein-bottle sheet: three seams, two twisted
fig mobius-polygon docs/examples/twisted-ring.hxd 0            # a Moebius-band sheet: a boundary a boundary
rm -rf "$T"
