// SPDX-License-Identifier: MIT
#include "solver/output/xdmf_document.hpp"

#include "solver/errors.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace tribex::solver::output {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);  // round-trips every double
  return buf;
}

// XDMF AttributeType for a stored component count; ParaView 5.11 reads Scalar, Vector, Tensor (9)
// identically in XDMFReader and Xdmf3ReaderS, and any other count as a multi-component Matrix.
const char* attribute_type(int components) {
  switch (components) {
    case 1: return "Scalar";
    case 3: return "Vector";
    case 9: return "Tensor";
    default: return "Matrix";
  }
}

// Block names come from mesh files and may hold any character; attribute values need escaping.
std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

XdmfDocument::XdmfDocument(std::string h5_file_name, long long node_count, long long element_count,
                           std::vector<XdmfBlock> blocks, std::string length_unit)
    : h5_file_(std::move(h5_file_name)),
      nodes_(node_count),
      elements_(element_count),
      blocks_(std::move(blocks)),
      length_unit_(std::move(length_unit)) {}

std::string XdmfDocument::step_name(int k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "step_%06d", k);
  return buf;
}

std::string XdmfDocument::h5_item(const std::string& dataset, long long rows, int cols, bool integer,
                                  const XdmfBlock* block) const {
  // (appended piece by piece: GCC 12 warns -Wrestrict, wrongly, on `" " + std::to_string(cols)`)
  std::string per_row;
  if (cols > 1) per_row.append(" ").append(std::to_string(cols));
  const auto dims = [&](long long r) { return std::to_string(r).append(per_row); };
  std::string item = std::string("<DataItem Dimensions=\"") + dims(rows) + "\" NumberType=\"" +
                     (integer ? "Int" : "Float") + "\" Precision=\"" + (integer ? "4" : "8") +
                     "\" Format=\"HDF\">" + h5_file_ + ":" + dataset + "</DataItem>";
  if (block == nullptr || (block->first == 0 && block->count == rows)) return item;
  // Rows [first, first + count) of the whole array: start, stride, count per dimension. Both of
  // ParaView 5.11's readers (Xdmf2 and Xdmf3) read HDF5 hyperslabs of only those rows.
  const std::string c = cols > 1 ? " 0" : "", one = cols > 1 ? " 1" : "", &w = per_row;
  // Xdmf3 takes the array type from the outer item ("Skipping unrecognized array type" without it).
  return "<DataItem ItemType=\"HyperSlab\" Dimensions=\"" + dims(block->count) + "\" Type=\"HyperSlab\" NumberType=\"" +
         (integer ? "Int" : "Float") + "\" Precision=\"" + (integer ? "4" : "8") + "\">"
         "<DataItem Dimensions=\"3 " + std::to_string(cols > 1 ? 2 : 1) + "\" NumberType=\"Int\" Format=\"XML\">" +
         std::to_string(block->first) + c + " 1" + one + " " + std::to_string(block->count) + w + "</DataItem>" + item +
         "</DataItem>";
}

std::string XdmfDocument::mesh_elements(std::size_t b, const std::string& in) const {
  const XdmfBlock& block = blocks_[b];
  return in + "<Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" + std::to_string(block.count) + "\">" +
         h5_item("/mesh/connectivity", elements_, 8, true, &block) + "</Topology>\n" + in +
         "<Geometry GeometryType=\"XYZ\">" + h5_item("/mesh/coordinates", nodes_, 3, false) + "</Geometry>\n" + in +
         "<Attribute Name=\"block_id\" AttributeType=\"Scalar\" Center=\"Cell\">" +
         h5_item("/mesh/block_id", elements_, 1, true, &block) + "</Attribute>\n";
}

std::string XdmfDocument::block_grid(std::size_t b, int step, double time,
                                     const std::vector<XdmfAttribute>& attributes, bool with_time) const {
  const std::string in = "        ";
  std::string g = "      <Grid Name=\"" + xml_escaped(blocks_[b].name) + "\" GridType=\"Uniform\">\n";
  if (with_time) g += in + "<Time Value=\"" + number(time) + "\"/>\n";
  if (step == 0) {
    g += mesh_elements(b, in);
  } else {
    // The mesh of this block's first step, by reference (docs/conventions.md B.2: the mesh once).
    g += in + "<xi:include xpointer=\"xpointer(//Grid[@Name='results']/Grid[" + std::to_string(b + 1) +
         "]/Grid[1]/*[self::Topology or self::Geometry or self::Attribute[@Name='block_id']])\"/>\n";
  }
  for (const auto& a : attributes) {
    const bool node = a.center == Center::node;
    // The bare name (ParaView's Calculator and Python take it unquoted); the unit as an Information
    // child, like the dataset's `units` attribute (README.md "Units").
    const std::string unit = a.unit.empty() ? "" : "<Information Name=\"units\" Value=\"" + xml_escaped(a.unit) + "\"/>";
    g += in + "<Attribute Name=\"" + xml_escaped(a.name) + "\" AttributeType=\"" + attribute_type(a.components) +
         "\" Center=\"" + (node ? "Node" : "Cell") + "\">" + unit +
         h5_item(a.h5_dataset, node ? nodes_ : elements_, a.components, false, node ? nullptr : &blocks_[b]) +
         "</Attribute>\n";
  }
  return g + "      </Grid>\n";
}

void XdmfDocument::add_step(double time, const std::vector<XdmfAttribute>& attributes) {
  steps_xml_.resize(blocks_.size());
  for (std::size_t b = 0; b < blocks_.size(); ++b) steps_xml_[b] += block_grid(b, step_count_, time, attributes, true);
  ++step_count_;
}

std::string XdmfDocument::text() const {
  std::string t =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"2.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      "  <Domain>\n"
      "    <Information Name=\"length_unit\" Value=\"" + length_unit_ + "\"/>\n";
  if (step_count_ == 0) {
    t += "    <Grid Name=\"mesh\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
    for (std::size_t b = 0; b < blocks_.size(); ++b) t += block_grid(b, 0, 0.0, {}, false);
  } else {
    // One temporal collection per block, named after it, inside one spatial collection: ParaView's
    // XDMF Reader keeps a block's name constant over time this way (a spatial collection per step
    // makes it "tip[1]", "tip[2]", ... from the second step on).
    t += "    <Grid Name=\"results\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
    for (std::size_t b = 0; b < blocks_.size(); ++b)
      t += "    <Grid Name=\"" + xml_escaped(blocks_[b].name) + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n" +
           steps_xml_[b] + "    </Grid>\n";
  }
  t += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return t;
}

void XdmfDocument::write_atomically(const std::string& path) const {
  const std::string tmp = path + ".tmp";
  const std::string t = text();
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr)
    throw output_failure(tmp, errno);
  const bool ok = std::fwrite(t.data(), 1, t.size(), f) == t.size();
  const int write_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (!ok || !closed) {
    const int err = ok ? errno : write_errno;
    std::remove(tmp.c_str());
    throw output_failure(path, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw output_failure(path, err);
  }
}

}  // namespace tribex::solver::output
