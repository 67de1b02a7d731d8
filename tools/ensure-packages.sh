#!/usr/bin/env bash
# Install the optional Debian packages interphase uses, when they are missing and we can:
#   freefem++   (FreeFem++: RVE coefficient tables and their tests)
#   gnuplot-nox (gnuplot: PNG plots of the driver and of the tables)
#   pkgconf     (pkg-config: the test of the installed interphase.pc)
#   valgrind    (callgrind: the Debug suite's check of the UMAT's dispatch, umat_dispatch, and
#               tools/bench-ratios.sh's instruction counts)
#   python3-numpy, python3-scipy, python3-matplotlib, python3-pytest (the Python package
#   drivers/python/interphase, its examples and its tests), checked as modules of Debian's
#   /usr/bin/python3 (another python3 first on PATH, e.g. pyenv's, does not see Debian's packages)
#   flang-19 and libomp-19-dev (LLVM flang 19 with its OpenMP: the second compiler of
#               tools/run-tests.sh; asked for by name only, not by default)
# Usage: tools/ensure-packages.sh [freefem] [gnuplot] [pkgconfig] [valgrind] [numpy] [scipy] [matplotlib] [pytest]
#        [flang]
#        (default: freefem gnuplot)
# Never fails: where a package cannot be installed it says so, and the parts that need it
# skip with their own clear message.
set -u
want=("$@")
[ ${#want[@]} -eq 0 ] && want=(freefem gnuplot)

declare -A cmd_of=([freefem]=FreeFem++ [gnuplot]=gnuplot [pkgconfig]=pkg-config [valgrind]=valgrind [flang]=flang-new-19)
declare -A module_of=([numpy]=numpy [scipy]=scipy [matplotlib]=matplotlib [pytest]=pytest)
declare -A pkg_of=([freefem]=freefem++ [gnuplot]=gnuplot-nox [pkgconfig]=pkgconf [valgrind]=valgrind [numpy]=python3-numpy [scipy]=python3-scipy
                   [matplotlib]=python3-matplotlib [pytest]=python3-pytest [flang]="flang-19 libomp-19-dev")
debian_python=/usr/bin/python3

missing=()
for w in "${want[@]}"; do
  c=${cmd_of[$w]:-}
  if [ "$w" = flang ]; then
    # the compiler and the OpenMP runtime it links (the thread-safety test needs both)
    if ! command -v "$c" >/dev/null 2>&1 || [ ! -e /usr/lib/llvm-19/lib/libomp.so ]; then
      # shellcheck disable=SC2206  # two package names
      missing+=(${pkg_of[$w]})
    fi
    continue
  fi
  m=${module_of[$w]:-}
  if [ -n "$c" ]; then
    command -v "$c" >/dev/null 2>&1 || missing+=("${pkg_of[$w]}")
  elif [ -n "$m" ]; then
    { [ -x "$debian_python" ] && "$debian_python" -c "import $m" >/dev/null 2>&1; } || missing+=("${pkg_of[$w]}")
  else
    echo "ensure-packages: unknown component '$w'" >&2
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
  echo "ensure-packages: apt-get not available; not installing ${missing[*]} (dependent steps will be skipped)"
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then sudo="sudo -n"; else
    echo "ensure-packages: not root; not installing ${missing[*]} (dependent steps will be skipped)"
    exit 0
  fi
fi
echo "ensure-packages: installing ${missing[*]} from Debian's packages"
export DEBIAN_FRONTEND=noninteractive
if $sudo apt-get update -qq >/dev/null 2>&1 && \
   $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null 2>&1; then
  echo "ensure-packages: installed ${missing[*]}"
else
  echo "ensure-packages: could not install ${missing[*]} (dependent steps will be skipped)"
fi
exit 0
