#!/bin/bash
# build-calculix.sh: build what running interphase inside CalculiX needs (docs/calculix.md).
#
#   examples/calculix/build-calculix.sh [--cache-dir DIR] [--build-dir DIR] [--ccx FILE] [--lib-only]
#
#   1. ccx with external-behaviour support (-DCALCULIX_EXTERNAL_BEHAVIOURS_SUPPORT), built from
#      Debian's source package calculix-ccx (apt-get source; its build dependencies from Debian
#      with apt-get build-dep), into DIR/ccx. Debian's own ccx cannot call a user's UMAT (its
#      umat is the built-in example, bound inside the program). Cached: an existing DIR/ccx with
#      external-behaviour support is kept.
#   2. DIR/libINTERPHASE.so from the one-file user source (make-user-file.sh --calculix), the
#      library a material named @ABAQUS_INTERPHASE_UMAT... loads (with DIR on LD_LIBRARY_PATH),
#      with the load-time hook src/abaqus/calculix_start.c that loads INTERPHASE_TABLE and
#      INTERPHASE_RCURVE; rebuilt whenever a source is newer than it.
#
#   --cache-dir DIR  where ccx and the library go (default: <repository>/build/calculix)
#   --build-dir DIR  a configured and built interphase build tree, for the generated sources (the
#                    built-in RVE table); default <repository>/build/release
#   --ccx FILE       use this ccx instead of building one; refused unless it has external-behaviour
#                    support (the stock Debian binary has not: it would run a deck with such a
#                    material to "Job finished" with zero stress)
#   --lib-only       build the library only (ccx must be in DIR already, or given with --ccx)
#
# Exit status: 0 done; 77 ccx cannot be had here (not root, no apt-get, no source package: the
# tests skip with this message), 1 then instead when CI=true; 1 any other failure.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cache=$root/build/calculix
build_dir=$root/build/release
ccx_given=""
lib_only=no
while [ $# -gt 0 ]; do
   case "$1" in
      --cache-dir) cache=$2; shift ;;
      --build-dir) build_dir=$2; shift ;;
      --ccx) ccx_given=$2; shift ;;
      --lib-only) lib_only=yes ;;
      -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;;
      *) echo "build-calculix.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
   esac
   shift
done
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
# one build at a time in a cache (parallel tests call this script too)
exec 9>"$cache/.lock"
flock 9
say() { echo "build-calculix.sh: $*"; }
# what cannot be had here: exit 77 (the tests skip), but with CI=true a failure
unavailable() {
   if [ "${CI:-}" = true ]; then echo "build-calculix.sh: FAILED (CI): $*" >&2; exit 1; fi
   echo "build-calculix.sh: SKIP: $*" >&2
   exit 77
}

# A ccx has external-behaviour support when it carries the loader's own messages (external.c is
# compiled to nothing without the define). The decks' runner also checks the stresses it gets.
has_external_support() {
   [ -x "$1" ] && grep -q -a "unable to load function" "$1"
}

# the library (step 2) needs a built interphase tree, for its generated sources
need_build_tree() {
   [ -d "$build_dir/generated" ] || {
      echo "build-calculix.sh: $build_dir is not a built interphase tree (cmake -S . -B $build_dir -DCMAKE_BUILD_TYPE=Release && cmake --build $build_dir)" >&2
      exit 1
   }
}

# ---- 1. ccx -----------------------------------------------------------------------------------
if [ -n "$ccx_given" ]; then
   if ! has_external_support "$ccx_given"; then
      echo "build-calculix.sh: $ccx_given has no external-behaviour support (built without" >&2
      echo "  -DCALCULIX_EXTERNAL_BEHAVIOURS_SUPPORT, as Debian's ccx): it cannot call interphase's UMAT" >&2
      exit 1
   fi
   ln -sf "$(cd "$(dirname "$ccx_given")" && pwd)/$(basename "$ccx_given")" "$cache/ccx"
elif [ $lib_only = yes ]; then
   has_external_support "$cache/ccx" || { echo "build-calculix.sh: no ccx in $cache (run without --lib-only)" >&2; exit 1; }
elif has_external_support "$cache/ccx"; then
   say "ccx with external-behaviour support: $cache/ccx (cached)"
