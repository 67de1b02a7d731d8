#!/usr/bin/env bash
# make-table.sh -- RVE coefficient table (paper section 3.3) from a parameter file.
#
#   bash rve_freefem/make-table.sh [options] PARAMS OUT.dat
#   bash rve_freefem/make-table.sh --check [--refine R] [--a-over-b LIST] PARAMS [OUT.dat]
#
# Writes OUT.dat (format: tables/README.md), OUT-fields.dat (D(x), u^f(x), sigma^f(x) for the a
# values in fields_a_over_b) and OUT-diag.txt (per-a mesh size, unknowns, time and identity residuals).
# The table's header records the command as given and the parameter file: its path, its SHA-256
# and each setting as read (# params_line = key = value).
# Options:
#   --refine R      multiply the mesh refinement level of PARAMS by R (convergence studies)
#   --jobs N        FreeFEM processes run in parallel (default 2)
#   --a-over-b "v1 v2 ..."   compute only these a/b values (and a = 0 and a = b, which every table
#                   has); the fields_a_over_b/fields_a_mm values are not added: the side file holds
#                   those that are in the list (the others are named in a note)
#   --no-fields     do not write the side file (its a values stay in the table)
#   --check         check the parameters (and, with --refine, the mesh at that level), run nothing
# An option may be given once (a second --refine, say, is refused, not taken over the first).
# A table has at least 4 rows (a = 0 and a = b included): the loader's spline needs them.
# Needs bash, awk and FreeFem++ (Debian package freefem++).  Exit code 0 on success, 2 for bad
# parameters or usage, 3 for a missing program or unreadable file, 4 if a FreeFEM run failed.
set -u
export LC_ALL=C

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prog="make-table.sh"
die() { local code=$1; shift; echo "$prog: error: $*" >&2; exit "$code"; }
note() { echo "$prog: note: $*" >&2; }
# a warning goes to standard error and into the table's header (# warning = ...), so that a table
# made from implausible parameters carries it
warnings=()
warn() { echo "$prog: warning: $*" >&2; warnings+=("$*"); }

# the command as given, for the table's '# command =' line: each argument as the shell reads it
# back (quoted when it has blanks or characters the shell would take otherwise)
command_given="bash rve_freefem/make-table.sh"
for arg in "$@"; do
  case "$arg" in
    ''|*[!A-Za-z0-9_./:=+,@%-]*) command_given+=" '${arg//\'/\'\\\'\'}'" ;;
    *) command_given+=" $arg" ;;
  esac
done
refine_mult=1
jobs=2
a_override=""
a_override_given=0
want_fields=1
check_only=0
given=" "
while [ $# -gt 0 ]; do
  # an option given twice is refused: which of its values counts is not guessed
  case "$1" in
    --refine|--jobs|--a-over-b|--no-fields|--check)
      case "$given" in *" $1 "*) die 2 "$1 given twice" ;; esac
      given="$given$1 " ;;
  esac
  case "$1" in
    --refine) [ $# -ge 2 ] || die 2 "--refine needs a value"; refine_mult=$2; shift 2 ;;
    --jobs) [ $# -ge 2 ] || die 2 "--jobs needs a value"; jobs=$2; shift 2 ;;
    --a-over-b) [ $# -ge 2 ] || die 2 "--a-over-b needs a list"; a_override=$2; a_override_given=1; shift 2 ;;
    --no-fields) want_fields=0; shift ;;
    --check) check_only=1; shift ;;
    # the help is the comment block at the top of this file
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    --) shift; break ;;
    -*) die 2 "unknown option $1" ;;
    *) break ;;
  esac
done
usage="usage: $prog [--refine R] [--jobs N] [--a-over-b LIST] [--no-fields] PARAMS OUT.dat (or --check [--refine R] PARAMS)"
if [ "$check_only" = 1 ]; then
  [ $# -eq 1 ] || [ $# -eq 2 ] || die 2 "$usage"
else
  [ $# -eq 2 ] || die 2 "$usage"
fi
params=$1
out=${2:-}
[ -f "$params" ] && [ -r "$params" ] || die 3 "cannot read parameter file '$params'"
# the output, before any FreeFEM run: a file name in a directory that can be written
if [ -n "$out" ]; then
  [ -d "$out" ] && die 2 "the output '$out' is a directory: name the table file (e.g. ${out%/}/$(basename "${params%.params}").dat)"
  outdir=$(dirname "$out")
  [ -d "$outdir" ] && [ -w "$outdir" ] || die 3 "cannot write $out: its directory $outdir does not exist or is not writable"
  # the table, its diag and side files must not overwrite the parameter file they are made from
  # (the diag and side files are named after the table: its name without .dat, then -diag.txt or
  # -fields.dat; with --no-fields the side file is not written)
  [ "$out" -ef "$params" ] && die 2 "the output '$out' is the parameter file '$params' itself: name the table file (e.g. $(dirname "$params")/$(basename "${params%.params}").dat)"
  for f in "${out%.dat}-diag.txt" "${out%.dat}-fields.dat"; do
    case "$f" in *-fields.dat) [ "$want_fields" = 1 ] || continue; what="side file" ;; *) what="diagnostics file" ;; esac
    [ "$f" -ef "$params" ] && die 2 "the table '$out' would write its $what '$f' (the table's name without .dat, then ${f#"${out%.dat}"}), which is the parameter file '$params': it would overwrite it; name the table otherwise (e.g. ${out%.dat}-table.dat) or rename the parameter file"
  done
fi
if [ "$check_only" = 0 ]; then
  command -v FreeFem++ >/dev/null 2>&1 || die 3 "FreeFem++ not found: install the Debian package freefem++"
