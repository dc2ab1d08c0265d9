// SPDX-License-Identifier: MIT
#include "tools/pstd/deck.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "inputs/did_you_mean.hpp"
#include "tools/common/errors.hpp"

namespace tribex::pstd {

namespace {

enum class Kind { value, path, flag, negated_flag };
struct Key {
  const char* deck;
  const char* option;
  Kind kind;
};
// Deck keys and the options they stand for (see `tribex pstd --help` for meanings and defaults).
constexpr Key keys[] = {
    {"afm", "--afm", Kind::path},
    {"line", "--line", Kind::value},
    {"substrate file", "--substrate-file", Kind::path},
    {"counterface file", "--counterface-file", Kind::path},
    {"dx", "--dx", Kind::value},
    {"rms", "--rms", Kind::value},
    {"correlation length", "--corr", Kind::value},
    {"source dx", "--source-dx", Kind::value},
    {"substrate length", "--substrate-length", Kind::value},
    {"segments", "--segments", Kind::value},
    {"segment length", "--segment-length", Kind::value},
    {"seed", "--seed", Kind::value},
    {"sampling", "--sampling", Kind::value},
    {"law", "--law", Kind::value},
    {"youngs modulus", "--E", Kind::value},
    {"poissons ratio", "--nu", Kind::value},
    {"depth", "--depth", Kind::value},
    {"shear strength", "--tau", Kind::value},
    {"normal force", "--normal-force", Kind::value},
    {"restoring", "--restoring", Kind::value},
    {"travel", "--travel", Kind::value},
    {"start displacement", "--start-displacement", Kind::value},
    {"copies", "--copies", Kind::value},
    {"study", "--study", Kind::flag},
    {"plots", "--no-plots", Kind::negated_flag},
    {"pstd length factor", "--pstd-length-factor", Kind::value},
    {"pstd gap factor", "--pstd-gap-factor", Kind::value},
    {"output", "-o", Kind::value},  // relative to the working directory, like every output of tribex
};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string lower_words(const std::string& s) {  // lower case, runs of blanks -> one space
  std::string out;
  for (char c : s) {
    if (c == ' ' || c == '\t') {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  return trim(out);
}

}  // namespace

DeckArgs read_deck(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw tools::BadInput(path + ": cannot open the deck; check the path");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  DeckArgs out;
  std::vector<std::string> names;
  for (const auto& k : keys) names.emplace_back(k.deck);
  std::string line;
  int number = 0, begin_line = 0;
  bool inside = false, ended = false;
  std::map<std::string, int> seen;
  while (std::getline(in, line)) {
    ++number;
    const std::string at = path + ":" + std::to_string(number);
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const std::string text = trim(line);
    if (text.empty()) continue;
    const std::string words = lower_words(text);
    if (!inside) {
      if (ended) throw tools::BadInput(at + ": text after 'end pstd'; a deck holds one 'begin pstd' block");
      if (words != "begin pstd")
        throw tools::BadInput(at + ": expected 'begin pstd', found '" + text + "'");
      inside = true;
      begin_line = number;
      continue;
    }
    if (words == "end" || words == "end pstd") {
      inside = false;
      ended = true;
      continue;
    }
    // key [=] value: the key is the longest known key that starts the line.
    std::string key, value;
    if (const auto eq = text.find('='); eq != std::string::npos) {
      key = lower_words(text.substr(0, eq));
      value = trim(text.substr(eq + 1));
    } else {
      for (const auto& k : keys) {
        const std::string name = k.deck;
        if (words.rfind(name, 0) == 0 && (words.size() == name.size() || words[name.size()] == ' ') &&
            name.size() > key.size())
          key = name;
      }
      value = key.empty() ? "" : trim(text.substr(std::min(text.size(), text.find_first_not_of(" \t") + key.size())));
      if (key.empty()) key = words.substr(0, words.find(' '));
    }
    const auto match = std::find_if(std::begin(keys), std::end(keys), [&](const Key& k) { return key == k.deck; });
    if (match == std::end(keys)) {
      const std::string hint = inputs::closest_match(key, names);
      throw tools::BadInput(at + ": unknown key '" + key + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                            "; tribex pstd --help lists the deck keys");
    }
    if (seen.count(key))
      throw tools::BadInput(at + ": key '" + key + "' was already given on line " + std::to_string(seen[key]));
    seen[key] = number;
    if (value.empty()) throw tools::BadInput(at + ": key '" + key + "' needs a value");
    out.where[match->option] = at;
    if (match->kind == Kind::flag || match->kind == Kind::negated_flag) {
      const std::string v = lower_words(value);
      const bool yes = v == "yes" || v == "on" || v == "true";
      if (!yes && v != "no" && v != "off" && v != "false")
        throw tools::BadInput(at + ": key '" + key + "' takes yes or no, got '" + value + "'");
      if (yes == (match->kind == Kind::flag)) out.args.emplace_back(match->option);
      continue;
    }
    if (match->kind == Kind::path && std::filesystem::path(value).is_relative() && !folder.empty())
      value = (folder / value).lexically_normal().string();
    out.args.emplace_back(match->option);
    out.args.push_back(value);
  }
  if (inside) throw tools::BadInput(path + ":" + std::to_string(begin_line) + ": 'begin pstd' has no matching 'end'");
  if (!ended) throw tools::BadInput(path + ": no 'begin pstd' block found");
  return out;
}

std::string deck_keys_help() {
  std::string s;
  for (const auto& k : keys) {
    std::string line = std::string("  ") + k.deck;
    line.resize(24, ' ');
    s += line + k.option + (k.kind == Kind::flag || k.kind == Kind::negated_flag ? "  (yes|no)\n" : "\n");
  }
  return s;
}

}  // namespace tribex::pstd
