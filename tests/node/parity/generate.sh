#!/usr/bin/env bash
# Writes logs.txt: operation logs from the property test's random-sequence generator (fixed seeds
# 20261122.., printed by HEXDUAL_PROPERTY_TRACE), one line per sequence with at least one applied
# step: "START<TAB>LOG". START is the mesh the property test uses for that seed.
set -euo pipefail
cd "$(dirname "$0")"
root=../../..
HEXDUAL_PROPERTY_SEQUENCES=${SEQUENCES:-750} HEXDUAL_PROPERTY_TRACE=1 \
  "$root/build/native/hexdual_tests" --test-case='property*' 2>trace.tmp >/dev/null
node -e '
const meshes = ["grid 3x3x3", "grid 4x4x4", "ring 8x3x3", "grid 2x2x2", "grid 4x3x3"];
const logs = new Map();
for (const line of require("fs").readFileSync("trace.tmp", "utf8").split("\n")) {
  const m = line.match(/^seed (\d+) step \d+: (.*) -> /);
  if (!m) continue;
  if (!logs.has(m[1])) logs.set(m[1], []);
  logs.get(m[1]).push(m[2]);
}
const out = [...logs].map(([seed, steps]) => `${meshes[(Number(seed) - 20261122) % 5]}\t${seed}\tv1;${steps.join(";")}`);
require("fs").writeFileSync("logs.txt", out.join("\n") + "\n");
console.log(`${out.length} logs`);
'
rm trace.tmp
