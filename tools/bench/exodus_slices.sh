#!/bin/sh
# SPDX-License-Identifier: MIT
# The set-up memory of a mesh read from an Exodus II file, serial set-up against the read in slices
# (`set-up = distributed`, issue 57 scope 2; docs/measurements/2026-11-29-exodus-slices.md):
#
#   tools/bench/exodus_slices.sh BUILD OUT RANKS...      e.g. tools/bench/exodus_slices.sh build /tmp/exo 4 16
#
# Writes counts_indenter.i's mesh (1,009,000 hex8) to OUT/mesh.exo with BUILD/bin/tribex_write_deck_mesh
# (about 60 MB: made here, never committed), writes OUT/deck.i (counts_indenter.i with its two generated
# boxes replaced by `database name = OUT/mesh.exo`) and runs partition_methods.py on it with methods metis,
# ptscotch (rank 0 reads the file) and distributed (every rank reads its slices) at each rank count.
set -e
[ $# -ge 3 ] || { echo "usage: tools/bench/exodus_slices.sh BUILD OUT RANKS..." >&2; exit 2; }
build=$1 out=$2
shift 2
here=$(dirname "$0")
mkdir -p "$out"
out=$(cd "$out" && pwd)
[ -f "$out/mesh.exo" ] || "$build/bin/tribex_write_deck_mesh" "$here/counts_indenter.i" "$out/mesh.exo"
awk -v mesh="$out/mesh.exo" '
  /begin generated box block/ { skip = 1; print "    database name = " mesh }
  !skip { print }
  /end generated box indenter/ { skip = 0 }
' "$here/counts_indenter.i" > "$out/deck.i"
/usr/bin/python3 "$here/partition_methods.py" "$build/bin/tribex" "$out/deck.i" "$out" --ranks "$@" \
  --methods metis ptscotch distributed
