// SPDX-License-Identifier: MIT
// Exodus II mesh files (.exo, .e, .g, .gen) read and written through the Exodus II C API
// (Debian's libexodusii, on netCDF). Mapping (mesh/README.md, "Exodus II mapping rules"):
// element blocks -> blocks (HEX8 only), node sets -> node sets, side sets -> side sets with
// face = Exodus side - 1. Unnamed entities get Sierra's default names: block_<id>, nodelist_<id>,
// surface_<id>.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::mesh {

/// The netCDF flavour an Exodus file is written in. tribex writes 64-bit-offset classic files (no
/// HDF5 inside, read by every Exodus tool); netCDF-4 (HDF5-based) is offered for tests and users
/// that need it. Reading takes any of classic, 64-bit offset, CDF5 and netCDF-4.
enum class ExodusFormat { offset64, netcdf4 };

/// True for the names tribex treats as Exodus II: .exo .e .g .gen (case-insensitive).
bool is_exodus_path(const std::string& path);

/// The length unit of an Exodus file's coordinates. tribex's results.exo names it in an info record
/// "tribex length unit: U" (U = m, um or nm; solver/output/README.md "Exodus II output"); a file
/// without that record is in metres.
struct ExodusLengthUnit {
  std::string name = "m";
  double per_metre = 1.0;  // value in this unit = value in metres x per_metre
};
inline constexpr const char* exodus_length_unit_record = "tribex length unit: ";

/// Throws MeshError (one line: file name, what is wrong, the fix) for a missing or unreadable file,
/// a file that is not Exodus II, a 2-D mesh, a block that is not HEX8, indices out of range, or an
/// invalid mesh (validate). Nodes no hex uses are dropped (node sets keep the others). Coordinates
/// come back in metres: a file whose info records name another length unit is divided by it.
Mesh read_exodus(const std::string& path);

/// Validates the mesh, writes it to `.NAME.partial` beside `path` and renames it (a failed write
/// leaves nothing half-written). Blocks in element order with ids 1..B, node and side sets in name
/// order with ids 1..N, all named. MeshError on failure.
void write_exodus(const Mesh& mesh, const std::string& path, ExodusFormat format = ExodusFormat::offset64);

namespace exodus {

/// For the results writer (solver/output/exodus_writer.cpp): creates `path` (clobbering it), writes
/// the mesh as write_exodus does and returns the open Exodus id (the caller closes it with
/// ex_close). `title` is the database title (at most 80 characters kept). The coordinates are
/// written in `unit` (metres x per_metre), named in the info records with `notes` (one line each,
/// at most 80 characters kept). Throws MeshError.
/// keep_empty_blocks: a block without elements is written too (ids 1..B over every block of `mesh`, in
/// element order), as a per-rank results file must so that every rank's block ids are the whole mesh's.
/// name_length: the longest name the file will hold (the caller's variable names too): the file's name
/// dimension is fixed at creation, and the library cuts longer names put later to it (with a warning).
int create_with_mesh(const Mesh& mesh, const std::string& path, const std::string& title, ExodusFormat format,
                     const ExodusLengthUnit& unit = {}, const std::vector<std::string>& notes = {},
                     bool keep_empty_blocks = false, std::size_t name_length = 32);

/// The length unit the open file `exo` names in its info records (metres when none does); MeshError
/// naming `path` for a unit other than m, um, nm.
ExodusLengthUnit length_unit_of(int exo, const std::string& path);

/// An Exodus file opened with every check read_exodus makes before it reads the arrays (exists, netCDF
/// signature, the header's sizes against the file: exodus_prescan.hpp, 3-D, counts within the limits,
/// every non-empty block HEX8 and the blocks' elements the header's). Shared by read_exodus and the
/// read in slices (exodus_slices.hpp).
struct Header {
  int id = -1;  // the open Exodus id: the caller closes it (ex_close)
  std::string kind;  // "classic", "64-bit offset", "CDF5", "netCDF-4"
  int name_length = 32;
  int nodes = 0, elements = 0, node_sets = 0, side_sets = 0;  // as the file states them
  std::vector<Block> blocks;   // the non-empty blocks in file order, element ranges in Exodus's numbering
  std::vector<int> block_ids;  // [block] its Exodus id
  double per_metre = 1.0;      // the coordinates' length unit (length_unit_of)
};
/// Throws MeshError (one line, naming `path`). `walk_header` false skips the netCDF header's walk (the
/// file's first 16 MiB read and checked), for a rank whose file another rank has just walked (file_slice_source.hpp).
Header open_checked(const std::string& path, bool walk_header = true);

/// One kind of set (node or side) of an open file: names (Sierra's defaults for unnamed ones), ids and
/// entry counts, in file order. MeshError for a set that cannot be read or two sets of one name.
struct SetOutline {
  std::vector<std::string> names;
  std::vector<int> ids;
  std::vector<long long> entries;
};
SetOutline set_outline(int exo, const Header& h, bool side_sets, const std::string& path);

/// The Exodus library's last error text, for messages ("" when it has none).
std::string last_error();

}  // namespace exodus
}  // namespace tribex::mesh
