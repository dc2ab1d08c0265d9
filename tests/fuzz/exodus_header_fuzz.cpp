// SPDX-License-Identifier: MIT
// libFuzzer target for Exodus II mesh files (issue 54, item 11): any bytes, written to a scratch file,
// must give a Mesh or a MeshError from read_exodus (the header walk of mesh/exodus_prescan.cpp, then
// the Exodus library), never a crash, a hang, an allocation beyond what the file holds or another
// exception. Built only with -DTRIBEX_FUZZ=ON (clang); tests/fuzz/CMakeLists.txt.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "tests/fuzz/skip_library_teardown.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/exodus_prescan.hpp"
#include "mesh/mesh_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {  // the walk alone, on the bytes as they are
    tribex::mesh::prescan_netcdf_classic("fuzz.exo", bytes, size);
  } catch (const tribex::mesh::MeshError&) {
  }
  static const std::string path = "exodus_fuzz_" + std::to_string(getpid()) + ".exo";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    tribex::mesh::read_exodus(path);
  } catch (const tribex::mesh::MeshError&) {
    // expected for almost every input
  }
  return 0;
}
