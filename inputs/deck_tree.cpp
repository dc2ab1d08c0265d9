// SPDX-License-Identifier: MIT
// GCC 12 reports a false -Wrestrict inside std::string operator+ (GCC bug 105651) for the
// message building below; the code is correct, so silence it for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include "inputs/deck_tree.hpp"

#include <algorithm>

#include "inputs/did_you_mean.hpp"

namespace tribex::inputs {
namespace {

std::vector<std::string> split_words(const std::string& s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] == ' ') {
      ++i;
      continue;
    }
    const std::size_t b = i;
    while (i < s.size() && s[i] != ' ') ++i;
    out.push_back(s.substr(b, i - b));
  }
  return out;
}

// Number of leading words of `words` (from `from`) that spell `phrase`, or 0 if they do not.
// (Walks the phrase in place: this runs for every key of a scope on every line.)
std::size_t prefix_match(const std::vector<std::string>& lowered, std::size_t from, const std::string& phrase) {
  const std::string_view p(phrase);
  std::size_t n = 0, start = 0;
  while (start < p.size()) {
    std::size_t stop = p.find(' ', start);
    if (stop == std::string_view::npos) stop = p.size();
    if (from + n >= lowered.size() || lowered[from + n] != p.substr(start, stop - start)) return 0;
    ++n;
    start = stop + 1;
  }
  return n;
}

std::string join(const std::vector<Word>& words, std::size_t from, std::size_t to) {
  std::string s;
  for (std::size_t i = from; i < to && i < words.size(); ++i) {
    if (!s.empty()) s += ' ';
    s += words[i].text;
  }
  return s;
}

std::string opening(const Scope& s) {
  return "'begin " + s.type() + (s.name.empty() ? "" : " " + s.name) + "' at " + s.where.file + ":" +
         std::to_string(s.where.line);
}

// The phrase among `candidates` closest to the leading words of the line (each candidate is
// compared with as many words as it has), for did-you-mean hints.
std::string closest_phrase(const std::vector<std::string>& lowered, std::size_t from,
                           const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_score = static_cast<std::size_t>(-1);
  for (const auto& c : candidates) {
    const std::size_t n = split_words(c).size();
    std::string text;
    for (std::size_t k = from; k < lowered.size() && k < from + n; ++k) text += (text.empty() ? "" : " ") + lowered[k];
    if (closest_match(text, {c}).empty()) continue;
    const std::size_t d = edit_distance(text, c);
    if (d < best_score) {
      best_score = d;
      best = c;
    }
  }
  return best;
}

class TreeBuilder {
 public:
  TreeBuilder(const std::string& file_name, DiagnosticSink& sink) : file_name_(file_name), sink_(sink) {
    Scope root;
    root.schema = &root_schema();
    root.where = {file_name, 1, 1};
    stack_.push_back(std::move(root));
  }

  Scope run(const std::vector<LogicalLine>& lines) {
    for (const auto& line : lines) handle(line);
    while (stack_.size() > 1) {
      const Scope& open = stack_.back();
      sink_.error(open.where, open.path,
                  opening(open) + " has no matching 'end'; add 'end " + open.type() + "' after its last line");
      close_top();
    }
    Scope root = std::move(stack_.back());
    if (lines.empty() && sink_.empty()) {
      sink_.error({file_name_, 1, 1}, "", "the deck is empty; a deck is 'begin sierra NAME' ... 'end sierra'");
    } else if (!lines.empty() && root.children.empty() && !outside_reported_) {
      sink_.error(lines.front().where(), "",
                  "no 'begin sierra' block; a deck is 'begin sierra NAME' ... 'end sierra'");
    }
    return root;
  }

 private:
  void handle(const LogicalLine& line) {
    std::vector<std::string> lowered;
    lowered.reserve(line.words.size());
    for (const auto& w : line.words) lowered.push_back(lower(w.text));
    if (lowered[0] == "begin") return begin(line, lowered);
    if (lowered[0] == "end") return end(line, lowered);
    if (skip_depth_ > 0) return;
    Scope& top = stack_.back();
    if (stack_.size() == 1) {
      if (!outside_reported_) {
        sink_.error(line.where(), "",
                    "'" + join(line.words, 0, 3) +
                        "' stands outside 'begin sierra' ... 'end sierra'; every line belongs inside that block");
        outside_reported_ = true;
      }
      return;
    }
    if (top.schema->rows) return row(line);
    key_line(line, lowered);
  }

