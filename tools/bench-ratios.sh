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
#   - instructions per UMAT call (callgrind, inclusive cost of umat_ over 6000 calls of the
#     mixed history) in DIR/callgrind, the no-LTO build for -march=x86-64-v2 (valgrind 3.19 does
#     not decode every AVX instruction a -march=native build may use), if valgrind is installed;
#   - the UMAT in the one-file Abaqus/Standard source (make-user-file.sh) compiled alone with
#     -O3, the inlining flags and no LTO, as docs/abaqus.md recommends, and linked with the
#     benchmark driver (compiled with the flags the CMake Release build gives it, so that the
#     builds are timed by the same loop): best ns per call (-march=native) and instructions per
#     call (callgrind, -march=x86-64-v2);
#   - the benchmark's own cost: the same driver linked with an empty UMAT (the loop, the 37
#     arguments and CMNAME's hidden length, and the call, nothing else), best ns per call;
#   - instructions per VUMAT point (callgrind, nblock = 4096, 4096 points x 140 increments):
#     vumat_ and the plain copy of its arrays, in the one-file Abaqus/Explicit source
#     (examples/abaqus/make-user-file.sh --explicit) compiled as docs/abaqus.md recommends, with
#     -march=x86-64-v3 (AVX2) for valgrind: the build an Abaqus/Explicit host makes;
#   - the UMAT in a host's order (256 points per increment, each with its own state) against one
#     point, the benchmark's own loop subtracted in each (no LTO, 2-D, cases 1, 3 and 7).
# --quick: fewer points and calls (a smoke test of the script, not figures to record).
# KEEP_WORK=1 in the environment keeps the work directory (the one-file builds' logs) on exit.
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
      -h|--help) sed -n '2,/^# Not a test/p' "$0"; exit 0 ;;
      *) echo "bench-ratios.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
   esac
   shift
done
# (absolute: the one-file builds below run in their own directories)
mkdir -p "$root"
root=$(cd "$root" && pwd)
rel=$root/release
nolto=$root/nolto
cgtree=$root/callgrind
if [ $build = yes ]; then
   cmake -S "$here" -B "$rel" -DCMAKE_BUILD_TYPE=Release >/dev/null
   cmake --build "$rel" -j2 --target interphase-bench interphase-bench-vumat >/dev/null
   cmake -S "$here" -B "$nolto" -DCMAKE_BUILD_TYPE=Release -DINTERPHASE_LTO=OFF >/dev/null
   cmake --build "$nolto" -j2 --target interphase-bench >/dev/null
   if command -v valgrind >/dev/null 2>&1; then
      cmake -S "$here" -B "$cgtree" -DCMAKE_BUILD_TYPE=Release -DINTERPHASE_LTO=OFF -DINTERPHASE_ARCH=x86-64-v2 >/dev/null
      cmake --build "$cgtree" -j2 --target interphase-bench >/dev/null
   fi
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
trap '[ -n "${KEEP_WORK:-}" ] || rm -rf "$work"' EXIT
if [ -n "${KEEP_WORK:-}" ]; then echo "bench-ratios.sh: the work directory $work is kept (KEEP_WORK)"; fi

commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
if ! git -C "$here" diff --quiet HEAD 2>/dev/null; then commit="$commit+changes"; fi
echo "interphase bench-ratios: $(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit, $(uname -n)," \
   "load average $(cut -d' ' -f1-3 /proc/loadavg)"

"$rel/tests/threads/interphase-bench-vumat" "$points" >"$work/vumat.txt"
"$rel/drivers/interphase-bench" "$calls" 5 >"$work/umat-lto.txt"
"$nolto/drivers/interphase-bench" "$calls" 5 >"$work/umat-nolto.txt"