fi
case "$jobs" in ''|*[!0-9]*) die 2 "--jobs = '$jobs' must be a positive integer" ;; esac
# (leading zeros dropped: 08 is 8, not an octal number, wherever the shell computes with it)
while [ "${#jobs}" -gt 1 ] && [ "${jobs#0}" != "$jobs" ]; do jobs=${jobs#0}; done
[ "${#jobs}" -le 4 ] || die 2 "--jobs = $jobs is too large: at most 9999 parallel FreeFEM runs"
[ "$jobs" -ge 1 ] || die 2 "--jobs = $jobs must be >= 1"

# ---------------------------------------------------------------- read and check the parameters
# prints "key<TAB>value" lines; fails on syntax errors and unknown keys.  A carriage return at
# the end of a line (a file saved with Windows line endings) is dropped.
parsed=$(awk -v file="$params" '
  BEGIN { n = split("h_m h_b b E_m nu_m E_b nu_b order hmax ftip htipmax grow fseg refine huni a_over_b_list a_over_b_uniform ligament_over_b a_list_mm fields_a_over_b fields_a_mm", k, " ")
          for (i = 1; i <= n; i++) known[k[i]] = 1 }
  NR == 1 && index($0, "\357\273\277") == 1 {
    printf "make-table.sh: error: %s:1: the file starts with a UTF-8 byte-order mark (bytes EF BB BF): save it without one\n", file > "/dev/stderr"
    bad = 1; sub(/^\357\273\277/, "") }
  { sub(/\r$/, ""); sub(/#.*/, "") }
  /^[ \t]*$/ { next }
  {
    eq = index($0, "=")
    if (eq == 0) { printf "make-table.sh: error: %s:%d: expected key = value: %s\n", file, NR, $0 > "/dev/stderr"; bad = 1; next }
    key = substr($0, 1, eq - 1); val = substr($0, eq + 1)
    gsub(/^[ \t]+|[ \t]+$/, "", key); gsub(/^[ \t]+|[ \t]+$/, "", val); gsub(/[ \t]+/, " ", val)
    if (!(key in known)) { printf "make-table.sh: error: %s:%d: unknown key \"%s\"\n", file, NR, key > "/dev/stderr"; bad = 1; next }
    if (key in seen) { printf "make-table.sh: error: %s:%d: key \"%s\" given twice\n", file, NR, key > "/dev/stderr"; bad = 1; next }
    seen[key] = 1
    printf "%s\t%s\t%d\n", key, val, NR
  }
  END { exit bad }' "$params") || die 2 "bad parameter file '$params' (see above)"
# (for the provenance header: the file as it was read)
params_sha=$(sha256sum < "$params" | awk '{ print $1 }')

get() { printf '%s\n' "$parsed" | awk -F'\t' -v k="$1" '$1 == k { print $2; f = 1 } END { exit !f }'; }
# where a key was given, for the messages about its value: "PARAMS:LINE: "
loc() { printf '%s:%s: ' "$params" "$(printf '%s\n' "$parsed" | awk -F'\t' -v k="$1" '$1 == k { print $3; exit }')"; }
# numbers: a decimal literal (no d exponent, no inf/nan) that is a finite double whose magnitude,
# when not 0, lies in [1e-100, 1e100] (so that products and quotients of two stay finite);
# numcode prints nothing and returns 0, 1 (not a number), 2 (not finite) or 3 (out of range)
numcode() {
  printf '%s\n' "$1" | awk '{
    if ($0 !~ /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/) exit 1
    v = $0 + 0; if (sprintf("%g", v) ~ /inf|nan/) exit 2
    # a literal whose digits are not all zero but that reads as 0 underflowed (1e-400)
    m = $0; sub(/[eE].*/, "", m)
    if (v == 0 && m ~ /[1-9]/) exit 3
    if (v < 0) v = -v
    if (v != 0 && (v > 1e100 || v < 1e-100)) exit 3
    exit 0 }'
}
# checknum WHAT VALUE: die with a message unless VALUE is such a number
checknum() {
  numcode "$2"
  case $? in
    0) ;;
    2) die 2 "$1 = '$2' is not a finite number (beyond the range of a double)" ;;
    3) die 2 "$1 = '$2' is out of range: a non-zero value must lie between 1e-100 and 1e100 in magnitude" ;;
    *) case "$2" in
         *[0-9][dDqQ][+-]*[0-9]*|*[0-9][dDqQ][0-9]*) die 2 "$1 = '$2' is not a number here: write the exponent with e (FreeFEM reads no d or q exponent)" ;;
       esac
       die 2 "$1 = '$2' is not a number" ;;
  esac
}
# checklist WHAT LIST [EMPTY-HINT]: every word a number (checknum); an empty list is refused
# (EMPTY-HINT: what to do then; a key's line by default)
checklist() {
  local v
  [ -n "$(printf '%s' "$2" | tr -d ' \t')" ] || die 2 "$1 is empty: ${3:-give at least one value (or remove the line)}"
  for v in $2; do checknum "$1: value" "$v"; done
}
# the largest mesh make-table.sh runs: elements along the interface and the sides of the meshed
# quarter for one a (see 'the mesh, before FreeFEM runs' below)
NMAX_EDGES=3000
# awk comparison helper: test EXPR on x
chk() { awk -v x="$1" "BEGIN { exit !($2) }"; }

declare -A P
for key in h_m h_b b E_m nu_m E_b nu_b; do
  P[$key]=$(get "$key") || die 2 "parameter '$key' missing in '$params'"
  checknum "$(loc "$key")parameter '$key'" "${P[$key]}"
done
for key in h_m h_b b E_m E_b; do
  chk "${P[$key]}" "x > 0" || die 2 "$(loc "$key")parameter '$key' = ${P[$key]} must be positive"
done
for key in nu_m nu_b; do
  chk "${P[$key]}" "x < 0.5" || die 2 "$(loc "$key")parameter '$key' = ${P[$key]}: Poisson's ratio must be < 0.5 (plane strain)"
  chk "${P[$key]}" "x > -1" || die 2 "$(loc "$key")parameter '$key' = ${P[$key]}: Poisson's ratio must be > -1"
