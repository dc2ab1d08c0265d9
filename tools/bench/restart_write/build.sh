#!/bin/sh
# SPDX-License-Identifier: MIT
# Compiles restart_write_bench.cpp against the libraries of a tribex build folder (that build's restart
# writer), e.g. the build of an earlier commit to time its writer with the same source.
#   tools/bench/restart_write/build.sh BUILD_DIR OUTPUT_BINARY
set -e
B=$(cd "$1" && pwd)
SRC=$(cd "$(dirname "$0")/../../.." && pwd)
c++ -O2 -std=c++20 -DOMPI_SKIP_MPICXX -I"$SRC" -isystem /usr/include/hdf5/openmpi \
  -isystem /usr/lib/x86_64-linux-gnu/openmpi/include -isystem /usr/lib/x86_64-linux-gnu/openmpi/include/openmpi \
  "$SRC/tools/bench/restart_write/restart_write_bench.cpp" -o "$2" \
  -Wl,-rpath,/usr/lib/x86_64-linux-gnu/openmpi/lib:/usr/lib/x86_64-linux-gnu/hdf5/openmpi \
  "$B/libtribex_solver.a" "$B/libtribex_inputs.a" "$B/libtribex_contact.a" "$B/libtribex_mesh.a" \
  /usr/lib/x86_64-linux-gnu/libgmsh.so /usr/lib/x86_64-linux-gnu/hdf5/openmpi/libhdf5.so \
  /usr/lib/x86_64-linux-gnu/libmetis.so /usr/lib/x86_64-linux-gnu/libptscotch.so \
  /usr/lib/x86_64-linux-gnu/libptscotcherr.so /usr/lib/x86_64-linux-gnu/openmpi/lib/libmpi.so \
  /usr/lib/x86_64-linux-gnu/libexoIIv2c.so /usr/lib/x86_64-linux-gnu/libnetcdf_mpi.so.19 -lz -lcrypto -lm
