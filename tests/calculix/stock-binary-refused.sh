#!/bin/bash
# ctest calculix_stock_binary_refused: Debian's ccx (package calculix-ccx, installed here when it is
# missing and we are root) cannot call a user's UMAT; build-calculix.sh --ccx must refuse it with
# a message that says so, and run-case.sh must refuse a cache whose ccx is such a binary.
set -uo pipefail
cx=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
skip() { if [ "${CI:-}" = true ]; then echo "FAILED: $*"; exit 1; fi; echo "SKIP: $*"; exit 77; }
if [ ! -x /usr/bin/ccx ]; then
   [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1 || skip "Debian's ccx is not installed and cannot be (not root)"
   DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends calculix-ccx >"$work/apt.log" 2>&1 || \
      skip "apt-get install calculix-ccx failed (see $work/apt.log)"
fi
stock=$(readlink -f /usr/bin/ccx)
status=0
out=$(bash "$cx/build-calculix.sh" --cache-dir "$work/cache" --ccx "$stock" --lib-only 2>&1)
rc=$?
if [ $rc -ne 1 ] || ! grep -q "no external-behaviour support" <<< "$out"; then
   echo "FAILED: build-calculix.sh --ccx $stock: exit $rc, output: $out"
   status=1
else
   echo "build-calculix.sh refuses $stock: $(head -n 1 <<< "$out")"
fi
mkdir -p "$work/cache"
ln -sf "$stock" "$work/cache/ccx"
touch "$work/cache/libINTERPHASE.so"
printf '*HEADING\nempty\n' > "$work/empty.inp"
out=$(bash "$cx/run-case.sh" "$work/empty.inp" --cache-dir "$work/cache" --output-dir "$work/run" 2>&1)
rc=$?
if [ $rc -ne 1 ] || ! grep -q "no external-behaviour support" <<< "$out"; then
   echo "FAILED: run-case.sh with $stock: exit $rc, output: $out"
   status=1
else
   echo "run-case.sh refuses it: $out"
fi
# A ccx that passes the string check but whose joint carries nothing (what Debian's binary does
# on a one-element deck: "Job finished" with zero stress) is refused by what it computed.
mkdir -p "$work/fake"
cat > "$work/fake/ccx" <<'FAKE'
#!/bin/bash
# a stand-in ccx for the test (the loader's message "unable to load function" appears here only
# so that the string check passes): zero joint stress and work, "Job finished"
job=$2
for t in 1 2; do
   printf ' total force (fx,fy,fz) for set TOP and time  %s\n\n   0. -1.0E+04 0.\n\n' "$t"
   printf ' displacements (vx,vy,vz) for set TOPREF and time  %s\n\n   1 0. 0. 0.\n\n' "$t"
   printf ' total internal energy for set JOINT and time  %s\n\n   0.\n\n' "$t"
   printf ' strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz) for set REPLAY and time  %s\n\n   8 1 0. 0. 0. 0. 0. 0.\n\n' "$t"
   printf ' stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set REPLAY and time  %s\n\n   8 1 0. 0. 0. 0. 0. 0.\n\n' "$t"
   printf ' internal state variables (elem, integ.pnt.,values) for set REPLAY and time  %s\n\n   8 1 0. 0. 0. 0.\n\n' "$t"
done > "$job.dat"
echo " Job finished"
FAKE
chmod +x "$work/fake/ccx"
touch "$work/fake/libINTERPHASE.so"
out=$(bash "$cx/run-case.sh" "$work/empty.inp" --cache-dir "$work/fake" --output-dir "$work/fake-run" --no-plot 2>&1)
rc=$?
if [ $rc -ne 1 ] || ! grep -q "did not call interphase's UMAT" <<< "$out"; then
   echo "FAILED: run-case.sh accepted a run with zero joint stress: exit $rc, output: $out"
   status=1
else
   echo "run-case.sh refuses a run whose joint carried no stress: $out"
fi
exit $status