done
# mesh controls with defaults
declare -A D=([order]=P2 [hmax]=1 [ftip]=0.005 [htipmax]=0.005 [grow]=1.25 [fseg]=0.1 [refine]=1 [huni]=0)
for key in order hmax ftip htipmax grow fseg refine huni; do
  P[$key]=$(get "$key") || P[$key]=${D[$key]}
done
case "${P[order]}" in P1|P2) ;; *) die 2 "$(loc order)parameter 'order' = '${P[order]}' must be P1 or P2" ;; esac
for key in hmax ftip htipmax grow fseg refine huni; do
  checknum "$(loc "$key")parameter '$key'" "${P[$key]}"
done
for key in hmax ftip htipmax; do chk "${P[$key]}" "x > 0" || die 2 "$(loc "$key")parameter '$key' = ${P[$key]} must be positive"; done
chk "${P[ftip]}" "x < 1" || die 2 "$(loc ftip)parameter 'ftip' must be < 1"
chk "${P[grow]}" "x >= 1 && x < 3" || die 2 "$(loc grow)parameter 'grow' = ${P[grow]} must be in [1, 3)"
chk "${P[fseg]}" "x > 0 && x <= 1" || die 2 "$(loc fseg)parameter 'fseg' = ${P[fseg]} must be in (0, 1]"
chk "${P[refine]}" "x >= 1" || die 2 "$(loc refine)parameter 'refine' = ${P[refine]} must be >= 1"
chk "${P[huni]}" "x >= 0" || die 2 "$(loc huni)parameter 'huni' = ${P[huni]} must be >= 0"
checknum "--refine" "$refine_mult"
chk "$refine_mult" "x >= 1" || die 2 "--refine must be a number >= 1"
refine=$(awk -v a="${P[refine]}" -v m="$refine_mult" 'BEGIN { printf "%.17g", a * m }')
uniform=0
chk "${P[huni]}" "x > 0" && uniform=1
bval=${P[b]}
# plausibility, not validity: the identities every table is checked against hold for any units
# and any mesh, so neither check-table.sh nor the loader can see a modulus given in GPa, a length
# in m, or a mesh whose far-field size exceeds a layer (docs/rve.md, 'A table for your own brick
# and mortar').  Warnings only: the run goes on.
for key in E_m E_b; do
  chk "${P[$key]}" "x < 100" && warn "$(loc "$key")'$key' = ${P[$key]} MPa is softer than mortars and bricks usually are: moduli are in MPa (a value in GPa is 1000 times too small, and the table's stiffnesses with it)"
  chk "${P[$key]}" "x > 1e6" && warn "$(loc "$key")'$key' = ${P[$key]} MPa is stiffer than any mortar or brick: moduli are in MPa (a value in Pa is 1e6 times too large)"
done
for key in h_m h_b b; do
  chk "${P[$key]}" "x < 0.5" && warn "$(loc "$key")'$key' = ${P[$key]} mm is smaller than any mortar joint or brick dimension: lengths are in mm (a value in m is 1000 times too small; the mesh sizes are in mm too)"
done
if [ "$uniform" = 0 ]; then
  thin=$(awk -v m="${P[h_m]}" -v b="${P[h_b]}" 'BEGIN { if (m <= b) print "h_m"; else print "h_b" }')
  awk -v h="${P[hmax]}" -v r="$refine" -v t="${P[$thin]}" 'BEGIN { exit !(h / r > t) }' \
    && warn "$(loc hmax)hmax/refine = $(awk -v h="${P[hmax]}" -v r="$refine" 'BEGIN { printf "%.6g", h / r }') mm is larger than the thinner layer ($thin = ${P[$thin]} mm): the mesh has less than one far-field element through it and the table will not be converged, although every identity check passes; the mesh sizes hmax, htipmax are lengths in mm, not fractions of the RVE: scale them with the layers and check with convergence.sh (docs/rve.md)"
fi
# uniform mesh: rve.edp meshes huni x huni squares and uses neither the graded mesh's keys nor
# the refinement level; a value given for one of them has no effect, which the user may not know
if [ "$uniform" = 1 ]; then
  for key in hmax ftip htipmax grow fseg refine; do
    get "$key" > /dev/null && warn "$(loc "$key")'$key' = ${P[$key]} is not used: with huni = ${P[huni]} ($(loc huni | sed 's/: $//')) the mesh is uniform squares of side huni: neither the graded mesh's keys (hmax, ftip, htipmax, grow, fseg) nor the refinement level refine have an effect (remove the line, or huni for the graded mesh)"
  done
  chk "$refine_mult" "x != 1" && warn "--refine $refine_mult is not used: with huni = ${P[huni]} ($(loc huni | sed 's/: $//')) the mesh is uniform squares of side huni, which the refinement level does not change (for a finer uniform mesh, divide huni)"
fi
# uniform mesh: the layers and the RVE must be whole numbers of squares (rve.edp's test)
if [ "$uniform" = 1 ]; then
  for key in b h_m h_b; do
    awk -v x="${P[$key]}" -v u="${P[huni]}" 'BEGIN { q = x / u; r = int(q + 0.5); d = q - r; if (d < 0) d = -d; exit !(d <= 1e-9 * q) }' \
      || die 2 "$(loc huni)parameter 'huni' = ${P[huni]}: the uniform mesh needs $key = ${P[$key]} to be a whole multiple of huni"
  done
fi

