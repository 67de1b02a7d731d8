#!/bin/bash
# ctest calculix_deck_options: make-deck.sh writes --mu into PROPS(3) of the joint and
# --precompression into step 1's pressure, refuses values that are not numbers >= 0, and
# run-case.sh refuses a deck whose interphase material lost its leading @ (CalculiX would run its
# own example UMAT for it, silently). Needs no ccx.
set -uo pipefail
cx=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
status=0
failed() { echo "FAILED: $*"; status=1; }
printf '# t u\n0 0\n1 0.1\n' > "$work/h.txt"
for dim in 2 3; do
   deck=$work/d$dim.inp
   bash "$cx/make-deck.sh" --dim $dim --model simplified --history "$work/h.txt" --mu 0.5 --precompression 1.25 \
      -o "$deck" >/dev/null || failed "make-deck.sh --dim $dim --mu 0.5 --precompression 1.25 failed"
   props=$(awk 'u { print; exit } /^\*USER MATERIAL/ { u = 1 }' "$deck")
   [ "$(cut -d, -f3 <<< "$props" | tr -d ' ')" = 0.5 ] || failed "$dim-D: PROPS(3) is not 0.5: '$props'"
   grep -q "^TOPEL, P$((dim == 3 ? 5 : 3)), 1.25$" "$deck" || failed "$dim-D: no 'TOPEL, P.., 1.25' pressure line"
done
# the defaults are those of the shipped decks (calculix_decks_current checks them whole)
bash "$cx/make-deck.sh" --dim 2 --model micromechanical --history "$work/h.txt" -o "$work/default.inp" >/dev/null
grep -q '^2\., 1\., 0\.75, ' "$work/default.inp" || failed "default mu is not 0.75"
grep -q '^TOPEL, P3, 0\.5$' "$work/default.inp" || failed "default pressure is not 0.5"
for bad in "--mu -0.5" "--mu 0,5" "--mu x" "--precompression -1" "--precompression 1e" "--precompression ''"; do
   out=$(eval bash "$cx/make-deck.sh" --dim 2 --model simplified --history "$work/h.txt" $bad -o "$work/bad.inp" 2>&1)
   rc=$?
   opt=${bad%% *}
   if [ $rc -ne 2 ] || ! grep -q -- "make-deck.sh: $opt must be" <<< "$out"; then
      failed "make-deck.sh $bad: exit $rc, output: $out"
   fi
done
# a material named ABAQUS... without the leading @
sed 's/@ABAQUS_INTERPHASE_UMAT@JOINT/ABAQUS_INTERPHASE_UMAT_JOINT/' "$work/d2.inp" > "$work/plain.inp"
out=$(bash "$cx/run-case.sh" "$work/plain.inp" --cache-dir "$work/no-cache" --output-dir "$work/run" 2>&1)
rc=$?
if [ $rc -ne 1 ] || ! grep -q "material ABAQUS_INTERPHASE_UMAT_JOINT has no leading @" <<< "$out"; then
   failed "run-case.sh on a deck without @: exit $rc, output: $out"
fi
[ $status -eq 0 ] && echo "make-deck.sh options and run-case.sh's material-name check: passed"
exit $status
