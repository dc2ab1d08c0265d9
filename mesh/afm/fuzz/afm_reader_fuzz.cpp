// SPDX-License-Identifier: MIT
// libFuzzer target for the height-map readers: any bytes must give a HeightMap or a MeshError, never a
// crash, a hang or another exception. The readers take a path, so each input is written to a file in
// /dev/shm first; format detection is by content, so one target reaches all four readers.
// Built only with -DTRIBEX_FUZZ=ON (clang); see CMakeLists.txt here.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "mesh/afm/height_map.hpp"
#include "mesh/afm/preprocess.hpp"
#include "mesh/mesh_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/dev/shm/tribex_afm_fuzz_" + std::to_string(getpid());
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  for (int channel : {-1, 1}) {
    try {
      const auto map = tribex::mesh::afm::read_height_map(path, channel);
      // A map that loads must also survive the pre-processing.
      (void)tribex::mesh::afm::rms(tribex::mesh::afm::level_plane(map));
    } catch (const tribex::mesh::MeshError&) {
      // expected for almost every input
    }
  }
  return 0;
}
