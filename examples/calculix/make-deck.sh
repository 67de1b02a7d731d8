#!/bin/bash
# make-deck.sh: write a CalculiX deck of the masonry couplet shear test of interphase-fe2d
# (drivers/fe2d/cases/couplet-*.nml: the same bricks, joint law and loads), with the bed joint as a
# thin continuum layer whose material is interphase's UMAT (docs/calculix.md).
#
#   examples/calculix/make-deck.sh --dim 2|3 --model simplified|micromechanical --history FILE
#                                  [--thickness T] [--mu MU] [--precompression P] [--nx N] [--ny N]
#                                  [--nz N] [--increments N] [--replay-element K] -o DECK.inp
#
#   --dim 2          CPE4 (plane strain, 100 mm thick); 3: C3D8, 100 mm deep in z with the
#                    out-of-plane displacement held (plane strain, as interphase-fe2d), nz elements
#   --model          simplified: the paper's section 3.4 with Table 1 (couplet-simplified-*);
#                    micromechanical: the built-in RVE table with the contact band chi = 0.6 and
#                    the viscosity eta = 0.001 s (couplet-micro-viscous-*)
#   --history FILE   two columns t u_shear (mm), '#' comments: drivers/fe2d/cases/*.txt
#   --thickness T    the joint layer's thickness t (mm), default 0.1; the bricks stay 50 mm high
#   --mu MU          the joint's friction coefficient, PROPS(3) (default 0.75, as the fe2d cases)
#   --precompression P  the pressure on the top face in step 1 (MPa, default 0.5; 0 for none)
#   --nx, --ny, --nz elements per brick along x (16), y (4) and z (3-D only, 2)
#   --increments N   nominal increments per history segment (default 20)
#   --tolerance R    Newton's residual tolerance, relative to the mean force (default 1e-5; ccx's
#                    own default is 5e-3, too loose for a comparison at 1e-3)
#   --replay-element K  also print strains, stresses and STATEV of joint element K (default 8,
#                    mid-joint) at every increment, for the single-point replay
#
# Bricks 200 x 50 mm, E = 16000 MPa, nu = 0.15; P = 0.5 MPa precompression on the top face (step 1),
# then the top face's horizontal displacement follows the history (steps 2, 3, ...: one for each
# run of segments in one direction and of one duration, a new step at each reversal) while it is
# free vertically; the bottom face is fixed. The joint material's constants are interphase's PROPS
# (docs/abaqus.md) with the options: stiffness 2 (CalculiX assembles a symmetric stiffness), layer
# thickness t, normal axis 2, host 1 (CalculiX: SSE and SPD are not kept).
set -euo pipefail

dim=""
model=""
history=""
t=0.1
mu=0.75
precompression=0.5
nx=16
ny=4
nz=2
increments=20
tolerance=1e-5
replay=8
output=""
while [ $# -gt 0 ]; do
   case "$1" in
      --dim) dim=$2; shift ;;
      --model) model=$2; shift ;;
      --history) history=$2; shift ;;
      --thickness) t=$2; shift ;;
      --mu) mu=$2; shift ;;
      --precompression) precompression=$2; shift ;;
      --nx) nx=$2; shift ;;
      --ny) ny=$2; shift ;;
      --nz) nz=$2; shift ;;
      --increments) increments=$2; shift ;;
      --tolerance) tolerance=$2; shift ;;
      --replay-element) replay=$2; shift ;;
      -o) output=$2; shift ;;
      -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;;
      *) echo "make-deck.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
   esac
   shift
done
fail() { echo "make-deck.sh: $*" >&2; exit 2; }
case "$dim" in 2|3) ;; *) fail "--dim must be 2 or 3" ;; esac
case "$model" in simplified|micromechanical) ;; *) fail "--model must be simplified or micromechanical" ;; esac
[ -n "$output" ] || fail "no output deck (-o DECK.inp)"
[ -f "$history" ] || fail "history file '$history' not found"
for v in nx ny nz increments replay; do
   [[ ${!v} =~ ^[1-9][0-9]*$ ]] || fail "--$v must be a positive integer, got '${!v}'"
