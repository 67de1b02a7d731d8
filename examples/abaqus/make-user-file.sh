#!/bin/bash
# make-user-file.sh: write interphase as ONE Fortran source file for Abaqus's `user=` option.
#
#   examples/abaqus/make-user-file.sh [--explicit] [--build-dir DIR] [-o FILE]
#
#   (default)      Abaqus/Standard: umat + the STDB_ABQERR message hook
#   --explicit     Abaqus/Explicit: vumat + the XPLB_ABQERR message hook
#   --calculix     CalculiX: umat + the CalculiX message hook (standard output; exit 201 on a
#                  fatal error), for lib<NAME>.so (examples/calculix/build-calculix.sh)
#   --uexternaldb  also the start-of-analysis hook that loads a custom RVE table or R-curve
#                  (INTERPHASE_TABLE, INTERPHASE_RCURVE): src/abaqus/uexternaldb.f90 for
#                  Abaqus/Standard, src/abaqus/vexternaldb.f90 with --explicit
#   --build-dir    a configured and built interphase build directory, for the sources generated at
#                  build time (the compiled-in RVE table, generated/*.f90); default ./build/release
#   -o FILE        output file (default interphase_abaqus_standard.f90 / _explicit.f90)
#
# The file holds the entry point, the Abaqus message hook and every module they use, directly or
# not, in dependency order (each module before its users), found from the `use` statements of
# src/*.f90, src/abaqus/*.f90 and <build-dir>/generated/*.f90. It is free-form Fortran 2008:
#   abaqus job=couplet2d input=couplet2d_coh2d4.inp user=interphase_abaqus_standard.f90
# (name it .f if your Abaqus version accepts only that suffix and add the free-form flag of your
# compiler to abaqus_v6.env: Intel -free; gfortran -ffree-form -ffree-line-length-132; flang
# -ffree-form). See docs/abaqus.md.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
solver=standard
build_dir=$PWD/build/release
with_uexternaldb=no
output=""
while [ $# -gt 0 ]; do
   case "$1" in
      --explicit) solver=explicit ;;
      --standard) solver=standard ;;
      --calculix) solver=calculix ;;
      --uexternaldb) with_uexternaldb=yes ;;
      --build-dir) build_dir=$2; shift ;;
      -o) output=$2; shift ;;
      -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;;
      *) echo "make-user-file.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
   esac
   shift
done
[ -n "$output" ] || output=interphase_abaqus_$solver.f90
out_dir=$(dirname -- "$output")
if [ ! -d "$out_dir" ]; then
   echo "make-user-file.sh: the output folder '$out_dir' (of -o $output) does not exist" >&2
   exit 2
fi
if [ $solver = standard ]; then
   roots=("$root/src/abaqus/umat.f90" "$root/src/abaqus/host_abaqus_standard.f90")
   if [ $with_uexternaldb = yes ]; then roots+=("$root/src/abaqus/uexternaldb.f90"); fi
elif [ $solver = calculix ]; then
   # (calculix_start.f90: the loading of custom tables at start-up, called by the library's
   # load-time hook src/abaqus/calculix_start.c, which build-calculix.sh compiles beside)
   roots=("$root/src/abaqus/umat.f90" "$root/src/abaqus/host_calculix.f90" "$root/src/abaqus/calculix_start.f90")
   if [ $with_uexternaldb = yes ]; then
      echo "make-user-file.sh: CalculiX calls no UEXTERNALDB: --uexternaldb does not apply to --calculix" >&2
      exit 2
   fi
else
   roots=("$root/src/abaqus/vumat.f90" "$root/src/abaqus/host_abaqus_explicit.f90")
   if [ $with_uexternaldb = yes ]; then roots+=("$root/src/abaqus/vexternaldb.f90"); fi
fi

case $solver in
   calculix) host_label=CalculiX ;;
   *) host_label=Abaqus/${solver^} ;;
esac

