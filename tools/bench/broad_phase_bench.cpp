// SPDX-License-Identifier: MIT
// `tribex bench broad-phase --faces N`: the contact broad phase alone, our uniform bucket grid
// (contact/search/bucket_search) against CGAL's box_intersection_d on the same boxes (face boxes
// inflated by the search margin, slave nodes as degenerate boxes). Used to decide which search
// tribex keeps (tools/bench/README.md); CGAL is linked into this benchmark only.
#include <CGAL/box_intersection_d.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "contact/search/bucket_search.hpp"
#include "contact/surface.hpp"
#include "mesh/box.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {

int broad_phase_bench(const std::vector<std::string>& argv) {
  const char* usage = "tribex bench broad-phase [--faces N] [--repeat R]\n";
  tools::Args args(argv, "tribex bench broad-phase", usage);
  if (args.answered_help()) return tools::exit_ok;
  const long faces = args.integer("--faces", 10000);
  const long repeat = args.integer("--repeat", 5);
  args.finish();
  if (faces < 4 || faces > 4000000) throw tools::BadInput("tribex bench broad-phase: --faces must be in 4..4000000");
  const int n = static_cast<int>(std::lround(std::sqrt(double(faces))));
  const double h = 1e-9;
  const int m = static_cast<int>(std::lround(n * 1.1)) - 2;
  mesh::Mesh mesh = mesh::generate_box({"lower", {0, 0, -h}, {n * h, n * h, h}, {n, n, 1}, "", 1.0});
  mesh::append(mesh, mesh::generate_box({"upper", {0.37 * h, 0.41 * h, -0.01 * h}, {m * h / 1.1, m * h / 1.1, h},
                                         {m, m, 1}, "", 1.0}));
  const auto slave = contact::make_surface(mesh, "slave", {"upper_zmin"});
  const auto master = contact::make_surface(mesh, "master", {"lower_zmax"});
  const double margin = master.mean_edge;
  const double* x = mesh.coordinates.data();
  using Clock = std::chrono::steady_clock;

  contact::BucketSearch bucket;
  std::vector<int> offset, candidates;
  double ours = INFINITY;
  for (long r = 0; r < repeat; ++r) {
    const auto t0 = Clock::now();
    bucket.find_candidates(x, slave, master, margin, offset, candidates);
    ours = std::min(ours, std::chrono::duration<double>(Clock::now() - t0).count());
  }

  using Box = CGAL::Box_intersection_d::Box_d<double, 3, CGAL::Box_intersection_d::ID_EXPLICIT>;
  double cgal = INFINITY;
  std::size_t cgal_pairs = 0;
  for (long r = 0; r < repeat; ++r) {
    const auto t0 = Clock::now();
    std::vector<Box> face_boxes, node_boxes;
    face_boxes.reserve(static_cast<std::size_t>(master.face_count()));
    for (int f = 0; f < master.face_count(); ++f) {
      double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) {
          lo[i] = std::min(lo[i], x[3 * master.face_nodes[4 * f + a] + i] - margin);
          hi[i] = std::max(hi[i], x[3 * master.face_nodes[4 * f + a] + i] + margin);
        }
      face_boxes.emplace_back(lo, hi);
    }
    for (std::size_t k = 0; k < slave.nodes.size(); ++k) {
      double p[3] = {x[3 * slave.nodes[k]], x[3 * slave.nodes[k] + 1], x[3 * slave.nodes[k] + 2]};
      node_boxes.emplace_back(p, p);
    }
    std::size_t pairs = 0;
    CGAL::box_intersection_d(face_boxes.begin(), face_boxes.end(), node_boxes.begin(), node_boxes.end(),
                             [&](const Box&, const Box&) { ++pairs; });
    cgal = std::min(cgal, std::chrono::duration<double>(Clock::now() - t0).count());
    cgal_pairs = pairs;
  }
  std::printf("master faces %d, slave nodes %zu, margin %.3g m\n", master.face_count(), slave.nodes.size(), margin);
  std::printf("bucket grid: %.3f ms, %zu candidate pairs\n", 1e3 * ours, candidates.size());
  std::printf("CGAL box_intersection_d: %.3f ms, %zu candidate pairs\n", 1e3 * cgal, cgal_pairs);
  std::printf("bucket_over_cgal_time=%.3f\n", ours / cgal);
  return 0;
}

}  // namespace tribex::cli
