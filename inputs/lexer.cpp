// SPDX-License-Identifier: MIT
#include "inputs/lexer.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

namespace tribex::inputs {
namespace {

namespace fs = std::filesystem;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\f' || c == '\v'; }

SourceLocation at(const std::string& file, int line, int column) { return {file, line, column}; }

class Lexer {
 public:
  Lexer(DiagnosticSink& sink, const LexerLimits& limits) : sink_(sink), limits_(limits) {}

  void lex_text(std::string_view text, const std::string& file_name) {
    total_bytes_ += text.size();
    // A UTF-8 byte-order mark (what some Windows editors write first) is not part of the text.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (text.size() > limits_.max_file_bytes || total_bytes_ > limits_.max_total_bytes) {
      sink_.error(at(file_name, 1, 1), "",
                  "the deck and its includes exceed " + std::to_string(limits_.max_total_bytes >> 20) +
                      " MiB (this file: " + std::to_string(text.size()) + " bytes); a deck is a short text file");
      return;
    }
    if (const auto bad = first_invalid_byte(text); bad != std::string_view::npos) {
      int line = 1;
      std::size_t line_start = 0;
      for (std::size_t i = 0; i < bad; ++i) {
        if (text[i] == '\n') {
          ++line;
          line_start = i + 1;
        }
      }
      sink_.error(at(file_name, line, static_cast<int>(bad - line_start) + 1), "",
                  "not a text deck: " + std::string(text[bad] == '\0' ? "NUL byte" : "invalid UTF-8 byte") +
                      " at byte offset " + std::to_string(bad) + "; give a plain-text (UTF-8) deck file");
      return;
    }
    // CR-only line ends (classic Mac OS) read as one line, all comment after a first '#' (issue 54, item 16).
    if (text.find('\n') == std::string_view::npos && std::count(text.begin(), text.end(), '\r') > 1) {
      sink_.error(at(file_name, 1, 1), "",
                  "the deck has CR-only line ends (classic Mac OS: " +
                      std::to_string(std::count(text.begin(), text.end(), '\r')) +
                      " carriage returns, no newline), read as one line; convert them: tr '\\r' '\\n' < IN > OUT");
      return;
    }
    std::error_code ec;
    const fs::path self = fs::weakly_canonical(fs::absolute(file_name, ec), ec);
    stack_.push_back(self.string());

    std::optional<LogicalLine> pending;  // a line continued with a trailing backslash
    int line_number = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view raw = text.substr(pos, end - pos);
      pos = end + 1;
      ++line_number;

      const bool continued = lex_physical_line(raw, file_name, line_number, pending);
      if (!continued && pending) {
        if (!pending->words.empty()) emit(std::move(*pending), file_name);
        pending.reset();
      }
    }
    if (pending && !pending->words.empty()) emit(std::move(*pending), file_name);
    stack_.pop_back();
  }