# The one-file sources are compiled with the flags docs/abaqus.md recommends for gfortran, the
# CMake Release build's inlining flags (INTERPHASE_INLINE_PARAMS of CMakeLists.txt) included.
onefile_inline="--param=max-inline-insns-auto=400 --param=inline-unit-growth=200 --param=large-function-growth=400"
onefile_inline+=" -fno-ipa-icf"
# the UMAT in the one-file Abaqus/Standard source (make-user-file.sh), compiled ALONE with -O3
# and without LTO as docs/abaqus.md recommends, linked with the benchmark driver: the build an
# Abaqus/Standard host makes. Built twice: -march=native for the wall clock, -march=x86-64-v2
# for callgrind. (Needs the generated table and driver version source of a build tree.) The
# driver is compiled with the CMake Release build's flags for it (without LTO), as in DIR/nolto:
# its loop alone takes 3-4 ns a call more at -O3 than at -O2 (docs/performance.md), so that
# drivers compiled differently would not time the builds alike. With native, also the same
# driver linked with an empty UMAT (bench-umat-empty: standard.o's umat made a weak symbol, which
# the empty one replaces), the benchmark's own cost.
onefile_umat() {
   local arch=$1 dir=$work/standard-$1
   local driver_flags="-O3 -march=$arch -frecursive -ffp-contract=off $onefile_inline"
   mkdir -p "$dir"
   (cd "$dir" && bash "$here/examples/abaqus/make-user-file.sh" --build-dir "$nolto" -o standard.f90 >/dev/null \
      && printf '%s\n' 'subroutine stdb_abqerr(lop, string, intv, realv, charv)' \
         '   integer, intent(in) :: lop, intv(*)' '   character(len=*), intent(in) :: string' \
         '   double precision, intent(in) :: realv(*)' '   character(len=8), intent(in) :: charv(*)' \
         'end subroutine stdb_abqerr' >stub.f90 \
      && gfortran -O3 -march="$arch" -fno-trapping-math -ffp-contract=off -frecursive $onefile_inline \
         -c standard.f90 \
      && gfortran -O2 -fno-inline -c stub.f90 \
      && gfortran $driver_flags -c "$here/drivers/interphase_driver_text.f90" "$nolto/drivers/interphase_driver_version.f90" \
      && gfortran $driver_flags -c "$here/drivers/interphase_driver_cli.f90" \
      && gcc -O2 -c "$here/drivers/interphase_driver_posix.c" \
      && gfortran $driver_flags -c "$here/drivers/bench_umat.f90" \
      && gfortran -o bench-umat-standard bench_umat.o standard.o stub.o interphase_driver_cli.o \
         interphase_driver_posix.o interphase_driver_text.o interphase_driver_version.o -llapack) \
      >"$work/standard-$arch.log" 2>&1 || return 1
   [ "$arch" = native ] || return 0
   (cd "$dir" && printf '%s\n' \
         'subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &' \
         '      time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, nstatv, props, nprops, &' \
         '      coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, layer, kspt, jstep, kinc)' \
         '   implicit none' \
         '   integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc, jstep(4)' \
         '   double precision, intent(inout) :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens), sse, spd' \
         '   double precision, intent(inout) :: scd, rpl, pnewdt, ddsddt(ntens), drplde(ntens), drpldt' \
         '   double precision, intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp' \
         '   double precision, intent(in) :: predef(*), dpred(*), props(nprops), coords(3), drot(3, 3)' \
         '   double precision, intent(in) :: celent, dfgrd0(3, 3), dfgrd1(3, 3)' \
         '   character(len=80), intent(in) :: cmname' \
         'end subroutine umat' >empty_umat.f90 \
      && gfortran -O2 -c empty_umat.f90 \
      && objcopy --weaken-symbol=umat_ standard.o standard-weak.o \
      && gfortran -o bench-umat-empty bench_umat.o empty_umat.o standard-weak.o stub.o interphase_driver_cli.o \
         interphase_driver_posix.o interphase_driver_text.o interphase_driver_version.o -llapack) \
      >>"$work/standard-$arch.log" 2>&1
}
onefile_umat native || true
if [ -x "$work/standard-native/bench-umat-standard" ]; then
   "$work/standard-native/bench-umat-standard" "$calls" 5 >"$work/umat-onefile.txt"