# ---------------------------------------------------------------- crack half-lengths (mm)
# every table has a = 0 and a = b; the keys (or --a-over-b) add the values in between
alist_raw=$(printf '0\n%s\n' "$bval")
given=""     # the keys (or option) that gave a values, for the messages
# where each a came from, "a<TAB>SOURCE" lines (SOURCE "PARAMS:LINE: key" or the option), so that
# a message about one a names the entry that gave it, not every list of the file
asrc_map=$(printf '0\ta = 0 (in every table)\n%s\ta = b (in every table)' "$bval")
# add_a SOURCE VALUES: VALUES (one a in mm per line) are crack half-lengths given by SOURCE
add_a() {
  local x
  alist_raw+=$'\n'$2
  for x in $2; do asrc_map+=$'\n'$x$'\t'$1; done
}
if [ "$a_override_given" = 1 ]; then
  checklist "--a-over-b" "$a_override" "give at least one value of a/b in (0, 1), e.g. --a-over-b \"0.5 0.9\" (a = 0 and a = b are added), or leave the option out to use the parameter file's crack lengths"
  for f in $a_override; do
    chk "$f" "x >= 0" || die 2 "--a-over-b: a/b = $f < 0"
    chk "$f" "x <= 1" || die 2 "--a-over-b: crack half-length a/b = $f > 1: a must not exceed b"
  done
  add_a "--a-over-b" "$(for f in $a_override; do awk -v f="$f" -v b="$bval" 'BEGIN { printf "%.15g\n", (f == 1) ? b : f * b }'; done)"
  given="--a-over-b \"$a_override\""
