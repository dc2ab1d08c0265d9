// SPDX-License-Identifier: MIT
// Per-block element data in struct-of-arrays form: reference-configuration operators computed once
// at set-up (the kernels are total-Lagrangian: F = I + (1/V0) u_iI B0_JI), the material, the
// section's numerical parameters, and output buffers. Local element index e runs over
// [0, count); the global element is first_element + e.
#pragma once

#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "inputs/deck.hpp"
#include "materials/material.hpp"
#include "mesh/mesh.hpp"

namespace tribex::solver {

struct ElementBlock {
  std::string name;
  int first_element = 0;
  int count = 0;
  materials::Material material;
  inputs::ElementFormulation formulation = inputs::ElementFormulation::mean_quadrature;
  double linear_bulk_viscosity = 0.06;     // b1
  double quadratic_bulk_viscosity = 1.2;   // b2
  double hourglass_stiffness = 0.05;       // kappa_hg
  double hourglass_viscosity = 0.0;        // nu_hg
  double rho_c = 0.0;                      // rho c_d at the reference state, kg/(m^2 s)

  // Records of several values per element are interleaved by element in groups of
  // `interleave_width` (below): value k of element e at lane_index(e, k, per_element), so that the
  // kernels load 1, 2 or 4 consecutive elements' value k with one load (8: two loads, load_record).
  // [e] arrays are plain.
  std::vector<double> B0;        // [3][8] per element, interleaved: reference gradient operator (m^2)
  std::vector<double> volume0;   // [e] (m^3)
  std::vector<double> length0;   // [e] reference characteristic length (m)
  // selective mass scaling (solver/setup/mass_scaling.hpp): density factor s_e >= 1 of the lumped mass and
  // the stable-step estimate; empty when the block is not scaled (every s_e = 1). The kernels keep
  // the physical density (bulk and hourglass viscosity, docs/theory.md 1.4.1).
  std::vector<double> mass_scale;  // [e]
  // mean quadrature only
  // hourglass vectors in factored form, gamma_aI = Gamma_aI - c_aj B0_jI (hex8/geometry.hpp):
  std::vector<double> hg_coefficients;  // c_aj = (X_jJ Gamma_aJ)/V0, [4][3] per element, interleaved (1/m^2)
  std::vector<double> hg_k;      // [e] kappa M (B.B)/(24 V): f = hg_k gamma gamma^T u   (N/m)
  std::vector<double> hg_c;      // [e] nu rho c sqrt(B.B/3)/8: f = hg_c gamma gamma^T v  (N s/m)
  // fully integrated only, interleaved (the kernel forms J^{-1} and det J at its points from the
  // reference coordinates each step, hex8/sum_factorized.hpp; these are the same bits, kept for the
  // volume averages of point values in the outputs):
  std::vector<double> wdetJ;         // Gauss weight x det J, [8] per element (m^3)
  // material state, state_size_of(material) doubles per material point, n -> n+1 in the force pass:
  // [e][k] (mean quadrature), pair-interleaved [e][point][k] (fully integrated); empty if stateless
  std::vector<double> state;
  // When set, the kernels add each element's viscous nodal forces (bulk viscosity, and hourglass
  // viscosity under mean quadrature) here, [node][3] (N): the energy ledger pairs them with
  // v^{n+1/2} (docs/theory.md 1.3). Not owned; the integrator points it at its array.
  double* viscous_force = nullptr;
  // output (filled only on steps that write element fields)
  std::vector<double> stress;    // [e][6] Cauchy, Voigt xx yy zz xy yz zx (Pa)
};

/// Elements per interleaved group: the widest lane count a kernel uses (4 doubles per AVX2
/// register); narrower kernels read the group's lanes in pairs or one by one.
inline constexpr int interleave_width = 4;

/// Interleaved storage: value k of element e, for arrays of `per_element` values per element; the
/// record count is rounded up to whole groups (the last group's unused lanes are zero).
inline std::size_t lane_index(int e, int k, int per_element) {
  constexpr std::size_t w = interleave_width;
  return w * static_cast<std::size_t>(per_element) * static_cast<std::size_t>(e / interleave_width) +
         w * static_cast<std::size_t>(k) + static_cast<std::size_t>(e % interleave_width);
}
inline std::size_t interleaved_size(int count, int per_element) {
  constexpr int w = interleave_width;
  return static_cast<std::size_t>(w) * static_cast<std::size_t>(per_element) * static_cast<std::size_t>((count + w - 1) / w);
}
/// Value k of elements e .. e + lane_count<T> - 1 of an interleaved record array (e a multiple of
/// the lane count): one load up to the group width; eight lanes (AVX-512) span two groups, one
/// load from each. The groups stay four wide for every kernel, so the state arrays of restart
/// files keep one layout whatever the CPU that wrote them.
template <class T>
inline T load_record(const std::vector<double>& a, int e, int k, int per_element) {
  const double* p = a.data() + lane_index(e, k, per_element);
#ifdef __AVX512F__
  if constexpr (materials::lane_count<T> == 8)
    return materials::join_lanes(materials::load_lanes<materials::double4>(p),
                                 materials::load_lanes<materials::double4>(p + interleave_width * per_element));
  else
#endif
    return materials::load_lanes<T>(p);
}
/// The inverse of load_record.
template <class T>
inline void store_record(std::vector<double>& a, int e, int k, int per_element, const T& x) {
  double* p = a.data() + lane_index(e, k, per_element);
  if constexpr (materials::lane_count<T> <= interleave_width) {
    materials::store_lanes(p, x);
  } else {
    std::memcpy(p, &x, sizeof(T) / 2);
    std::memcpy(p + interleave_width * per_element, reinterpret_cast<const char*>(&x) + sizeof(T) / 2, sizeof(T) / 2);
  }
}
/// Element e's reference gradient operator B0 [3][8] (m^2) out of the interleaved record.
inline void reference_gradient(const ElementBlock& block, int e, double B[24]) {
  for (int k = 0; k < 24; ++k) B[k] = block.B0[lane_index(e, k, 24)];
}
/// The interleaved records of `elements` (indices into `from`), grouped anew in that order:
/// a rank's share of a block, or one element on its own. Empty stays empty (no such data).
std::vector<double> select_interleaved(const std::vector<double>& from, std::span<const int> elements, int per_element);

/// Element mean of the equivalent plastic strain (materials that declare
/// equivalent_plastic_strain_index; 0 for the others) into out[e], e over the block.
void equivalent_plastic_strain(const ElementBlock& block, double* out);

/// Build the reference data of one block. Throws solver::SetupError naming the first element with
/// a non-positive volume or Jacobian (1-based, as gmsh and ParaView show them + 1; `global_element`
/// maps a rank's local elements to the whole mesh's numbers, empty: the mesh is the whole mesh).
ElementBlock make_element_block(const mesh::Mesh& mesh, const mesh::Block& block,
                                const materials::Material& material, const inputs::SectionSpec& section,
                                const std::vector<int>& global_element = {});

}  // namespace tribex::solver
