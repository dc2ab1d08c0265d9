#!/bin/sh
# SPDX-License-Identifier: MIT
# check_implies_setup.sh TRIBEX DIR: for every file in DIR that `tribex check` accepts (exit 0), the run's
# whole set-up must succeed too: `tribex run FILE --stop-at-step 0` ends with 130 (stopped after step 0),
# 0, or 3 (a numerical failure in step 0, after set-up), never 1, 2 or a crash (issue 29: "a deck that
# check accepts never fails set-up"). Used on the deck fuzz
# corpus after the fuzzer has grown it (tests/fuzz/CMakeLists.txt). Prints the counts; exit 1 on a breach.
tribex="$1"; dir="$2"; scratch=$(mktemp -d) || exit 1
accepted=0; refused=0; breaches=0
for f in "$dir"/*; do
  f=$(readlink -f "$f")
  if (cd "$(dirname "$f")" && timeout 60 "$tribex" check "$f" > /dev/null 2>&1); then
    accepted=$((accepted + 1))
    (cd "$(dirname "$f")" && timeout 120 "$tribex" run "$f" --stop-at-step 0 --quiet -o "$scratch/out" > "$scratch/said.txt" 2>&1)
    rc=$?
    if [ $rc -ne 130 ] && [ $rc -ne 0 ] && [ $rc -ne 3 ]; then
      breaches=$((breaches + 1))
      echo "BREACH: $f: check accepted it, the run's set-up ended with $rc: $(tail -1 "$scratch/said.txt")"
    fi
    rm -rf "$scratch/out"
  else
    refused=$((refused + 1))
  fi
done
rm -rf "$scratch"
echo "check accepted $accepted file(s), refused $refused; set-up failed after check for $breaches"
[ $breaches -eq 0 ]
