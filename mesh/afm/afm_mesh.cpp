// SPDX-License-Identifier: MIT
// Structured hex8 grid on the spline surface of an AFM map. Node (i, j, k) has index
// i + (nx+1)(j + (ny+1) k), element (i, j, k) index i + nx (j + ny k), k = 0 at the bottom: the
// substrate layers come first, then the coating layers, so each block is one contiguous range.
#include "mesh/afm/afm_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "mesh/afm/cubic_spline.hpp"
#include "mesh/afm/graded_axis.hpp"
#include "mesh/afm/preprocess.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {
namespace {

std::string nm(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g nm", v * 1e9);
  return b;
}

// An element count as "%.3g" (1e+14 for what no integer type of the mesh could hold).
std::string format_count(double count) {
  char b[32];
  std::snprintf(b, sizeof b, count < 1e9 ? "%.0f" : "%.3g", count);
  return b;
}

std::string rect(const std::array<double, 4>& r) {
  std::string s = "(";  // built by appends: GCC 12 gives a false -Wrestrict on "(" + std::string
  s += nm(r[0]);
  s += ", ";
  s += nm(r[1]);
  s += ") + ";
  s += nm(r[2]);
  s += " x ";
  s += nm(r[3]);
  return s;
}


void check_spec(const HeightMap& map, const AfmMeshSpec& s) {
  const std::string& f = map.source;
  auto finite_positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!finite_positive(s.element_size))
    throw MeshError(f + ": element size " + nm(s.element_size) + " must be positive (e.g. 0.5nm)");
  if (!finite_positive(s.depth)) throw MeshError(f + ": depth " + nm(s.depth) + " must be positive (e.g. 50nm)");
  if (!(std::isfinite(s.coating_thickness) && s.coating_thickness >= 0.0))
    throw MeshError(f + ": coating thickness " + nm(s.coating_thickness) + " must be >= 0");
  if (s.coating_layers < 1 || s.coating_layers > 100)
    throw MeshError(f + ": coating layers " + std::to_string(s.coating_layers) + " must lie in 1 to 100");
  if (!(s.grading_ratio >= 1.0 && s.grading_ratio <= 1.3))
    throw MeshError(f + ": grading ratio " + std::to_string(s.grading_ratio) + " must lie in [1, 1.3]");
  // A coating layer under 1e-6 of the element size gives degenerate elements (det J underflows; issue 54,
  // item 16: 1e-30 m was reported as a hex8 node-order fault).
  const double thinnest = 1e-6 * s.element_size * s.coating_layers;
  if (s.coating_thickness > 0.0 && s.coating_thickness < thinnest)
    throw MeshError(f + ": coating thickness " + nm(s.coating_thickness) + " gives " + std::to_string(s.coating_layers) +
                    " layers under 1e-6 of the element size " + nm(s.element_size) +
                    " each (their elements would be degenerate); give 0 (no coating) or at least " + nm(thinnest));
  if (!(s.depth > s.coating_thickness + s.element_size))
    throw MeshError(f + ": depth " + nm(s.depth) + " must exceed the coating thickness plus one element (" +
                    nm(s.coating_thickness + s.element_size) + "); give a larger depth");
}

