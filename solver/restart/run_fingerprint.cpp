// SPDX-License-Identifier: MIT
#include "solver/restart/run_fingerprint.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

#include "inputs/schema.hpp"
#include "inputs/sha256.hpp"
#include "solver/output/run_log.hpp"

namespace tribex::solver {

std::vector<long long> as_codes(const std::string& text) {
  return std::vector<long long>(text.begin(), text.end());
}
std::string from_codes(const std::vector<long long>& codes) {
  std::string text;
  for (long long c : codes) text.push_back(static_cast<char>(c));
  return text;
}
std::string mesh_sha256(const mesh::Mesh& m) {
  inputs::Sha256 hash;  // the arrays' bytes, not a copy of them (rank 0 hashes the whole mesh)
  hash.update({reinterpret_cast<const char*>(m.coordinates.data()), m.coordinates.size() * sizeof(double)});
  hash.update({reinterpret_cast<const char*>(m.connectivity.data()), m.connectivity.size() * sizeof(int)});
  return hash.hex();
}

std::string mesh_sha256(const mesh::GeneratedPlan& plan) {
  inputs::Sha256 hash;
  constexpr int chunk = 65536;
  for (int first = 0; first < plan.node_count; first += chunk) {
    const std::vector<double> x = mesh::node_coordinates(plan, first, std::min(chunk, plan.node_count - first));
    hash.update({reinterpret_cast<const char*>(x.data()), x.size() * sizeof(double)});
  }
  for (int first = 0; first < plan.element_count; first += chunk) {
    const std::vector<int> c = mesh::element_nodes(plan, first, std::min(chunk, plan.element_count - first));
    hash.update({reinterpret_cast<const char*>(c.data()), c.size() * sizeof(int)});
  }
  return hash.hex();
}

std::string mesh_sha256(const mesh::MeshSlices& file) {
  // read_exodus's mesh drops the nodes no element uses and numbers the others in file order: a bit per node
  // marks the used ones (one pass over the connectivity), a count per 64 nodes gives each its new number.
  constexpr int chunk = 65536;
  const int nodes = file.node_count(), elements = file.element_count();
  std::vector<std::uint64_t> used((static_cast<std::size_t>(nodes) + 63) / 64, 0);
  for (int first = 0; first < elements; first += chunk)
    for (int n : file.connectivity(first, std::min(chunk, elements - first)))
      used[static_cast<std::size_t>(n) / 64] |= std::uint64_t(1) << (n % 64);
  std::vector<int> before(used.size() + 1, 0);  // [word] the used nodes before it
  for (std::size_t w = 0; w < used.size(); ++w) before[w + 1] = before[w] + std::popcount(used[w]);
  const auto is_used = [&](int n) { return (used[static_cast<std::size_t>(n) / 64] >> (n % 64)) & 1; };
  inputs::Sha256 hash;
  for (int first = 0; first < nodes; first += chunk) {
    std::vector<double> x = file.coordinates(first, std::min(chunk, nodes - first));
    std::size_t kept = 0;
    for (std::size_t i = 0; i < x.size() / 3; ++i)
      if (is_used(first + static_cast<int>(i))) std::copy_n(x.begin() + 3 * static_cast<std::ptrdiff_t>(i), 3, x.begin() + 3 * static_cast<std::ptrdiff_t>(kept++));
    hash.update({reinterpret_cast<const char*>(x.data()), 3 * kept * sizeof(double)});
  }
  for (int first = 0; first < elements; first += chunk) {
    std::vector<int> c = file.connectivity(first, std::min(chunk, elements - first));
    for (int& n : c) {
      const std::uint64_t below = used[static_cast<std::size_t>(n) / 64] & ((std::uint64_t(1) << (n % 64)) - 1);
      n = before[static_cast<std::size_t>(n) / 64] + std::popcount(below);
    }
    hash.update({reinterpret_cast<const char*>(c.data()), c.size() * sizeof(int)});
  }
  return hash.hex();
}

namespace {

std::string trimmed(std::string_view s) {
  const std::size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string_view::npos ? std::string() : std::string(s.substr(a, b - a + 1));
}

/// Whether the line of `text` starting at `start` is `key = its default` inside a block whose schema has
/// that key: a key tribex gained after the restart file was written, whose default keeps the behaviour
/// the file's run had, so the file's resolved deck lacks the line and the run is not changed by it.
bool added_at_default(const std::string& text, std::size_t start, const std::string& line) {
  const std::size_t eq = line.find(" = ");
  if (eq == std::string::npos) return false;
  const std::string key = trimmed(line.substr(0, eq)), value = trimmed(line.substr(eq + 3));
  const std::size_t indent = line.find_first_not_of(' ');
  // the enclosing block: the nearest line above, less indented, that begins one
  for (std::size_t end = start; end > 1;) {
    const std::size_t begin = text.rfind('\n', end - 2) == std::string::npos ? 0 : text.rfind('\n', end - 2) + 1;
    const std::string above = text.substr(begin, end - 1 - begin);
    end = begin;
    const std::size_t above_indent = above.find_first_not_of(' ');
    if (above_indent == std::string::npos || above_indent >= indent) continue;
    if (above.compare(above_indent, 6, "begin ") != 0) return false;
    // "begin TYPE [NAME]": the longest run of words that names a block type
    std::string type = trimmed(above.substr(above_indent + 6));
    for (;;) {
      if (const inputs::BlockSchema* block = inputs::find_block_schema(type)) {
        const inputs::KeySchema* k = block->key(key);
        return k && !k->default_text.empty() && k->default_text == value;
      }
      const std::size_t last = type.rfind(' ');
      if (last == std::string::npos) return false;
      type.resize(last);
    }
  }
  return false;
}

}  // namespace

std::string restart_difference(const StateArchive& archive, const std::string& deck_text, const std::string& mesh_hash) {
  if (!archive.has("deck_text") || !archive.has("mesh_sha256")) return "";  // an earlier tribex: not recorded
  if (from_codes(archive.integer_array("mesh_sha256")) != mesh_hash) return "the mesh differs (coordinates or connectivity)";
  const std::string old_text = from_codes(archive.integer_array("deck_text"));
  if (old_text == deck_text) return "";
  std::size_t line = 1, a = 0, b = 0;
  while (true) {
    const std::size_t ea = old_text.find('\n', a), eb = deck_text.find('\n', b);
    const std::string la = old_text.substr(a, ea == std::string::npos ? std::string::npos : ea - a);
    const std::string lb = deck_text.substr(b, eb == std::string::npos ? std::string::npos : eb - b);
    if (la != lb && eb != std::string::npos && added_at_default(deck_text, b, lb)) {
      b = eb + 1;  // a key added since, at its default: the same run
      continue;
    }
    if (la != lb)
      return format("the resolved deck differs at its line %zu: '%s' then, '%s' now", line,
                    la.c_str(), lb.c_str());
    if (ea == std::string::npos && eb == std::string::npos) return "";  // equal but for added defaults
    if (ea == std::string::npos || eb == std::string::npos) return "the resolved deck differs at its end";
    a = ea + 1;
    b = eb + 1;
    ++line;
  }
}

}  // namespace tribex::solver
