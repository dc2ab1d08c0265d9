#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The before/after check of a refactor (issue 55): run a fixed set of verification decks with the
# binary BIN into OUTROOT/<deck>, 18 serially and 2 at 2 MPI ranks; then compare two such folders
# pair by pair with tools/bench/compare_outputs.py (bitwise, or round-off with its size).
#
#   tools/bench/refactor_check.sh BIN_BEFORE /tmp/before     # copy build/bin/tribex first
#   tools/bench/refactor_check.sh build/bin/tribex /tmp/after
#   for d in /tmp/before/*/; do n=$(basename $d); echo "$n: $(/usr/bin/python3 tools/bench/compare_outputs.py $d /tmp/after/$n | tr '\n' ' ')"; done
#
# Run from the repository root. OUTROOT/rc.txt lists each run's exit code.
set -u
BIN=$(readlink -f "$1"); OUT=$2
mkdir -p "$OUT"; : > "$OUT/rc.txt"
decks="verification/hertz/hertz_coarse.i verification/hertz/hertz_coarse_mass_scaled.i verification/hertz/hertz_coarse_mixed.i
verification/dmt/dmt_coarse.i verification/impact/impact.i verification/impact/impact_mortar.i verification/coulomb/block_pull.i
verification/junction_flats/junction_flats.i verification/plasticity/uniaxial.i verification/plasticity/shear.i
verification/rough_flats/rough_flats.i verification/rough_flats/noncontact.i verification/silent_boundary/p_silent_scaled.i
verification/silent_boundary/s_silent.i verification/contact_patch/contact_patch.i verification/sphere_sliding/sphere_sliding_coarse.i
verification/coating_energy/decks/base_mass_scaled.i inputs/examples/wave_bar.i"
for d in $decks; do
  n=$(basename "$d" .i); rm -rf "${OUT:?}/$n"
  "$BIN" run "$d" -o "$OUT/$n" --quiet > "$OUT/$n.log" 2>&1; echo "$n rc=$?" >> "$OUT/rc.txt"
done
for d in verification/hertz/hertz_coarse.i verification/impact/impact_mortar.i; do
  n=mpi_$(basename "$d" .i); rm -rf "${OUT:?}/$n"
  mpirun --allow-run-as-root --oversubscribe -np 2 "$BIN" run "$d" -o "$OUT/$n" --quiet > "$OUT/$n.log" 2>&1
  echo "$n rc=$?" >> "$OUT/rc.txt"
done
