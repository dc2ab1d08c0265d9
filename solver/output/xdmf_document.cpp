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
                           std::vector<std::string> block_names)
    : h5_file_(std::move(h5_file_name)),
      nodes_(node_count),
      elements_(element_count),
      block_names_(std::move(block_names)) {}

std::string XdmfDocument::step_name(int k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "step_%06d", k);
  return buf;
}

std::string XdmfDocument::h5_item(const std::string& dataset, long long rows, int cols,
                                  bool integer) const {
  std::string dims = std::to_string(rows);
  if (cols > 1) {
    dims += ' ';
    dims += std::to_string(cols);
  }
  return std::string("<DataItem Dimensions=\"") + dims + "\" NumberType=\"" + (integer ? "Int" : "Float") +
         "\" Precision=\"" + (integer ? "4" : "8") + "\" Format=\"HDF\">" + h5_file_ + ":" + dataset +
         "</DataItem>";
}

std::string XdmfDocument::mesh_elements(const std::string& in) const {
  std::string names;
  for (std::size_t b = 0; b < block_names_.size(); ++b) {
    if (b > 0) names += ' ';
    names += std::to_string(b);
    names += ':';
    names += xml_escaped(block_names_[b]);
  }
  return in + "<Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" + std::to_string(elements_) +
         "\">" + h5_item("/mesh/connectivity", elements_, 8, true) + "</Topology>\n" + in +
         "<Geometry GeometryType=\"XYZ\">" + h5_item("/mesh/coordinates", nodes_, 3, false) +
         "</Geometry>\n" + in + "<Attribute Name=\"block_id\" AttributeType=\"Scalar\" Center=\"Cell\">" +
         h5_item("/mesh/block_id", elements_, 1, true) + "</Attribute>\n" + in +
         "<Information Name=\"block_names\" Value=\"" + names + "\"/>\n";
}

void XdmfDocument::add_step(double time, const std::vector<XdmfAttribute>& attributes) {
  const std::string in = "        ";
  std::string g = "      <Grid Name=\"" + step_name(step_count_) + "\" GridType=\"Uniform\">\n" + in +
                  "<Time Value=\"" + number(time) + "\"/>\n";
  if (step_count_ == 0) {
    g += mesh_elements(in);
  } else {
    // The mesh of step 0, pulled in by reference (docs/conventions.md B.2: write the mesh once).
    g += in + "<xi:include xpointer=\"xpointer(//Grid[@Name='" + step_name(0) +
         "']/*[self::Topology or self::Geometry or self::Attribute[@Name='block_id']])\"/>\n";
  }
  for (const auto& a : attributes) {
    const long long rows = a.center == Center::node ? nodes_ : elements_;
    g += in + "<Attribute Name=\"" + a.name + "\" AttributeType=\"" + attribute_type(a.components) +
         "\" Center=\"" + (a.center == Center::node ? "Node" : "Cell") + "\">" +
         h5_item(a.h5_dataset, rows, a.components, false) + "</Attribute>\n";
  }
  g += "      </Grid>\n";
  steps_xml_ += g;
  ++step_count_;
}

std::string XdmfDocument::text() const {
  std::string t =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"2.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      "  <Domain>\n";
  if (step_count_ == 0) {
    t += "    <Grid Name=\"mesh\" GridType=\"Uniform\">\n" + mesh_elements("      ") + "    </Grid>\n";
  } else {
    t += "    <Grid Name=\"results\" GridType=\"Collection\" CollectionType=\"Temporal\">\n" + steps_xml_ +
         "    </Grid>\n";
  }
  t += "  </Domain>\n</Xdmf>\n";
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
