#!/usr/bin/env bash
# check-table.sh -- verify an RVE coefficient table against the exact identities of
# docs/rve.md ('Exact identities').
#
#   bash rve_freefem/check-table.sh TABLE.dat [TABLE-diag.txt]
#   bash rve_freefem/check-table.sh --help      (this text)
#
# What the reader refuses is named with the file and its line: 'mybrick.dat:47: column 3 (C_TT)
# is not a finite number: 12,5'; the reading stops there, as the loader's does.
# Checks (each prints its largest residual; any failure gives exit code 1):
#   format     (a note, not a failure, where the header's n_a is not the number of rows; a
#              warning, not a failure, where the rows are sparser near a = b than docs/rve.md
#              recommends: the shortest ligament (b - a)/b above 1e-4, or fewer than 3 rows per
#              decade of the ligament below 0.1 b)
#              the table read as the loader reads it (rve_freefem/table-reader.awk, the reader
#              of every rve_freefem tool): every header line '# key = value', a key the loader
#              reads given once, its numbers in range (b, h, the layers' E and h positive, nu in
#              (-1, 0.5), h = h_m + h_b), one '# columns:' line (the 23 columns of format 1, or
#              those and I_fNT, format 2, by name in any order), that many finite numbers per
#              row, at least 4 rows (the loader's not-a-knot spline), a strictly ascending from 0
#              to b; a carriage return ending a line is dropped (CRLF files), a number is
#              [sign](digits[.[digits]] | .digits)[(e|E|d|D)[sign]digits] (a Fortran d exponent
#              too) within the range of a double (1e400 is refused); and the provenance keys
#              make-table.sh writes. (The loader's check of the spline between the rows is not
#              made here: loading the table makes it, e.g. interphase-point with table = '...'.)
#   closed     a = 0: C_TT, C_NN = closed forms (Chat), cross terms 0            tol TOL_CLOSED
#   eq52       C(a) + C^c(a) = C(0) for every a (all four components)          tol TOL_EQ52
#   crack      T^c_T = Chat_TT, S^c_N = Chat_NN at every a (crack means)      tol TOL_EXACT
#   symmetry   C_TN, C_NT, Dbar_TN, Dbar_NT, T^c_N, S^c_T, C^f_N, S^f = 0      tol TOL_EXACT
#   full       a = b: C = 0, Dbar = h I, C^c = C(0), C^f_T = T^f = -Chat_TT/h, ufbar = 1
#   reciproc.  C^c_TT = Chat_TT (a/b) Dbar_TT / h, C^c_NN likewise, and
#              C^f_T = -(Chat_TT/h) (a/b) ufbar (Betti with the intact laminate) tol TOL_EQ52
#   betti-i    (i)   C_TT = Chat_TT (1 - D Dbar_TT/h), C_NN likewise          tol TOL_BETTI
#   betti-ii   (ii') C^f_T = D T^f Dbar_TT/h + I/(2bh)       (with I_fNT)       tol TOL_BETTI
#   betti-iii  (iii') Dbar_TT T^f + ufbar T^c_T = -I/(2a)   (with I_fNT, a > 0) tol TOL_BETTI
#              and I = 0 at a = 0 (the limit a -> 0+)                          tol TOL_BETTI
#              (docs/rve.md, 'Betti relations'; residuals of (ii'), (iii') relative to the
#              largest term of the relation, of (i) to Chat)
#   signs      T^f < 0, 0 < ufbar <= 1, 0 <= C <= Chat, C_TT and C_NN non-increasing in a
#   diag       (with the diag file) it is the table's: one data line per row with the row's a
#              (to 1e-5 b) and the four residuals below as numbers (a missing one, nan, or the
#              side file given instead fails here, not as a residual of 0)
#   pointwise  (with the diag file) max over crack nodes of |t - Chat|/Chat in p2, of the
#              p3 shear stress |t - T^f|/|T^f| (uniform crack stress) and of the p3 jump error
#                                                                              tol TOL_POINT
# Residuals are relative to the natural scale of each quantity (Chat, h, Chat_TT/h).
set -u
export LC_ALL=C
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
TOL_CLOSED=1e-10
TOL_EQ52=1e-8
TOL_EXACT=1e-10
TOL_POINT=1e-9
# Betti relations: round-off level. Measured on the committed tables and the ctest runs
# (coarse-paper, coarse-other, griffith): (i) <= 1.1e-14, (ii') <= 1.5e-12 (at a = 0.05 mm,
# where C^f_T is 1e-3 of K^ and the largest term), (iii') <= 1.3e-13; 1e-10 leaves a margin of
# ~70 for other FreeFEM/UMFPACK/BLAS builds.
TOL_BETTI=1e-10

