#!/usr/bin/env bash
# Mesh-convergence study of interphase-fe2d: the couplet case with the simplified model at
# mesh levels nx x ny = 4x1, 8x2, 16x4, 32x8 (and 64x16 with --fine) elements per brick;
# prints the peak shear force, its change from the previous level and the final force.
#   drivers/fe2d/mesh-study.sh [--build-dir DIR] [--case CASE.nml] [--fine]
# --build-dir DIR  the build tree (default: build/release, the README's)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "$here/../.." && pwd)/build/release"   # the README's build tree
case_file="$here/cases/couplet-simplified-monotonic.nml"
levels="4:1 8:2 16:4 32:8"
usage="usage: $0 [--build-dir DIR] [--case CASE.nml] [--fine] | --help
  --build-dir DIR  the build tree holding drivers/fe2d/interphase-fe2d (default: build/release)"
die() { echo "mesh-study.sh: error: $*" >&2; exit 2; }
given=" "
while [ $# -gt 0 ]; do
  # (an option given twice: which one counts is not guessed)
  case "$given" in *" $1 "*) die "$1 given twice" ;; esac
  case "$1" in
    --build-dir|--case) [ $# -ge 2 ] && [ -n "$2" ] || die "$1 needs a value"; given="$given$1 " ;;
    --fine) given="$given$1 " ;;
  esac
  case "$1" in
    -h|--help) echo "$usage"; exit 0 ;;
    --build-dir) build="$2"; shift 2 ;;
    --case)
      [ -f "$2" ] && [ -r "$2" ] || die "--case $2: cannot read the case file (no such file, or not a readable file)"
      case_file="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    --fine) levels="$levels 64:16"; shift ;;
    *) echo "mesh-study.sh: error: unknown argument '$1'" >&2; echo "$usage" >&2; exit 2 ;;
  esac
done
exe="$build/drivers/fe2d/interphase-fe2d"
[ -x "$exe" ] || { echo "mesh-study.sh: error: no $exe: build first (cmake -S $(cd "$here/../.." && pwd) -B $build -DCMAKE_BUILD_TYPE=Release && cmake --build $build -j2 --target interphase-fe2d), or name a build tree with --build-dir" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
case_dir="$(dirname "$case_file")"
# the case runs from $work: its relative paths (history, and &joint's table and rcurve_file), in
# either quotes and with any blanks around '=', are made absolute in the case's folder (absolute
# ones are kept); the folder written as sed's replacement ('\', '&', '#' escaped) inside a
# namelist string (its quote doubled)
dir_sq=$(printf '%s' "$case_dir" | sed -e "s/'/''/g" -e 's/[\\&#]/\\&/g')
dir_dq=$(printf '%s' "$case_dir" | sed -e 's/"/""/g' -e 's/[\\&#]/\\&/g')
printf '%-8s %-14s %-12s %-14s\n' "mesh" "peak (N)" "change (N)" "final (N)"
previous=""
for level in $levels; do
  nx="${level%%:*}"; ny="${level##*:}"
  # nx, ny and output wherever they stand (one entry a line or several, any case; comments
  # after '!' untouched), then nx, ny given right after '&mesh' (an empty '&mesh /' too)
  sed -E -e ':c' -e 's/^([^!]*)\b(nx|ny)[[:space:]]*=[[:space:]]*[0-9]+[[:space:]]*,?/\1/I' -e 't c' \
      -e 's/^([^!]*)\boutput[[:space:]]*=[[:space:]]*(\x27[^\x27]*\x27|"[^"]*")[[:space:]]*,?/\1/I' \
      -e "s/^([^!]*)&mesh\b/\1\&mesh nx = $nx, ny = $ny,/I" \
      -e "s#\\b(history|table|rcurve_file)([[:space:]]*=[[:space:]]*)'([^'/][^']*)'#\\1\\2'$dir_sq/\\3'#Ig" \
      -e "s#\\b(history|table|rcurve_file)([[:space:]]*=[[:space:]]*)\"([^\"/][^\"]*)\"#\\1\\2\"$dir_dq/\\3\"#Ig" \
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
