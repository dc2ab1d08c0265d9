// SPDX-License-Identifier: MIT
// The constants A and b of the coated-substrate area law (report Eq. 3.1 / B.2,
// f = A (P/(Ebar_c h_c^2))^b) as a function of the modulus ratio Ebar_c/Ebar, read from the
// table that the coated-substrate FE study writes (verification/coated/results.csv):
//   ebar_c_over_ebar,A,b[,A_sigma,b_sigma]
// and interpolated linearly in ln(Ebar_c/Ebar) (the report's Table B.1 doubles the ratio from
// row to row). A ratio outside the table is refused: the power law is a fit, not a model.
#pragma once

#include <string>
#include <vector>

namespace tribex::fit {

struct AreaLawConstants {
  double A = 1.0, b = 0.0;
  double A_sigma = 0.0, b_sigma = 0.0;  // 0 when the table gives none
};

class CoatingTable {
 public:
  /// Reads `path`; throws tools::BadInput (file:line and the fix) on a missing file or column,
  /// ratios that are not positive and increasing, or A <= 0.
  static CoatingTable read(const std::string& path);
  CoatingTable(std::string path, std::vector<double> ratio, std::vector<AreaLawConstants> rows);

  bool covers(double ratio) const;
  /// Interpolated constants; throws tools::BadInput when `ratio` is outside the table.
  AreaLawConstants at(double ratio) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<double> ratio_;
  std::vector<AreaLawConstants> rows_;
};

}  // namespace tribex::fit
