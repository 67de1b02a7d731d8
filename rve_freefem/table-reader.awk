# table-reader.awk -- read one RVE coefficient table as the library's loader reads it
# (src/interphase_rve_table.f90, tables/README.md 'Format') and write it in the canonical column
# order: the one reader of check-table.sh, compare-tables.sh, plot-coefficients.sh and
# convergence.sh, so that they all take the columns by name, in any order, and refuse what the
# loader refuses in the file's form.
#
#   awk -f table-reader.awk -v dest=CANONICAL.dat [-v file=NAME] TABLE.dat
#
# With file, each refusal names it: "NAME:LINE: what" (the file's line number) where the refusal
# is about one line, "NAME: what" otherwise; without it, "line LINE: what" and "what".
# Writes to dest the header lines as read (the numbers of the keys the loader reads as %.17g), the line "# columns: a D C_TT ... ufbar" (I_fNT last
# where the table has it) and the rows with their numbers in that order (%.17g: the values read,
# a Fortran d exponent read as e). Prints what it refuses, one line each, on standard output and
# exits 1 (dest is then incomplete); exits 0 otherwise, printing nothing.
#
# Read as the loader reads: a carriage return ending a line dropped (CRLF files); a UTF-8
# byte-order mark refused; blanks and tabs before and after a "#"; every header line
# "# key = value" (the key all before the first " = "); a key the loader reads given once, and
# neither it nor a key spelt like it (B, fromat: the loader's near_reader_key) anywhere else, nor
# after the "# columns:" line;
# b, h, h_m, h_b, E_m, E_b, Chat_TT, Chat_NN one number in [1e-20, 1e20], nu_m and nu_b one number
# in (-1, 0.5), a_Tf_limit in [-1e20, 0] and, with E_m nu_m E_b nu_b, their short-crack limit
# (1e-8); h_m with h_b, and E_m nu_m E_b nu_b all or none; format and interpolation_variable
# values the loader knows; b and h given; h = h_m + h_b (1e-12 h) where the layers are given; one "# columns:"
# line naming the 23 columns of format 1 (and I_fNT, format 2), each once; every row as many
# numbers, each 0 or of magnitude in [2.2250738585072014e-308, 1e100] (1e-400, 1e-310 refused), [sign](digits[.[digits]] | .digits)[(e|E|d|D)[sign]digits]; a strictly
# ascending from 0 to b (the reading stops at the first row it cannot read, a number missing or
# one more, or a field not a number or out of range, as the loader stops: no follow-on errors,
# such as an a out of order after "12,5" in the a column); at least 4 rows (the loader's not-a-knot spline); the a = 0 row's Dbar_TT
# and Dbar_NN 0 (within 1e-8 h) with the elastic constants, else in [0, h].
function abs(x) { return x < 0 ? -x : x }
function isnumber(s) { return s ~ /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eEdD][+-]?[0-9]+)?$/ }
# its value (a d/D exponent read as e); finite() is false beyond the range of a double
function numval(s) { sub(/[dD]/, "e", s); return s + 0 }
function finite(x) { return sprintf("%g", x) !~ /inf|nan/ }
# a refusal "line N: what" is printed "FILE:N: what" and any other "FILE: what" when file is given
function comma_to_point(s) { sub(/,/, ".", s); return s }
function refuse(text) {
  if (file != "") { if (text ~ /^line [0-9]+: /) { sub(/^line /, "", text); text = file ":" text } else text = file ": " text }
  print text; bad = 1
}
# the name of column i of the file's "# columns:" line
function colname(i) { return (i <= ncol) ? names[i] : "beyond the columns line" }
# a literal whose digits are not all zero but whose value is below the smallest normal double
# reads as 0 or a subnormal: the loader refuses it as out of range (a value, never its string,
# is compared: mawk compares a field such as "1e-400" as a string)
function underflows(s,   m, x) {
  m = s; sub(/[eEdD].*$/, "", m)
  if (m !~ /[1-9]/) return 0
  x = numval(s) + 0
  return (x < 0 ? -x : x) < 2.2250738585072014e-308
}
function header_number(key, value, lower, upper) {
  if (!isnumber(value) || !finite(numval(value)) || underflows(value)) return 0
  if (upper == "") return numval(value) > lower
  return numval(value) > lower && numval(value) < upper
}
# as the loader's near_reader_key: the key read that `k` is spelt like ("" when none): the same
# but for case, "_", "-" and blanks; for keys of six characters or more one character left out,
# added or two neighbours swapped; for interpolation_variable any two edits; a provenance key never
function squeezed(s) { s = tolower(s); gsub(/[-_ \t]/, "", s); return s }
function dropped_one(s, t,   i) {
  if (length(s) != length(t) - 1) return 0
  for (i = 1; i <= length(t); i++) if (s == substr(t, 1, i - 1) substr(t, i + 1)) return 1
  return 0
}
function one_slip(s, t,   i) {
  if (dropped_one(s, t) || dropped_one(t, s)) return 1
  if (length(s) != length(t)) return 0
  for (i = 1; i < length(t); i++)
    if (substr(t, i, 1) != substr(t, i + 1, 1) && s == substr(t, 1, i - 1) substr(t, i + 1, 1) substr(t, i, 1) substr(t, i + 2)) return 1
  return 0
}
function edit_distance(s, t,   i, j, d, ls, lt, c) {
  ls = length(s); lt = length(t)
  for (j = 0; j <= lt; j++) d[0, j] = j
  for (i = 1; i <= ls; i++) {
    d[i, 0] = i
    for (j = 1; j <= lt; j++) {
      c = d[i - 1, j - 1] + (substr(s, i, 1) == substr(t, j, 1) ? 0 : 1)
      if (d[i - 1, j] + 1 < c) c = d[i - 1, j] + 1
      if (d[i, j - 1] + 1 < c) c = d[i, j - 1] + 1
      d[i, j] = c
    }
  }
  return d[ls, lt]
}
function near_key(k,   i, key) {
  if (k == "" || (k in provenance)) return ""
  for (i = 1; i <= nread; i++) if (k == readkeys[i] || squeezed(k) == squeezed(readkeys[i])) return readkeys[i]
  for (i = 1; i <= nread; i++) {
    key = readkeys[i]
    if (length(key) >= 16) { if (edit_distance(tolower(k), tolower(key)) <= 2) return key }
    else if (length(key) >= 6) { if (one_slip(tolower(k), tolower(key))) return key }
  }
  return ""
}
# the short-crack limit -E*/(4(1 - beta^2)) of the header's E, nu (the loader's short_crack_a_tf)
function short_crack_a_tf(em, num, eb, nub,   es, gm, gb, km, kb, beta) {
  es = 2 / ((1 - num * num) / em + (1 - nub * nub) / eb)
  gm = em / (2 * (1 + num)); gb = eb / (2 * (1 + nub)); km = 3 - 4 * num; kb = 3 - 4 * nub
  beta = (gm * (kb - 1) - gb * (km - 1)) / (gm * (kb + 1) + gb * (km + 1))
  return -es / (4 * (1 - beta * beta))
}
BEGIN {
  ncanon = split("a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar I_fNT", canon, " ")
  nread = split("b h a_Tf_limit E_m nu_m E_b nu_b h_m h_b Chat_TT Chat_NN format interpolation_variable", readkeys, " ")
  for (i = 1; i <= nread; i++) isread[readkeys[i]] = 1
  split("b h h_m h_b E_m E_b Chat_TT Chat_NN", poskeys, " "); for (i in poskeys) positive[poskeys[i]] = 1
  np = split("title command params_file params_sha256 params_line script script_sha256 freefem_version date units model crack_jump element mesh hmax ftip htipmax grow fseg huni refine smallest_tip_spacing unknowns_min unknowns_max n_a a0_row crack_means I_fNT wall_time_s warning", pk, " ")
  for (i = 1; i <= np; i++) provenance[pk[i]] = 1
  if (dest == "") { print "table-reader.awk: dest (the canonical table to write) not given"; exit 2 }
  printf "" > dest
}
{ sub(/\r$/, "") }
NR == 1 && index($0, "\357\273\277") == 1 {
  refuse("line 1: the file starts with a UTF-8 byte-order mark (bytes EF BB BF): save it without one")
  sub(/^\357\273\277/, "")
}
/^[ \t]*#/ {
  # (as the loader: blanks and tabs before and after the #; the line written as "# " and the rest;
  # a tab in a header line is a blank, so "# Chat_TT<TAB>= 1" is the key Chat_TT)
  rest = $0; sub(/^[ \t]*#[ \t]*/, "", rest); gsub(/\t/, " ", rest)
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
    if (eqpos >= 2 && near_key(substr(rest, 1, eqpos - 1)) != "")
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
          else if ((k in positive) && (numval(f) < 1e-20 || numval(f) > 1e20)) refuse("line " NR ": " k " = \"" f "\" lies outside [1e-20, 1e20]")
          if ((k == "nu_m" || k == "nu_b") && !header_number(k, f, -1, 0.5)) refuse("line " NR ": " k " = \"" f "\" is not one number in (-1, 0.5)")
          if (k == "a_Tf_limit" && !(header_number(k, f, -1e21, 1) && numval(f) >= -1e20 && numval(f) <= 0)) refuse("line " NR ": a_Tf_limit = \"" f "\" is not one number in [-1e20, 0]")
          if (k == "format" && f != "interphase-rve-table 1" && f != "interphase-rve-table 2") refuse("line " NR ": format = \"" f "\" is not one the loader knows")
          if (k == "interpolation_variable" && f != "w" && f != "D") refuse("line " NR ": interpolation_variable must be w or D, not \"" f "\"")
          keyline[k] = NR
          # (its number as read, a d exponent as e: the tools read the canonical header with awk)
          if (isnumber(f) && finite(numval(f))) { line = "# " k " = " sprintf("%.17g", numval(f)); hv = f }
        }
      }
      else if (near_key(k) != "") refuse("line " NR ": unknown key \"" k "\": is it \"" near_key(k) "\"? (the keys are case-sensitive)")
      hdr[k] = hv
    }
  }
  print line > dest
  next
}
NF == 0 { next }
{
  n++
  if (ncolsline == 0) { refuse("line " NR ": a data row (row " n ") comes before the # columns: line"); aborted = 1; exit 1 }
  # (as the loader, the reading stops at the first row it cannot read: a value taken for an
  # unreadable one would make follow-on errors, an a out of order among them)
  if (NF != ncol) { refuse("line " NR ": " NF " numbers where the # columns: line names " ncol); aborted = 1; exit 1 }
  delete x
  for (i = 1; i <= NF; i++) {
    if (!isnumber($i) || !finite(numval($i)))
      refuse("line " NR ": column " i " (" colname(i) ") is not a finite number: " $i ($i ~ /^[+-]?[0-9]*,[0-9]/ ? " (a decimal comma? write a point: " comma_to_point($i) ")" : ""))
    else if (underflows($i)) refuse("line " NR ": column " i " (" colname(i) ") is out of range (|x| < 2.2e-308): " $i)
    else if (abs(numval($i)) > 1e100) refuse("line " NR ": column " i " (" colname(i) ") lies beyond 1e100 in magnitude: " $i)
    else { x[i] = numval($i); continue }
    aborted = 1; exit 1
  }
  for (i = 1; i <= NF && i <= ncol; i++) if (pos[i] > 0) val[pos[i]] = x[i]
  if (n > 1 && !(val[1] > a_prev)) refuse("line " NR ": a = " val[1] " does not exceed the previous row's a = " a_prev " (line " a_prev_line ")")
  if (n == 1) { a_first = val[1]; dbar0["Dbar_TT"] = val[7]; dbar0["Dbar_NN"] = val[10]; dbar0_line = NR }
  a_prev = val[1]; a_prev_line = NR
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
  # a key without its partners would go unused; a_Tf_limit must agree with the elastic constants
  if (("h_m" in keyline) != ("h_b" in keyline)) refuse("the header gives " (("h_m" in keyline) ? "h_m but not h_b" : "h_b but not h_m") " (h = h_m + h_b is checked with both)")
  ne = ("E_m" in keyline) + ("nu_m" in keyline) + ("E_b" in keyline) + ("nu_b" in keyline)
  if (ne > 0 && ne < 4) {
    lack = ""; split("E_m nu_m E_b nu_b", ek, " ")
    for (i = 1; i <= 4; i++) if (!(ek[i] in keyline)) lack = lack (lack == "" ? "" : ", ") ek[i]
    refuse("the header gives some of E_m, nu_m, E_b, nu_b but not " lack " (the loader reads all four or none)")
  }
  if (ne == 4 && ("a_Tf_limit" in keyline) && !bad) {
    lim = short_crack_a_tf(numval(hdr["E_m"]), numval(hdr["nu_m"]), numval(hdr["E_b"]), numval(hdr["nu_b"]))
    if (abs(numval(hdr["a_Tf_limit"]) - lim) > 1e-8 * abs(lim))
      refuse("line " keyline["a_Tf_limit"] ": a_Tf_limit = " hdr["a_Tf_limit"] " contradicts the header's E_m, nu_m, E_b, nu_b, which give " sprintf("%.17g", lim))
  }
  # the a = 0 row's mean crack jumps, as the loader checks them: 0 (within 1e-8 h) for a crack
  # between two elastic layers (the header's E_m, nu_m, E_b, nu_b), else within [0, h]
  if (n >= 1 && ("h" in hdr) && header_number("h", hdr["h"], 0, "")) {
    h = numval(hdr["h"])
    for (k in dbar0) {
      if (ne == 4 && abs(dbar0[k]) > 1e-8 * h)
        refuse("line " dbar0_line ": " k " = " dbar0[k] " at a = 0, where the limit a -> 0+ is 0 (within 1e-8 h) for a crack between the header's elastic layers")
      else if (ne != 4 && (dbar0[k] < -1e-8 * h || dbar0[k] > h * (1 + 1e-8)))
        refuse("line " dbar0_line ": " k " = " dbar0[k] " at a = 0 lies outside [0, h = " h " mm]")
    }
  }
  if (n < 4) refuse(n " rows: a table needs at least 4 (a = 0, a = b and 2 between; the loader's not-a-knot cubic spline)")
  else if (("b" in hdr) && header_number("b", hdr["b"], 0, "")) {
    b = numval(hdr["b"])
    if (a_first != 0 || abs(a_prev - b) > 1e-12 * b) refuse("rows must run from a = 0 to a = b = " b " mm (they run from " a_first " to " a_prev ")")
  }
  close(dest)
  exit bad
}