// Mean and RMS of the pixels whose centres lie in the window (all pixels if none do).
void window_statistics(const HeightMap& map, const std::array<double, 4>& w, double& mean, double& rms_out) {
  double sum = 0.0;
  std::size_t n = 0;
  for (int pass = 0; pass < 2 && n == 0; ++pass)
    for (std::size_t iy = 0; iy < map.ny; ++iy)
      for (std::size_t ix = 0; ix < map.nx; ++ix) {
        const double x = (static_cast<double>(ix) + 0.5) * map.dx, y = (static_cast<double>(iy) + 0.5) * map.dy;
        if (pass == 0 && !(x >= w[0] && x <= w[0] + w[2] && y >= w[1] && y <= w[1] + w[3])) continue;
        sum += map.at(ix, iy);
        ++n;
      }
  mean = sum / static_cast<double>(n);
  double sum2 = 0.0;
  n = 0;
  for (std::size_t iy = 0; iy < map.ny; ++iy)
    for (std::size_t ix = 0; ix < map.nx; ++ix) {
      const double x = (static_cast<double>(ix) + 0.5) * map.dx, y = (static_cast<double>(iy) + 0.5) * map.dy;
      if (!(x >= w[0] && x <= w[0] + w[2] && y >= w[1] && y <= w[1] + w[3])) continue;
      sum2 += (map.at(ix, iy) - mean) * (map.at(ix, iy) - mean);
      ++n;
    }
  rms_out = n ? std::sqrt(sum2 / static_cast<double>(n)) : 0.0;
}

}  // namespace

