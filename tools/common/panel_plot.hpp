// SPDX-License-Identifier: MIT
// PNG plots of the data-reduction commands: the data go to temporary CSV panels next to the
// PNG and tools/plot/plot_panels.py (Debian's /usr/bin/python3 + matplotlib, Agg) draws them.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tribex::tools {

struct PlotPanel {
  std::string xlabel, ylabel, title;
  /// First column is x; names starting with "fit" are drawn as lines. NaN cells are skipped.
  std::vector<std::pair<std::string, std::vector<double>>> columns;
};

/// Draws `panels` into `png`; returns false (after a warning on stderr) when Python or matplotlib
/// is unavailable. Throws tools::BadInput when the folder of `png` cannot be written.
bool write_plot(const std::string& png, const std::string& title, const std::vector<PlotPanel>& panels);

/// `s` in single quotes for /bin/sh (a ' inside as '\''): the plot scripts' arguments.
std::string shell_quote(const std::string& s);

/// "dir/name.csv" -> "dir/name.png" (the default plot path next to the input).
std::string default_plot_path(const std::string& input);

}  // namespace tribex::tools
