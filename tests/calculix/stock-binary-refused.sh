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
exit $status