else
  if v=$(get a_over_b_list); then
    checklist "$(loc a_over_b_list)a_over_b_list" "$v"
    src="$(loc a_over_b_list)a_over_b_list"
    for f in $v; do
      chk "$f" "x >= 0" || die 2 "$(loc a_over_b_list)a_over_b_list: a/b = $f < 0"
      chk "$f" "x <= 1" || die 2 "$(loc a_over_b_list)a_over_b_list: crack half-length a/b = $f > 1: a must not exceed b"
      add_a "$src" "$(awk -v f="$f" -v b="$bval" 'BEGIN { printf "%.15g", f * b }')"
    done
    given+=" a_over_b_list = $v;"
  fi
  if v=$(get a_list_mm); then
    checklist "$(loc a_list_mm)a_list_mm" "$v"
    src="$(loc a_list_mm)a_list_mm"
    for f in $v; do
      chk "$f" "x >= 0" || die 2 "$(loc a_list_mm)a_list_mm: a = $f < 0"
      awk -v x="$f" -v b="$bval" 'BEGIN { exit !(x <= b) }' || die 2 "$(loc a_list_mm)a_list_mm: crack half-length a = $f > b = $bval"
      add_a "$src" "$f"
    done
    given+=" a_list_mm = $v;"
  fi
  if v=$(get a_over_b_uniform); then
    set -- $v
    [ $# -eq 3 ] || die 2 "$(loc a_over_b_uniform)a_over_b_uniform needs 'start stop step', got '$v'"
    checklist "$(loc a_over_b_uniform)a_over_b_uniform" "$v"
    chk "$3" "x > 0" || die 2 "$(loc a_over_b_uniform)a_over_b_uniform = $v: step = $3 must be > 0"
    # (each condition on its own, naming the value that fails it: need 0 <= start <= stop <= 1)
    chk "$1" "x >= 0" || die 2 "$(loc a_over_b_uniform)a_over_b_uniform = $v: start = $1 must be >= 0 (need 0 <= start <= stop <= 1)"
    chk "$2" "x <= 1" || die 2 "$(loc a_over_b_uniform)a_over_b_uniform = $v: stop = $2 must be <= 1 (a must not exceed b; need 0 <= start <= stop <= 1)"
    awk -v s="$1" -v e="$2" 'BEGIN { exit !(s <= e) }' || die 2 "$(loc a_over_b_uniform)a_over_b_uniform = $v: start = $1 exceeds stop = $2 (need 0 <= start <= stop <= 1)"
    # the stop is a point of the range: a step that does not divide stop - start would drop it
    awk -v s="$1" -v e="$2" -v d="$3" 'BEGIN { q = (e - s) / d; exit !(q - int(q + 0.5) <= 1e-9 * (q > 1 ? q : 1) && int(q + 0.5) - q <= 1e-9 * (q > 1 ? q : 1)) }' \
      || die 2 "$(loc a_over_b_uniform)a_over_b_uniform = $v: the step does not divide stop - start, so the points would be $(awk -v s="$1" -v e="$2" -v d="$3" 'BEGIN { for (x = s; x <= e + 1e-12; x += d) printf "%g ", x }')without the stop $2"
    add_a "$(loc a_over_b_uniform)a_over_b_uniform" "$(awk -v s="$1" -v e="$2" -v d="$3" -v b="$bval" 'BEGIN { n = int((e - s) / d + 1e-9); for (i = 0; i <= n; i++) printf "%.15g\n", (s + i * d) * b }')"
    given+=" a_over_b_uniform = $v;"
  fi
  if v=$(get ligament_over_b); then
    set -- $v
    [ $# -eq 3 ] || die 2 "$(loc ligament_over_b)ligament_over_b needs 'from to per-decade', got '$v'"
    checklist "$(loc ligament_over_b)ligament_over_b" "$v"
    # (each condition on its own, naming the value that fails it: need 0 < to <= from <= 1, per-decade >= 1)
    chk "$1" "x > 0 && x <= 1" || die 2 "$(loc ligament_over_b)ligament_over_b = $v: from = $1 must lie in (0, 1] (the longest ligament, a fraction of b; need 0 < to <= from <= 1)"
    chk "$2" "x > 0" || die 2 "$(loc ligament_over_b)ligament_over_b = $v: to = $2 must be > 0 (the shortest ligament, a fraction of b; need 0 < to <= from <= 1)"
    awk -v f="$1" -v t="$2" 'BEGIN { exit !(t <= f) }' || die 2 "$(loc ligament_over_b)ligament_over_b = $v: to = $2 exceeds from = $1 (the ligaments run from 'from' down to 'to'; need 0 < to <= from <= 1)"
    chk "$3" "x >= 1" || die 2 "$(loc ligament_over_b)ligament_over_b = $v: per-decade = $3 must be >= 1"
    # a whole number per decade, and the last ligament one of the points: else it would be dropped
    chk "$3" "x == int(x)" || die 2 "$(loc ligament_over_b)ligament_over_b = $v: per-decade = $3 must be a whole number"
    awk -v f="$1" -v t="$2" -v n="$3" 'BEGIN { q = n * log(f / t) / log(10); r = int(q + 0.5); exit !(q - r <= 1e-9 * (q > 1 ? q : 1) && r - q <= 1e-9 * (q > 1 ? q : 1)) }' \
      || die 2 "$(loc ligament_over_b)ligament_over_b = $v: 'to' is not a whole number of steps 10^(-1/$3) below 'from', so it would not be a point (per-decade * log10(from/to) = $(awk -v f="$1" -v t="$2" -v n="$3" 'BEGIN { printf "%.6g", n * log(f / t) / log(10) }'))"
    add_a "$(loc ligament_over_b)ligament_over_b" "$(awk -v f="$1" -v t="$2" -v n="$3" -v b="$bval" 'BEGIN { m = int(n * log(f / t) / log(10) + 1e-9); for (j = 0; j <= m; j++) { l = f * 10 ^ (-j / n); printf "%.15g\n", b - l * b } }')"
    given+=" ligament_over_b = $v;"
  fi
fi
# the a values of the side file: part of the table (so --no-fields keeps the rows), except with
# --a-over-b, where the side file holds those of them that are in the list
fields_raw=""
fields_map=""   # (their sources, as asrc_map)
if v=$(get fields_a_over_b); then
  checklist "$(loc fields_a_over_b)fields_a_over_b" "$v"
  src="$(loc fields_a_over_b)fields_a_over_b"
  for f in $v; do
    chk "$f" "x >= 0 && x <= 1" || die 2 "$(loc fields_a_over_b)fields_a_over_b: a/b = $f outside [0, 1]"
    x=$(awk -v f="$f" -v b="$bval" 'BEGIN { printf "%.15g", (f == 1) ? b : f * b }')
    fields_raw+=$x$'\n'
    fields_map+=$x$'\t'$src$'\n'
  done
  [ "$a_override_given" = 1 ] || given+=" fields_a_over_b = $v;"
fi
if v=$(get fields_a_mm); then
  checklist "$(loc fields_a_mm)fields_a_mm" "$v"
  src="$(loc fields_a_mm)fields_a_mm"
  for f in $v; do
    awk -v x="$f" -v b="$bval" 'BEGIN { exit !(x >= 0 && x <= b) }' || die 2 "$(loc fields_a_mm)fields_a_mm: a = $f outside [0, b]"
    fields_raw+=$f$'\n'
    fields_map+=$f$'\t'$src$'\n'
  done
  [ "$a_override_given" = 1 ] || given+=" fields_a_mm = $v;"
fi
[ "$a_override_given" = 1 ] || { alist_raw+=$'\n'$fields_raw; asrc_map+=$'\n'$fields_map; }
# sorted, duplicates (to 1e-12 b) removed
alist=$(printf '%s\n' "$alist_raw" | awk 'NF' | sort -g | awk -v b="$bval" 'NR == 1 || $1 - last > 1e-12 * b { print; last = $1 }')
na=$(printf '%s\n' "$alist" | wc -l)
# the loader interpolates the rows with a not-a-knot cubic spline, which needs 4 of them
if [ "$na" -lt 4 ]; then
  given=${given%;}
  die 2 "${given:+${given# }: }$((na - 2)) distinct crack half-length(s) strictly between 0 and b; with a = 0 and a = b the table would have $na rows, but it needs at least 4 (the loader's not-a-knot cubic spline): give at least 2 values of a/b in (0, 1)"
fi
# side-file a values: with --a-over-b only those in the list (rve.edp matches them to 1e-9 b)
fields_sel=$(printf '%s' "$fields_raw" | awk 'NF')
if [ "$a_override_given" = 1 ] && [ -n "$fields_sel" ]; then
  inlist=$(printf '%s\n' "$fields_sel" | awk -v b="$bval" -v list="$alist" 'BEGIN { n = split(list, A, "\n") }
    { for (i = 1; i <= n; i++) { d = $1 - A[i]; if (d < 0) d = -d; if (d < 1e-9 * b) { print; next } } }')
  dropped=$(printf '%s\n' "$fields_sel" | awk -v b="$bval" -v list="$inlist" 'BEGIN { n = split(list, A, "\n") }
    { for (i = 1; i <= n; i++) { d = $1 - A[i]; if (d < 0) d = -d; if (d < 1e-9 * b) next } printf "%s%s", sep, $1; sep = " " }')
  [ "$want_fields" = 0 ] || [ -z "$dropped" ] || \
    note "--a-over-b: the side-file crack half-lengths a = $dropped mm (fields_a_over_b, fields_a_mm) are not in the list: no distributions for them"
  fields_sel=$inlist
fi

# ---------------------------------------------------------------- the mesh, before FreeFEM runs
if [ "$uniform" = 1 ]; then
  # every a must fall on a node of the squares (rve.edp's test)
  bad=$(printf '%s\n' "$alist" | awk -v u="${P[huni]}" -v b="$bval" '{ q = $1 / u; d = q - int(q + 0.5); if (d < 0) d = -d; if (d > 1e-9 * b / u) { printf "%s%s", sep, $1; sep = " " } }')
  [ -z "$bad" ] || die 2 "$(loc huni)parameter 'huni' = ${P[huni]}: the crack half-lengths a = $bad mm are not multiples of huni (the crack tips must be nodes of the uniform mesh)"
else
  # rve.edp's graded point sets (its grade()), counted before any run: the shortest tip spacing
  # FreeFEM accepts, and the size of the mesh of one a.  The unknowns of one a are ~100-250 times
  # the elements along the interface and the four sides of the meshed quarter (measured); the
  # paper's table needs at most 173 of them at refine 1, 654 at refine 4 (~200 000 unknowns).
  # Above NMAX_EDGES the mesh of one a takes gigabytes: grow = 1, or a grow
  # close to 1, keeps the spacing at the tip size along the whole line (grow = 1 with ftip = 0.05
  # and a = 0.05 mm: 14 000 elements, > 12 GB per FreeFEM process).
  # (where each crack length was given, asrc_map, for the message of one the mesh cannot take:
  # the entry that gave it, not every list of the file)
  printf '%s\n' "$alist" | MT_ASRC_MAP=$asrc_map awk -v b="$bval" -v hm="${P[h_m]}" -v hb="${P[h_b]}" -v hmax="${P[hmax]}" -v ftip="${P[ftip]}" \
      -v htipmax="${P[htipmax]}" -v grow="${P[grow]}" -v fseg="${P[fseg]}" -v refine="$refine" -v rm="$refine_mult" \
      -v nmax="$NMAX_EDGES" -v ncap=10000000 '
    function min(x, y) { return x < y ? x : y }
    function max(x, y) { return x > y ? x : y }
    # the number of intervals of rve.edp grade(p, L, s0, g, smax) (counting stops at ncap);
    # first, last = its first and last spacing; cnt[kind] counts the intervals at the cap smax
    # (kind "h": hmax/refine, "f": fseg * segment/refine), cnt["g"] those below it, still growing
    function grade(L, s0, g, smax, kind,   n, pos, s) {
      n = 0; pos = 0; s = min(s0, smax); first = s
      while (L - pos > 1.5 * s) { cnt[s >= smax * (1 - 1e-6) ? kind : "g"]++; pos += s; n++; s = min(s * g, smax); if (n >= ncap) break }
      cnt[s >= smax * (1 - 1e-6) ? kind : "g"]++
      if (n == 0) first = L
      last = L - pos; return n + 1
    }
    # the entries that gave the crack half-length x (mm)
    function source(x,   i, j, out, seen) {
      out = ""
      for (i = 1; i <= nsrc; i++) {
        if ((j = index(srcline[i], "\t")) == 0) continue
        if (abs(substr(srcline[i], 1, j - 1) - x) <= 1e-9 * b && !(substr(srcline[i], j + 1) in seen)) {
          seen[substr(srcline[i], j + 1)] = 1; out = out (out == "" ? "" : ", ") substr(srcline[i], j + 1)
        }
      }
      return out
    }
    function abs(x) { return x < 0 ? -x : x }
    BEGIN { hfar = hmax / refine; gr = grow ^ (1 / refine); diam = sqrt(b * b + max(hm, hb) ^ 2); hlim = 1.1e-7 * diam
            nsrc = split(ENVIRON["MT_ASRC_MAP"], srcline, "\n") }
    {
      a = $1 + 0; if (a > b) a = b
      if (a > 0 && a < b) {
        L1 = b - a; htip = min(htipmax, ftip * min(L1, a)) / refine
        if (htip < hlim) {
          printf "make-table.sh: error: a = %s mm (b - a = %.6g mm): crack or ligament too short for this mesh (tip spacing %.3g mm < %.3g mm, FreeFEM'"'"'s limit) at refine %s; need min(a, b - a) >= %.3g mm, or a larger ftip%s (this crack length: %s)\n", \
            $1, L1, htip, hlim, refine, hlim * refine / ftip, (rm != 1 ? " or a lower --refine" : ""), source($1) > "/dev/stderr"
          exit 1
        }
        delete cnt
        ni = grade(L1, htip, gr, min(hfar, fseg * L1 / refine), (fseg * L1 / refine < hfar) ? "f" : "h"); sL = last
        ni += grade(a, htip, gr, min(hfar, fseg * a / refine), (fseg * a / refine < hfar) ? "f" : "h"); sR = last
      } else {
        delete cnt
        ni = grade(b, hfar, 1, hfar, "h"); sL = first; sR = last
      }
      ns = grade(hm, sL, gr, hfar, "h") + grade(hm, sR, gr, hfar, "h") + grade(hb, sL, gr, hfar, "h") + grade(hb, sR, gr, hfar, "h")
      if (ni + ns > nmax) {
        # the cause named: most of the elements are either still growing from the tip spacing
        # (grow^(1/refine) close to 1), or at the far-field size hmax/refine (hmax small against
        # b and the layers), or at the cap fseg * segment/refine (fseg small)
        ng = cnt["g"] + 0; nh = cnt["h"] + 0; nf = cnt["f"] + 0
        lower = (rm != 1 ? " or a lower --refine" : (refine != 1 ? " or a lower refine" : ""))
        growing = sprintf("%d of them grow from the tip spacing min(htipmax, ftip*min(a, b - a))/refine = %.3g mm by only grow^(1/refine) = %.6g per element", ng, htip, gr)
        if (ng >= nh && ng >= nf) {
          if (gr < 1.1 && grow >= 1.1)
            cause = sprintf("%s (grow = %s at refine %s): the refinement is too high for this grow; use a lower refinement, or a larger ftip or htipmax", growing, grow, refine)
          else
            cause = sprintf("%s: grow = %s %s; use grow > 1 (1.1 to 1.6 are usual), a larger ftip or htipmax%s", growing, grow, (grow == 1 ? "keeps the spacing at the tip size" : "is too close to 1"), lower)
        } else if (nh >= nf) {
          cause = sprintf("%d of them at the far-field spacing hmax/refine = %.3g mm, over the interface (b = %s mm) and the sides (h_m = %s, h_b = %s mm): %s is too small for this RVE (grow = %s is not the cause); use a larger hmax%s", \
            nh, hfar, b, hm, hb, (refine == 1 ? "hmax = " hmax " mm" : "hmax/refine = " hmax "/" refine " mm"), grow, lower)
        } else {
          cause = sprintf("%d of them at the cap fseg*segment/refine along the crack and the ligament: fseg = %s is too small (grow = %s is not the cause); use a larger fseg%s", nf, fseg, grow, lower)
        }
        printf "make-table.sh: error: grow = %s, ftip = %s, htipmax = %s, hmax = %s, fseg = %s, refine %s: at a = %s mm the mesh would need %s%d elements along the interface and %d along the sides (of the meshed quarter), more than the %d allowed (the mesh of one a would take gigabytes): %s (this crack length: %s)\n", \
          grow, ftip, htipmax, hmax, fseg, refine, $1, (ni >= ncap ? "more than " : ""), ni, ns, nmax, cause, source($1) > "/dev/stderr"
        exit 1
      }
    }' || exit 2
fi
if [ "$check_only" = 1 ]; then
  echo "$prog: $params: parameters ok ($na crack half-lengths, refine $refine)"
  exit 0
fi
# ---------------------------------------------------------------- run FreeFEM
outdir=$(dirname "$out")
[ -d "$outdir" ] || die 3 "output directory '$outdir' does not exist"
base=${out%.dat}
work=$(mktemp -d "${TMPDIR:-/tmp}/rve-table.XXXXXX") || die 3 "cannot create a scratch directory"
trap 'rm -rf "$work"' EXIT

script="$here/rve.edp"
[ -r "$script" ] || die 3 "cannot read $script"
if [ "${P[order]}" = P1 ]; then
  { echo "macro FEORDER P1 //"; cat "$script"; } > "$work/rve.edp"
else
  cp "$script" "$work/rve.edp"
fi
if [ "$want_fields" = 1 ] && [ -n "$fields_sel" ]; then printf '%s\n' "$fields_sel" > "$work/fields.list"; else : > "$work/fields.list"; fi
{ wc -l < "$work/fields.list"; cat "$work/fields.list"; } > "$work/fields.count"

# deal the a values to the jobs round robin from the largest a down (similar cost per job)
njobs=$(( jobs < na ? jobs : na ))
for ((j = 0; j < njobs; j++)); do
  printf '%s\n' "$alist" | sort -gr | awk -v j="$j" -v n="$njobs" '(NR - 1) % n == j' | sort -g > "$work/a$j.list"
  { wc -l < "$work/a$j.list"; cat "$work/a$j.list"; } > "$work/a$j.count"
done

# the uniform mesh (huni > 0) does not use the graded mesh's controls; rve.edp computes the graded
# point sets all the same, so it gets the defaults (checked cheap) instead of the user's values
declare -A G
for key in hmax ftip htipmax grow fseg; do
  if [ "$uniform" = 1 ]; then G[$key]=${D[$key]}; else G[$key]=${P[$key]}; fi
done
echo "$prog: $na crack half-lengths, element ${P[order]}, refine $refine, $njobs parallel FreeFEM job(s)"
t_start=$(date +%s.%N)
pids=()
for ((j = 0; j < njobs; j++)); do
  (
    set -o pipefail
    FreeFem++ -nw -v 0 "$work/rve.edp" \
      -hm "${P[h_m]}" -hb "${P[h_b]}" -b "${P[b]}" -Em "${P[E_m]}" -num "${P[nu_m]}" -Eb "${P[E_b]}" -nub "${P[nu_b]}" \
      -hmax "${G[hmax]}" -ftip "${G[ftip]}" -htipmax "${G[htipmax]}" -grow "${G[grow]}" -fseg "${G[fseg]}" \
      -refine "$refine" -huni "${P[huni]}" \
      -alist "$work/a$j.count" -out "$work/rows$j" -diag "$work/diag$j" \
      -fields "$work/fields$j" -fieldsa "$work/fields.count" 2> "$work/err$j" \
      | while IFS= read -r line; do case "$line" in *"a = "*" mm  (a/b = "*) printf '[job %d] %s\n' "$j" "$line" ;; *) printf '%s\n' "$line" >> "$work/err$j" ;; esac; done
  ) &
  pids+=($!)
done
failed=""
for ((j = 0; j < njobs; j++)); do
  wait "${pids[$j]}" || failed+=" $j"
done
if [ -n "$failed" ]; then
  # the jobs' messages, each once (a check that fails for every a fails in every job)
  echo "$prog: error: FreeFEM job(s)$failed failed:" >&2
  for j in $failed; do
    grep -v -e '^ *$' -e 'current line' -e 'call die' -e '^exit(' -e 'err code' "$work/err$j" | head -20
  done | awk '!seen[$0]++' | sed 's/^/  /' >&2
  exit 4
fi
t_end=$(date +%s.%N)
wall=$(awk -v a="$t_start" -v b="$t_end" 'BEGIN { printf "%.1f", b - a }')

cat "$work"/rows* | sort -g -k1,1 > "$work/rows"
cat "$work"/diag* | sort -g -k2,2 > "$work/diag"
nrows=$(wc -l < "$work/rows")
[ "$nrows" -eq "$na" ] || die 4 "expected $na rows, got $nrows"

# a = 0: T^f and ufbar have no value (T^f -> -infinity like 1/a): take those of the smallest a > 0
a1=$(awk '$1 > 0 { print $1; exit }' "$work/rows")
awk -v a1="${a1:-}" '
  NR == FNR { if ($1 == a1) { tf = $21; uf = $23 } next }
  { if ($21 == "lim0") { if (a1 == "") { $21 = "nan"; $23 = "nan" } else { $21 = tf; $23 = uf } } print }
' "$work/rows" "$work/rows" > "$work/rows.filled"

# ---------------------------------------------------------------- provenance header
ffver=$(FreeFem++ 2>&1 | awk '/version/ { sub(/^.*version */, ""); sub(/ .*/, ""); print; exit }')
debver=$(dpkg-query -W -f='${Version}' freefem++ 2>/dev/null || echo unknown)
sha=$(sha256sum "$script" | awk '{ print $1 }')
umin=$(awk '{ for (i = 1; i < NF; i++) if ($i == "ndof=") print $(i + 1) }' "$work/diag" | sort -g | head -1)
umax=$(awk '{ for (i = 1; i < NF; i++) if ($i == "ndof=") print $(i + 1) }' "$work/diag" | sort -g | tail -1)
hmin=$(awk '{ for (i = 1; i < NF; i++) if ($i == "htip=") print $(i + 1) }' "$work/diag" | sort -g | head -1)
chat=$(awk -v hm="${P[h_m]}" -v hb="${P[h_b]}" -v Em="${P[E_m]}" -v nm="${P[nu_m]}" -v Eb="${P[E_b]}" -v nb="${P[nu_b]}" 'BEGIN {
  Gm = Em / (2 * (1 + nm)); Gb = Eb / (2 * (1 + nb))
  Mm = Em * (1 - nm) / ((1 + nm) * (1 - 2 * nm)); Mb = Eb * (1 - nb) / ((1 + nb) * (1 - 2 * nb))
  h = hm + hb; printf "%.17g %.17g", h / (hm / Gm + hb / Gb), h / (hm / Mm + hb / Mb) }')
set -- $chat
{
  echo "# title = interphase RVE coefficient table (generated by rve_freefem/make-table.sh; do not edit)"
  echo "# format = interphase-rve-table 2"
  # the command as given (--jobs and --no-fields too, which change no number), and the parameter
  # file's content: its SHA-256 and each of its settings as read (comments and blank lines
  # dropped), so that the crack-length lists and mesh keys can be read back from the table
  echo "# command = $command_given"
  echo "# params_file = $params"
  echo "# params_sha256 = $params_sha"
  printf '%s\n' "$parsed" | awk -F'\t' '{ printf "# params_line = %s = %s\n", $1, $2 }'
  for w in "${warnings[@]}"; do echo "# warning = $w"; done
  echo "# script = rve_freefem/rve.edp"
  echo "# script_sha256 = $sha"
  echo "# freefem_version = $ffver (Debian package freefem++ $debver)"
  echo "# date = $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "# units = mm, MPa; E is s/h with h the RVE height h_m + h_b; E_NT engineering shear strain"
  echo "# model = plane strain; periodic lateral sides; brick y in [-h_b,0] (bottom fixed), mortar y in [0,h_m] (top displaced h*E); crack |x-b| < a on y = 0"
  echo "# crack_jump = two meshes coupled by Lagrange multipliers (imposed exactly)"
  for key in h_m h_b b E_m nu_m E_b nu_b; do echo "# $key = ${P[$key]}"; done
  echo "# h = $(awk -v a="${P[h_m]}" -v b="${P[h_b]}" 'BEGIN { printf "%.17g", a + b }')"
  echo "# Chat_TT = $1"
  echo "# Chat_NN = $2"
  echo "# element = ${P[order]}"
  if chk "${P[huni]}" "x > 0"; then
    echo "# mesh = uniform squares (each split into two triangles), side huni"
    echo "# huni = ${P[huni]}"
  else
    echo "# mesh = graded: interface spacing min(htipmax, ftip*min(a, b-a))/refine at the tips, growing by the factor grow^(1/refine), capped at min(hmax, fseg*segment)/refine; half RVE meshed and mirrored about x b"
    for key in hmax ftip htipmax grow fseg; do echo "# $key = ${P[$key]}"; done
  fi
  echo "# refine = $refine"
  echo "# smallest_tip_spacing = $hmin"
  echo "# unknowns_min = $umin"
  echo "# unknowns_max = $umax"
  echo "# n_a = $na"
  echo "# a0_row = no crack; Dbar, C^c, C^f, S^f are 0 and T^c, S^c equal C(0) (exact limits a -> 0+); T^f and ufbar copied from the smallest a > 0 (a: ${a1:-none} mm); T^f tends to -infinity like 1/a"
  echo "# crack_means = Dbar, ufbar: integral over the crack divided by 2a; T, S: sum of the multipliers divided by the sum of the interface weights over the crack nodes"
  echo "# I_fNT = integral over the crack of sigma^f(x) D_NT(x) dx (MPa mm): p3 normal crack stress per unit slip times the p1 normal jump per unit E_T, summed as multipliers x D_NT at the crack nodes; 0 at a = 0 (limit); the Betti relations of docs/rve.md"
  echo "# wall_time_s = $wall"
  echo "# columns: a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar I_fNT"
  cat "$work/rows.filled"
} > "$out.tmp" && mv "$out.tmp" "$out" || die 3 "cannot write $out"
{
  echo "# diagnostics for $out: per a, unknowns (ndof), mortar/brick DOFs, interface pairs, crack pairs,"
  echo "# triangles, smallest tip spacing (mm), time (s), max pointwise relative residuals of"
  echo "# T^c_T = Chat_TT (resTc), S^c_N = Chat_NN (resSc), uniform p3 shear stress (resTfpt), p3 jump = (u^f,0) (resuf)"
  cat "$work/diag"
} > "$base-diag.txt"
if [ "$want_fields" = 1 ] && [ -s "$work/fields.list" ]; then
  {
    echo "# distributions along the interface for $out (same provenance); x in [0, 2b), crack |x - b| < a"
    echo "# D_ij(x) = crack jump component i per unit E_j (mm); uf = u^f(x) (max 1); sf = sigma^f(x), p3 normal crack stress per unit slip (MPa/mm, odd about x = b; multiplier / interface weight); all 0 on the bonded part"
    echo "# one block per a (gnuplot index 0, 1, ...), blocks separated by two blank lines, ascending a"
    echo "# columns: a x D_TT D_NT D_TN D_NN uf sf"
    # paragraph mode: one record per block ("# a = ..." line + data); sort the blocks by a
    cat "$work"/fields[0-9]* | awk 'BEGIN { RS = "" } { split($0, l, "\n"); k = l[1]; sub(/^# a = /, "", k); key[++n] = k + 0; txt[n] = $0 }
      END { for (i = 2; i <= n; i++) { t = key[i]; u = txt[i]; for (j = i - 1; j >= 1 && key[j] > t; j--) { key[j + 1] = key[j]; txt[j + 1] = txt[j] } key[j + 1] = t; txt[j + 1] = u }
            for (i = 1; i <= n; i++) printf "%s\n%s", txt[i], (i < n ? "\n\n" : "") }'
  } > "$base-fields.dat"
fi
if ! { [ "$want_fields" = 1 ] && [ -s "$work/fields.list" ]; } && [ -e "$base-fields.dat" ]; then
  note "no side file written by this run: $base-fields.dat is from an earlier one"
fi
echo "$prog: wrote $out ($na rows) in $wall s wall time"
