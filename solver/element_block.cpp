// SPDX-License-Identifier: MIT
#include "solver/element_block.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "solver/errors.hpp"
#include "solver/hex8/geometry.hpp"

namespace tribex::solver {

ElementBlock make_element_block(const mesh::Mesh& mesh, const mesh::Block& block,
                                const materials::Material& material, const inputs::SectionSpec& section,
                                const std::vector<int>& global_element) {
  ElementBlock b;
  b.name = block.name;
  b.first_element = block.first_element;
  b.count = block.element_count;
  b.material = material;
  b.formulation = section.formulation;
  b.linear_bulk_viscosity = section.linear_bulk_viscosity;
  b.quadratic_bulk_viscosity = section.quadratic_bulk_viscosity;
  b.hourglass_stiffness = section.hourglass_stiffness;
  b.hourglass_viscosity = section.hourglass_viscosity;
  const double rho = materials::density_of(material);
  const double M = materials::wave_modulus_of(material);
  const double c = std::sqrt(M / rho);
  b.rho_c = rho * c;

  const std::size_t n = static_cast<std::size_t>(b.count);
  b.B0.assign(interleaved_size(b.count, 24), 0.0);
  b.volume0.resize(n);
  b.length0.resize(n);
  b.stress.assign(6 * n, 0.0);
  const bool mq = b.formulation == inputs::ElementFormulation::mean_quadrature;
  if (mq) {
    b.hg_coefficients.assign(interleaved_size(b.count, 12), 0.0);
    b.hg_k.resize(n);
    b.hg_c.resize(n);
  } else {
    b.wdetJ.assign(interleaved_size(b.count, 8), 0.0);
  }
  if (const int ns = materials::state_size_of(material); ns > 0)
    b.state.assign(mq ? ns * n : interleaved_size(b.count, 8 * ns), 0.0);
  for (int e = 0; e < b.count; ++e) {
    const int global = b.first_element + e;
    double X[24];
    for (int I = 0; I < 8; ++I)
      for (int i = 0; i < 3; ++i) X[3 * I + i] = mesh.coordinates[3 * mesh.connectivity[8 * global + I] + i];
    double B[24];
    const double V = hex8::gradient_operator(X, B);
    if (!(V > 0.0) || hex8::min_corner_jacobian(X) <= 0.0)
      throw SetupError("element " + std::to_string((global_element.empty() ? global : global_element[global]) + 1) + " of block '" + b.name +
                       "' is inverted or degenerate (volume " + std::to_string(V) +
                       " m^3); fix the mesh (node order or geometry)");
    for (int k = 0; k < 24; ++k) b.B0[lane_index(e, k, 24)] = B[k];
    b.volume0[e] = V;
    b.length0[e] = hex8::characteristic_length(B, V);
    if (mq) {
      double coefficients[12];
      hex8::hourglass_coefficients(X, V, coefficients);
      for (int k = 0; k < 12; ++k) b.hg_coefficients[lane_index(e, k, 12)] = coefficients[k];
      double bb = 0.0;
      for (int k = 0; k < 24; ++k) bb += B[k] * B[k];
      // docs/theory.md 2.2: Q^s = kappa M (B.B)/(3V) q, q = gamma.u/sqrt(8), f = Q gamma/sqrt(8)
      b.hg_k[e] = b.hourglass_stiffness * M * bb / (24.0 * V);
      // Q^v = nu rho c sqrt(B.B/3) qdot
      b.hg_c[e] = b.hourglass_viscosity * b.rho_c * std::sqrt(bb / 3.0) / 8.0;
    } else {
      double Q[72], w[8];
      hex8::gauss_point_inverse_jacobians(X, Q, w);
      for (int k = 0; k < 8; ++k) b.wdetJ[lane_index(e, k, 8)] = w[k];
    }
  }
  return b;
}

void equivalent_plastic_strain(const ElementBlock& block, double* out) {
  std::visit(
      [&](const auto& mat) {
        using M = std::decay_t<decltype(mat)>;
        if constexpr (requires { M::equivalent_plastic_strain_index; }) {
          constexpr int ns = M::state_size, k = M::equivalent_plastic_strain_index;
          for (int e = 0; e < block.count; ++e) {
            if (block.formulation == inputs::ElementFormulation::mean_quadrature) {
              out[e] = block.state[static_cast<std::size_t>(ns) * e + k];
              continue;
            }
            double sum = 0.0;  // volume average over the 8 points
            for (int p = 0; p < 8; ++p)
              sum += block.wdetJ[lane_index(e, p, 8)] * block.state[lane_index(e, ns * p + k, 8 * ns)];
            out[e] = sum / block.volume0[e];
          }
        } else {
          std::fill(out, out + block.count, 0.0);
        }
      },
      block.material);
}

std::vector<double> select_interleaved(const std::vector<double>& from, std::span<const int> elements, int per_element) {
  if (from.empty()) return {};
  std::vector<double> to(interleaved_size(static_cast<int>(elements.size()), per_element), 0.0);
  for (std::size_t slot = 0; slot < elements.size(); ++slot)
    for (int k = 0; k < per_element; ++k)
      to[lane_index(static_cast<int>(slot), k, per_element)] = from[lane_index(elements[slot], k, per_element)];
  return to;
}

}  // namespace tribex::solver
