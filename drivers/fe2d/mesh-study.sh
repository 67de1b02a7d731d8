#!/usr/bin/env bash
# Mesh-convergence study of interphase-fe2d: the couplet case with the simplified model at
# mesh levels nx x ny = 4x1, 8x2, 16x4, 32x8 (and 64x16 with --fine) elements per brick;
# prints the peak shear force, its change from the previous level and the final force.
#   drivers/fe2d/mesh-study.sh [--build-dir DIR] [--case CASE.nml] [--fine]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$here/../../build"
case_file="$here/cases/couplet-simplified-monotonic.nml"
levels="4:1 8:2 16:4 32:8"
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --case) case_file="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    --fine) levels="$levels 64:16"; shift ;;
    *) echo "usage: $0 [--build-dir DIR] [--case CASE.nml] [--fine]" >&2; exit 2 ;;
  esac
done
exe="$build/drivers/fe2d/interphase-fe2d"
[ -x "$exe" ] || { echo "no $exe: build first (cmake --build $build --target interphase-fe2d)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
case_dir="$(dirname "$case_file")"
printf '%-8s %-14s %-12s %-14s\n' "mesh" "peak (N)" "change (N)" "final (N)"
previous=""
for level in $levels; do
  nx="${level%%:*}"; ny="${level##*:}"
  # nx, ny and output wherever they stand (one entry a line or several, any case; comments
  # after '!' untouched), then nx, ny given right after '&mesh' (an empty '&mesh /' too)
  sed -E -e ':c' -e 's/^([^!]*)\b(nx|ny)[[:space:]]*=[[:space:]]*[0-9]+[[:space:]]*,?/\1/I' -e 't c' \
      -e 's/^([^!]*)\boutput[[:space:]]*=[[:space:]]*(\x27[^\x27]*\x27|"[^"]*")[[:space:]]*,?/\1/I' \
      -e "s/^([^!]*)&mesh\b/\1\&mesh nx = $nx, ny = $ny,/I" \
      -e "s#history = '([^']*)'#history = '$case_dir/\1'#" \
      "$case_file" > "$work/case.nml"
  "$exe" "$work/case.nml" --no-plot --output-dir "$work/out" > "$work/stdout"
  # the mesh that ran, from the log's header: a study of one mesh repeated is no study
  if ! head -n 1 "$work/out/case.log" | grep -q " $nx x $ny elements per brick"; then
    echo "mesh-study.sh: $case_file: the run did not use ${nx} x ${ny} elements per brick" \
      "($(head -n 1 "$work/out/case.log")); the &mesh group could not be rewritten" >&2
    exit 1
  fi
  peak=$(awk -F, 'NR > 1 { v = $4 < 0 ? -$4 : $4; if (v > m) m = v } END { printf "%.2f", m }' "$work/out/case.csv")
  final=$(awk -F, 'END { printf "%.2f", $4 }' "$work/out/case.csv")
  change=""
  [ -n "$previous" ] && change=$(awk -v a="$peak" -v b="$previous" 'BEGIN { printf "%.2f", a - b }')
  printf '%-8s %-14s %-12s %-14s\n' "${nx}x${ny}" "$peak" "$change" "$final"
  previous="$peak"
done
