// SPDX-License-Identifier: MIT
// `tribex bench block`: the standard element benchmark of issue "Foundation" (tools/bench/README.md).
// A unit cube of N^3 hex8, steel (rho 7800 kg/m^3, K 160 GPa, G 80 GPa), nodes on x = 0 fixed,
// nodes on x = 1 pulled at 10 m/s in x, time step half the stable estimate, no output in the loop.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <string_view>

#include "inputs/cube_deck.hpp"
#include "solver/integrators/central_difference.hpp"
#include "solver/hex8/internal_forces.hpp"
#include "solver/model.hpp"
#include "tools/bench/allocation_counter.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {

int contact_bench(const std::vector<std::string>& argv);      // contact_bench.cpp
int broad_phase_bench(const std::vector<std::string>& argv);  // broad_phase_bench.cpp

namespace {

const char* usage =
    "tribex bench contact [--faces N] [--steps S]   (search + enforcement cost, see --help)\n"
    "tribex bench broad-phase [--faces N]           (bucket grid against CGAL box_intersection_d)\n"
    "tribex bench block [--n N] [--element mean_quadrature|fully_integrated]\n"
    "                   [--material elastic|neohookean] [--steps S] [--lanes 2|4|8] [--isa sse2|avx2|avx512]\n"
    "  Times the explicit loop on a unit cube of N^3 hex8 elements (default N 20, 200 steps).\n"
    "  Prints loop-only and whole-command ns per element per step, heap allocations inside the\n"
    "  loop and the peak resident memory; the last line is ns_per_element_step=VALUE (loop only).\n"
    "  --lanes: elements per kernel call (default: the widest the CPU has, 8 with AVX-512F and VL, 4 with AVX2,\n"
    "  else 2, but at most 4 for mean quadrature; a width the CPU lacks runs at its widest).\n"
    "  --isa: the best instruction set the kernels may use (default: the CPU's best; four lanes run\n"
    "  with AVX-512VL's 32 registers where the CPU has them, with AVX2's 16 under --isa avx2).\n";

// `--isa` values, in solver::KernelIsa's order
constexpr std::string_view isa_names[] = {"sse2", "avx2", "avx512"};

inputs::Deck block_deck(int n, inputs::ElementFormulation formulation, inputs::MaterialModel model) {
  const double K = 160e9, G = 80e9;
  inputs::Deck deck = inputs::cube_deck({.name = "bench_block",
                                         .path = "(tribex bench block)",
                                         .finite_element_model = "cube",
                                         .block = "cube",
                                         .material = "steel",
                                         .section = "hex8",
                                         .intervals = n,
                                         .size = 1.0,
                                         .model = model,
                                         .formulation = formulation,
                                         .youngs_modulus = 9 * K * G / (3 * K + G),              // E = 9KG/(3K+G)
                                         .poissons_ratio = (3 * K - 2 * G) / (2 * (3 * K + G)),  // nu = (3K-2G)/(2(3K+G))
                                         .density = 7800.0});
  inputs::FunctionSpec pull{"pull", {0.0, 1.0}, {10.0, 10.0}, {}};  // 10 m/s
  deck.functions.push_back(pull);
  auto& proc = deck.procedure;  // termination time 1 s: the loop is stopped by the step count
  proc.time_control.time_step_scale_factor = 0.5;
  proc.region.fixed_displacements.push_back({"cube_xmin", {inputs::Component::x, inputs::Component::y, inputs::Component::z}, {}});
  proc.region.prescribed_motions.push_back(
      {inputs::PrescribedMotionSpec::Kind::velocity, "cube_xmax", inputs::Component::x, "pull", 1.0, {}, {}});
  return deck;
}

}  // namespace

