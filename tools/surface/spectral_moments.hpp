// SPDX-License-Identifier: MIT
// Spectral moments of a height map and the summit statistics that follow from them.
//
// Profile moments along a direction x (docs/theory.md 10.1, report Eq. 4.5), heights from the mean plane:
//   m0 = <z^2>,  m2 = <(dz/dx)^2>,  m4 = <(d^2z/dx^2)^2>
// with central differences z'_i = (z_{i+1} - z_{i-1}) / (2 dx), z''_i = (z_{i+1} - 2 z_i + z_{i-1}) / dx^2
// averaged over every interior point of every profile.
//
// Summit statistics of the equivalent isotropic surface (moments averaged over x and y; Nayak 1971,
// Bush-Gibson-Thomas 1975, as used by McCool 1986; docs/theory.md 10.2):
//   alpha = m0 m4 / m2^2                    bandwidth (>= 1.5 for a Gaussian surface)
//   eta   = m4 / (6 pi sqrt(3) m2)          summit density, 1/m^2
//   R_s   = 1 / ((8/3) sqrt(m4 / pi))       mean summit radius, m (large-alpha approximation)
//   sigma_s = sqrt((1 - 0.8968 / alpha) m0) summit-height standard deviation, m
//   zbar_s  = 4 sqrt(m0 / (pi alpha))       mean summit height above the mean plane, m
#pragma once

#include <vector>

#include "mesh/afm/height_map.hpp"

namespace tribex::surface {

struct Moments {
  double m0 = 0.0;  // m^2
  double m2 = 0.0;  // dimensionless
  double m4 = 0.0;  // 1/m^2
};

enum class Direction { x, y };

/// Moments of the profiles along x (fast scan, rows) or y (across, columns). The map should already be
/// levelled; m0 is taken about the map mean.
Moments profile_moments(const mesh::afm::HeightMap& map, Direction along);

/// Average of the x and y moments (McCool's equivalent isotropic surface).
Moments isotropic_moments(const mesh::afm::HeightMap& map);

/// Moments of two rough surfaces in contact: the sum (McCool 1986; report Section 4.3).
Moments combine(const Moments& a, const Moments& b);

struct SummitStatistics {
  double alpha = 0.0;
  double density = 0.0;   // eta, 1/m^2
  double radius = 0.0;    // R_s, m
  double sigma_s = 0.0;   // m
  double mean_height = 0.0;  // zbar_s, m
};

SummitStatistics summit_statistics(const Moments& m);

struct Summit {
  std::size_t ix = 0, iy = 0;
  double height = 0.0;     // m above the map mean
  double curvature = 0.0;  // kappa = -(z_xx + z_yy)/2, 1/m (docs/theory.md 10.5)
};

/// Grid points higher than all 8 neighbours (interior points only), with their curvature.
std::vector<Summit> find_summits(const mesh::afm::HeightMap& map);

}  // namespace tribex::surface