done
# an option's value: an unsigned number (digits, a decimal point, an exponent), written into the
# deck as it is given
unsigned_number() { [[ $2 =~ ^[0-9]+([.][0-9]*)?([eE][-+]?[0-9]+)?$ ]] || fail "--$1 must be $3, got '$2'"; }
unsigned_number tolerance "$tolerance" "a positive number"
unsigned_number thickness "$t" "a positive number"
# (interphase checks mu's range when ccx calls it; the end force of a shear test is
# mu x P x 200 mm x 100 mm)
unsigned_number mu "$mu" "a number >= 0 (digits, a decimal point, an exponent; no sign)"
unsigned_number precompression "$precompression" \
   "a pressure >= 0 in MPa (digits, a decimal point, an exponent; no sign)"
[ "$replay" -le "$nx" ] || fail "--replay-element $replay: the joint has $nx elements (x 1 in 3-D: the first row)"

# The joint's constants: the law's PROPS, then the option constants nb + 1 ... nb + 7 (growth slip,
# contact band, viscosity, stiffness, layer thickness, normal axis, host)
if [ "$model" = simplified ]; then
   # model 1, displacement law 1, mu, s0_N, sf_N, s0_T, sf_T (Table 1), K_N, K_T (docs/abaqus.md)
   law="1., 1., $mu, 0.00044, 0.04, 0.00072, 0.06, 482.69742679680568, 198.75776397515528"
   options="0., 0., 0., 2., $t, 2., 1."
   nstatv=4
else
   # model 2, displacement law 1, mu, Table 1, built-in table 0
   law="2., 1., $mu, 0.00044, 0.04, 0.00072, 0.06, 0."
   options="0., 0.6, 0.001, 2., $t, 2., 1."
   nstatv=5
fi

awk -v dim="$dim" -v model="$model" -v t="$t" -v nx="$nx" -v ny="$ny" -v nz="$nz" -v ninc="$increments" \
    -v replay="$replay" -v tol="$tolerance" -v law="$law" -v pressure="$precompression" -v options="$options" -v nstatv="$nstatv" -v hist="$history" '
