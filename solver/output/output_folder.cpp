// SPDX-License-Identifier: MIT
#include "solver/output/output_folder.hpp"

#include <string>
#include <system_error>
#include <vector>

#include "solver/errors.hpp"

namespace tribex::solver {

std::size_t clear_owned_outputs(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return 0;
  std::vector<fs::path> owned;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const bool restart = name.rfind("restart", 0) == 0 && (name.ends_with(".h5") || name.ends_with(".h5.link"));
    const bool output = name == "history.csv" || name == "history_columns.csv" || name == "results.h5" || name == "results.xdmf" ||
                        name == "summary.json" || name == "summary.json.tmp" || name == "log.txt" ||
                        name == "results.xdmf.tmp" || name == "results.exo" || name == ".results.exo.partial";
    if (restart || output) owned.push_back(entry.path());
  }
  for (const auto& p : owned) {
    fs::remove(p, ec);  // a symlink itself, not its target
    if (ec) throw SetupError("cannot remove the earlier run's " + p.string() + " (" + ec.message() +
                             "); remove it or choose another output folder (-o)");
  }
  return owned.size();
}

}  // namespace tribex::solver