else
   echo "(the one-file Standard benchmark did not build: see below)"; cat "$work/standard-native.log"
   : >"$work/umat-onefile.txt"
fi
if [ -x "$work/standard-native/bench-umat-empty" ]; then
   "$work/standard-native/bench-umat-empty" "$calls" 5 >"$work/umat-empty.txt"
else
   if [ -x "$work/standard-native/bench-umat-standard" ]; then
      echo "(the benchmark with an empty UMAT did not build: see below)"; cat "$work/standard-native.log"
   fi
   : >"$work/umat-empty.txt"
fi

have_valgrind=no
declare -A vir=() cir=()
if command -v valgrind >/dev/null 2>&1 && [ -x "$cgtree/drivers/interphase-bench" ]; then
   have_valgrind=yes
   for c in 1 2 3 4 5 6 7 8; do
      valgrind --tool=callgrind --callgrind-out-file="$work/cg.$c" --toggle-collect=umat_ \
         "$cgtree/drivers/interphase-bench" "$callgrind_calls" 1 "$c" >/dev/null 2>"$work/cg.$c.log"
      # the collected events: the totals line of the profile ("summary: Ir")
      awk -v calls=$((callgrind_calls + 1)) '/^summary:/ {printf "%.0f\n", $2/calls}' "$work/cg.$c" >"$work/ir.$c"
   done
   # the UMAT in the one-file Standard source
   onefile_umat x86-64-v2 || true
   for c in 1 2 3 4 5 6 7 8; do
      echo - >"$work/irf.$c"
      if [ -x "$work/standard-x86-64-v2/bench-umat-standard" ]; then
         valgrind --tool=callgrind --callgrind-out-file="$work/cgf.$c" --toggle-collect=umat_ \
            "$work/standard-x86-64-v2/bench-umat-standard" "$callgrind_calls" 1 "$c" >/dev/null 2>"$work/cgf.$c.log"
         awk -v calls=$((callgrind_calls + 1)) '/^summary:/ {printf "%.0f\n", $2/calls}' "$work/cgf.$c" >"$work/irf.$c"
      fi
   done
   # the VUMAT in the one-file Explicit source (needs the generated table of a build tree)
   (cd "$work" && bash "$here/examples/abaqus/make-user-file.sh" --explicit --build-dir "$cgtree" \
         -o explicit.f90 >/dev/null \
      && printf '%s\n' 'subroutine xplb_abqerr(lop, string, intv, realv, charv)' \
         '   integer, intent(in) :: lop, intv(*)' '   character(len=*), intent(in) :: string' \
         '   double precision, intent(in) :: realv(*)' '   character(len=8), intent(in) :: charv(*)' \
         'end subroutine xplb_abqerr' >stub.f90 \
      && gfortran -O3 -march=x86-64-v3 -fno-trapping-math -ffp-contract=off -frecursive $onefile_inline -c explicit.f90 \
      && gfortran -O2 -fno-inline -c stub.f90 "$here/tests/threads/bench_vumat.f90" \
      && gfortran -o bench-vumat-explicit bench_vumat.o explicit.o stub.o -llapack) >"$work/explicit.log" 2>&1
   if [ -x "$work/bench-vumat-explicit" ]; then
      for c in 1 2 3 4; do
         for what in vumat_ 'plain_copy*'; do
            valgrind --tool=callgrind --callgrind-out-file="$work/cgv" --toggle-collect="$what" \
               "$work/bench-vumat-explicit" 4096 "$c" >/dev/null 2>>"$work/explicit.log"
            n=$(awk '/^summary:/ {printf "%.1f", $2/(4096*140)}' "$work/cgv")
            if [ "$what" = vumat_ ]; then vir[$c]=$n; else cir[$c]=$n; fi
         done
      done
   fi