  void begin(const LogicalLine& line, const std::vector<std::string>& lowered) {
    if (skip_depth_ > 0) {
      ++skip_depth_;
      return;
    }
    Scope& parent = stack_.back();
    const BlockSchema& ps = *parent.schema;
    const std::string where_text = parent.path.empty() ? "the file" : "'begin " + parent.type() + "'";
    if (lowered.size() < 2) {
      sink_.error(line.where(), parent.path, "'begin' needs a block type; allowed in " + where_text + ": " + allowed_children(ps));
      skip_depth_ = 1;
      return;
    }
    // Longest allowed TYPE that spells the leading words; the rest of the line is the NAME.
    const BlockSchema* schema = nullptr;
    std::size_t used = 0;
    for (const auto& c : ps.children) {
      const std::size_t n = prefix_match(lowered, 1, c.type);
      if (n > used) {
        used = n;
        schema = find_block_schema(c.type);
      }
    }
    if (!schema) {
      std::string known;
      std::size_t known_n = 0;
      for (const auto& b : all_block_schemas()) {
        const std::size_t n = prefix_match(lowered, 1, b.type);
        if (n > known_n) {
          known_n = n;
          known = b.type;
        }
      }
      if (!known.empty() && stack_.size() == 1) {
        sink_.error(line.where(), "",
                    "block 'begin " + known + "' cannot stand at the top of the file; wrap the deck in 'begin sierra "
                    "NAME' ... 'end sierra'");
        outside_reported_ = true;
      } else if (!known.empty()) {
        stack_.front().rejected_blocks.emplace_back(known, join(line.words, 1 + known_n, line.words.size()));
        sink_.error(line.where(), parent.path,
                    "block 'begin " + known + "' cannot stand inside " + where_text + "; allowed here: " +
                        allowed_children(ps) + "; move it to its proper enclosing block");
      } else {
        std::vector<std::string> candidates;
        for (const auto& c : ps.children) candidates.push_back(c.type);
        const std::string hint = closest_phrase(lowered, 1, candidates);
        if (!hint.empty()) {
          const std::size_t n = split_words(hint).size();
          stack_.front().rejected_blocks.emplace_back(hint, join(line.words, 1 + n, line.words.size()));
        }
        sink_.error(line.where(), parent.path,
                    "unknown block 'begin " + join(line.words, 1, line.words.size()) + "'" +
                        (hint.empty() ? "" : "; did you mean 'begin " + hint + "'?") + " allowed in " + where_text +
                        ": " + allowed_children(ps));
      }
      skip_depth_ = 1;
      return;
    }
    Scope scope;
    scope.schema = schema;
    scope.where = line.where();
    scope.path = parent.path.empty() ? schema->type : parent.path + "/" + schema->type;
    scope.name = join(line.words, 1 + used, line.words.size());
    check_name(scope, line);
    check_sibling(parent, scope);
    stack_.push_back(std::move(scope));
  }

  void check_name(Scope& scope, const LogicalLine& line) {
    const BlockSchema& s = *scope.schema;
    if (s.name == NameRule::required && scope.name.empty()) {
      sink_.error(line.where(), scope.path,
                  "'begin " + s.type + "' needs a name: 'begin " + s.type + " NAME'" +
                      (s.name_allowed.empty() ? "" : " with NAME one of " + join_choices(s.name_allowed)));
    } else if (s.name == NameRule::none && !scope.name.empty()) {
      sink_.error(line.where(), scope.path,
                  "'begin " + s.type + "' takes no name, got '" + scope.name + "'; remove it");
    } else if (!s.name_allowed.empty() && !scope.name.empty()) {
      const std::string c = canonical_choice(scope.name, s.name_allowed, s.name_aliases);
      if (c.empty()) {
        sink_.error(line.where(), scope.path,
                    "'" + scope.name + "' is not a known " + s.type + "; allowed: " + join_choices(s.name_allowed));
      } else {
        scope.name = c;
      }
    }
  }

