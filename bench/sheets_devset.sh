#!/usr/bin/env bash
# `hexdual sheets --all` over the development set (../shared/meshes, or $HEXDUAL_MESHES): wall and
# CPU time, peak RSS, sheets and layout methods per mesh, as a markdown table. Each mesh is
# gunzipped into a temporary directory first; meshes the readers refuse are listed with the reason.
set -euo pipefail
cd "$(dirname "$0")/.."
MESHES=${HEXDUAL_MESHES:-../shared/meshes}
HEXDUAL=${HEXDUAL:-build/native/hexdual}
[ -d "$MESHES" ] || { echo "no development-set meshes at $MESHES" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "| mesh | hexes | sheets | methods | wall s | CPU s (user+sys) | CPU s per 10k hexes | peak RSS MB |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for gz in "$MESHES"/*.gz; do
  name=$(basename "$gz" .gz)
  gzip -dc "$gz" > "$tmp/$name"
  out="$tmp/out-$name"
  mkdir -p "$out"
  if ! /usr/bin/time -v "$HEXDUAL" sheets "$tmp/$name" --all --json "$out" > /dev/null 2> "$tmp/time"; then
    echo "| $name | | | refused: $(grep -v '^\s' "$tmp/time" | head -1 | sed "s|$tmp/||; s/|/\\\\|/g") | | | | |"
    continue
  fi
  hexes=$("$HEXDUAL" info "$tmp/$name" | awk '$1 == "hexes" { print $2 }')
  sheets=$(ls "$out" | wc -l)
  methods=$(cat "$out"/*.json | grep -o '"method":"[a-z]*"' | sort | uniq -c | awk '{ sub(/"method":"/, "", $2); sub(/"/, "", $2); printf "%s%s %d", (n++ ? ", " : ""), $2, $1 }')
  awk -v name="$name" -v hexes="$hexes" -v sheets="$sheets" -v methods="$methods" '
    /Elapsed \(wall clock\)/ { n = split($NF, p, ":"); wall = (n == 3 ? p[1] * 3600 + p[2] * 60 + p[3] : p[1] * 60 + p[2]) }
    /User time/ { user = $NF } /System time/ { sys = $NF } /Maximum resident/ { rss = $NF / 1024 }
    END { cpu = user + sys; printf "| %s | %d | %d | %s | %.2f | %.2f | %.2f | %.1f |\n", name, hexes, sheets, methods, wall, cpu, cpu / hexes * 1e4, rss }
  ' "$tmp/time"
  rm -rf "$out" "$tmp/$name"
done
