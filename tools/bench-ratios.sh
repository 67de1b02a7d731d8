#!/usr/bin/env bash
# bench-ratios.sh: the speed figures of docs/performance.md as ratios measured in one run, and
# the UMAT's instruction counts per call, in one table.
#
#   tools/bench-ratios.sh [--no-build] [--quick] [--build-root DIR]
#
# Builds (unless --no-build) two Release configurations under DIR (default ./build):
#   DIR/release  the default Release build (-march=native, LTO): interphase-bench-vumat and
#                interphase-bench;
#   DIR/nolto    the same without LTO (-DINTERPHASE_LTO=OFF), as a host like Abaqus links the
#                static libraries: interphase-bench.
# Then it prints, each figure from one process run (a ratio's two sides measured side by side):
#   - the VUMAT at nblock = 4096 against the plain copy of its arrays (interphase-bench-vumat),
#     simplified and micromechanical model, 2-D and 3-D;
#   - the UMAT (best ns per call, interphase-bench, both builds): micromechanical against
#     simplified, and the fracture-mechanics law (LFM) against the displacement law;
#   - instructions per UMAT call (callgrind, no-LTO build, inclusive cost of umat_ over 6000
#     calls of the mixed history), if valgrind is installed.
# --quick: fewer points and calls (a smoke test of the script, not figures to record).
# Not a test: nothing is checked against a goal here; docs/performance.md records the figures.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
root=$here/build
build=yes
quick=no
while [ $# -gt 0 ]; do
   case "$1" in
      --no-build) build=no ;;
      --quick) quick=yes ;;
      --build-root) root=$2; shift ;;
      -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
      *) echo "bench-ratios.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
   esac
   shift
done
rel=$root/release
nolto=$root/nolto
if [ $build = yes ]; then
   cmake -S "$here" -B "$rel" -DCMAKE_BUILD_TYPE=Release >/dev/null
   cmake --build "$rel" -j2 --target interphase-bench interphase-bench-vumat >/dev/null
   cmake -S "$here" -B "$nolto" -DCMAKE_BUILD_TYPE=Release -DINTERPHASE_LTO=OFF >/dev/null
   cmake --build "$nolto" -j2 --target interphase-bench >/dev/null
fi
for exe in "$rel/tests/threads/interphase-bench-vumat" "$rel/drivers/interphase-bench" "$nolto/drivers/interphase-bench"; do
   if [ ! -x "$exe" ]; then
      echo "bench-ratios.sh: $exe is missing: run without --no-build, or build it" >&2
      exit 2
   fi
done
points=65536
calls=999996
callgrind_calls=6000
if [ $quick = yes ]; then points=8192; calls=60000; callgrind_calls=600; fi
work=$(mktemp -d "${TMPDIR:-/tmp}/interphase-bench-ratios.XXXXXX")
trap 'rm -rf "$work"' EXIT

commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
if ! git -C "$here" diff --quiet HEAD 2>/dev/null; then commit="$commit+changes"; fi
echo "interphase bench-ratios: $(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit, $(uname -n)," \
   "load average $(cut -d' ' -f1-3 /proc/loadavg)"

"$rel/tests/threads/interphase-bench-vumat" "$points" >"$work/vumat.txt"
"$rel/drivers/interphase-bench" "$calls" 5 >"$work/umat-lto.txt"
"$nolto/drivers/interphase-bench" "$calls" 5 >"$work/umat-nolto.txt"

have_valgrind=no
if command -v valgrind >/dev/null 2>&1; then
   have_valgrind=yes
   for c in 1 2 3 4 5 6 7 8; do
      valgrind --tool=callgrind --callgrind-out-file="$work/cg.$c" --toggle-collect=umat_ \
         "$nolto/drivers/interphase-bench" "$callgrind_calls" 1 "$c" >/dev/null 2>"$work/cg.$c.log"
      # the collected events: the totals line of the profile ("summary: Ir")
      awk -v calls=$((callgrind_calls + 1)) '/^summary:/ {printf "%.0f\n", $2/calls}' "$work/cg.$c" >"$work/ir.$c"
   done
fi

echo
echo "VUMAT at nblock = 4096, ns per point, best of 5 each (interphase-bench-vumat $points):"
printf '%-46s %10s %10s %8s\n' "case" "vumat" "copy" "ratio"
awk '/^VUMAT, / {sub(/^VUMAT, /, ""); sub(/, mixed history.*/, ""); title=$0}
     $1 == 4096 {printf "%-46s %10.2f %10.2f %8.2f\n", title, $2, $3, $2/$3}' "$work/vumat.txt"

# best ns per call of row `name`, `history` from interphase-bench output
# (the name is right-aligned in its column: matched anywhere in the line)
umat_ns() { awk -v name="$2" -v hist="$3" 'index($0, name) > 0 && index($0, hist) > 0 {print $(NF-2)}' "$1"; }
echo
echo "UMAT, best ns per call of 5 runs ($calls calls each), and ratios within each build:"
printf '%-34s %10s %10s %12s\n' "case" "LTO" "no LTO" "instr./call"
rows=("simplified + disp.|mixed 2-D" "simplified + disp.|mixed 3-D" "micromech. + disp.|mixed 2-D"
      "micromech. + disp.|mixed 3-D" "simplified + LFM|mixed 2-D" "simplified + LFM|mixed 3-D"
      "micromech. + LFM|mixed 2-D" "micromech. + LFM|mixed 3-D")
declare -A lto nol ir
c=0
for row in "${rows[@]}"; do
   c=$((c + 1))
   name=${row%%|*}
   hist=${row##*|}
   lto[$c]=$(umat_ns "$work/umat-lto.txt" "$name" "$hist")
   nol[$c]=$(umat_ns "$work/umat-nolto.txt" "$name" "$hist")
   ir[$c]=-
   if [ $have_valgrind = yes ]; then ir[$c]=$(cat "$work/ir.$c"); fi
   printf '%-34s %10s %10s %12s\n' "$name ${hist#mixed }" "${lto[$c]}" "${nol[$c]}" "${ir[$c]}"
done
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {if (a == "-" || b == "-" || b + 0 == 0) print "-"; else printf "%.2f", a/b}'; }
echo
printf '%-50s %8s %8s %12s\n' "ratio" "LTO" "no LTO" "instructions"
printf '%-50s %8s %8s %12s\n' "micromechanical / simplified, displacement, 2-D" "$(ratio "${lto[3]}" "${lto[1]}")" \
   "$(ratio "${nol[3]}" "${nol[1]}")" "$(ratio "${ir[3]}" "${ir[1]}")"
printf '%-50s %8s %8s %12s\n' "micromechanical / simplified, displacement, 3-D" "$(ratio "${lto[4]}" "${lto[2]}")" \
   "$(ratio "${nol[4]}" "${nol[2]}")" "$(ratio "${ir[4]}" "${ir[2]}")"
printf '%-50s %8s %8s %12s\n' "LFM / displacement law, simplified 2-D" "$(ratio "${lto[5]}" "${lto[1]}")" \
   "$(ratio "${nol[5]}" "${nol[1]}")" "$(ratio "${ir[5]}" "${ir[1]}")"
printf '%-50s %8s %8s %12s\n' "LFM / displacement law, micromechanical 2-D" "$(ratio "${lto[7]}" "${lto[3]}")" \
   "$(ratio "${nol[7]}" "${nol[3]}")" "$(ratio "${ir[7]}" "${ir[3]}")"
if [ $have_valgrind = no ]; then echo "(valgrind not installed: no instruction counts)"; fi