else
   # (said before ccx's build of a few minutes, not after it)
   need_build_tree
   command -v apt-get >/dev/null 2>&1 || unavailable "no apt-get: cannot fetch Debian's calculix-ccx source"
   [ "$(id -u)" -eq 0 ] || unavailable "not root: cannot install calculix-ccx's build dependencies (run as root, or pass --ccx)"
   export DEBIAN_FRONTEND=noninteractive
   # a deb-src stanza for every deb stanza of the machine's Debian sources (deb822 form)
   src_list=/etc/apt/sources.list.d/interphase-deb-src.sources
   if ! grep -rqs "^Types:.*deb-src" /etc/apt/sources.list.d/ && ! grep -qs "^deb-src" /etc/apt/sources.list; then
      if [ -f /etc/apt/sources.list.d/debian.sources ]; then
         sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources > "$src_list"
      elif [ -f /etc/apt/sources.list ]; then
         src_list=/etc/apt/sources.list.d/interphase-deb-src.list
         sed -n 's/^deb /deb-src /p' /etc/apt/sources.list > "$src_list"
      else
         unavailable "no Debian source list to mirror as deb-src"
      fi
      say "added Debian source stanzas ($src_list)"
   fi
   say "apt-get update"
   apt-get update -qq >/dev/null 2>&1 || unavailable "apt-get update failed"
   say "installing calculix-ccx's build dependencies (apt-get build-dep)"
   apt-get build-dep -y -qq calculix-ccx >"$cache/build-dep.log" 2>&1 || \
      unavailable "apt-get build-dep calculix-ccx failed (see $cache/build-dep.log)"
   rm -rf "$cache/source"
   mkdir -p "$cache/source"
   say "fetching Debian's calculix-ccx source"
   (cd "$cache/source" && apt-get source -qq calculix-ccx >"$cache/source.log" 2>&1) || \
      unavailable "apt-get source calculix-ccx failed (see $cache/source.log)"
   src=""
   for d in "$cache"/source/calculix-ccx-*/ccx_*/src; do [ -d "$d" ] && src=$d && break; done
   [ -n "$src" ] || { echo "build-calculix.sh: no ccx_*/src in the source package (see $cache/source.log)" >&2; exit 1; }
   version=$(basename "$(dirname "$src")")
   say "building $version with external-behaviour support in $src (a few minutes)"
   # Debian's flags (debian/rules) plus the define and the dynamic loader, as upstream's
   # Makefile_MFront does
   cflags='-Wall -O2 -I/usr/include/spooles -DARCH="Linux" -DSPOOLES -DARPACK -DMATRIXSTORAGE -DUSE_MT=1 -DCALCULIX_EXTERNAL_BEHAVIOURS_SUPPORT'
   (cd "$src" && make -j "$(nproc 2>/dev/null || echo 2)" CFLAGS="$cflags" \
      FFLAGS="-O2 -fallow-argument-mismatch -fopenmp" \
      LIBS="-lspooles -lpthread -larpack -llapack -lblas -lm -lc -ldl" >"$cache/make.log" 2>&1) || \
      { echo "build-calculix.sh: building ccx failed (see $cache/make.log)" >&2; exit 1; }
   cp "$src/$version" "$cache/ccx.new"
   has_external_support "$cache/ccx.new" || { echo "build-calculix.sh: the new ccx lacks external-behaviour support" >&2; exit 1; }
   mv "$cache/ccx.new" "$cache/ccx"
   say "built $cache/ccx"
fi

# ---- 2. libINTERPHASE.so ----------------------------------------------------------------------
need_build_tree
lib=$cache/libINTERPHASE.so
fc=${FC:-gfortran}
if [ ! -f "$lib" ] || [ -n "$(find "$root/src" "$build_dir/generated" \( -name '*.f90' -o -name '*.inc' -o -name '*.c' \) -newer "$lib" | head -n 1)" ]; then
   "$root/examples/abaqus/make-user-file.sh" --calculix --build-dir "$build_dir" -o "$cache/interphase_calculix.f90" >/dev/null
   # -O2 as a host's user-subroutine build; UMAT is the name the deck's material gives
   # (@ABAQUS_INTERPHASE_UMAT: the deck is upper-cased), umat_ the Fortran one
   # calculix_start.c: the load-time hook that loads INTERPHASE_TABLE / INTERPHASE_RCURVE
   (cd "$cache" && "${CC:-cc}" -O2 -fPIC -c "$root/src/abaqus/calculix_start.c" -o calculix_start.o && \
      "$fc" -O2 -fPIC -shared -ffree-line-length-none -o libINTERPHASE.so.new interphase_calculix.f90 calculix_start.o \
      -Wl,--defsym,UMAT=umat_ -llapack -lblas) || { echo "build-calculix.sh: compiling libINTERPHASE.so failed" >&2; exit 1; }
   rm -f "$cache"/*.mod
   mv "$lib.new" "$lib"
   say "built $lib"
else
   say "library up to date: $lib"
fi
