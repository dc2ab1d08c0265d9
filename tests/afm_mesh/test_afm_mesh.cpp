// SPDX-License-Identifier: MIT
// The AFM substrate mesh: acceptance items "Spline surface" (top nodes on an analytic surface within
// 1 % of its RMS) and "Mesh quality" (min scaled Jacobian > 0.3 on real tracks, nothing inverted),
// plus the coating, the side sets and bad specs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "mesh/afm/afm_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/mesh_error.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/errors.hpp"

using namespace tribex::mesh;
using namespace tribex::mesh::afm;

namespace {

constexpr double nm = 1e-9;

// Sum of sines, wavelengths 11 to 23 pixels (an AFM image oversamples its features), RMS ~ 1.2 nm.
double sines(double x, double y) {
  const double pi2 = 2.0 * std::numbers::pi;
  return 1.5 * nm * std::sin(pi2 * x / (16 * nm) + 0.3) * std::sin(pi2 * y / (23 * nm) + 1.1) +
         0.8 * nm * std::sin(pi2 * (x + 0.6 * y) / (11 * nm)) + 0.5 * nm * std::cos(pi2 * (0.7 * x - y) / (13 * nm));
}

HeightMap sampled_sines(std::size_t n, double d) {
  HeightMap m;
  m.nx = m.ny = n;
  m.dx = m.dy = d;
  m.source = "sum-of-sines map";
  for (std::size_t iy = 0; iy < n; ++iy)
    for (std::size_t ix = 0; ix < n; ++ix) m.heights.push_back(sines((ix + 0.5) * d, (iy + 0.5) * d));
  return m;
}

double rms_of_sines(const std::array<double, 4>& w) {
  double s = 0, s2 = 0;
  const int n = 400;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double z = sines(w[0] + w[2] * (i + 0.5) / n, w[1] + w[3] * (j + 0.5) / n);
      s += z;
      s2 += z * z;
    }
  s /= n * n;
  return std::sqrt(s2 / (n * n) - s * s);
}

std::array<double, 3> area_vector(const Mesh& m, const Side& s) {
  const auto n = m.side_nodes(s);
  const double* x = m.coordinates.data();
  double d1[3], d2[3];
  for (int i = 0; i < 3; ++i) {
    d1[i] = x[3 * n[2] + i] - x[3 * n[0] + i];
    d2[i] = x[3 * n[3] + i] - x[3 * n[1] + i];
  }
  return {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]), 0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
}

std::string sample(const char* name) { return std::string(TRIBEX_AFM_DATA_DIR) + "/" + name; }

}  // namespace

TEST(AfmMesh, TopNodesLieOnAnAnalyticSurfaceWithinOnePercentOfItsRms) {
  // 64 x 64 pixels of 1 nm; mesh a 40 x 40 nm window at 0.5 nm (between and on the pixels).
  const HeightMap map = sampled_sines(64, 1.0 * nm);
  AfmMeshSpec spec;
  spec.window = {{12 * nm, 12 * nm, 40 * nm, 40 * nm}};
  spec.track = {{20 * nm, 12 * nm, 24 * nm, 40 * nm}};
  spec.depth = 20 * nm;
  AfmMeshReport r;
  const Mesh m = generate_afm_mesh(map, spec, &r);
  const double rms = rms_of_sines(*spec.window);
  double worst = 0.0;
  const auto& top = m.node_sets.at("substrate_top");
  ASSERT_EQ(top.size(), static_cast<std::size_t>((r.nx + 1) * (r.ny + 1)));
  for (int n : top) {
    const double* c = &m.coordinates[3 * n];
    worst = std::max(worst, std::abs(c[2] - sines(c[0], c[1])));
  }
  std::printf("[ sines ] RMS %.4g nm, worst top-node error %.3g nm = %.3g %% of RMS, min SJ %.3f\n", rms / nm, worst / nm,
              100 * worst / rms, r.min_scaled_jacobian);
  EXPECT_LT(worst, 0.01 * rms);
  EXPECT_GT(worst, 1e-6 * rms);  // interpolation, not the analytic function itself
  EXPECT_GT(r.min_scaled_jacobian, 0.3);
  EXPECT_LE(r.track_element_size, 0.5 * nm * (1 + 1e-9));
}