# module name -> file that defines it
declare -A module_file=()
candidates=("$root"/src/*.f90 "$root"/src/abaqus/*.f90)
if [ -d "$build_dir/generated" ]; then candidates+=("$build_dir"/generated/*.f90); fi
for f in "${candidates[@]}"; do
   [ -f "$f" ] || continue
   while read -r name; do
      module_file[$name]=$f
   done < <(sed -n -E 's/^[[:space:]]*module[[:space:]]+([A-Za-z0-9_]+)[[:space:]]*(!.*)?$/\1/Ip' "$f" \
              | tr 'A-Z' 'a-z' | grep -v '^procedure$' || true)
done

# modules a file uses (intrinsic modules excluded)
uses_of() {
   sed -n -E 's/^[[:space:]]*use[[:space:]]+([A-Za-z0-9_]+).*/\1/Ip' "$1" | tr 'A-Z' 'a-z' | sort -u
}

# depth-first: every file after the files of the modules it uses
declare -A state=()
order=()
visit() {
   local f=$1 m dep
   case "${state[$f]:-}" in
      done) return ;;
      active) echo "make-user-file.sh: circular module dependency through $f" >&2; exit 1 ;;
   esac
   state[$f]=active
   for m in $(uses_of "$f"); do
      dep=${module_file[$m]:-}
      if [ -z "$dep" ]; then
         echo "make-user-file.sh: module '$m' used by $f is not in src/ or $build_dir/generated/" >&2
         echo "  (generated sources need a built tree: cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release && cmake --build build/release; then --build-dir build/release)" >&2
         exit 1
      fi
      visit "$dep"
   done
   state[$f]=done
   order+=("$f")
}
# intrinsic modules are never defined in our sources: mark them as known-external
for m in iso_fortran_env iso_c_binding ieee_arithmetic ieee_exceptions ieee_features omp_lib; do
   module_file[$m]=__intrinsic__
done
state[__intrinsic__]=done
for f in "${roots[@]}"; do visit "$f"; done

# a source with its INCLUDE lines replaced by the files they name (src/*.inc: one source of the
# procedures and statements included where the compiler must inline them), so that the one file
# needs no other file. An INCLUDE line must name one file of src/ in quotes, alone on its line; an included
# file may include others in turn (the UMAT's paths: src/interphase_umat_cohesive_path.inc
# includes interphase_law_update.inc, which includes interphase_displacement_damage.inc), to a
# depth of 3 (what else starts with INCLUDE is refused, not copied).
expand_includes() {
   local line name lower depth=${2:-0}
   while IFS= read -r line || [ -n "$line" ]; do
      lower=${line,,}
      if [[ $lower =~ ^[[:space:]]*include[[:space:]]*[\'\"] ]]; then
         if [[ $line =~ ^[[:space:]]*[Ii][Nn][Cc][Ll][Uu][Dd][Ee][[:space:]]+[\'\"]([^\'\"]+)[\'\"][[:space:]]*$ ]]; then
            name=${BASH_REMATCH[1]}
         else
            echo "make-user-file.sh: $1: an INCLUDE line that is not one quoted file name alone: $line" >&2
            return 1
         fi
         if [ ! -f "$root/src/$name" ]; then
            echo "make-user-file.sh: $1 includes '$name', which is not in src/" >&2
            return 1
         fi
         if [ "$depth" -ge 3 ]; then
            echo "make-user-file.sh: $1 includes '$name' at a depth beyond 3 (not supported)" >&2
            return 1
         fi
         echo "   ! ---- included from src/$name ----"
         expand_includes "$root/src/$name" $((depth + 1)) || return 1
         echo "   ! ---- end of src/$name ----"
      else
         printf '%s\n' "$line"
      fi
   done < "$1"
}

{
   echo "! interphase $(sed -n -E 's/^project\(interphase VERSION ([0-9.]+).*/\1/p' "$root/CMakeLists.txt") for ${host_label}: ONE source file."
   echo "! Generated by examples/abaqus/make-user-file.sh -- do not edit; regenerate from the sources."
   echo "! Files, in dependency order:"
   for f in "${order[@]}"; do echo "!   ${f#$root/}"; done
   for f in "${order[@]}"; do
      echo
      echo "! ==== ${f#$root/} ===="
      expand_includes "$f" || { rm -f "$output.tmp"; exit 1; }
   done
} > "$output.tmp" || { rm -f "$output.tmp"; exit 1; }
mv "$output.tmp" "$output"
echo "make-user-file.sh: wrote $output (${#order[@]} files, ${host_label})"