Mesh generate_afm_mesh(const HeightMap& map, const AfmMeshSpec& spec, AfmMeshReport* report) {
  check_height_map(map, map.source);
  check_spec(map, spec);
  const std::string& f = map.source;
  const double sx = map.size_x(), sy = map.size_y(), tol = 1e-9 * std::max(sx, sy);
  const std::array<double, 4> window = spec.window.value_or(std::array<double, 4>{0.0, 0.0, sx, sy});
  if (!(window[2] > 0 && window[3] > 0 && window[0] >= -tol && window[1] >= -tol && window[0] + window[2] <= sx + tol &&
        window[1] + window[3] <= sy + tol))
    throw MeshError(f + ": window " + rect(window) + " must be non-empty and inside the " + nm(sx) + " x " + nm(sy) +
                    " map; choose X0,Y0,W,H with X0+W <= " + nm(sx) + " and Y0+H <= " + nm(sy));
  // A window narrower than a few pixels has no measured relief of its own: its surface is the spline
  // between a handful of heights, and its mean and RMS come from a pixel or two (an "RMS 0 nm" mesh,
  // a window `tribex surface stats` refuses). Refused unless the deck or command line asks for it.
  const double span_x = window[2] / map.dx, span_y = window[3] / map.dy;
  if (!spec.interpolate_small_window && (span_x < min_window_pixels || span_y < min_window_pixels)) {
    char spans[64];
    std::snprintf(spans, sizeof spans, "%.3g x %.3g", span_x, span_y);
    throw MeshError(f + ": window " + rect(window) + " spans " + spans + " pixels (pixel " + nm(map.dx) + " x " +
                    nm(map.dy) + "); a mesh that follows measured heights needs at least " +
                    std::to_string(min_window_pixels) + " a side: enlarge it to " + nm(min_window_pixels * map.dx) +
                    " x " + nm(min_window_pixels * map.dy) +
                    ", or mesh the spline between pixels with 'small window = interpolate' (--small-window interpolate)");
  }
  const std::array<double, 4> track = spec.track.value_or(window);
  if (!(track[2] > 0 && track[3] > 0 && track[0] >= window[0] - tol && track[1] >= window[1] - tol &&
        track[0] + track[2] <= window[0] + window[2] + tol && track[1] + track[3] <= window[1] + window[3] + tol))
    throw MeshError(f + ": track " + rect(track) + " must be non-empty and inside the window " + rect(window));

  const double h = spec.element_size, r = spec.grading_ratio;
  // The element count is estimated before anything of the mesh's size is allocated: the track alone
  // needs (W/h) x (H/h) columns of at least one element each.
  const auto over_limit = [&](double count, const std::string& what) {
    return MeshError(f + ": " + what + " " + format_count(count) + " elements, over the limit of " +
                     std::to_string(spec.max_elements) + "; use a larger element size, a smaller track or window, or " +
                     "raise the limit (--max-elements)");
  };
  const double track_columns = std::ceil(track[2] / h) * std::ceil(track[3] / h);
  if (!(track_columns <= static_cast<double>(spec.max_elements)))
    throw over_limit(track_columns, "the track alone (" + nm(track[2]) + " x " + nm(track[3]) + " at " + nm(h) + ") needs at least");
  const auto xs = graded_axis(window[0], window[0] + window[2], track[0], track[0] + track[2], h, r);
  const auto ys = graded_axis(window[1], window[1] + window[3], track[1], track[1] + track[3], h, r);
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  if (static_cast<double>(nx) * ny > static_cast<double>(spec.max_elements))
    throw over_limit(static_cast<double>(nx) * ny, "the window's " + std::to_string(nx) + " x " + std::to_string(ny) +
                                                       " columns need at least");

  // Layers with depth. Reference substrate thickness T = depth - t_c under the mean height; the
  // blended layers stretch by (s - t_c - z_bot)/T over a point of the surface, so the first layer is
  // sized for the highest point: at most h there (and at most r times a coating layer), then graded.
  double z_ref = 0.0, surface_rms = 0.0;
  window_statistics(map, window, z_ref, surface_rms);
  const double t_c = spec.coating_thickness, z_bot = z_ref - spec.depth, thickness = spec.depth - t_c;
  const std::vector<double> surface = SplineSurface(map).evaluate_grid(xs, ys);
  const auto [lowest, highest] = std::minmax_element(surface.begin(), surface.end());
  if (!(*lowest - t_c - z_bot > 0.0))
    throw MeshError(f + ": the surface dips " + nm(z_ref - *lowest) + " below its mean inside the window, deeper than depth " +
                    nm(spec.depth) + " minus the coating; give a depth of at least " + nm(2.0 * (z_ref - *lowest) + t_c));
  const double stretch = std::max(1.0, (*highest - t_c - z_bot) / thickness);
  const int nc = t_c > 0.0 ? spec.coating_layers : 0;
  const double first = (nc > 0 ? std::min(h, r * t_c / nc) : h) / stretch;
  auto layer_sizes = graded_sizes(thickness, first / r, r);  // ordered from the top down
  const int nzs = static_cast<int>(layer_sizes.size()), nz = nzs + nc;
  std::vector<double> sigma(static_cast<std::size_t>(nzs) + 1, 0.0);  // 0 at the bottom, 1 under the coating
  for (int k = 0; k < nzs; ++k) sigma[k + 1] = sigma[k] + layer_sizes[nzs - 1 - k] / thickness;
  sigma[nzs] = 1.0;

  const long elements = static_cast<long>(nx) * ny * nz;
  if (elements > spec.max_elements)
    throw over_limit(static_cast<double>(elements), "the mesh (" + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                                                        std::to_string(nz) + ") would have");

  Mesh m;
  const int px = nx + 1, py = ny + 1;
  auto node = [&](int i, int j, int k) { return i + px * (j + py * k); };
  m.coordinates.resize(3 * static_cast<std::size_t>(px) * py * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double s = surface[static_cast<std::size_t>(j) * px + i];
        const double z = k <= nzs ? z_bot + (s - t_c - z_bot) * sigma[k] : s - t_c + t_c * (k - nzs) / nc;
        double* c = &m.coordinates[3 * static_cast<std::size_t>(node(i, j, k))];
        c[0] = xs[i];
        c[1] = ys[j];
        c[2] = k == nz ? s : z;  // the top exactly on the spline surface
      }
  m.connectivity.resize(8 * static_cast<std::size_t>(elements));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        int* e = &m.connectivity[8 * (static_cast<std::size_t>(i) + nx * (j + static_cast<std::size_t>(ny) * k))];
        const int n0 = node(i, j, k);
        const int bottom[4] = {n0, n0 + 1, n0 + 1 + px, n0 + px};
        for (int a = 0; a < 4; ++a) {
          e[a] = bottom[a];
          e[a + 4] = bottom[a] + px * py;
        }
      }
  m.blocks.push_back({"substrate", 0, nx * ny * nzs});
  if (nc > 0) m.blocks.push_back({"coating", nx * ny * nzs, nx * ny * nc});

  auto element = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  auto& top = m.side_sets["substrate_top"];
  auto& track_top = m.side_sets["substrate_track"];
  auto& bottom = m.side_sets["substrate_bottom"];
  auto in_track = [&](int i, int j) {
    const double xc = 0.5 * (xs[i] + xs[i + 1]), yc = 0.5 * (ys[j] + ys[j + 1]);
    return xc >= track[0] && xc <= track[0] + track[2] && yc >= track[1] && yc <= track[1] + track[3];
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      top.push_back({element(i, j, nz - 1), 5});
      if (in_track(i, j)) track_top.push_back({element(i, j, nz - 1), 5});
      bottom.push_back({element(i, j, 0), 4});
    }
  auto& xmin = m.side_sets["substrate_xmin"];
  auto& xmax = m.side_sets["substrate_xmax"];
  auto& ymin = m.side_sets["substrate_ymin"];
  auto& ymax = m.side_sets["substrate_ymax"];
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      xmin.push_back({element(0, j, k), 3});
      xmax.push_back({element(nx - 1, j, k), 1});
    }
    for (int i = 0; i < nx; ++i) {
      ymin.push_back({element(i, 0, k), 0});
      ymax.push_back({element(i, ny - 1, k), 2});
    }
  }
  auto& sides = m.side_sets["substrate_sides"];
  for (const auto* part : {&xmin, &xmax, &ymin, &ymax}) sides.insert(sides.end(), part->begin(), part->end());
  for (const auto& [name, set] : m.side_sets) {
    std::vector<int> nodes;
    for (const Side& sd : set)
      for (int a = 0; a < 4; ++a) nodes.push_back(m.connectivity[8 * static_cast<std::size_t>(sd.element) + hex8_face_nodes[sd.face][a]]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    m.node_sets[name] = std::move(nodes);
  }

  validate(m, "AFM mesh of " + f);

  if (report) {
    AfmMeshReport& rep = *report;
    rep = AfmMeshReport{};
    rep.nx = nx;
    rep.ny = ny;
    rep.substrate_layers = nzs;
    rep.coating_layers = nc;
    rep.window = window;
    rep.track = track;
    rep.z_reference = z_ref;
    rep.z_bottom = z_bot;
    rep.surface_rms = surface_rms;
    double sum = 0.0, lo = std::numeric_limits<double>::infinity(), lo_track = lo;
    for (int e = 0; e < m.element_count(); ++e) {
      const double q = scaled_jacobian(m, e);
      sum += q;
      lo = std::min(lo, q);
      const int i = e % nx, j = (e / nx) % ny;
      if (in_track(i, j)) lo_track = std::min(lo_track, q);
    }
    rep.min_scaled_jacobian = lo;
    rep.mean_scaled_jacobian = sum / m.element_count();
    rep.min_scaled_jacobian_track = lo_track;
    // Largest grid spacing in the track: in-plane spacings and the top layer's thickness.
    double size = 0.0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (!in_track(i, j)) continue;
        size = std::max({size, xs[i + 1] - xs[i], ys[j + 1] - ys[j]});
        for (int a = 0; a < 4; ++a) {
          const int c = m.connectivity[8 * static_cast<std::size_t>(element(i, j, nz - 1)) + a];
          const int t = m.connectivity[8 * static_cast<std::size_t>(element(i, j, nz - 1)) + a + 4];
          size = std::max(size, m.coordinates[3 * static_cast<std::size_t>(t) + 2] - m.coordinates[3 * static_cast<std::size_t>(c) + 2]);
        }
      }
    rep.track_element_size = size;
  }
  return m;
}

Mesh mesh_afm_file(const std::string& path, int channel, const AfmMeshSpec& spec, AfmMeshReport* report) {
  return generate_afm_mesh(level_plane(read_height_map(path, channel)), spec, report);
}

}  // namespace tribex::mesh::afm