int bench_command(const std::vector<std::string>& argv) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  if (!argv.empty() && argv[0] == "contact")
    return contact_bench(std::vector<std::string>(argv.begin() + 1, argv.end()));
  if (!argv.empty() && argv[0] == "broad-phase")
    return broad_phase_bench(std::vector<std::string>(argv.begin() + 1, argv.end()));
  tools::Args args(argv, "tribex bench", usage);
  if (args.answered_help()) return tools::exit_ok;
  const std::string what = args.positional(0, "benchmark name (block)");
  const long n = args.integer("--n", 20);
  const long steps = args.integer("--steps", 200);
  const std::string element = args.text("--element", "mean_quadrature");
  const std::string material = args.text("--material", "elastic");
  const long lanes = args.integer("--lanes", 0);
  const std::string isa = args.text("--isa", "avx512");
  args.finish();
  if (what != "block") throw tools::BadInput("tribex bench: unknown benchmark '" + what + "' (known: block, contact, broad-phase)");
  if (n < 1 || n > 400) throw tools::BadInput("tribex bench: --n must be in 1..400");
  if (steps < 1) throw tools::BadInput("tribex bench: --steps must be >= 1");
  if (lanes != 0 && lanes != 2 && lanes != 4 && lanes != 8) throw tools::BadInput("tribex bench: --lanes must be 2, 4 or 8");
  solver::set_element_lane_width(static_cast<int>(lanes));
  const auto* named_isa = std::find(std::begin(isa_names), std::end(isa_names), isa);
  if (named_isa == std::end(isa_names)) throw tools::BadInput("tribex bench: --isa must be sse2, avx2 or avx512");
  solver::limit_element_isa(static_cast<solver::KernelIsa>(named_isa - std::begin(isa_names)));
  inputs::ElementFormulation formulation;
  if (element == "mean_quadrature") formulation = inputs::ElementFormulation::mean_quadrature;
  else if (element == "fully_integrated") formulation = inputs::ElementFormulation::fully_integrated;
  else throw tools::BadInput("tribex bench: --element must be mean_quadrature or fully_integrated");
  inputs::MaterialModel model;
  if (material == "elastic") model = "elastic";
  else if (material == "neohookean" || material == "neo_hookean") model = "neo_hookean";
  else throw tools::BadInput("tribex bench: --material must be elastic or neohookean");

  const inputs::Deck deck = block_deck(static_cast<int>(n), formulation, model);
  solver::Model m = solver::build_model(deck);
  solver::CentralDifference integrator(m, deck.procedure.time_control);
  integrator.init();
  const std::function<void()> nothing;
  const auto allocations_before = bench::allocation_count();
  const auto loop_start = Clock::now();
  for (long s = 0; s < steps; ++s) integrator.step(nothing);
  const double loop = std::chrono::duration<double>(Clock::now() - loop_start).count();
  const auto allocations = bench::allocation_count() - allocations_before;
  const double total = std::chrono::duration<double>(Clock::now() - t0).count();
  rusage usage_info{};
  getrusage(RUSAGE_SELF, &usage_info);
  const double elements = double(m.mesh.element_count());
  const double per = 1e9 * loop / (elements * double(steps));
  std::printf("block %ld^3 = %.0f elements, %s, %s, %d lanes (%s), %ld steps of %.4g s\n", n, elements, element.c_str(),
              material.c_str(), solver::element_lane_width(formulation), isa_names[int(solver::element_isa())].data(), steps,
              integrator.next_dt());
  std::printf("loop %.4f s, whole command %.4f s\n", loop, total);
  std::printf("whole_command_ns_per_element_step=%.2f\n", 1e9 * total / (elements * double(steps)));
  std::printf("heap_allocations_in_loop=%llu\n", static_cast<unsigned long long>(allocations));
  std::printf("peak_rss_mib=%.1f\n", double(usage_info.ru_maxrss) / 1024.0);
  std::printf("energy_error=%.3e\n", integrator.energies().relative_error());
  std::printf("ns_per_element_step=%.2f\n", per);
  return 0;
}

}  // namespace tribex::cli
