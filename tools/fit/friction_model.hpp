// SPDX-License-Identifier: MIT
// Friction against applied load for one sliding single-asperity contact: F = tau A(L) (report
// Eq. C.1), or F = tau0 A + alpha_p int_A p dA for a pressure-dependent shear strength
// tau = tau0 + alpha_p p (Eq. C.2, Briscoe-Tabor; docs/theory.md 9.3). The contact area A(L) is one of
//   coated  report Eq. 3.1 with the DMT-like effective load P = L + 2 pi R W (report 3.3):
//           A = pi [3PR(1 + Ebar/Ebar_c)/(4 Ebar)]^(2/3) f,  f = min(1, max(f_deep, A_fit (P/(Ebar_c h_c^2))^b)),
//           f_deep = (2/(1 + Ebar/Ebar_c))^(2/3) (docs/theory.md 11.1); carried load P.
//   dmt     a^3 = R (L + 2 pi W R)/K, K = 4E*/3 (docs/theory.md 8.2); carried load L + 2 pi W R.
//   jkr     a^3 = (R/K)[L + 3 pi W R + sqrt(6 pi W R L + (3 pi W R)^2)] (8.3); carried load: the JKR
//           pressure p0 sqrt(1-r^2/a^2) - p1/sqrt(1-r^2/a^2) integrated where it is compressive.
//   cos     Carpick-Ogletree-Salmeron a = a0 [(alpha + sqrt(1 - L/L_c))/(1 + alpha)]^(2/3) with
//           lambda = -0.924 ln(1 - 1.02 alpha) and the Pietrement-Troyon L_c(lambda), a0(lambda) (9.1).
//   md      exact Maugis-Dugdale (maugis_dugdale.hpp) at a fixed lambda, or lambda from z0 with the
//           Lennard-Jones peak stress sigma0 = 16W/(9 sqrt3 z0) (6.5); carried load P + sigma0 pi (c^2 - a^2).
// Uncoated models use E* of the tip and substrate, 1/E* = 2/Ebar (both Si) unless given.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "tools/fit/coating_table.hpp"

namespace tribex::fit {

enum class AreaModel { coated, dmt, jkr, cos, maugis_dugdale };

/// "coated", "dmt", "jkr", "cos", "md"; nullopt for anything else.
std::optional<AreaModel> parse_area_model(const std::string& name);
std::string model_name(AreaModel m);

struct FrictionSetup {
  AreaModel model = AreaModel::coated;
  double radius = 27e-9;                   // tip radius R
  double youngs = 161e9, poisson = 0.23;   // tip and substrate (Si, report 3.2)
  std::optional<double> reduced_modulus;   // E* for the uncoated models; default Ebar/2
  double coating_youngs = 8e9, coating_poisson = 0.4, coating_thickness = 2e-9;  // report 3.3
  std::optional<AreaLawConstants> area_law;  // --A/--b; otherwise `table`
  std::optional<CoatingTable> table;
  std::optional<double> md_lambda, md_z0;  // md: one of the two
  std::optional<double> cos_alpha;         // cos: fixed alpha; free when unset
  bool pressure_dependent = false;         // fit alpha_p as well
  bool free_coating_modulus = false;       // coated: fit E_c as well (not identifiable: see README)
};

/// Every parameter of the friction law; the model says which are fitted.
struct FrictionParams {
  double tau = 0;                    // tau* (or tau0 with a pressure-dependent shear), Pa
  double work_of_adhesion = 0;       // W, J/m^2
  double pressure_coefficient = 0;   // alpha_p, dimensionless
  double cos_alpha = 0;              // COS transition parameter, 0 (DMT) .. 1 (JKR)
  double coating_youngs = 0;         // E_c, Pa
};

struct ContactState {
  double area = 0;          // m^2
  double carried_load = 0;  // int_A max(p, 0) dA where the model knows p (N)
};

class FrictionModel {
 public:
  /// Checks the setup; throws tools::BadInput naming the option to fix.
  explicit FrictionModel(FrictionSetup setup);
  const FrictionSetup& setup() const { return s_; }

  /// Names of the fitted parameters, in vector order: tau, W [, alpha_p] [, cos_alpha] [, Ec].
  std::vector<std::string> free_names() const;
  Eigen::VectorXd to_vector(const FrictionParams& p) const;
  /// Fitted entries from `v`, the others from the setup.
  FrictionParams from_vector(const Eigen::VectorXd& v) const;
  /// Parameters with tau and W given and the others at their setup/default values.
  FrictionParams defaults(double tau, double work_of_adhesion) const;

  /// Contact at load L; nullopt below the model's pull-off load or outside the parameters' domain.
  std::optional<ContactState> contact(const FrictionParams& p, double load) const;
  /// Friction at every load; nullopt when any load is outside the domain.
  std::optional<std::vector<double>> friction(const FrictionParams& p, const std::vector<double>& loads) const;
  /// Load-controlled pull-off load (negative).
  double pull_off_load(const FrictionParams& p) const;
  /// Maugis parameter of the md and cos models (cos: from alpha); NaN for the others.
  double lambda(const FrictionParams& p) const;
  /// Area-law constants and f at load L for the coated model.
  AreaLawConstants area_law(double coating_youngs) const;
  double plane_strain_modulus() const;  // Ebar = E/(1-nu^2)
  double reduced_modulus() const;       // E* of the uncoated models

 private:
  FrictionSetup s_;
};

}  // namespace tribex::fit