TEST(AfmMesh, WholeMapUpToItsEdgesStaysWithinOnePercentOfRms) {
  // Up to the map edges (and the half pixel beyond the outermost pixel centres): the not-a-knot ends
  // keep the spline fourth-order there; natural ends gave 4.4 % of RMS at the edges of this map.
  const HeightMap map = sampled_sines(48, 0.5 * nm);
  AfmMeshSpec spec;
  spec.element_size = 0.5 * nm;
  spec.depth = 10 * nm;
  AfmMeshReport r;
  const Mesh m = generate_afm_mesh(map, spec, &r);
  const double rms = rms_of_sines({0, 0, 24 * nm, 24 * nm});
  double worst = 0.0;
  for (int n : m.node_sets.at("substrate_top")) {
    const double* c = &m.coordinates[3 * n];
    worst = std::max(worst, std::abs(c[2] - sines(c[0], c[1])));
  }
  std::printf("[ sines, whole map ] worst top-node error %.3g %% of RMS\n", 100 * worst / rms);
  EXPECT_LT(worst, 0.01 * rms);
}

TEST(AfmMesh, CoatingIsItsOwnBlockBondedToTheSubstrate) {
  const HeightMap map = sampled_sines(32, 1.0 * nm);
  AfmMeshSpec spec;
  spec.window = {{4 * nm, 4 * nm, 20 * nm, 12 * nm}};
  spec.depth = 15 * nm;
  spec.coating_thickness = 2 * nm;
  spec.coating_layers = 6;
  AfmMeshReport r;
  const Mesh m = generate_afm_mesh(map, spec, &r);
  const Block* sub = m.find_block("substrate");
  const Block* coat = m.find_block("coating");
  ASSERT_TRUE(sub && coat);
  const int columns = r.nx * r.ny;
  EXPECT_EQ(coat->element_count, 6 * columns);
  EXPECT_EQ(sub->element_count, r.substrate_layers * columns);
  EXPECT_EQ(r.coating_layers, 6);
  // Bonded: the bottom face of each coating element is the top face of the substrate element under it
  // (the same node indices), and every coating column is 2 nm thick along z.
  for (int c = 0; c < columns; ++c) {
    const int lowest_coat = coat->first_element + c, highest_sub = sub->first_element + sub->element_count - columns + c;
    for (int a = 0; a < 4; ++a) EXPECT_EQ(m.connectivity[8 * lowest_coat + a], m.connectivity[8 * highest_sub + a + 4]);
    const int top_coat = coat->first_element + coat->element_count - columns + c;
    const double z_top = m.coordinates[3 * m.connectivity[8 * top_coat + 4] + 2];
    const double z_bottom = m.coordinates[3 * m.connectivity[8 * lowest_coat] + 2];
    EXPECT_NEAR(z_top - z_bottom, 2 * nm, 1e-6 * nm);
  }
  // The contact surface is the coating's top.
  for (const Side& s : m.side_sets.at("substrate_top")) {
    EXPECT_GE(s.element, coat->first_element);
    EXPECT_EQ(s.face, 5);
  }
  EXPECT_GT(r.min_scaled_jacobian, 0.3);
}