  void check_sibling(const Scope& parent, const Scope& scope) {
    const ChildRule* rule = parent.schema->child(scope.type());
    int count = 0;
    for (const auto& sibling : parent.children) {
      if (sibling.schema != scope.schema) continue;
      ++count;
      if (scope.schema->unique_names && !scope.name.empty() && sibling.name == scope.name) {
        sink_.error(scope.where, scope.path,
                    "duplicate 'begin " + scope.type() + " " + scope.name + "' (first at " + sibling.where.file +
                        ":" + std::to_string(sibling.where.line) + "); names must be unique, rename one");
        return;
      }
    }
    if (rule && count + 1 > rule->max) {
      sink_.error(scope.where, scope.path,
                  "at most " + std::to_string(rule->max) + " 'begin " + scope.type() + "' block(s) allowed in 'begin " +
                      parent.type() + "'; remove this one");
    }
  }

  void end(const LogicalLine& line, const std::vector<std::string>& lowered) {
    if (skip_depth_ > 0) {
      --skip_depth_;
      return;
    }
    if (stack_.size() == 1) {
      sink_.error(line.where(), "", "'end' without a matching 'begin'; remove it");
      return;
    }
    if (lowered.size() == 1 || closes(stack_.back(), line, lowered)) {
      close_top();
      return;
    }
    // Not the innermost block: if it closes an enclosing one, the blocks between lack their `end`.
    for (std::size_t j = stack_.size() - 1; j-- > 1;) {
      if (closes(stack_[j], line, lowered)) {
        while (stack_.size() - 1 > j) {
          const Scope& open = stack_.back();
          sink_.error(line.where(), open.path,
                      "missing 'end " + open.type() + "' for " + opening(open) + "; add it before this line");
          close_top();
        }
        close_top();
        return;
      }
    }
    const Scope& open = stack_.back();
    sink_.error(line.where(), open.path,
                "'" + join(line.words, 0, line.words.size()) + "' does not match " + opening(open) +
                    "; write 'end " + open.type() + (open.name.empty() ? "" : " " + open.name) + "' or just 'end'");
    close_top();
  }

  // `end TYPE [NAME]` closes `scope`?
  static bool closes(const Scope& scope, const LogicalLine& line, const std::vector<std::string>& lowered) {
    const std::size_t n = prefix_match(lowered, 1, scope.type());
    if (n == 0) return false;
    // No NAME after TYPE, or a block whose NAME was missing (already reported): any NAME closes it.
    if (1 + n == line.words.size() || scope.name.empty()) return true;
    const std::string name = join(line.words, 1 + n, line.words.size());
    if (name == scope.name) return true;
    return !scope.schema->name_allowed.empty() &&
           canonical_choice(name, scope.schema->name_allowed, scope.schema->name_aliases) == scope.name;
  }

  void close_top() {
    Scope done = std::move(stack_.back());
    stack_.pop_back();
    for (const auto& k : done.schema->keys) {
      const bool misspelt = std::find(done.misspelt.begin(), done.misspelt.end(), &k) != done.misspelt.end();
      if (k.required && !done.find(k.name) && !misspelt) {
        sink_.error(done.where, done.path,
                    "missing required key '" + k.name + "' in " + opening(done) + "; add '" + k.name + " = ...'");
      }
    }
    for (const auto& c : done.schema->children) {
      if (c.min > 0 && static_cast<int>(done.children_of(c.type).size()) < c.min) {
        sink_.error(done.where, done.path,
                    opening(done) + " needs at least " + std::to_string(c.min) + " 'begin " + c.type + "' block(s)");
      }
    }
    stack_.back().children.push_back(std::move(done));
  }

