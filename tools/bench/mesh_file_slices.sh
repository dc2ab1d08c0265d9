#!/bin/sh
# SPDX-License-Identifier: MIT
# The set-up memory of a mesh read from a file, serial set-up against the read in slices (`set-up =
# distributed`, issue 57 scope 2; docs/measurements/2026-11-29-exodus-slices.md, sections for Exodus and "gmsh"):
#
#   tools/bench/mesh_file_slices.sh exo|msh BUILD OUT RANKS...   e.g. tools/bench/mesh_file_slices.sh exo build /tmp/exo 4 16
#
# Writes counts_indenter.i's mesh (1,009,000 hex8) to OUT/mesh.exo (Exodus II, about 60 MB) or OUT/mesh.msh
# (binary MSH 4.1, about 125 MB) with BUILD/bin/tribex_write_deck_mesh (made here, never committed), writes
# OUT/deck.i (counts_indenter.i with its two generated boxes replaced by `database name = OUT/mesh.FORMAT`) and
# runs partition_methods.py on it at each rank count with the methods ptscotch (rank 0 reads the file) and
# distributed (every rank reads its slices), and metis for Exodus.
set -e
[ $# -ge 4 ] && { [ "$1" = exo ] || [ "$1" = msh ]; } ||
  { echo "usage: tools/bench/mesh_file_slices.sh exo|msh BUILD OUT RANKS..." >&2; exit 2; }
format=$1 build=$2 out=$3
shift 3
here=$(dirname "$0")
mkdir -p "$out"
out=$(cd "$out" && pwd)
mesh="$out/mesh.$format"
[ -f "$mesh" ] || "$build/bin/tribex_write_deck_mesh" "$here/counts_indenter.i" "$mesh"
awk -v mesh="$mesh" '
  /begin generated box block/ { skip = 1; print "    database name = " mesh }
  !skip { print }
  /end generated box indenter/ { skip = 0 }
' "$here/counts_indenter.i" > "$out/deck.i"
if [ "$format" = exo ]; then methods="metis ptscotch distributed"; else methods="ptscotch distributed"; fi
# shellcheck disable=SC2086 # the methods are words
/usr/bin/python3 "$here/partition_methods.py" "$build/bin/tribex" "$out/deck.i" "$out" --ranks "$@" --methods $methods
