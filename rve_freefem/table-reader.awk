# table-reader.awk -- read one RVE coefficient table as the library's loader reads it
# (src/interphase_rve_table.f90, tables/README.md 'Format') and write it in the canonical column
# order: the one reader of check-table.sh, compare-tables.sh, plot-coefficients.sh and
# convergence.sh, so that they all take the columns by name, in any order, and refuse what the
# loader refuses in the file's form.
#
#   awk -f table-reader.awk -v dest=CANONICAL.dat TABLE.dat
#
# Writes to dest the header lines as read (the numbers of the keys the loader reads as %.17g), the line "# columns: a D C_TT ... ufbar" (I_fNT last
# where the table has it) and the rows with their numbers in that order (%.17g: the values read,
# a Fortran d exponent read as e). Prints what it refuses, one line each, on standard output and
# exits 1 (dest is then incomplete); exits 0 otherwise, printing nothing.
#
# Read as the loader reads: a carriage return ending a line dropped (CRLF files); a UTF-8
# byte-order mark refused; blanks and tabs before and after a "#"; every header line
# "# key = value" (the key all before the first " = "); a key the loader reads given once, and not
# after the "# columns:" line (where the loader refuses it too; it also refuses misspellings of
# such keys there, which this reader does not look for);
# b, h, h_m, h_b, E_m, E_b, Chat_TT, Chat_NN one positive number, nu_m and nu_b one number in
# (-1, 0.5); b and h given; h = h_m + h_b (1e-12 h) where the layers are given; one "# columns:"
# line naming the 23 columns of format 1 (and I_fNT, format 2), each once; every row as many
# finite numbers, [sign](digits[.[digits]] | .digits)[(e|E|d|D)[sign]digits]; a strictly
# ascending from 0 to b; at least 4 rows (the loader's not-a-knot spline).
function abs(x) { return x < 0 ? -x : x }
function isnumber(s) { return s ~ /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eEdD][+-]?[0-9]+)?$/ }
# its value (a d/D exponent read as e); finite() is false beyond the range of a double
function numval(s) { sub(/[dD]/, "e", s); return s + 0 }
function finite(x) { return sprintf("%g", x) !~ /inf|nan/ }
function refuse(text) { print text; bad = 1 }
function header_number(key, value, lower, upper) {
  if (!isnumber(value) || !finite(numval(value))) return 0
  if (upper == "") return numval(value) > lower
  return numval(value) > lower && numval(value) < upper
}
BEGIN {
  ncanon = split("a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar I_fNT", canon, " ")
  nread = split("b h a_Tf_limit E_m nu_m E_b nu_b h_m h_b Chat_TT Chat_NN format interpolation_variable", readkeys, " ")
  for (i = 1; i <= nread; i++) isread[readkeys[i]] = 1
  split("b h h_m h_b E_m E_b Chat_TT Chat_NN", poskeys, " "); for (i in poskeys) positive[poskeys[i]] = 1
  if (dest == "") { print "table-reader.awk: dest (the canonical table to write) not given"; exit 2 }
  printf "" > dest
}
{ sub(/\r$/, "") }
NR == 1 && index($0, "\357\273\277") == 1 {
  refuse("line 1: the file starts with a UTF-8 byte-order mark (bytes EF BB BF): save it without one")
  sub(/^\357\273\277/, "")
}
/^[ \t]*#/ {
  # (as the loader: blanks and tabs before and after the #; the line written as "# " and the rest)
  rest = $0; sub(/^[ \t]*#[ \t]*/, "", rest)
  line = "# " rest
  if (rest ~ /^columns:/) {
    ncolsline++
    if (ncolsline > 1) { refuse("line " NR ": a second \"# columns:\" line"); next }
    c = rest; sub(/^columns:/, "", c)
    ncol = split(c, names, " ")
    for (i = 1; i <= ncol; i++) {
      pos[i] = 0
      for (j = 1; j <= ncanon; j++) if (names[i] == canon[j]) pos[i] = j
      if (pos[i] == 0) refuse("the # columns: line names an unknown column " names[i])
      else if (pos[i] in seen) refuse("the # columns: line names " names[i] " twice")
      else seen[pos[i]] = 1
    }
    for (j = 1; j <= 23; j++) if (!(j in seen)) refuse("the # columns: line does not name " canon[j])
    withI = (24 in seen)
    out = "# columns:"; for (j = 1; j <= (withI ? 24 : 23); j++) out = out " " canon[j]
    print out > dest
    next
  }
  # "key = value": the key all before the first " = " (as the loader, which ignores keys it does
  # not read)
  eqpos = index(rest, " = ")
  if (ncolsline > 0) {
    # after the header: a key the loader reads would be ignored there, and the loader refuses it
    if (eqpos >= 2 && (substr(rest, 1, eqpos - 1) in isread))
      refuse("line " NR ": key \"" substr(rest, 1, eqpos - 1) "\" after the \"# columns:\" line, where the header has ended")
  } else {
    if (eqpos < 2) refuse("header line is not \"# key = value\": " $0)
    else {
      k = substr(rest, 1, eqpos - 1); hv = substr(rest, eqpos + 3)
      if (k in isread) {
        if (k in hdr) refuse("line " NR ": key \"" k "\" given twice")
        else {
          f = hv; gsub(/^[ \t]+|[ \t]+$/, "", f)
          if ((k in positive) && !header_number(k, f, 0, "")) refuse("line " NR ": " k " = \"" f "\" is not one positive number")
          if ((k == "nu_m" || k == "nu_b") && !header_number(k, f, -1, 0.5)) refuse("line " NR ": " k " = \"" f "\" is not one number in (-1, 0.5)")
          # (its number as read, a d exponent as e: the tools read the canonical header with awk)
          if (isnumber(f) && finite(numval(f))) { line = "# " k " = " sprintf("%.17g", numval(f)); hv = f }
        }
      }
      hdr[k] = hv
    }
  }
  print line > dest
  next
}
NF == 0 { next }
{
  n++
  if (ncolsline == 0) { refuse("row " n " (line " NR ") comes before the # columns: line"); aborted = 1; exit 1 }
  if (NF != ncol) refuse("row " n " has " NF " fields, the columns line names " ncol)
  delete x
  for (i = 1; i <= NF; i++) {
    if (!isnumber($i) || !finite(numval($i))) { refuse("row " n " field " i " not a finite number: " $i); x[i] = 0 }
    else x[i] = numval($i)
  }
  for (i = 1; i <= NF && i <= ncol; i++) if (pos[i] > 0) val[pos[i]] = x[i]
  if (n > 1 && !(val[1] > a_prev)) refuse("row " n " (line " NR "): a = " val[1] " does not exceed the previous a = " a_prev)
  if (n == 1) a_first = val[1]
  a_prev = val[1]
  out = ""; for (j = 1; j <= (withI ? 24 : 23); j++) out = out (j > 1 ? " " : "") sprintf("%.17g", val[j])
  print out > dest
}
END {
  if (aborted) { close(dest); exit 1 }
  if (ncolsline == 0) refuse("the # columns: line is missing")
  if (!("b" in hdr) || !("h" in hdr)) refuse("the header before \"# columns:\" must give \"b = ...\" and \"h = ...\"")
  else if (("h_m" in hdr) && ("h_b" in hdr) && header_number("h", hdr["h"], 0, "") && header_number("h_m", hdr["h_m"], 0, "") \
           && header_number("h_b", hdr["h_b"], 0, "")) {
    h = numval(hdr["h"]); hs = numval(hdr["h_m"]) + numval(hdr["h_b"])
    if (abs(hs - h) > 1e-12 * h) refuse("the header's h = " h " mm is not h_m + h_b = " hs " mm")
  }
  if (n < 4) refuse(n " rows: a table needs at least 4 (a = 0, a = b and 2 between; the loader's not-a-knot cubic spline)")
  else if (("b" in hdr) && header_number("b", hdr["b"], 0, "")) {
    b = numval(hdr["b"])
    if (a_first != 0 || abs(a_prev - b) > 1e-12 * b) refuse("rows must run from a = 0 to a = b = " b " mm (they run from " a_first " to " a_prev ")")
  }
  close(dest)
  exit bad
}