  void lex_file(const std::string& file_name, const SourceLocation* included_from) {
    auto report = [&](const std::string& message) {
      if (included_from) {
        sink_.error(*included_from, "", message);
      } else {
        sink_.error(at(file_name, 0, 0), "", message);
      }
    };
    std::error_code ec;
    if (!fs::exists(file_name, ec)) {
      report("cannot open deck file '" + file_name + "': no such file; check the path (relative paths are relative to the including deck)");
      return;
    }
    if (!fs::is_regular_file(file_name, ec)) {
      report("'" + file_name + "' is not a regular file; give a deck file");
      return;
    }
    const auto size = fs::file_size(file_name, ec);
    if (ec || size > limits_.max_file_bytes) {
      report("deck file '" + file_name + "' is larger than " + std::to_string(limits_.max_file_bytes >> 20) +
             " MiB; a deck is a short text file");
      return;
    }
    std::ifstream in(file_name, std::ios::binary);
    if (!in) {
      report("cannot read deck file '" + file_name + "'; check its permissions");
      return;
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    lex_text(buffer.str(), file_name);
  }

  std::vector<LogicalLine> take() { return std::move(lines_); }

 private:
  // Appends the words of one physical line to `pending`; returns true when it ends in `\`.
  bool lex_physical_line(std::string_view raw, const std::string& file, int line_number,
                         std::optional<LogicalLine>& pending) {
    // Comment: `#`/`$` at the start, after a blank, or right after the `\` of a continuation.
    std::size_t content_end = raw.size();
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const char c = raw[i];
      if ((c == '#' || c == '$') && (i == 0 || is_blank(raw[i - 1]) || raw[i - 1] == '\\')) {
        content_end = i;
        break;
      }
    }
    std::string_view content = raw.substr(0, content_end);
    while (!content.empty() && is_blank(content.back())) content.remove_suffix(1);
    bool continued = false;
    if (!content.empty() && content.back() == '\\') {
      continued = true;
      content.remove_suffix(1);
    }
    if (!pending) pending.emplace();
    std::size_t i = 0;
    while (i < content.size()) {
      if (is_blank(content[i])) {
        ++i;
        continue;
      }
      const std::size_t start = i;
      if (content[i] == '=') {
        ++i;
      } else {
        while (i < content.size() && !is_blank(content[i]) && content[i] != '=') ++i;
      }
      pending->words.push_back(
          {std::string(content.substr(start, i - start)), at(file, line_number, static_cast<int>(start) + 1)});
    }
    return continued;
  }

  void emit(LogicalLine line, const std::string& file_name) {
    if (lower(line.words.front().text) != "include") {
      lines_.push_back(std::move(line));
      return;
    }
    const SourceLocation where = line.where();
    if (line.words.size() < 2) {
      sink_.error(where, "", "'include' needs a file name: include FILE");
      return;
    }
    std::string target = line.words[1].text;
    for (std::size_t k = 2; k < line.words.size(); ++k) target += " " + line.words[k].text;
    fs::path path(target);
    if (path.is_relative()) path = fs::path(file_name).parent_path() / path;
    if (static_cast<int>(stack_.size()) >= limits_.max_include_depth) {
      sink_.error(where, "", "includes nested deeper than " + std::to_string(limits_.max_include_depth) +
                                 " files; flatten the include chain");
      return;
    }
    std::error_code ec;
    const std::string canonical = fs::weakly_canonical(fs::absolute(path, ec), ec).string();
    for (const auto& open : stack_) {
      if (open == canonical) {
        sink_.error(where, "", "include cycle: '" + path.string() +
                                   "' is already being read (it includes itself directly or indirectly); remove this include");
        return;
      }
    }
    lex_file(path.string(), &where);
  }

  DiagnosticSink& sink_;
  LexerLimits limits_;
  std::vector<std::string> stack_;  // canonical paths of the files being read (cycle check)
  std::vector<LogicalLine> lines_;
  std::size_t total_bytes_ = 0;
};

}  // namespace

std::string lower(std::string_view s) {
  std::string r(s);
  for (auto& c : r) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return r;
}

std::size_t first_invalid_byte(std::string_view text) {
  // UTF-8 (RFC 3629): lead byte gives the length; continuation bytes are 10xxxxxx; no overlong
  // forms, no surrogates, nothing above U+10FFFF.
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  std::size_t i = 0;
  while (i < n) {
    const unsigned char c = s[i];
    if (c == 0) return i;
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) {
      len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      len = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      len = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (i + len > n) return i;
    if (s[i + 1] < lo || s[i + 1] > hi) return i;
    for (std::size_t k = 2; k < len; ++k) {
      if (s[i + k] < 0x80 || s[i + k] > 0xBF) return i;
    }
    i += len;
  }
  return std::string_view::npos;
}

std::vector<LogicalLine> lex_deck_text(std::string_view text, const std::string& file_name, DiagnosticSink& sink,
                                       const LexerLimits& limits) {
  Lexer lexer(sink, limits);
  lexer.lex_text(text, file_name);
  return lexer.take();
}

std::vector<LogicalLine> lex_deck_file(const std::string& file_name, DiagnosticSink& sink,
                                       const LexerLimits& limits) {
  Lexer lexer(sink, limits);
  lexer.lex_file(file_name, nullptr);
  return lexer.take();
}

}  // namespace tribex::inputs
