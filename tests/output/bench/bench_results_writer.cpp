// SPDX-License-Identifier: MIT
// Benchmark: ResultsWriter write time per step on an N^3 hex box (default 60) with displacement
// and velocity (nodal vectors) and stress (element, Voigt 6 -> stored 9). Not a test.
//   tribex_bench_results_writer [N] [steps] [directory] [gzip level, default the writer's]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../sample_case.hpp"

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 60;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10;
  const std::string dir = argc > 3 ? argv[3] : "bench_results_output";
  tribex::solver::ResultsOptions options;
  if (argc > 4) options.gzip_level = std::atoi(argv[4]);
  if (n < 1 || steps < 1) {
    std::fprintf(stderr, "usage: %s [N>=1] [steps>=1] [directory]\n", argv[0]);
    return 2;
  }
  using clock = std::chrono::steady_clock;
  const auto mesh = tribex::test::make_hand_box(n, n, n);
  const std::size_t nodes = std::size_t(mesh.node_count()), elements = std::size_t(mesh.element_count());
  std::vector<double> u(3 * nodes), v(3 * nodes), sigma(6 * elements);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 1e-9 * double(i), v[i] = 1e-3 * double(i % 97);
  for (std::size_t i = 0; i < sigma.size(); ++i) sigma[i] = 1e6 * double(i % 13);

  auto t0 = clock::now();
  tribex::solver::ResultsWriter w(dir, mesh, nullptr, std::nullopt, options);
  const double setup = std::chrono::duration<double>(clock::now() - t0).count();
  const std::vector<tribex::solver::FieldView> nodal = {{"displacement", 3, u, "m"}, {"velocity", 3, v, "m/s"}};
  const std::vector<tribex::solver::FieldView> element = {{"stress", 6, sigma, "Pa"}};
  std::vector<double> per_step;
  for (int s = 0; s < steps; ++s) {
    t0 = clock::now();
    w.write_step(1e-9 * (s + 1), nodal, element);
    per_step.push_back(std::chrono::duration<double>(clock::now() - t0).count());
  }
  double sum = 0, lo = 1e30, hi = 0;
  for (double t : per_step) sum += t, lo = std::min(lo, t), hi = std::max(hi, t);
  const double mb = double((6 * nodes + 9 * elements) * sizeof(double)) / 1e6;
  std::printf("mesh %d^3: %zu nodes, %zu hexes; gzip level %d; setup (mesh write) %.1f ms\n", n, nodes, elements,
              options.gzip_level, 1e3 * setup);
  std::printf("%d steps: write_step mean %.1f ms, min %.1f ms, max %.1f ms, %.1f MB/step (%.0f MB/s mean)\n",
              steps, 1e3 * sum / steps, 1e3 * lo, 1e3 * hi, mb, mb * steps / sum);
  std::printf("results.h5: %.1f MB\n", double(std::filesystem::file_size(w.h5_path())) / 1e6);

  // Baseline on the same disk: plain fwrite of the same bytes per step (the floor for any format).
  const std::string raw = dir + "/baseline.bin";
  std::FILE* f = std::fopen(raw.c_str(), "wb");
  if (f == nullptr) return 1;
  std::vector<double> tensor(9 * elements, 1.0);
  double raw_sum = 0;
  for (int s = 0; s < steps; ++s) {
    t0 = clock::now();
    std::fwrite(u.data(), sizeof(double), u.size(), f);
    std::fwrite(v.data(), sizeof(double), v.size(), f);
    std::fwrite(tensor.data(), sizeof(double), tensor.size(), f);
    std::fflush(f);
    raw_sum += std::chrono::duration<double>(clock::now() - t0).count();
  }
  std::fclose(f);
  std::filesystem::remove(raw);
  std::printf("baseline fwrite of the same bytes: mean %.1f ms/step\n", 1e3 * raw_sum / steps);
  return 0;
}
