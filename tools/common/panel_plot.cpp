// SPDX-License-Identifier: MIT
#include "tools/common/panel_plot.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tools/common/errors.hpp"
#include "tools/common/text_file.hpp"

#ifndef TRIBEX_PANEL_PLOT_SCRIPT
#define TRIBEX_PANEL_PLOT_SCRIPT "tools/plot/plot_panels.py"
#endif

namespace tribex::tools {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string default_plot_path(const std::string& input) {
  std::filesystem::path p(input);
  p.replace_extension(".png");
  return p.string();
}

bool write_plot(const std::string& png, const std::string& title, const std::vector<PlotPanel>& panels) {
  // The plot is drawn into PNG.tmp.png and renamed (tools/plot/plot_panels.py): only regular files replaced.
  require_output_file(png);
  require_output_file(png + ".tmp.png");
  for (std::size_t k = 0; k < panels.size(); ++k) require_output_file(png + ".panel" + std::to_string(k) + ".csv");
  std::vector<std::string> files;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const std::string path = png + ".panel" + std::to_string(k) + ".csv";
    std::ofstream out(path);
    if (!out) throw tools::BadInput(png + ": cannot write next to the plot (check the folder exists; or set -o)");
    const auto& p = panels[k];
    out << "# " << p.xlabel << "|" << p.ylabel << "|" << p.title << "\n";
    std::size_t rows = 0;
    for (std::size_t c = 0; c < p.columns.size(); ++c) {
      out << (c ? "," : "") << p.columns[c].first;
      rows = std::max(rows, p.columns[c].second.size());
    }
    out << "\n";
    char buf[32];
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t c = 0; c < p.columns.size(); ++c) {
        const auto& v = p.columns[c].second;
        buf[0] = '\0';
        if (r < v.size() && std::isfinite(v[r])) std::snprintf(buf, sizeof buf, "%.9g", v[r]);
        out << (c ? "," : "") << buf;
      }
      out << "\n";
    }
    files.push_back(path);
  }
  // Built with append: GCC 12 warns (-Wrestrict, a known false positive) on `" " + std::string`.
  std::string cmd = "/usr/bin/python3";
  for (const std::string& part : {std::string(TRIBEX_PANEL_PLOT_SCRIPT), png, title}) {
    cmd += ' ';
    cmd += shell_quote(part);
  }
  for (const auto& f : files) {
    cmd += ' ';
    cmd += shell_quote(f);
  }
  const int rc = std::system(cmd.c_str());
  for (const auto& f : files) std::filesystem::remove(f);
  if (rc != 0) {
    std::fprintf(stderr, "warning: the plot %s was not drawn (/usr/bin/python3 with matplotlib failed); "
                 "the fitted values above are unaffected\n", png.c_str());
    return false;
  }
  return true;
}

}  // namespace tribex::tools
