// SPDX-License-Identifier: MIT
#include "tools/fit/coating_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tools/common/csv_record.hpp"
#include "tools/common/errors.hpp"

namespace tribex::fit {

CoatingTable::CoatingTable(std::string path, std::vector<double> ratio, std::vector<AreaLawConstants> rows)
    : path_(std::move(path)), ratio_(std::move(ratio)), rows_(std::move(rows)) {}

CoatingTable CoatingTable::read(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw tools::BadInput(path + ": coating table not found (the coated-substrate FE study writes it as "
                          "ebar_c_over_ebar,A,b[,A_sigma,b_sigma]; pass --coating-table FILE, or --A and --b)");
  const auto rec = tools::CsvRecord::read(path);
  namespace dim = inputs::dim;
  const auto& ratio = rec.column("ebar_c_over_ebar", dim::none);
  const auto& a = rec.column("A", dim::none);
  const auto& b = rec.column("b", dim::none);
  rec.require_rows(1, "(one row per modulus ratio Ebar_c/Ebar)");
  const bool sig_a = rec.has("A_sigma"), sig_b = rec.has("b_sigma");
  std::vector<AreaLawConstants> rows;
  for (std::size_t i = 0; i < rec.size(); ++i) {
    if (!(ratio[i] > 0)) throw tools::BadInput(rec.where(i) + ": ebar_c_over_ebar must be > 0");
    if (!(a[i] > 0)) throw tools::BadInput(rec.where(i) + ": A must be > 0 (f = A P~^b is an area factor)");
    AreaLawConstants c{a[i], b[i], 0.0, 0.0};
    if (sig_a) c.A_sigma = rec.column("A_sigma", dim::none)[i];
    if (sig_b) c.b_sigma = rec.column("b_sigma", dim::none)[i];
    if (c.A_sigma < 0 || c.b_sigma < 0) throw tools::BadInput(rec.where(i) + ": A_sigma and b_sigma must be >= 0");
    rows.push_back(c);
  }
  rec.require_increasing("ebar_c_over_ebar");
  return CoatingTable(path, ratio, rows);
}

bool CoatingTable::covers(double ratio) const {
  if (ratio_.empty() || !(ratio > 0)) return false;
  const double tol = 1e-9 * ratio_.back();
  return ratio >= ratio_.front() - tol && ratio <= ratio_.back() + tol;
}

AreaLawConstants CoatingTable::at(double ratio) const {
  if (!covers(ratio)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "Ebar_c/Ebar = %.4g is outside the table's range [%.4g, %.4g]",
                  ratio, ratio_.empty() ? 0.0 : ratio_.front(), ratio_.empty() ? 0.0 : ratio_.back());
    throw tools::BadInput(path_ + ": " + buf + " (extend the table or pass --A and --b)");
  }
  if (ratio_.size() == 1) return rows_[0];
  std::size_t k = 1;
  while (k + 1 < ratio_.size() && ratio > ratio_[k]) ++k;
  const double t = std::clamp((std::log(ratio) - std::log(ratio_[k - 1])) / (std::log(ratio_[k]) - std::log(ratio_[k - 1])),
                              0.0, 1.0);
  const auto& lo = rows_[k - 1];
  const auto& hi = rows_[k];
  auto mix = [t](double x, double y) { return x + t * (y - x); };
  return {mix(lo.A, hi.A), mix(lo.b, hi.b), mix(lo.A_sigma, hi.A_sigma), mix(lo.b_sigma, hi.b_sigma)};
}

}  // namespace tribex::fit
