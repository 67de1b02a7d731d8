#!/usr/bin/env bash
# Fortran source lines of at most 132 characters (the free-form limit of the standard, comments
# included; gfortran's -ffree-line-length-132 does not look at comments, so a long comment line
# builds here and may be refused by another compiler or the one-file sources' strict flags).
# Usage: check_line_length.sh DIR...   Exit status 1, naming each line, when one is longer.
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: check_line_length.sh DIR..." >&2; exit 2; }
found=$(find "$@" -type f \( -name '*.f90' -o -name '*.F90' -o -name '*.inc' \) -print0 | sort -z \
  | xargs -0 awk 'length($0) > 132 { print FILENAME ":" FNR ": " length($0) " characters" }')
if [ -n "$found" ]; then
  echo "$found"
  echo "check_line_length.sh: lines longer than 132 characters"
  exit 1
fi
echo "check_line_length.sh: no line longer than 132 characters"
