// SPDX-License-Identifier: MIT
#include "solver/output/output_manifest.hpp"

#include <hdf5.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "solver/errors.hpp"
#include "solver/output/h5_handles.hpp"
#include "solver/output/json.hpp"

namespace tribex::solver {
namespace {

constexpr const char* kFormat = "tribex output folder manifest 1";

// The JSON the manifest writer makes: one object of strings and a "files" array of flat objects
// of strings and non-negative integers. Anything else is refused (a hand-edited or foreign file).
class ManifestParser {
 public:
  ManifestParser(const std::string& text, const std::string& where) : s_(text), where_(where) {}

  OutputManifest parse() {
    OutputManifest m;
    std::map<std::string, std::string*> fields = {{"run_id", &m.run_id},   {"deck", &m.deck},
                                                  {"deck_sha256", &m.deck_sha256}, {"mesh_sha256", &m.mesh_sha256},
                                                  {"started", &m.started}, {"host", &m.host}};
    std::string format;
    fields["format"] = &format;
    expect('{');
    do {
      const std::string key = string();
      expect(':');
      if (key == "files") {
        m.files = entries();
      } else if (key == "segments") {
        m.segments = segments();
      } else if (fields.count(key)) {
        *fields[key] = string();
      } else {
        fail("unknown key '" + key + "'");
      }
    } while (take(','));
    expect('}');
    skip_space();
    if (i_ != s_.size() || format != kFormat) fail("not a tribex manifest");
    if (m.run_id.size() != 32) fail("no run_id");
    return m;
  }

 private:
  std::vector<ManifestEntry> entries() {
    std::vector<ManifestEntry> files;
    expect('[');
    if (take(']')) return files;
    do {
      ManifestEntry e;
      expect('{');
      do {
        const std::string key = string();
        expect(':');
        if (key == "name") e.name = string();
        else if (key == "device") e.device = integer();
        else if (key == "inode") e.inode = integer();
        else fail("unknown file key '" + key + "'");
      } while (take(','));
      expect('}');
      if (e.name.empty() || e.name.find('/') != std::string::npos || e.name == "." || e.name == "..")
        fail("a file name that is not a plain name");
      files.push_back(e);
    } while (take(','));
    expect(']');
    return files;
  }
  std::vector<RunSegment> segments() {
    std::vector<RunSegment> list;
    expect('[');
    if (take(']')) return list;
    do {
      RunSegment g;
      expect('{');
      do {
        const std::string key = string();
        expect(':');
        if (key == "ranks") g.ranks = static_cast<int>(std::min<unsigned long long>(integer(), 1u << 30));
        else if (key == "from_time") g.from_time = real();
        else fail("unknown segment key '" + key + "'");
      } while (take(','));
      expect('}');
      if (g.ranks < 1) fail("a segment of no ranks");
      list.push_back(g);
    } while (take(','));
    expect(']');
    return list;
  }
  double real() {  // as manifest_json writes it: %.17g, finite
    skip_space();
    const std::size_t start = i_;
    while (i_ < s_.size() && std::strchr("0123456789+-.eE", s_[i_]) != nullptr && i_ - start < 32) ++i_;
    char* end = nullptr;
    const std::string text = s_.substr(start, i_ - start);
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) fail("expected a number");
    return v;
  }
  void skip_space() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
  }
  bool take(char c) {
    skip_space();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'");
  }
  std::string string() {
    expect('"');
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c == '\\') {
        if (i_ >= s_.size()) break;
        c = s_[i_++];
        if (c == 'u' && i_ + 4 <= s_.size()) {  // json_string writes control characters only as \u00XX
          c = static_cast<char>(std::stoi(s_.substr(i_, 4), nullptr, 16));
          i_ += 4;
        } else if (c == 'n') {
          c = '\n';
        } else if (c == 't') {
          c = '\t';
        }
      }
      out += c;
    }
    expect('"');
    return out;
  }
  unsigned long long integer() {
    skip_space();
    const std::size_t start = i_;
    while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9' && i_ - start < 20) ++i_;
    if (i_ == start) fail("expected a number");
    return std::stoull(s_.substr(start, i_ - start));
  }
  [[noreturn]] void fail(const std::string& what) {
    throw SetupError(where_ + ": not a readable tribex output manifest (" + what + " at byte " + std::to_string(i_) +
                     "); if no tribex run owns this folder, remove the file, or choose another output folder (-o)");
  }
  const std::string& s_;
  std::string where_;
  std::size_t i_ = 0;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string head_of(const std::filesystem::path& file, std::size_t bytes) {
  std::ifstream in(file, std::ios::binary);
  std::string text(bytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(bytes));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

bool is_restart_file(const std::string& name) {
  return name.rfind("restart", 0) == 0 && ends_with(name, ".h5");
}

}  // namespace

