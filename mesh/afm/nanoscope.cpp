// SPDX-License-Identifier: MIT
// Bruker / Digital Instruments Nanoscope reader (header versions 5 to 10, 16- and 32-bit data).
//
// 1. The Latin-1 header is "\key: value" lines; "\*Name" opens a section; it ends at "\*File list end".
//    "\Data length" of the first section is the header size in bytes.
// 2. "\@Sens. NAME: V VALUE UNIT/V" lines give the soft scales (e.g. nm/V).
// 3. Each "\*Ciao image list" section is one channel: Data offset, Bytes/pixel, Samps/line,
//    Number of lines, Scan Size "sx sy unit", "@2:Image Data: S [Quantity] ...",
//    "@2:Z scale: V [Sens. NAME] (hard V/LSB) VALUE V".
// 4. height = count * VALUE / 2^(8*bytes) * soft   (i.e. /65536 for int16, /2^32 for int32), unit of soft.
// 5. Orientation as Gwyddion/SurfaceTopography: x along the fast scan, y = line index counted backwards.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>

#include "mesh/afm/height_map.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {
namespace {

struct HeaderLine {
  std::string key, value;
  std::size_t offset;  // byte offset of the line in the file
  int line = 0;        // 1-based line number (messages say FILE:LINE:1)
};

struct Channel {
  std::map<std::string, HeaderLine> keys;  // lower-case key -> line
  std::size_t offset;                      // of the section line
  int line = 0;
};

// "FILE:LINE:1" for a header line (the header is text; the data after it are binary, named by byte).
std::string at(const std::string& path, int line) { return path + ":" + std::to_string(line) + ":1"; }

struct Header {
  std::size_t size = 0;
  std::map<std::string, HeaderLine> file_list;
  std::map<std::string, std::pair<double, std::string>> sens;  // "zsens" -> (value, "nm/V")
  std::vector<Channel> channels;
};

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

/// Metres per unit for a length unit as Nanoscope writes it ("nm", "~m" for micrometre, "pm").
std::optional<double> length_unit(std::string u) {
  u = trim(u);
  if (u == "nm") return 1e-9;
  if (u == "~m" || u == "um" || u == "\xb5m" || u == "\xc2\xb5m") return 1e-6;
  if (u == "pm") return 1e-12;
  if (u == "mm") return 1e-3;
  if (u == "m") return 1.0;
  if (u == "A" || u == "\xc5") return 1e-10;
  return std::nullopt;
}

std::optional<double> to_number(const std::string& text) {
  std::string t = trim(text);
  double v = 0.0;
  auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

Header parse_header(const std::string& path, const std::string& bytes) {
  Header h;
  // The header size is the first "\Data length:" line; search only a bounded prefix.
  std::size_t pos = 0;
  std::string section;
  bool ended = false;
  const std::size_t limit = std::min<std::size_t>(bytes.size(), 1u << 20);
  int line_no = 0;
  while (pos < limit) {
    std::size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos || eol > limit) eol = limit;
    std::string line = bytes.substr(pos, eol - pos);
    const std::size_t line_offset = pos;
    ++line_no;
    pos = eol + 1;
    while (!line.empty() && (line.back() == '\r' || line.back() == '\x1a')) line.pop_back();
    if (line.empty()) continue;
    if (line[0] != '\\')
      throw MeshError(at(path, line_no) + ": expected a Nanoscope header line starting with '\\' (the header is corrupt)");
    if (line.size() > 1 && line[1] == '*') {
      section = lower(trim(line.substr(2)));
      if (section == "file list end") {
        ended = true;
        break;
      }
      if (section == "ciao image list") h.channels.push_back(Channel{{}, line_offset, line_no});
      continue;
    }
    const std::size_t colon = line.find(':', (line.size() > 1 && line[1] == '@') ? 4 : 1);
    if (colon == std::string::npos) continue;  // keys without value carry nothing we need
    HeaderLine hl{lower(trim(line.substr(1, colon - 1))), trim(line.substr(colon + 1)), line_offset, line_no};
    if (section == "file list" && !h.file_list.count(hl.key)) h.file_list[hl.key] = hl;
    if (hl.key.rfind("@sens. ", 0) == 0) {
      // "\@Sens. Zsens: V 34.55678 nm/V"
      std::string v = hl.value;
      if (v.rfind("V ", 0) == 0) v = v.substr(2);
      v = trim(v);
      const std::size_t sp = v.find(' ');
      const std::string token = v.substr(0, sp);
      auto num = to_number(token);
      // A NaN, infinite, zero or negative sensitivity would silently uncalibrate (or invert) its channel.
      const std::string word = lower(token);
      if ((num && !(*num > 0.0)) || (!num && (word.find("nan") != std::string::npos || word.find("inf") != std::string::npos)))
        throw MeshError(at(path, line_no) + ": '\\" + line.substr(1) + "': the sensitivity must be a positive finite "
                        "number (the header is corrupt)");
      if (num) h.sens[hl.key.substr(7)] = {*num, sp == std::string::npos ? "" : trim(v.substr(sp + 1))};
    }
    if (section == "ciao image list" && !h.channels.empty()) h.channels.back().keys[hl.key] = hl;
  }
  if (!ended)
    throw MeshError(at(path, line_no) +
                    ": expected the header line '\\*File list end' by here (the file is truncated or not a Nanoscope file)");
  auto dl = h.file_list.find("data length");
  if (dl == h.file_list.end())
    throw MeshError(path + ": expected '\\Data length' in the '\\*File list' section (the header size is unknown)");
  auto size = to_number(dl->second.value);
  if (!size || *size <= 0 || *size > static_cast<double>(bytes.size()))
    throw MeshError(at(path, dl->second.line) + ": '\\Data length: " + dl->second.value +
                    "' is not a header size within the file's " + std::to_string(bytes.size()) + " bytes");
  h.size = static_cast<std::size_t>(*size);
  if (h.channels.empty())
    throw MeshError(path + ": expected at least one '\\*Ciao image list' section (the file holds no image)");
  return h;
}

const HeaderLine& need(const std::string& path, const Channel& c, const std::string& key, int index) {
  auto it = c.keys.find(key);
  if (it == c.keys.end())
    throw MeshError(at(path, c.line) + ": channel " + std::to_string(index) +
                    " lacks the header key '\\" + key + "' (the header is incomplete)");
  return it->second;
}

long need_int(const std::string& path, const Channel& c, const std::string& key, int index, long lo, long hi) {
  const HeaderLine& l = need(path, c, key, index);
  auto v = to_number(l.value);
  if (!v || *v != std::floor(*v) || *v < static_cast<double>(lo) || *v > static_cast<double>(hi))
    throw MeshError(at(path, l.line) + ": '\\" + key + ": " + l.value +
                    "' must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<long>(*v);
}

std::string channel_name(const Channel& c) {
  // "\@2:Image Data: S [ZSensor] "Height Sensor"" -> ZSensor
  auto it = c.keys.find("@2:image data");
  if (it == c.keys.end()) it = c.keys.find("image data");
  if (it == c.keys.end()) return "";
  const std::string& v = it->second.value;
  const auto a = v.find('['), b = v.find(']');
  if (a != std::string::npos && b != std::string::npos && b > a) return v.substr(a + 1, b - a - 1);
  const auto q = v.find('"');
  return q == std::string::npos ? trim(v) : trim(v.substr(q));
}

struct ZScale {
  double hard = 0.0;       // V at full scale (VALUE)
  double soft = 0.0;       // unit per V
  double unit_to_m = 0.0;  // 0 when the soft unit is not a length
  std::size_t offset = 0;
  int line = 0;
};

std::optional<ZScale> z_scale(const std::string& path, const Header& h, const Channel& c) {
  auto it = c.keys.find("@2:z scale");
  if (it == c.keys.end()) return std::nullopt;
  const std::string& v = it->second.value;  // V [Sens. ZsensSens] (0.000375 V/LSB) 24.57563 V
  ZScale z;
  z.offset = it->second.offset;
  z.line = it->second.line;
  const auto a = v.find('['), b = v.find(']'), close = v.rfind(')');
  if (a == std::string::npos || b == std::string::npos || close == std::string::npos || b < a)
    throw MeshError(at(path, z.line) +
                    ": expected '\\@2:Z scale: V [Sens. NAME] (x V/LSB) VALUE V', got '" + v + "'");
  std::string sens = lower(trim(v.substr(a + 1, b - a - 1)));
  if (sens.rfind("sens. ", 0) == 0) sens = sens.substr(6);
  std::string tail = trim(v.substr(close + 1));
  const auto sp = tail.find(' ');
  auto hard = to_number(tail.substr(0, sp));
  if (!hard)
    throw MeshError(at(path, z.line) + ": expected a number after ')' in the Z scale line, got '" +
                    tail + "'");
  z.hard = *hard;
  if (!(z.hard > 0.0))
    throw MeshError(at(path, z.line) + ": the Z scale " + tail + " must be positive (a negative or zero scale would "
                    "invert or flatten the surface; the header is corrupt)");
  auto s = h.sens.find(sens);
  if (s == h.sens.end()) return z;  // no soft scale: not a calibrated height
  z.soft = s->second.first;
  const std::string unit = s->second.second;
  const auto slash = unit.find("/V");
  if (slash != std::string::npos) {
    if (auto m = length_unit(unit.substr(0, slash))) z.unit_to_m = *m;
  }
  return z;
}

bool name_is_height(const std::string& name) {
  const std::string n = lower(name);
  return n.find("height") != std::string::npos || n.find("zsensor") != std::string::npos ||
         n.find("z sensor") != std::string::npos || n == "topography";
}

}  // namespace

std::vector<ChannelInfo> nanoscope_channels(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  const Header h = parse_header(path, bytes);
  std::vector<ChannelInfo> out;
  for (const auto& c : h.channels) {
    auto z = z_scale(path, h, c);
    const std::string name = channel_name(c);
    out.push_back({name, name_is_height(name) && z && z->unit_to_m > 0.0});
  }
  return out;
}

HeightMap read_nanoscope(const std::string& path, int channel) {
  const std::string bytes = read_file_bytes(path);
  const Header h = parse_header(path, bytes);
  const int count = static_cast<int>(h.channels.size());
  if (channel < 0) {
    for (int i = 0; i < count && channel < 0; ++i) {
      auto z = z_scale(path, h, h.channels[static_cast<std::size_t>(i)]);
      if (name_is_height(channel_name(h.channels[static_cast<std::size_t>(i)])) && z && z->unit_to_m > 0.0) channel = i;
    }
    if (channel < 0) throw MeshError(path + ": no height channel found (none has a length-calibrated Z scale)");
  }
  if (channel >= count)
    throw MeshError(path + ": channel " + std::to_string(channel) + " does not exist; the file has channels 0.." +
                    std::to_string(count - 1));
  const Channel& c = h.channels[static_cast<std::size_t>(channel)];
  const std::string name = channel_name(c);
  const long bpp = need_int(path, c, "bytes/pixel", channel, 1, 8);
  if (bpp != 2 && bpp != 4)
    throw MeshError(at(path, need(path, c, "bytes/pixel", channel).line) +
                    ": Bytes/pixel must be 2 or 4, got " + std::to_string(bpp));
  const long samps = need_int(path, c, "samps/line", channel, 1, 1 << 16);
  const long lines = need_int(path, c, "number of lines", channel, 1, 1 << 16);
  const long offset = need_int(path, c, "data offset", channel, 0, 1L << 40);
  auto z = z_scale(path, h, c);
  if (!z || z->unit_to_m <= 0.0 || !name_is_height(name))
    throw MeshError(path + ": channel " + std::to_string(channel) + " (" + name +
                    ") is not a height channel (its Z scale has no length unit); pick a height channel with --channel");
  if (!(std::isfinite(z->hard) && std::isfinite(z->soft)) || z->hard == 0.0 || z->soft == 0.0 ||
      std::fabs(z->hard * z->soft * z->unit_to_m) > 1.0)
    throw MeshError(at(path, z->line) + ": Z scale " + std::to_string(z->hard) + " V x " +
                    std::to_string(z->soft) + " per V is zero or absurd (> 1 m full scale); the header is corrupt");
  // Scan size "sx sy unit" (older files: "\Scan size"; both lower-cased here).
  const HeaderLine& ss = need(path, c, "scan size", channel);
  double sx = 0, sy = 0;
  {
    std::string v = ss.value;
    const auto s1 = v.find(' ');
    const auto s2 = s1 == std::string::npos ? s1 : v.find(' ', s1 + 1);
    auto a = s1 == std::string::npos ? std::nullopt : to_number(v.substr(0, s1));
    auto b = s2 == std::string::npos ? std::nullopt : to_number(v.substr(s1 + 1, s2 - s1 - 1));
    auto u = s2 == std::string::npos ? std::nullopt : length_unit(v.substr(s2 + 1));
    if (!a || !b || !u || *a <= 0 || *b <= 0)
      throw MeshError(at(path, ss.line) + ": expected '\\Scan Size: SX SY UNIT' with positive sizes and a length unit, got '" +
                      v + "'");
    sx = *a * *u;
    sy = *b * *u;
  }
  const std::size_t n = static_cast<std::size_t>(samps) * static_cast<std::size_t>(lines);
  const std::size_t need_bytes = n * static_cast<std::size_t>(bpp);
  if (c.keys.count("data length")) {
    const long declared = need_int(path, c, "data length", channel, 0, 1L << 40);
    if (static_cast<std::size_t>(declared) < need_bytes)
      throw MeshError(at(path, need(path, c, "data length", channel).line) + ": channel " +
                      std::to_string(channel) + " declares " + std::to_string(declared) + " data bytes but " +
                      std::to_string(samps) + " x " + std::to_string(lines) + " pixels x " + std::to_string(bpp) +
                      " bytes need " + std::to_string(need_bytes) + " (Samps/line, Number of lines or Bytes/pixel is wrong)");
  }
  if (static_cast<std::size_t>(offset) < h.size || static_cast<std::size_t>(offset) > bytes.size() ||
      bytes.size() - static_cast<std::size_t>(offset) < need_bytes)
    throw MeshError(path + ": byte " + std::to_string(bytes.size()) + ": channel " + std::to_string(channel) + " needs " +
                    std::to_string(need_bytes) + " data bytes from offset " + std::to_string(offset) +
                    " (after the " + std::to_string(h.size) + "-byte header) but the file ends first (truncated file?)");
  HeightMap m;
  m.nx = static_cast<std::size_t>(samps);
  m.ny = static_cast<std::size_t>(lines);
  m.dx = sx / static_cast<double>(m.nx);
  m.dy = sy / static_cast<double>(m.ny);
  m.channel = name;
  m.source = path;
  m.heights.resize(n);
  // count * VALUE / 2^(8 bpp) * soft  (README step 5); in metres.
  const double scale = z->hard / std::ldexp(1.0, 8 * static_cast<int>(bpp)) * z->soft * z->unit_to_m;
  const unsigned char* data = reinterpret_cast<const unsigned char*>(bytes.data()) + offset;
  for (std::size_t line = 0; line < m.ny; ++line) {
    const std::size_t iy = m.ny - 1 - line;  // y counted backwards from the stored line order
    for (std::size_t ix = 0; ix < m.nx; ++ix) {
      const std::size_t k = (line * m.nx + ix) * static_cast<std::size_t>(bpp);
      double count_value;
      if (bpp == 2) {
        const std::uint16_t u = static_cast<std::uint16_t>(data[k] | (data[k + 1] << 8));
        count_value = static_cast<std::int16_t>(u);
      } else {
        const std::uint32_t u = static_cast<std::uint32_t>(data[k]) | (static_cast<std::uint32_t>(data[k + 1]) << 8) |
                                (static_cast<std::uint32_t>(data[k + 2]) << 16) | (static_cast<std::uint32_t>(data[k + 3]) << 24);
        count_value = static_cast<std::int32_t>(u);
      }
      m.heights[iy * m.nx + ix] = count_value * scale;
    }
  }
  check_height_map(m, path + ": channel " + std::to_string(channel));
  return m;
}

}  // namespace tribex::mesh::afm
