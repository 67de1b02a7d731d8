#!/usr/bin/env bash
# Run a Python program of the interphase tests with a python3 that has numpy, scipy, matplotlib
# and pytest: Debian's /usr/bin/python3 first (where python3-numpy & co. install; another python3
# first on PATH, e.g. pyenv's, does not see them), else the python3 on PATH; INTERPHASE_PYTHON,
# when set, names the one python3 to use.
# Usage: run-python.sh SKIP_CODE ARGS...   (runs: python3 ARGS...)
# Without such a python3 it says so and exits SKIP_CODE: 77 (ctest: skipped) on users' machines,
# 1 (failed) under strict CI (INTERPHASE_STRICT_CI, CI=true), where nothing may be skipped.
set -u
skip=${1:?usage: run-python.sh SKIP_CODE ARGS...}
shift
modules="numpy, scipy, matplotlib, pytest"
if [ -n "${INTERPHASE_PYTHON:-}" ]; then candidates=("$INTERPHASE_PYTHON")
else candidates=(/usr/bin/python3 "$(command -v python3 2>/dev/null)"); fi
for python in "${candidates[@]}"; do
  [ -n "$python" ] && [ -x "$python" ] || continue
  if "$python" -c "import $modules" >/dev/null 2>&1; then
    export PYTHONDONTWRITEBYTECODE=1 MPLBACKEND=Agg
    exec "$python" "$@"
  fi
done
if [ "$skip" = 77 ] && [ "${CI:-}" = true ]; then skip=1; fi
echo "python3 with $modules not found (tried ${candidates[*]}):" \
  "install Debian's python3-numpy python3-scipy python3-matplotlib python3-pytest" \
  "(bash tools/ensure-packages.sh numpy scipy matplotlib pytest); the Python tests are" \
  "$([ "$skip" = 77 ] && echo skipped || echo 'a failure here (strict CI)')"
exit "$skip"
