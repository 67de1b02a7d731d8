#!/usr/bin/env bash
# griffith.sh TABLE -- a short crack in a homogeneous RVE must behave as a Griffith crack in an
# infinite plane-strain body: elliptical jump, so (E' = E/(1-nu^2), M constrained modulus)
#   Dbar_NN = pi M a / E',  Dbar_TT = pi G a / E',  ufbar = pi/4,  T^f = -E'/(4a).
# Independent of the identities (which any mesh satisfies): this checks the FE accuracy and the
# scaling conventions.  Tolerance TOL_GRIFFITH (relative) covers the discretisation error of the
# test mesh (0.2-0.6 % measured with params/griffith.params; 4 % on a 5x coarser tip mesh) and the finite-size effect of the layers (~(a/h)^2 ~ 4e-4).
set -u
TOL_GRIFFITH=0.01
table=$1
[ -r "$table" ] || { echo "griffith.sh: cannot read $table" >&2; exit 3; }
awk -v tol="$TOL_GRIFFITH" '
function abs(x) { return x < 0 ? -x : x }
/^# E_m = / { E = $4 } /^# nu_m = / { nu = $4 } /^# E_b = / { Eb = $4 } /^# nu_b = / { nub = $4 } /^# b = / { b = $4 }
/^#/ || NF == 0 { next }
$1 > 0 && $1 < b {
  if (E != Eb || nu != nub) { print "griffith.sh: the table is not homogeneous"; exit 3 }
  pi = 3.14159265358979; Ep = E / (1 - nu^2); G = E / (2 * (1 + nu)); M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); a = $1
  r[1] = $10 / (pi * M * a / Ep); r[2] = $7 / (pi * G * a / Ep); r[3] = $23 / (pi / 4); r[4] = $21 / (-Ep / (4 * a))
  split("Dbar_NN Dbar_TT ufbar Tf", nm, " ")
  for (i = 1; i <= 4; i++) { ok = abs(r[i] - 1) <= tol; printf "a = %-8g %-8s FE / Griffith = %.6f  %s\n", a, nm[i], r[i], ok ? "ok" : "FAIL"; if (!ok) bad = 1 }
  n++
}
END { if (n == 0) { print "no crack rows"; exit 1 } exit bad }' "$table"
