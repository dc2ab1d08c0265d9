// SPDX-License-Identifier: MIT
// `tribex mesh SUBCOMMAND ...`: mesh generators that write gmsh .msh files. Today: `afm` (a
// substrate block on an AFM height map, mesh/afm/afm_mesh.hpp), and `convert` (gmsh .msh <->
// Exodus II .exo/.g, by the file extensions). `box` and `asperity` are free second words for later
// generators.
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesh/afm/afm_mesh.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/output_target.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/command.hpp"

namespace tribex::cli {
namespace {

using namespace tools::command;

const char* mesh_usage =
    "usage: tribex mesh GENERATOR [options]   (tribex mesh GENERATOR --help)\n"
    "generators:\n"
    "  afm     all-hex substrate block whose top follows an AFM height map (spline surface)\n"
    "  convert IN OUT: a mesh file from gmsh .msh to Exodus II .exo/.e/.g/.gen or back (by the extensions)\n";

// A mesh file is written by its extension: gmsh .msh, or Exodus II .exo/.e/.g/.gen. Any other
// extension is refused (exit 2) rather than written as gmsh under a name that says otherwise; so is
// a path that is not a regular file. Checked before anything is read or built.
void require_mesh_output(const std::string& out, const std::string& command) {
  const std::string ext = std::filesystem::path(out).extension().string();
  mesh::require_output_target(out);  // a folder, FIFO or device first: whatever its name (issue 54, item 16)
  if (!mesh::is_exodus_path(out) && ext != ".msh")
    throw BadInput(command + ": cannot write '" + out + "': unknown mesh extension '" + ext +
                   "'; give a gmsh .msh or an Exodus II .exo, .e, .g or .gen file");
}

void write_mesh_file(const mesh::Mesh& m, const std::string& out) {
  if (mesh::is_exodus_path(out))
    mesh::write_exodus(m, out);
  else
    mesh::write_gmsh(m, out);
}

const char* convert_usage =
    "usage: tribex mesh convert IN OUT\n"
    "Reads IN and writes OUT, each a gmsh .msh (4.1 binary when written) or an Exodus II .exo/.e/.g/.gen\n"
    "(64-bit-offset netCDF), chosen by the extension. Blocks, node sets and side sets keep their names\n"
    "(mesh/README.md: the gmsh and Exodus II mapping rules). The mesh is validated on reading.\n";

int convert(const std::vector<std::string>& argv) {
  Args a(argv, "tribex mesh convert", convert_usage);
  if (a.answered_help()) return tools::exit_ok;
  const std::string in = a.positional(0, "IN");
  const std::string out = a.positional(1, "OUT");
  a.finish();
  if (a.positional_count() != 2) throw BadInput("tribex mesh convert takes IN and OUT, got " + std::to_string(a.positional_count()) + " files");
  require_mesh_output(out, "tribex mesh convert");
  const mesh::Mesh m = mesh::is_exodus_path(in) ? mesh::read_exodus(in) : mesh::read_gmsh(in);
  write_mesh_file(m, out);
  std::printf("wrote %s: %d nodes, %d hex8 elements, %zu block(s), %zu node set(s), %zu side set(s)\n", out.c_str(),
              m.node_count(), m.element_count(), m.blocks.size(), m.node_sets.size(), m.side_sets.size());
  return tools::exit_ok;
}

const char* afm_usage =
    "usage: tribex mesh afm FILE -o MESH.msh|MESH.exo [options]\n"
    "All-hex8 substrate block whose top is the bicubic-spline surface through the AFM map (not-a-knot\n"
    "cubic splines along each pixel row, then each column), written as gmsh .msh 4.1 or, for an\n"
    "-o of .exo/.e/.g/.gen, as Exodus II (64-bit-offset netCDF).\n"
    "FILE: Nanoscope (.di/.spm/.000), Gwyddion .gsf, Gwyddion ASCII matrix, or x y z text; the map is\n"
    "levelled by its least-squares plane first. Coordinates are the map's (pixel centres at (i+1/2) dx).\n"
    "  --channel N             Nanoscope channel (default: first height channel)\n"
    "  --window X0,Y0,W,H      part of the map to mesh, e.g. 100nm,100nm,60nm,140nm (default: whole map)\n"
    "  --track X0,Y0,W,H       contact track inside the window: elements <= element size there (default: window)\n"
    "  --element-size H        largest element edge in the track and the top layer (default 0.5nm)\n"
    "  --depth D               from the window's mean height to the flat bottom (default 50nm)\n"
    "  --coating T             bonded coating of thickness T on top, block `coating` (default: none)\n"
    "  --coating-layers N      elements through the coating (default 6)\n"
    "  --grading-ratio R       size ratio of neighbours outside the track and with depth, in [1, 1.3] (default 1.3)\n"
    "  --small-window MODE     refuse (default): a window under 4 pixels a side is an error; interpolate: mesh\n"
    "                          the spline between the pixels anyway (a sub-pixel window of a coarse map)\n"
    "  --max-elements N        refuse a larger mesh, counted before it is built (default 20000000, ~6 GB to run)\n"
    "  -o FILE                 output .msh, or Exodus II .exo/.e/.g/.gen (required)\n"
    "Blocks substrate (+ coating); side sets = node sets: substrate_top (contact surface), substrate_track,\n"
    "substrate_bottom, substrate_sides, substrate_xmin/_xmax/_ymin/_ymax. Prints the element count, the track\n"
    "element size and the min/mean scaled Jacobian. `gmsh MESH.msh` opens the result.\n";

std::optional<std::array<double, 4>> rectangle(Args& a, const std::string& name) {
  const auto v = a.list(name, inputs::dim::length);
  if (v.empty()) return std::nullopt;
  if (v.size() != 4)
    throw BadInput(name + " needs 4 lengths X0,Y0,W,H (e.g. 0,0,35nm,100nm), got " + std::to_string(v.size()));
  return std::array<double, 4>{v[0], v[1], v[2], v[3]};
}

int afm(const std::vector<std::string>& argv) {
  Args a(argv, "tribex mesh afm", afm_usage);
  if (a.answered_help()) return tools::exit_ok;
  const std::string file = a.positional(0, "FILE");
  const long channel = a.integer("--channel", -1);
  mesh::afm::AfmMeshSpec spec;
  spec.window = rectangle(a, "--window");
  spec.track = rectangle(a, "--track");
  spec.element_size = a.quantity("--element-size", spec.element_size, inputs::dim::length);
  spec.depth = a.quantity("--depth", spec.depth, inputs::dim::length);
  spec.coating_thickness = a.quantity("--coating", 0.0, inputs::dim::length);
  const long layers = a.integer("--coating-layers", spec.coating_layers);
  spec.grading_ratio = a.real("--grading-ratio", spec.grading_ratio);
  spec.max_elements = a.integer("--max-elements", spec.max_elements);
  const std::string small_window = a.text("--small-window").value_or("refuse");
  const auto out = a.text("-o");
  a.finish();
  if (a.positional_count() > 1) throw BadInput("tribex mesh afm takes one FILE, got " + std::to_string(a.positional_count()));
  if (!out || out->empty()) throw BadInput("tribex mesh afm: give the output file with -o MESH.msh");
  if (channel < -1 || channel > 64) throw BadInput("--channel " + std::to_string(channel) + " is out of range (0 to 64)");
  if (layers < 1 || layers > 100) throw BadInput("--coating-layers " + std::to_string(layers) + " must lie in 1 to 100");
  spec.coating_layers = static_cast<int>(layers);
  if (small_window != "refuse" && small_window != "interpolate")
    throw BadInput("--small-window " + small_window + ": use refuse or interpolate");
  spec.interpolate_small_window = small_window == "interpolate";
  require_mesh_output(*out, "tribex mesh afm");
  if (spec.max_elements < 1 || spec.max_elements > 2'000'000'000)
    throw BadInput("--max-elements " + std::to_string(spec.max_elements) + " must lie in 1 to 2000000000");
  if (!(spec.grading_ratio >= 1.0 && spec.grading_ratio <= 1.3))
    throw BadInput("--grading-ratio " + std::to_string(spec.grading_ratio) + " must lie in [1, 1.3]");

  const auto t0 = std::chrono::steady_clock::now();
  mesh::afm::AfmMeshReport r;
  const mesh::Mesh m = mesh::afm::mesh_afm_file(file, static_cast<int>(channel), spec, &r);
  const auto t1 = std::chrono::steady_clock::now();
  write_mesh_file(m, *out);
  const auto t2 = std::chrono::steady_clock::now();
  const auto seconds = [](auto d) { return std::chrono::duration<double>(d).count(); };
  std::printf("map %s, window (%.6g, %.6g) nm + %.6g x %.6g nm, track (%.6g, %.6g) nm + %.6g x %.6g nm, RMS %.4g nm\n",
              file.c_str(), r.window[0] * 1e9, r.window[1] * 1e9, r.window[2] * 1e9, r.window[3] * 1e9, r.track[0] * 1e9,
              r.track[1] * 1e9, r.track[2] * 1e9, r.track[3] * 1e9, r.surface_rms * 1e9);
  std::printf("elements %d (%d x %d x (%d substrate + %d coating layers)), nodes %d\n", m.element_count(), r.nx, r.ny,
              r.substrate_layers, r.coating_layers, m.node_count());
  std::printf("track element size %.4g nm (asked %.4g nm); bottom at z = %.4g nm (mean height %.4g nm)\n",
              r.track_element_size * 1e9, spec.element_size * 1e9, r.z_bottom * 1e9, r.z_reference * 1e9);
  std::printf("scaled Jacobian: min %.4f, mean %.4f, min under the track %.4f\n", r.min_scaled_jacobian,
              r.mean_scaled_jacobian, r.min_scaled_jacobian_track);
  std::printf("wrote %s (mesh %.3g s, write %.3g s)\n", out->c_str(), seconds(t1 - t0), seconds(t2 - t1));
  return tools::exit_ok;
}

}  // namespace

int mesh_command(const std::vector<std::string>& argv) {
  if (argv.empty() || argv[0] == "--help" || argv[0] == "-h") {
    std::fputs(mesh_usage, argv.empty() ? stderr : stdout);
    return argv.empty() ? tools::exit_bad_input : tools::exit_ok;
  }
  const std::vector<std::string> rest(argv.begin() + 1, argv.end());
  if (argv[0] == "afm") return afm(rest);
  if (argv[0] == "convert") return convert(rest);
  throw BadInput("tribex mesh: unknown generator '" + argv[0] + "'; available: afm, convert (tribex mesh --help)");
}

}  // namespace tribex::cli