function node(i, j, k) { return k*nrow*ncol + j*ncol + i + 1 }
# what run-case.sh reads: the total reaction of the top face, the displacement of its reference node,
# the internal energy of the joint, and the strains, stresses and STATEV of the replay element
function outputs() {
   print "*NODE PRINT, NSET=TOP, TOTALS=ONLY"
   print "RF"
   print "*NODE PRINT, NSET=TOPREF"
   print "U"
   print "*EL PRINT, ELSET=JOINT, TOTALS=ONLY"
   print "ELSE"
   print "*EL PRINT, ELSET=REPLAY"
   print "E, S, SDV"
   print "*END STEP"
}
# Newton tolerances: the residual force below R times the mean force (ccx default 0.005; the
# same R after the I_P-th iteration, where ccx would accept 0.02) and the correction below 10 R
# times the largest increment; with the symmetric fixed-damage stiffness Newton converges
# linearly, so up to 200 iterations an increment before ccx gives up on it
function controls() {
   print "*CONTROLS, PARAMETERS=FIELD"
   printf "%.3g, %.3g, 0., 0., %.3g, 1.e-5, 1.e-3, 1.e-8\n", tol, 10*tol, tol
   print "*CONTROLS, PARAMETERS=TIME INCREMENTATION"
   print "4, 200, 9, 200, 10, 400, 0, 5"
}
BEGIN {
   L = 200.0; H = 50.0; W = 100.0
   ncol = nx + 1
   nrow = 2*ny + 2            # node rows: lower brick, the layer, upper brick
   nk = (dim == 3) ? nz + 1 : 1
   # the history
   nh = 0
   while ((getline line < hist) > 0) {
      sub(/#.*/, "", line)
      if (split(line, f, " ") < 2) continue
      nh++; ht[nh] = f[1] + 0; hu[nh] = f[2] + 0
   }
   if (nh < 2) { print "make-deck.sh: history " hist " has fewer than two rows" > "/dev/stderr"; exit 2 }
   for (h = 2; h <= nh; h++) if (!(ht[h] > ht[h - 1])) {
      print "make-deck.sh: history " hist ": time does not increase at row " h > "/dev/stderr"; exit 2 }

   printf "** interphase: couplet shear test, %d-D, %s model, joint layer t = %s mm\n", dim, model, t
   printf "** Generated by examples/calculix/make-deck.sh from %s (docs/calculix.md)\n", hist
   print "*HEADING"
   printf "interphase couplet shear test, %d-D, %s, t = %s mm\n", dim, model, t
   print "*NODE, NSET=NALL"
   for (k = 0; k < nk; k++) for (j = 0; j < nrow; j++) for (i = 0; i < ncol; i++) {
      x = L*i/nx
      if (j <= ny) y = H*j/ny; else y = H + t + H*(j - ny - 1)/ny
      z = W*k/nz
      if (dim == 3) printf "%d, %.10g, %.10g, %.10g\n", node(i, j, k), x, y, z
      else printf "%d, %.10g, %.10g\n", node(i, j, 0), x, y
   }
   # elements: row r of nrow - 1; row ny is the joint layer
   ne = 0
   for (pass = 1; pass <= 2; pass++) {
      if (pass == 1) printf "*ELEMENT, TYPE=%s, ELSET=JOINT\n", (dim == 3) ? "C3D8" : "CPE4"
      else printf "*ELEMENT, TYPE=%s, ELSET=BRICKS\n", (dim == 3) ? "C3D8" : "CPE4"
      for (k = 0; k < nk - (dim == 3); k++) for (r = 0; r < nrow - 1; r++) for (i = 0; i < nx; i++) {
         if ((pass == 1) != (r == ny)) continue
         ne++
         id[i, r, k] = ne
         if (dim == 3)
            printf "%d, %d, %d, %d, %d, %d, %d, %d, %d\n", ne, node(i, r, k), node(i + 1, r, k), node(i + 1, r + 1, k), \
               node(i, r + 1, k), node(i, r, k + 1), node(i + 1, r, k + 1), node(i + 1, r + 1, k + 1), node(i, r + 1, k + 1)
         else
            printf "%d, %d, %d, %d, %d\n", ne, node(i, r, 0), node(i + 1, r, 0), node(i + 1, r + 1, 0), node(i, r + 1, 0)
      }
   }
   print "*ELSET, ELSET=REPLAY"
   printf "%d\n", id[replay - 1, ny, 0]
   print "*ELSET, ELSET=TOPEL"
   for (k = 0; k < nk - (dim == 3); k++) for (i = 0; i < nx; i++) printf "%d\n", id[i, nrow - 2, k]
   print "*NSET, NSET=BOTTOM"
   for (k = 0; k < nk; k++) for (i = 0; i < ncol; i++) printf "%d\n", node(i, 0, k)
   print "*NSET, NSET=TOP"
   for (k = 0; k < nk; k++) for (i = 0; i < ncol; i++) printf "%d\n", node(i, nrow - 1, k)
   print "*NSET, NSET=TOPREF"
   printf "%d\n", node(0, nrow - 1, 0)

   print "*MATERIAL, NAME=BRICK"
   print "*ELASTIC"
   print "16000., 0.15"
   # the deck is upper-cased: library libINTERPHASE.so, function UMAT, this material JOINT
   print "*MATERIAL, NAME=@ABAQUS_INTERPHASE_UMAT@JOINT"
   nc = split(law ", " options, c, /, */)
   printf "*USER MATERIAL, CONSTANTS=%d\n", nc
   # eight values a line; the temperature (0) follows the last constant
   c[nc + 1] = "0."
   for (m = 1; m <= nc + 1; m++) printf "%s%s", c[m], (m % 8 == 0 || m == nc + 1) ? "\n" : ", "
   print "*DEPVAR"
   print nstatv
   if (dim == 3) {
      print "*SOLID SECTION, ELSET=BRICKS, MATERIAL=BRICK"
      print "*SOLID SECTION, ELSET=JOINT, MATERIAL=@ABAQUS_INTERPHASE_UMAT@JOINT"
   } else {
      print "*SOLID SECTION, ELSET=BRICKS, MATERIAL=BRICK"
      print W "."
      print "*SOLID SECTION, ELSET=JOINT, MATERIAL=@ABAQUS_INTERPHASE_UMAT@JOINT"
      print W "."
   }
   print "*BOUNDARY"
   print "BOTTOM, 1, " ((dim == 3) ? 3 : 2) ", 0."
   if (dim == 3) print "NALL, 3, 3, 0."
   print "*AMPLITUDE, NAME=SHEAR, TIME=TOTAL TIME"
   printf "0., 0.\n"
   for (h = 1; h <= nh; h++) printf "%.10g, %.10g\n", 1.0 + ht[h] - ht[1], hu[h]

   # step 1: the precompression, the top face held horizontally
   print "*STEP, INC=100000"
   controls()
   print "*STATIC"
   print "1., 1., 1.e-6, 1."
   print "*BOUNDARY"
   print "TOP, 1, 1, 0."
   print "*DLOAD"
   printf "TOPEL, P%d, %s\n", (dim == 3) ? 5 : 3, pressure
   outputs()
   # steps 2, 3, ...: the shear history, one step per run of segments that load in the same
   # direction over the same duration (the fine and the coarse segment of a monotonic history:
   # one step), a new step at every reversal, so that every increment sequence ends on the
   # reversals as interphase-fe2d does, with the same increment (the duration of a segment / N)
   # throughout. Not one step per segment: ccx solves the first iteration of the first increment
   # of a step linearly (nonlingeo.c, "first iteration in first increment: elastic tangent"), and
   # on a crack near D = 1 under precompression that iteration opened every joint point by about
   # 8 um, whatever the increment, so that cut-backs could not help (docs/calculix.md, When ccx
   # cuts back at the start of a step). The amplitude runs in total time (the precompression step
   # takes 0 to 1).
   h = 2
   while (h <= nh) {
      seg = ht[h] - ht[h - 1]
      dir = (hu[h] > hu[h - 1]) - (hu[h] < hu[h - 1])
      last = h
      while (last < nh && dir != 0) {
         next_seg = ht[last + 1] - ht[last]
         next_dir = (hu[last + 1] > hu[last]) - (hu[last + 1] < hu[last])
         if (next_dir != dir || next_seg < seg*(1 - 1.0e-12) || next_seg > seg*(1 + 1.0e-12)) break
         last++
      }
      dt = seg/ninc
      span = ht[last] - ht[h - 1]
      if (last == h)
         printf "** shear segment %d: t = %.10g to %.10g, u = %.10g to %.10g mm\n", h - 1, ht[h - 1], ht[h], hu[h - 1], hu[h]
      else
         printf "** shear segments %d to %d (one direction, one duration): t = %.10g to %.10g, u = %.10g to %.10g mm\n", \
            h - 1, last - 1, ht[h - 1], ht[last], hu[h - 1], hu[last]
      print "*STEP, INC=100000"
      controls()
      print "*STATIC"
      printf "%.10g, %.10g, %.10g, %.10g\n", dt, span, span*1.0e-6, dt
      print "*BOUNDARY, AMPLITUDE=SHEAR"
      print "TOP, 1, 1, 1."
      outputs()
      h = last + 1
   }
}' > "$output"
[ -s "$output" ] || fail "writing $output failed"
echo "make-deck.sh: wrote $output"
