// SPDX-License-Identifier: MIT
// PROVISIONAL interface (replaced by the implementation branch): results.h5 + results.xdmf.
#pragma once

#include <span>
#include <string>

#include "mesh/mesh.hpp"

namespace tribex::solver {

struct FieldView {
  std::string name;
  int components;
  std::span<const double> values;
};

class ResultsWriter {
 public:
  ResultsWriter(const std::string& directory, const mesh::Mesh& mesh);
  ~ResultsWriter();
  void write_step(double time, std::span<const FieldView> nodal, std::span<const FieldView> element);
  void flush();
};

}  // namespace tribex::solver
