#!/bin/sh
# SPDX-License-Identifier: MIT
# The set-up memory of a mesh read from a gmsh MSH 4.1 file, serial set-up against the read in slices
# (`set-up = distributed`, issue 57 scope 2; docs/measurements/2026-11-29-exodus-slices.md, section "gmsh"):
#
#   tools/bench/msh_slices.sh BUILD OUT RANKS...      e.g. tools/bench/msh_slices.sh build /tmp/msh 4 16
#
# Writes counts_indenter.i's mesh (1,009,000 hex8) to OUT/mesh.msh (binary MSH 4.1) with
# BUILD/bin/tribex_write_deck_mesh (made here, never committed), writes OUT/deck.i (counts_indenter.i with its
# two generated boxes replaced by `database name = OUT/mesh.msh`) and runs partition_methods.py on it with
# methods ptscotch (rank 0 reads the file with gmsh) and distributed (every rank reads its slices) at each rank count.
set -e
[ $# -ge 3 ] || { echo "usage: tools/bench/msh_slices.sh BUILD OUT RANKS..." >&2; exit 2; }
build=$1 out=$2
shift 2
here=$(dirname "$0")
mkdir -p "$out"
out=$(cd "$out" && pwd)
[ -f "$out/mesh.msh" ] || "$build/bin/tribex_write_deck_mesh" "$here/counts_indenter.i" "$out/mesh.msh"
awk -v mesh="$out/mesh.msh" '
  /begin generated box block/ { skip = 1; print "    database name = " mesh }
  !skip { print }
  /end generated box indenter/ { skip = 0 }
' "$here/counts_indenter.i" > "$out/deck.i"
/usr/bin/python3 "$here/partition_methods.py" "$build/bin/tribex" "$out/deck.i" "$out" --ranks "$@" \
  --methods ptscotch distributed
