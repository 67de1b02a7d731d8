#!/bin/bash
# make-decks.sh: (re)write the shipped decks examples/calculix/decks/*.inp with make-deck.sh, the
# couplet shear test of interphase-fe2d in CalculiX: 2-D (CPE4) and 3-D (C3D8), both models,
# monotonic and cyclic, joint layer t = 0.1 mm.
#   examples/calculix/make-decks.sh            rewrite them
#   examples/calculix/make-decks.sh --check DIR  write them into DIR and compare (ctest calculix_decks_current)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=$here/decks
check=no
if [ "${1:-}" = --check ]; then check=yes; target=${2:?make-decks.sh --check DIR}; fi
mkdir -p "$target"
cd "$root"
status=0
for dim in 2 3; do
   for model in simplified micromechanical; do
      for history in monotonic cyclic; do
         name=couplet${dim}d-$model-$history
         bash "$here/make-deck.sh" --dim $dim --model $model --history drivers/fe2d/cases/$history.txt \
            -o "$target/$name.inp" > /dev/null
         if [ $check = yes ] && ! cmp -s "$target/$name.inp" "$here/decks/$name.inp"; then
            echo "FAILED: examples/calculix/decks/$name.inp is not what make-deck.sh writes now (run examples/calculix/make-decks.sh)"
            status=1
         fi
      done
   done
done
[ $check = yes ] && [ $status -eq 0 ] && echo "the 8 shipped decks are current"
[ $check = no ] && echo "make-decks.sh: wrote 8 decks into $target"
exit $status
