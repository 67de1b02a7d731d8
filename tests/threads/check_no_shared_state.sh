#!/bin/bash
# Usage: check_no_shared_state.sh <dir>...
# Scans every .f90/.F90/.f/.F file, and every .inc file (sources the others include), under the
# given directories for state shared between calls (SAVE, COMMON, DATA, module variables that are
# not PARAMETER or PROTECTED, initialised local variables) with check_no_shared_state.awk. Exit status 0 when none is found, 1 otherwise.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
files=()
for dir in "$@"; do
   while IFS= read -r -d '' f; do files+=("$f"); done \
      < <(find "$dir" -type f \( -name '*.f90' -o -name '*.F90' -o -name '*.f' -o -name '*.F' -o -name '*.inc' \) -print0 | sort -z)
done
if [ ${#files[@]} -eq 0 ]; then
   echo "check_no_shared_state: no Fortran sources under: $*" >&2
   exit 2
fi
awk -v files_checked=${#files[@]} -f "$here/check_no_shared_state.awk" "${files[@]}"