fi

echo
echo "VUMAT at nblock = 4096, ns per point, best of 5 each (interphase-bench-vumat $points), and"
echo "instructions per point (callgrind, the one-file Explicit source, x86-64-v3):"
printf '%-46s %10s %10s %8s %10s %10s %8s\n' "case" "vumat" "copy" "ratio" "vumat Ir" "copy Ir" "ratio"
awk '/^VUMAT, / {sub(/^VUMAT, /, ""); sub(/, mixed history.*/, ""); title=$0}
     $1 == 4096 {printf "%-46s %10.2f %10.2f %8.2f\n", title, $2, $3, $2/$3}' "$work/vumat.txt" >"$work/vumat-rows.txt"
c=0
while IFS= read -r line; do
   c=$((c + 1))
   vi=${vir[$c]:--}
   ci=${cir[$c]:--}
   r=$(awk -v a="$vi" -v b="$ci" 'BEGIN {if (a == "-" || b == "-" || b + 0 == 0) print "-"; else printf "%.2f", a/b}')
   printf '%s %10s %10s %8s\n' "$line" "$vi" "$ci" "$r"
done <"$work/vumat-rows.txt"

# best ns per call of row `name`, `history` from interphase-bench output
# (the name is right-aligned in its column: matched anywhere in the line)
umat_ns() { awk -v name="$2" -v hist="$3" 'index($0, name) > 0 && index($0, hist) > 0 {print $(NF-2)}' "$1"; }
echo
echo "UMAT, best ns per call of 5 runs ($calls calls each) of the Release build with and without LTO"
echo "and of the one-file Standard source, and instructions per call (callgrind, x86-64-v2: the"
echo "static libraries without LTO, and the one-file source), and ratios within each build:"
printf '%-34s %10s %10s %10s %12s %12s\n' "case" "LTO" "no LTO" "one-file" "instr./call" "one-file"
# (instructions: DIR/callgrind, no LTO, x86-64-v2)
rows=("simplified + disp.|mixed 2-D" "simplified + disp.|mixed 3-D" "micromech. + disp.|mixed 2-D"
      "micromech. + disp.|mixed 3-D" "simplified + LFM|mixed 2-D" "simplified + LFM|mixed 3-D"
      "micromech. + LFM|mixed 2-D" "micromech. + LFM|mixed 3-D")