TEST(AfmMesh, SideSetsCoverTheBoundaryAndPointOutward) {
  const HeightMap map = sampled_sines(32, 1.0 * nm);
  AfmMeshSpec spec;
  spec.window = {{2 * nm, 3 * nm, 25 * nm, 20 * nm}};
  spec.track = {{10 * nm, 3 * nm, 8 * nm, 20 * nm}};
  spec.depth = 12 * nm;
  spec.coating_thickness = 1 * nm;
  spec.coating_layers = 3;
  AfmMeshReport r;
  const Mesh m = generate_afm_mesh(map, spec, &r);
  const int nz = r.substrate_layers + r.coating_layers;
  const struct {
    const char* name;
    int axis;
    double sign;
    std::size_t count;
  } expected[] = {{"substrate_top", 2, 1, static_cast<std::size_t>(r.nx * r.ny)},
                  {"substrate_bottom", 2, -1, static_cast<std::size_t>(r.nx * r.ny)},
                  {"substrate_xmin", 0, -1, static_cast<std::size_t>(r.ny * nz)},
                  {"substrate_xmax", 0, 1, static_cast<std::size_t>(r.ny * nz)},
                  {"substrate_ymin", 1, -1, static_cast<std::size_t>(r.nx * nz)},
                  {"substrate_ymax", 1, 1, static_cast<std::size_t>(r.nx * nz)}};
  for (const auto& e : expected) {
    const auto& set = m.side_sets.at(e.name);
    EXPECT_EQ(set.size(), e.count) << e.name;
    double projected = 0.0;
    for (const Side& s : set) {
      const auto a = area_vector(m, s);
      EXPECT_GT(e.sign * a[e.axis], 0.0) << e.name;
      projected += e.sign * a[e.axis];
    }
    if (e.axis == 2) {
      EXPECT_NEAR(projected, 25 * nm * 20 * nm, 1e-6 * 25 * nm * 20 * nm) << e.name;
    }
  }
  EXPECT_EQ(m.side_sets.at("substrate_sides").size(), static_cast<std::size_t>(2 * (r.nx + r.ny) * nz));
  // The flat bottom lies depth below the mean height of the window's pixels.
  for (int n : m.node_sets.at("substrate_bottom")) EXPECT_NEAR(m.coordinates[3 * n + 2], r.z_reference - 12 * nm, 1e-20);
  // The track side set: the top faces over x in [10, 18] nm only.
  EXPECT_EQ(m.side_sets.at("substrate_track").size(), static_cast<std::size_t>(16 * r.ny));
}

TEST(AfmMesh, RealTrackOnDi1HasGoodElements) {
  // di-1: 500 nm scan, 512 px (0.98 nm pixels), flattened Height channel. A 20 x 40 nm piece of a track.
  AfmMeshSpec spec;
  spec.window = {{230 * nm, 200 * nm, 30 * nm, 50 * nm}};
  spec.track = {{235 * nm, 205 * nm, 20 * nm, 40 * nm}};
  spec.depth = 25 * nm;
  AfmMeshReport r;
  const Mesh m = mesh_afm_file(sample("di-1.di"), 0, spec, &r);
  std::printf("[ di-1 ] %d elements, RMS %.3g nm, min SJ %.3f (track %.3f), mean %.3f, track size %.3g nm\n",
              m.element_count(), r.surface_rms / nm, r.min_scaled_jacobian, r.min_scaled_jacobian_track,
              r.mean_scaled_jacobian, r.track_element_size / nm);
  EXPECT_GT(r.min_scaled_jacobian_track, 0.3);
  EXPECT_GT(r.min_scaled_jacobian, 0.3);
  EXPECT_GT(r.surface_rms, 0.05 * nm);  // a real, rough surface, not a flat one
  EXPECT_LE(r.track_element_size, 0.5 * nm * (1 + 1e-9));
  EXPECT_NO_THROW(validate(m, "di-1 track"));
}

TEST(AfmMesh, RealTrackOnDi5WithCoatingHasGoodElements) {
  // di-5: 1 um scan, 512 px (1.95 nm pixels), 32-bit ZSensor.
  AfmMeshSpec spec;
  spec.window = {{400 * nm, 600 * nm, 24 * nm, 40 * nm}};
  spec.depth = 25 * nm;
  spec.coating_thickness = 2 * nm;
  AfmMeshReport r;
  const Mesh m = mesh_afm_file(sample("di-5.di"), -1, spec, &r);
  std::printf("[ di-5 ] %d elements, RMS %.3g nm, min SJ %.3f, mean %.3f\n", m.element_count(), r.surface_rms / nm,
              r.min_scaled_jacobian, r.mean_scaled_jacobian);
  EXPECT_GT(r.min_scaled_jacobian, 0.3);
  EXPECT_NE(m.find_block("coating"), nullptr);
}

