// SPDX-License-Identifier: MIT
// `tribex bench contact --faces N`: cost of contact search + enforcement per step against surface
// size. Two thin structured blocks with non-matching faces (N master faces, about N slave faces),
// the upper one overlapping the lower by 1 % of an element and sliding sideways by 0.02 element per
// step, so the narrow phase runs every step and the broad phase whenever the displacement trigger
// fires. Prints the time per step, per slave node, the number of broad-phase searches, and the
// share of one broad-phase search. `--enforcement mortar` times the segment-to-segment enforcement
// (contact/mortar/) on the same surfaces instead of node-to-face.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "contact/contact_manager.hpp"
#include "tools/bench/allocation_counter.hpp"
#include "mesh/box.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {

int contact_bench(const std::vector<std::string>& argv) {
  const char* usage =
      "tribex bench contact [--faces N] [--steps S] [--enforcement node-to-face|mortar]\n"
      "  Times contact search + enforcement on two flat surfaces with about N faces each (default 10000).\n";
  tools::Args args(argv, "tribex bench contact", usage);
  if (args.answered_help()) return tools::exit_ok;
  const long faces = args.integer("--faces", 10000);
  const long steps = args.integer("--steps", 200);
  const std::string enforcement = args.text("--enforcement", "node-to-face");
  args.finish();
  if (enforcement != "node-to-face" && enforcement != "mortar")
    throw tools::BadInput("tribex bench contact: --enforcement must be node-to-face or mortar, not '" + enforcement + "'");
  if (faces < 4 || faces > 4000000) throw tools::BadInput("tribex bench contact: --faces must be in 4..4000000");
  const int n = static_cast<int>(std::lround(std::sqrt(double(faces))));
  const double h = 1e-9;
  mesh::BoxSpec lower{"lower", {0, 0, -h}, {n * h, n * h, h}, {n, n, 1}, "", 1.0};
  // Slave faces 1.1x smaller than master faces, shifted: no node lines up with another.
  const int m = static_cast<int>(std::lround(n * 1.1)) - 2;
  mesh::BoxSpec upper{"upper", {0.37 * h, 0.41 * h, -0.01 * h}, {m * h / 1.1, m * h / 1.1, h}, {m, m, 1}, "", 1.0};
  mesh::Mesh mesh = mesh::generate_box(lower);
  mesh::append(mesh, mesh::generate_box(upper));
  std::vector<contact::ContactSurface> surfaces;
  surfaces.push_back(contact::make_surface(mesh, "slave", {"upper_zmin"}));
  surfaces.push_back(contact::make_surface(mesh, "master", {"lower_zmax"}));
  const std::vector<double> mass(static_cast<std::size_t>(mesh.node_count()), 1e-24);
  contact::InteractionSettings it;
  it.slave = 0;
  it.master = 1;
  if (enforcement == "mortar") it.enforcement = contact::Enforcement::mortar;
  contact::ContactManager manager(surfaces, {it}, mass, 1e-14, mesh.node_count());
  std::vector<double> x = mesh.coordinates, v(x.size(), 0.0), f(x.size(), 0.0);
  const auto& slave_nodes = manager.surfaces()[0].nodes;
  using Clock = std::chrono::steady_clock;
  double total = 0.0;
  long contact_nodes = 0;
  std::uint64_t allocations_before = 0;
  for (long s = 0; s < steps; ++s) {
    if (s == 1) allocations_before = bench::allocation_count();  // the first call sizes the buffers
    for (int node : slave_nodes) x[3 * node] += 0.02 * h;  // slide
    const auto t0 = Clock::now();
    const auto totals = manager.compute_forces(x.data(), v.data(), f.data());
    total += std::chrono::duration<double>(Clock::now() - t0).count();
    contact_nodes = totals.nodes;
  }
  const double per_step = total / double(steps);
  std::printf("master faces %d, slave faces %d, slave nodes %zu (in contact at the end: %ld)\n",
              manager.surfaces()[1].face_count(), manager.surfaces()[0].face_count(), slave_nodes.size(), contact_nodes);
  std::printf("enforcement: %s\n", enforcement.c_str());
  std::printf("broad-phase searches: %ld in %ld steps\n", manager.total_searches(), steps);
  std::printf("heap_allocations_after_first_step=%llu\n",
              static_cast<unsigned long long>(bench::allocation_count() - allocations_before));
  std::printf("contact_us_per_step=%.2f\n", 1e6 * per_step);
  std::printf("contact_ns_per_slave_node_step=%.2f\n", 1e9 * per_step / double(slave_nodes.size()));
  return 0;
}

}  // namespace tribex::cli