# the help is the comment block at the top of this file
case "${1:-}" in -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;; esac
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: check-table.sh TABLE.dat [DIAG.txt] (or --help)" >&2; exit 2; }
table=$1
diag=${2:-}
for f in "$table" ${diag:+"$diag"}; do
  [ ! -d "$f" ] || { echo "check-table.sh: error: $f is a directory, not a file" >&2; exit 3; }
  [ -r "$f" ] || { echo "check-table.sh: error: cannot read $f" >&2; exit 3; }
done

# the table as the loader reads it, in the canonical column order (rve_freefem/table-reader.awk:
# the format checks, the one reader of the rve_freefem tools)
canon=$(mktemp) || { echo "check-table.sh: error: cannot make a temporary file" >&2; exit 3; }
trap 'rm -f "$canon"' EXIT
if ! awk -f "$here/table-reader.awk" -v dest="$canon" -v file="$table" "$table"; then
  printf "%-10s %-4s %s\n" format FAIL "the table is not read as the loader reads it (above)"
  exit 1
fi

awk -v TC="$TOL_CLOSED" -v TE="$TOL_EQ52" -v TX="$TOL_EXACT" -v TP="$TOL_POINT" -v TB="$TOL_BETTI" -v diag="$diag" '
function abs(x) { return x < 0 ? -x : x }
function report(name, res, tol, what) {
  ok = (res <= tol)
  printf "%-10s %-4s max residual %.3e (tol %.0e)  %s\n", name, ok ? "ok" : "FAIL", res, tol, what
  if (!ok) fail = 1
}
BEGIN {
  nreq = split("h_m h_b b E_m nu_m E_b nu_b script freefem_version date element refine unknowns_min unknowns_max", req, " ")
}
# the canonical table: header lines, "# columns: a D ... ufbar [I_fNT]", rows in that order
/^# columns:/ { ncol = NF - 2; next }
/^#/ {
  if (ncol == 0 && match($0, /^# [A-Za-z_0-9]+ = /)) { k = $0; sub(/^# /, "", k); sub(/ = .*/, "", k); hv = $0; sub(/^# [A-Za-z_0-9]+ = /, "", hv); hdr[k] = hv }
  next
}
NF == 0 { next }
{ n++; for (i = 1; i <= NF; i++) v[n, i] = $i + 0 }
END {
  # ---- format (the reader checked the rest): the provenance keys make-table.sh writes
  fmt = 0
  for (i = 1; i <= nreq; i++) if (!(req[i] in hdr)) { printf "missing header key %s\n", req[i]; fmt = 1 }
  report("format", fmt, 0, "header, columns line, " n " rows of " ncol " numbers, a = 0 .. b ascending")
  if (fmt) exit 1
  # (information only: the row count of the provenance against the rows, e.g. rows deleted by hand)
  if (("n_a" in hdr) && hdr["n_a"] + 0 != n)
    printf "note: the header says n_a = %s but the table has %d rows: the provenance (command, params) no longer describes all of it\n", hdr["n_a"], n
  # (a warning only, the exit status unchanged: rows too sparse near a = b for the law.)  The
  # loader interpolates the rows, and near a = b the coefficients fall steeply to their limits:
  # a sparse table may fail the loader'"'"'s interpolant check there, or pass it and still be far off
  # (docs/rve.md).  The recommendation (docs/rve.md, '"'"'A table for your own brick and mortar'"'"',
  # step 3): ligaments (b - a)/b down to 1e-4, at least 3 per decade below 0.1 (1 % slack, for
  # values typed by hand in --a-over-b)
  LMIN = 1e-4; PER_DECADE = 3; lb = hdr["b"] + 0
  lmin = 2; amin = ""; gap = 1; gl1 = gl2 = ga1 = ga2 = ""
  for (i = 1; i < n; i++) {
    l = (lb - v[i, 1]) / lb
    if (l < lmin) { lmin = l; amin = v[i, 1] }
    if (i > 1 && l < 0.1 * (1 - 1e-6)) {
      lp = (lb - v[i - 1, 1]) / lb
      if (lp / l > gap) { gap = lp / l; gl1 = lp; gl2 = l; ga1 = v[i - 1, 1]; ga2 = v[i, 1] }
    }
  }
  if (lmin > LMIN * (1 + 1e-2))
    printf "warning: rows too sparse near a = b for the law: the shortest ligament (b - a)/b is %.6g (a = %.10g mm, b = %.10g mm), above %g; the coefficients fall steeply to their limits there, and the loader interpolates the rows, so the law between them may be far off even where loading passes: add rows geometrically close to b down to %g b (ligament_over_b = 0.1 %g %d, docs/rve.md)\n", lmin, amin, lb, LMIN, LMIN, LMIN, PER_DECADE
  if (gap > 10 ^ (1 / PER_DECADE) * (1 + 1e-2))
    printf "warning: rows too sparse near a = b for the law: between the ligaments (b - a)/b = %.6g (a = %.10g mm) and %.6g (a = %.10g mm) the rows are %.3g per decade, fewer than %d; add rows there (ligament_over_b = 0.1 %g %d, docs/rve.md)\n", gl1, ga1, gl2, ga2, log(10) / log(gap), PER_DECADE, LMIN, PER_DECADE
  hm = hdr["h_m"] + 0; hb = hdr["h_b"] + 0; b = hdr["b"] + 0; Em = hdr["E_m"] + 0; nm = hdr["nu_m"] + 0
  Eb = hdr["E_b"] + 0; nb = hdr["nu_b"] + 0
  h = hm + hb
  Gm = Em / (2 * (1 + nm)); Gb = Eb / (2 * (1 + nb))
  Mm = Em * (1 - nm) / ((1 + nm) * (1 - 2 * nm)); Mb = Eb * (1 - nb) / ((1 + nb) * (1 - 2 * nb))
  CT = h / (hm / Gm + hb / Gb); CN = h / (hm / Mm + hb / Mb); CM = (CT > CN) ? CT : CN
  KT = CT / h
  printf "closed forms: Chat_TT = %.12g MPa, Chat_NN = %.12g MPa (table a = 0: %.12g, %.12g)\n", CT, CN, v[1, 3], v[1, 6]
  # ---- closed forms at a = 0
  r = abs(v[1, 3] - CT) / CT; t = abs(v[1, 6] - CN) / CN; if (t > r) r = t
  t = abs(v[1, 4]) / CM; if (t > r) r = t; t = abs(v[1, 5]) / CM; if (t > r) r = t
  report("closed", r, TC, "a = 0: C = diag(Chat_TT, Chat_NN)")
  # ---- eq 52
  r = 0
  for (i = 1; i <= n; i++) for (j = 0; j < 4; j++) { t = abs(v[i, 3 + j] + v[i, 11 + j] - v[1, 3 + j]) / ((j == 0) ? CT : (j == 3) ? CN : CM); if (t > r) { r = t; ra = v[i, 1] } }
  report("eq52", r, TE, "C + C^c = C(0) at every a (worst a = " ra ")")
  # ---- crack stresses of p2
  r = 0
  for (i = 1; i <= n; i++) { t = abs(v[i, 15] - CT) / CT; if (t > r) r = t; t = abs(v[i, 18] - CN) / CN; if (t > r) r = t }
  report("crack", r, TX, "T^c_T = Chat_TT and S^c_N = Chat_NN at every a")
  # ---- symmetry zeros
  r = 0
  for (i = 1; i <= n; i++) {
    t = abs(v[i, 4]) / CM; if (t > r) r = t; t = abs(v[i, 5]) / CM; if (t > r) r = t
    t = abs(v[i, 8]) / h; if (t > r) r = t; t = abs(v[i, 9]) / h; if (t > r) r = t
    t = abs(v[i, 12]) / CM; if (t > r) r = t; t = abs(v[i, 13]) / CM; if (t > r) r = t
    t = abs(v[i, 16]) / CM; if (t > r) r = t; t = abs(v[i, 17]) / CM; if (t > r) r = t
    t = abs(v[i, 20]) / KT; if (t > r) r = t; t = abs(v[i, 22]) / KT; if (t > r) r = t
  }
  report("symmetry", r, TX, "C_TN C_NT Dbar_TN Dbar_NT Cc_TN Cc_NT Tc_N Sc_T Cf_N Sf = 0")
  # ---- fully cracked
  r = 0
  t = abs(v[n, 3]) / CT; if (t > r) r = t; t = abs(v[n, 6]) / CN; if (t > r) r = t
  t = abs(v[n, 7] - h) / h; if (t > r) r = t; t = abs(v[n, 10] - h) / h; if (t > r) r = t
  t = abs(v[n, 11] - v[1, 3]) / CT; if (t > r) r = t; t = abs(v[n, 14] - v[1, 6]) / CN; if (t > r) r = t
  t = abs(v[n, 19] + KT) / KT; if (t > r) r = t; t = abs(v[n, 21] + KT) / KT; if (t > r) r = t
  t = abs(v[n, 23] - 1); if (t > r) r = t
  report("full", r, TX, sprintf("a = b: C = 0, Dbar = h I, C^c = C(0), C^f_T = %.10g, T^f = %.10g (-Chat_TT/h = %.10g), ufbar = 1", v[n, 19], v[n, 21], -KT))
  # ---- reciprocity (Betti with the intact laminate)
  r = 0
  for (i = 1; i <= n; i++) {
    d = v[i, 1] / b
    t = abs(v[i, 11] - CT * d * v[i, 7] / h) / CT; if (t > r) r = t
    t = abs(v[i, 14] - CN * d * v[i, 10] / h) / CN; if (t > r) r = t
    t = abs(v[i, 19] + KT * d * v[i, 23]) / KT; if (t > r) r = t
  }
  report("reciproc", r, TE, "C^c_TT = Chat_TT D Dbar_TT/h, C^c_NN = Chat_NN D Dbar_NN/h, C^f_T = -Chat_TT D ufbar/h")
  # ---- Betti relations (docs/rve.md): (i) free of coupling; (ii), (iii) carry I = int sigma^f D_NT dx
  r = 0
  for (i = 1; i <= n; i++) {
    d = v[i, 2]
    t = abs(v[i, 3] - CT * (1 - d * v[i, 7] / h)) / CT; if (t > r) { r = t; ra = v[i, 1] }
    t = abs(v[i, 6] - CN * (1 - d * v[i, 10] / h)) / CN; if (t > r) { r = t; ra = v[i, 1] }
  }
  report("betti-i", r, TB, "(i) C = Chat (1 - D Dbar/h), TT and NN (worst a = " ra ")")
  if (ncol == 24) {
    r2 = r3 = 0; a2 = a3 = ""
    t = abs(v[1, 24]) / (2 * b * h * KT); if (t > r3) { r3 = t; a3 = 0 }
    for (i = 2; i <= n; i++) {
      a = v[i, 1]; d = v[i, 2]; I = v[i, 24]
      x1 = v[i, 19]; x2 = d * v[i, 21] * v[i, 7] / h; x3 = I / (2 * b * h)
      s = abs(x1); if (abs(x2) > s) s = abs(x2); if (abs(x3) > s) s = abs(x3)
      t = abs(x1 - x2 - x3) / s; if (t > r2) { r2 = t; a2 = a }
      y1 = v[i, 7] * v[i, 21]; y2 = v[i, 23] * v[i, 15]; y3 = I / (2 * a)
      s = abs(y1); if (abs(y2) > s) s = abs(y2); if (abs(y3) > s) s = abs(y3)
      t = abs(y1 + y2 + y3) / s; if (t > r3) { r3 = t; a3 = a }
    }
    report("betti-ii", r2, TB, "(ii) C^f_T = D T^f Dbar_TT/h + I/(2bh) (worst a = " a2 ")")
    report("betti-iii", r3, TB, "(iii) Dbar_TT T^f + ufbar T^c_T = -I/(2a), I = 0 at a = 0 (worst a = " a3 ")")
    # the short-crack defect of (iii) without I against its limit 4 eps^2 (information only)
    km = 3 - 4 * nm; kb = 3 - 4 * nb
    beta = (Gm * (kb - 1) - Gb * (km - 1)) / (Gm * (kb + 1) + Gb * (km + 1))
    eps = log((1 - beta) / (1 + beta)) / (2 * 3.14159265358979324)
    printf "short crack: defect -Dbar_TT T^f/(ufbar T^c_T) - 1 = %.5f %% at a = %g mm; 4 eps^2 = %.5f %% (beta = %.5f, eps = %.5f)\n", \
      100 * (-v[2, 7] * v[2, 21] / (v[2, 23] * v[2, 15]) - 1), v[2, 1], 400 * eps * eps, beta, eps
  } else {
    print "betti-ii   --   no I_fNT column (format 1 table): (ii) and (iii) not checked"
  }
  # ---- signs and bounds
  bad = 0
  for (i = 2; i <= n; i++) {
    if (!(v[i, 21] < 0)) { bad++; printf "  T^f >= 0 at a = %g\n", v[i, 1] }
    if (!(v[i, 23] > 0 && v[i, 23] <= 1 + 1e-12)) { bad++; printf "  ufbar outside (0,1] at a = %g\n", v[i, 1] }
    if (v[i, 3] > v[i - 1, 3] + 1e-9 * CT || v[i, 6] > v[i - 1, 6] + 1e-9 * CN) { bad++; printf "  C increases at a = %g\n", v[i, 1] }
    if (v[i, 3] < -1e-9 * CT || v[i, 6] < -1e-9 * CN) { bad++; printf "  C < 0 at a = %g\n", v[i, 1] }
  }
  report("signs", bad, 0, "T^f < 0, 0 < ufbar <= 1, C_TT and C_NN non-increasing and >= 0")
  if (diag != "") {
    # every data line of the diag file is one a of the table, in the order of its rows, with the
    # four residuals as numbers: a missing key, a residual that is not a number (nan) or the
    # side file given in its place must fail, not count as a residual of 0
    r1 = r2 = r3 = r4 = 0; nd = 0; ln = 0; dbad = 0
    num = "^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$"
    nk = split("a= resTc= resSc= resTfpt= resuf=", dk, " ")
    while ((getline line < diag) > 0) {
      ln++
      sub(/\r$/, "", line)
      if (line ~ /^#/ || line ~ /^[ \t]*$/) continue
      nd++
      m = split(line, f, " ")
      delete dv
      for (k = 1; k < m; k++) if (f[k] ~ /=$/) dv[f[k]] = f[k + 1]
      miss = ""; nan = ""
      for (j = 1; j <= nk; j++)
        if (!(dk[j] in dv)) miss = miss (miss == "" ? "" : " ") dk[j]
        else if (dv[dk[j]] !~ num) nan = nan (nan == "" ? "" : ", ") dk[j] " " dv[dk[j]]
      if (miss != "" && dbad++ < 5) printf "%s:%d: no %s on this line (a line of a diag file reads a= ... resTc= ... resSc= ... resTfpt= ... resuf= ...)\n", diag, ln, miss
      if (nan != "" && dbad++ < 5) printf "%s:%d: not a number: %s\n", diag, ln, nan
      if (nd <= n && ("a=" in dv) && dv["a="] ~ num && abs(dv["a="] - v[nd, 1]) > 1e-5 * b) {
        if (dbad++ < 5) printf "%s:%d: a = %s, but the table\047s row %d has a = %.17g: the diag file of another table?\n", diag, ln, dv["a="], nd, v[nd, 1]
      }
      if (dv["resTc="] + 0 > r1) r1 = dv["resTc="] + 0
      if (dv["resSc="] + 0 > r2) r2 = dv["resSc="] + 0
      if (dv["resTfpt="] + 0 > r3) r3 = dv["resTfpt="] + 0
      if (dv["resuf="] + 0 > r4) r4 = dv["resuf="] + 0
    }
    close(diag)
    if (nd != n) { printf "%s: %d data lines, the table %d rows\n", diag, nd, n; dbad++ }
    if (dbad) { report("diag", dbad, 0, "the diag file is the table\047s (one line per a, with the residuals)"); exit 1 }
    report("pointwise", (r1 > r2 ? r1 : r2), TP, "p2 crack stresses = Chat at every crack node")
    report("uniform", r3, TP, "p3 crack shear stress uniform (= T^f) at every crack node")
    report("p3jump", r4, TP, "p3 jump equals (u^f, 0) at every crack node")
  }
  exit fail
}' "$canon"