declare -A lto nol one ir irf
c=0
for row in "${rows[@]}"; do
   c=$((c + 1))
   name=${row%%|*}
   hist=${row##*|}
   lto[$c]=$(umat_ns "$work/umat-lto.txt" "$name" "$hist")
   nol[$c]=$(umat_ns "$work/umat-nolto.txt" "$name" "$hist")
   one[$c]=$(umat_ns "$work/umat-onefile.txt" "$name" "$hist")
   one[$c]=${one[$c]:--}
   ir[$c]=-
   irf[$c]=-
   if [ $have_valgrind = yes ]; then ir[$c]=$(cat "$work/ir.$c"); irf[$c]=$(cat "$work/irf.$c"); fi
   printf '%-34s %10s %10s %10s %12s %12s\n' "$name ${hist#mixed }" "${lto[$c]}" "${nol[$c]}" "${one[$c]}" \
      "${ir[$c]}" "${irf[$c]}"
done
empty2=$(umat_ns "$work/umat-empty.txt" "simplified + disp." "mixed 2-D")
empty3=$(umat_ns "$work/umat-empty.txt" "simplified + disp." "mixed 3-D")
echo "the benchmark's own loop, arguments and call: the same driver with an empty UMAT, best ns per"
echo "call: ${empty2:--} (2-D), ${empty3:--} (3-D); the no-LTO and one-file figures above include it"
echo "(with LTO the UMAT is specialised to the benchmark's constant arguments: no such call)"
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {if (a == "-" || b == "-" || b + 0 == 0) print "-"; else printf "%.2f", a/b}'; }
echo
printf '%-50s %8s %8s %8s %12s %12s\n' "ratio" "LTO" "no LTO" "one-file" "instructions" "one-file"
# one row of ratios: case i over case j in every build and count
ratio_row() {
   printf '%-50s %8s %8s %8s %12s %12s\n' "$1" "$(ratio "${lto[$2]}" "${lto[$3]}")" \
      "$(ratio "${nol[$2]}" "${nol[$3]}")" "$(ratio "${one[$2]}" "${one[$3]}")" \
      "$(ratio "${ir[$2]}" "${ir[$3]}")" "$(ratio "${irf[$2]}" "${irf[$3]}")"
}
ratio_row "micromechanical / simplified, displacement, 2-D" 3 1
ratio_row "micromechanical / simplified, displacement, 3-D" 4 2
ratio_row "LFM / displacement law, simplified 2-D" 5 1
ratio_row "LFM / displacement law, micromechanical 2-D" 7 3

# The UMAT in a host's order: 256 points per increment, each with its own state and its shear
# scaled by 0.5 + p/256 (interphase-bench's POINTS), against one point, both with 640 increments
# per segment (64 with --quick), in the build without LTO; the benchmark's own loop in either order from the driver
# with an empty UMAT; the UMAT's own time is the difference.
host_calls=983040; single_calls=3840; single_runs=300
if [ $quick = yes ]; then host_calls=98304; single_calls=384; single_runs=30; fi
echo
# (the mixed history has 6 segments: a run of N calls replays it with N/6 increments per segment)
echo "UMAT in a host's order (no LTO, 2-D, $((single_calls / 6)) increments per segment): best ns per call of one point"
echo "($single_calls calls, $single_runs runs) and of 256 points per increment (each its own state, its shear scaled"
echo "by 0.5 + p/256; $host_calls calls, 5 runs), less the benchmark's own loop in the same order"
echo "(the driver with an empty UMAT):"
printf '%-34s %10s %10s %10s %10s %8s\n' "case" "1 point" "256 points" "1, net" "256, net" "ratio"
e1=-; e256=-
if [ -x "$work/standard-native/bench-umat-empty" ]; then
   e1=$(umat_ns <("$work/standard-native/bench-umat-empty" "$single_calls" "$single_runs" 1 1) "simplified + disp." "mixed 2-D")
   e256=$(umat_ns <("$work/standard-native/bench-umat-empty" "$host_calls" 5 1 256) "simplified + disp." "mixed 2-D")
fi
for c in 1 3 7; do
   row=${rows[$((c - 1))]}
   name=${row%%|*}
   t1=$(umat_ns <("$nolto/drivers/interphase-bench" "$single_calls" "$single_runs" "$c" 1) "$name" "mixed 2-D")
   t256=$(umat_ns <("$nolto/drivers/interphase-bench" "$host_calls" 5 "$c" 256) "$name" "mixed 2-D")
   n1=$(awk -v a="$t1" -v b="$e1" 'BEGIN {if (b == "-") print "-"; else printf "%.1f", a - b}')
   n256=$(awk -v a="$t256" -v b="$e256" 'BEGIN {if (b == "-") print "-"; else printf "%.1f", a - b}')
   printf '%-34s %10s %10s %10s %10s %8s\n' "$name 2-D" "$t1" "$t256" "$n1" "$n256" "$(ratio "$n256" "$n1")"
done
echo "the benchmark's own loop with an empty UMAT: $e1 ns (1 point), $e256 ns (256 points)"
if [ $have_valgrind = no ]; then echo "(valgrind not installed, or no DIR/callgrind build: no instruction counts)"; fi
if [ $have_valgrind = yes ] && [ ${#vir[@]} -eq 0 ]; then
   echo "(the one-file Explicit benchmark did not build: see below)"; cat "$work/explicit.log"
fi
