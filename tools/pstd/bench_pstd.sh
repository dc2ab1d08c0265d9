#!/bin/sh
# SPDX-License-Identifier: MIT
# Benchmark of the PSTD model's acceptance case: the 10 um substrate at 1 nm sampling with ~76 initial contacts
# (21 linked copies of the 3-segment synthetic counterface, 1.6 mN per copy -> 77 initial contacts), full
# 10 um travel, no plots. Prints the command's own wall time (summary.json) and /usr/bin/time's figures.
# usage: tools/pstd/bench_pstd.sh [BUILD_DIR]   (default build)
set -e
bin="${1:-build}/bin/tribex"
out="$(mktemp -d)"
for i in 1 2 3; do
  /usr/bin/time -f "run $i: %e s wall, %U s user" "$bin" pstd --copies 21 --normal-force 1.6mN --no-plots --quiet -o "$out"
  grep -E '"(initial_contacts|wall_time_s)"' "$out/summary.json" | tr -d ' \n'; echo
done
rm -rf "$out"
