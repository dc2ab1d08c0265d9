// SPDX-License-Identifier: MIT
#include "tools/common/text_file.hpp"

#include <cstdio>
#include <fstream>

#include "mesh/output_target.hpp"
#include "tools/common/errors.hpp"

namespace tribex::tools {

void require_output_file(const std::string& path) {
  const std::string problem = mesh::output_target_problem(path);
  if (!problem.empty()) throw BadInput(problem + mesh::output_target_fix);
}

void write_text_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  require_output_file(path);
  require_output_file(tmp);
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw BadInput("cannot write '" + path + "' (check that its folder exists and is writable)");
    out << text;
    if (!out.flush()) {
      out.close();
      std::remove(tmp.c_str());
      throw BadInput("writing '" + path + "' failed (disk full?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw BadInput("cannot rename '" + tmp + "' to '" + path + "' (check the folder's permissions)");
  }
}

void write_text_output(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") {
    std::fputs(text.c_str(), stdout);
    return;
  }
  write_text_file(path, text);
}

}  // namespace tribex::tools