  void row(const LogicalLine& line) {
    Scope& top = stack_.back();
    Row r;
    r.where = line.where();
    for (const auto& w : line.words) {
      auto v = plain_number(w.text);
      if (!v) {
        sink_.error(w.where, top.path,
                    "'" + w.text + "' is not a plain number; each line of 'begin values' is 't f(t)' (units go in "
                    "'abscissa unit' / 'ordinate unit' of the function)");
        return;
      }
      r.numbers.push_back(*v);
    }
    if (r.numbers.size() != 2) {
      sink_.error(r.where, top.path,
                  "a row of 'begin values' has 2 numbers (t f(t)), got " + std::to_string(r.numbers.size()));
      return;
    }
    top.rows.push_back(std::move(r));
  }

  void key_line(const LogicalLine& line, const std::vector<std::string>& lowered) {
    Scope& top = stack_.back();
    const BlockSchema& s = *top.schema;
    const KeySchema* key = nullptr;
    std::size_t used = 0;
    for (const auto& k : s.keys) {
      const std::size_t n = prefix_match(lowered, 0, k.name);
      if (n > used) {
        used = n;
        key = &k;
      }
    }
    if (!key) {
      std::size_t d = 0;
      while (d < lowered.size() && lowered[d] != "=" && lowered[d] != "is" && lowered[d] != "are") ++d;
      std::vector<std::string> candidates;
      for (const auto& k : s.keys) candidates.push_back(k.name);
      std::string hint = closest_phrase(lowered, 0, candidates);
      std::string allowed = join_choices(candidates);
      if (allowed.empty()) allowed = "none (only blocks: " + allowed_children(s) + ")";
      const std::string shown = join(line.words, 0, d == 0 ? 1 : d);
      bool is_block = find_block_schema(lower(shown)) != nullptr;
      sink_.error(line.where(), top.path,
                  "unknown key '" + shown + "' in 'begin " + s.type + "'" +
                      (is_block ? "; a block needs 'begin " + lower(shown) + "'" : "") +
                      (hint.empty() ? "; allowed keys: " : "; did you mean '" + hint + "'? allowed keys: ") + allowed);
      // A misspelt required key is reported once, here, not again as missing.
      if (!hint.empty()) top.misspelt.push_back(s.key(hint));
      return;
    }
    for (const auto& existing : top.keys) {
      if (existing.schema == key && !key->repeatable) {
        sink_.error(line.where(), top.path,
                    "duplicate key '" + key->name + "' (first at " + existing.where.file + ":" +
                        std::to_string(existing.where.line) + "); give it once");
        return;
      }
    }
    if (used < lowered.size() && (lowered[used] == "=" || lowered[used] == "is" || lowered[used] == "are")) ++used;
    KeyLine kl;
    kl.schema = key;
    kl.where = line.where();
    kl.words.assign(line.words.begin() + static_cast<std::ptrdiff_t>(used), line.words.end());
    kl.value = convert_value(*key, kl.words, kl.where, top.path, sink_);
    top.keys.push_back(std::move(kl));
  }

  static std::string allowed_children(const BlockSchema& s) {
    std::vector<std::string> names;
    for (const auto& c : s.children) names.push_back("'begin " + c.type + "'");
    return names.empty() ? "no blocks" : join_choices(names);
  }

  std::string file_name_;
  DiagnosticSink& sink_;
  std::vector<Scope> stack_;
  int skip_depth_ = 0;  // inside an unknown or misplaced block: skipped up to its `end`
  bool outside_reported_ = false;
};

}  // namespace

const KeyLine* Scope::find(const std::string& key) const {
  for (const auto& k : keys) {
    if (k.schema->name == key) return &k;
  }
  return nullptr;
}

std::vector<const Scope*> Scope::children_of(const std::string& t) const {
  std::vector<const Scope*> out;
  for (const auto& c : children) {
    if (c.schema->type == t) out.push_back(&c);
  }
  return out;
}

Scope build_deck_tree(const std::vector<LogicalLine>& lines, const std::string& file_name, DiagnosticSink& sink) {
  return TreeBuilder(file_name, sink).run(lines);
}

}  // namespace tribex::inputs
