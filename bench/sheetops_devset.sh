#!/usr/bin/env bash
# Sheet extraction over the development set (../shared/meshes, or $HEXDUAL_MESHES): every sheet of
# every mesh that opens is extracted or refused (counted by rule), checked (validate, H - |sheet|,
# one sheet fewer, the tracked dual against a fresh extraction), undone (canonical hash), and
# inserted back with its inverse where there is one (isomorphic to the start). A markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."
MESHES=${HEXDUAL_MESHES:-../shared/meshes}
BENCH=${HEXDUAL_BENCH:-build/native/hexdual_bench}
[ -d "$MESHES" ] || { echo "no development-set meshes at $MESHES" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "| mesh | hexes | sheets | extracted | refused, by rule | inverse reported / applied and isomorphic | checks failed | CPU ms per extraction (mean / max) | dual update ms (mean) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for gz in "$MESHES"/*.gz; do
  name=$(basename "$gz" .gz)
  gzip -dc "$gz" > "$tmp/$name"
  if ! out=$("$BENCH" sheets-devset "$tmp/$name" 2> "$tmp/err"); then
    if [ -z "$out" ]; then
      echo "| $name | | | refused by the reader: $(head -1 "$tmp/err" | sed "s|$tmp/||; s/|/\\\\|/g") | | | | | |"
      rm -f "$tmp/$name"
      continue
    fi
  fi
  node -e '
    const r = JSON.parse(process.argv[1]);
    const applied = r.rules.applied ?? 0;
    const refused = Object.entries(r.rules).filter(([k]) => k !== "applied").map(([k, v]) => `${k} ${v}`).join(", ") || "none";
    const mean = applied ? (r.opMsTotal / applied).toFixed(2) : "-";
    const dual = applied ? (r.dualMsTotal / applied).toFixed(2) : "-";
    console.log(`| ${process.argv[2]} | ${r.hexes} | ${r.sheets} | ${applied} | ${refused} | ${r.inverses} / ${r.isomorphicBack} | ${r.checksFailed} | ${mean} / ${r.opMsMax.toFixed(2)} | ${dual} |`);
  ' "$out" "$name"
  rm -f "$tmp/$name"
done