const ManifestEntry* OutputManifest::find(const std::string& name) const {
  for (const auto& e : files)
    if (e.name == name) return &e;
  return nullptr;
}

void OutputManifest::add(const std::string& name) {
  if (!find(name)) files.push_back({name});
}

std::string manifest_json(const OutputManifest& m) {
  std::string out = "{\n  \"format\": " + json_string(kFormat) + ",\n";
  const std::pair<const char*, const std::string*> fields[] = {{"run_id", &m.run_id},   {"deck", &m.deck},
                                                               {"deck_sha256", &m.deck_sha256},
                                                               {"mesh_sha256", &m.mesh_sha256},
                                                               {"started", &m.started}, {"host", &m.host}};
  for (const auto& [key, value] : fields) out += "  \"" + std::string(key) + "\": " + json_string(*value) + ",\n";
  out += "  \"files\": [";
  for (std::size_t k = 0; k < m.files.size(); ++k)
    out += std::string(k ? "," : "") + "\n    {\"name\": " + json_string(m.files[k].name) +
           ", \"device\": " + std::to_string(m.files[k].device) + ", \"inode\": " + std::to_string(m.files[k].inode) + "}";
  out += "\n  ],\n  \"segments\": [";
  for (std::size_t k = 0; k < m.segments.size(); ++k) {
    char time[40];
    std::snprintf(time, sizeof time, "%.17g", m.segments[k].from_time);  // round-trips the double
    out += std::string(k ? "," : "") + "\n    {\"ranks\": " + std::to_string(m.segments[k].ranks) + ", \"from_time\": " + time + "}";
  }
  return out + "\n  ]\n}\n";
}

OutputManifest parse_manifest(const std::string& text, const std::string& where) {
  return ManifestParser(text, where).parse();
}

std::optional<OutputManifest> read_manifest(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / manifest_file_name;
  struct stat st{};
  if (lstat(path.c_str(), &st) != 0) return std::nullopt;
  if (!S_ISREG(st.st_mode) || st.st_size > (1 << 20))
    throw SetupError(path.string() + ": not a regular file of a tribex manifest; remove it, or choose another "
                                     "output folder (-o)");
  return parse_manifest(head_of(path, static_cast<std::size_t>(st.st_size)), path.string());
}

void write_manifest(const std::filesystem::path& folder, const OutputManifest& manifest) {
  const std::filesystem::path path = folder / manifest_file_name;
  const std::string tmp = path.string() + ".tmp", text = manifest_json(manifest);
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  const bool written = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const bool closed = f && std::fclose(f) == 0;
  if (!written || !closed || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw SetupError("cannot write " + path.string() + " (" + std::strerror(errno) +
                     "); free space on the device or choose another output folder (-o)");
  }
}

bool written_by_run(const std::filesystem::path& folder, const ManifestEntry& entry, const std::string& run_id) {
  const std::filesystem::path file = folder / entry.name;
  struct stat st{};
  if (lstat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  const std::string& n = entry.name;
  if (ends_with(n, ".tmp") || ends_with(n, ".part") || ends_with(n, ".link") || (n.starts_with(".results.exo") && ends_with(n, ".partial")) ||
      n == "results.xdmf")
    return true;
  if (n == "results.h5" || is_restart_file(n)) return h5_run_id(file.string()) == run_id;
  if (n == "summary.json") return head_of(file, 1 << 16).find("\"run_id\": \"" + run_id + "\"") != std::string::npos;
  if (n == "log.txt") {
    const std::string head = head_of(file, 4096);
    return head.substr(0, head.find('\n')).find("run " + run_id) != std::string::npos;
  }
  return entry.inode != 0 && entry.inode == static_cast<unsigned long long>(st.st_ino) &&
         entry.device == static_cast<unsigned long long>(st.st_dev);
}

std::string new_run_id() {
  std::random_device random;
  std::string id;
  char hex[9];
  for (int k = 0; k < 4; ++k) {
    std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(random()));
    id += hex;
  }
  return id;
}

std::string h5_run_id(const std::string& path) {
  struct stat st{};
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return "";  // never opens a FIFO or device
  output::QuietHdf5Errors quiet;
  if (H5Fis_hdf5(path.c_str()) <= 0) return "";
  output::H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  return file.valid() ? output::read_string_attribute(file.get(), "run_id") : std::string();
}

}  // namespace tribex::solver