TEST(AfmMesh, BadSpecsAreRefusedWithTheFix) {
  const HeightMap map = sampled_sines(16, 1.0 * nm);
  auto message = [&](AfmMeshSpec s) {
    try {
      generate_afm_mesh(map, s);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  AfmMeshSpec s;
  s.depth = 10 * nm;
  s.window = {{10 * nm, 0, 10 * nm, 10 * nm}};
  EXPECT_NE(message(s).find("inside the 16 nm x 16 nm map"), std::string::npos) << message(s);
  // Under 4 pixels a side (pixel 1 nm): refused with the smallest window and the opt-in, which meshes it.
  s.window = {{4.2 * nm, 4.2 * nm, 3.5 * nm, 8 * nm}};
  EXPECT_NE(message(s).find("spans 3.5 x 8 pixels (pixel 1 nm x 1 nm); a mesh that follows measured heights needs at "
                            "least 4 a side: enlarge it to 4 nm x 4 nm, or mesh the spline between pixels with "
                            "'small window = interpolate'"),
            std::string::npos)
      << message(s);
  s.interpolate_small_window = true;
  EXPECT_EQ(message(s), "no error");
  s.interpolate_small_window = false;
  s.window = {{4.2 * nm, 4.2 * nm, 4 * nm, 8 * nm}};
  EXPECT_EQ(message(s), "no error");
  s.window.reset();
  s.track = {{0, 0, 20 * nm, 4 * nm}};
  EXPECT_NE(message(s).find("inside the window"), std::string::npos) << message(s);
  s.track.reset();
  s.grading_ratio = 1.5;
  EXPECT_NE(message(s).find("grading ratio"), std::string::npos);
  s.grading_ratio = 1.2;
  s.depth = 1 * nm;
  s.coating_thickness = 1 * nm;
  EXPECT_NE(message(s).find("give a larger depth"), std::string::npos);
  s.coating_thickness = 0;
  s.depth = 1.5 * nm;  // the surface dips about 2.9 nm below its mean
  EXPECT_NE(message(s).find("give a depth of at least"), std::string::npos) << message(s);
}

TEST(MeshCommand, WritesAMshThatReadsBackWithItsBlocksAndSets) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_afm_mesh_test";
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "track.msh").string();
  std::filesystem::remove(out);
  const int rc = tribex::cli::mesh_command({"afm", sample("di-1.di"), "--channel", "0", "--window", "100nm,100nm,10nm,16nm",
                                            "--element-size", "0.5nm", "--depth", "10nm", "--coating", "1nm",
                                            "--coating-layers", "2", "-o", out});
  ASSERT_EQ(rc, 0);
  const Mesh m = read_gmsh(out);
  ASSERT_NE(m.find_block("substrate"), nullptr);
  ASSERT_NE(m.find_block("coating"), nullptr);
  for (const char* s : {"substrate_top", "substrate_bottom", "substrate_sides", "substrate_track", "substrate_xmin"})
    EXPECT_FALSE(m.side_sets.at(s).empty()) << s;
  EXPECT_EQ(m.element_count(), 20 * 32 * (m.find_block("substrate")->element_count / (20 * 32) + 2));
  std::filesystem::remove_all(dir);
}

TEST(MeshCommand, BadArgumentsAreBadInput) {
  using tribex::cli::mesh_command;
  EXPECT_THROW(mesh_command({"afm", sample("di-1.di"), "--window", "0,0,10nm", "-o", "x.msh"}), tribex::tools::BadInput);
  EXPECT_THROW(mesh_command({"afm", sample("di-1.di"), "--grading-ratio", "2", "-o", "x.msh"}), tribex::tools::BadInput);
  EXPECT_THROW(mesh_command({"afm", sample("di-1.di")}), tribex::tools::BadInput);
  EXPECT_THROW(mesh_command({"asperity"}), tribex::tools::BadInput);
  EXPECT_THROW(mesh_command({"afm", sample("di-1.di"), "--window", "450nm,0,100nm,10nm", "-o", "x.msh"}), MeshError);
  EXPECT_FALSE(std::filesystem::exists("x.msh"));
}
