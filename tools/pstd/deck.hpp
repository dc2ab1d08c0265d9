// SPDX-License-Identifier: MIT
// The `tribex pstd DECK.i` form: a Sierra-flavoured block whose keys are the command-line options.
//
//   # comment
//   begin pstd
//     afm          = ../../../shared/data/afm/matrix-3.txt   # input paths: relative to the deck's folder
//     normal force = 2.2 mN
//     study        = yes
//   end pstd
//
// Keys are case-insensitive, `=` is optional, `#` starts a comment. Options given on the command line after the
// deck override its values. Unknown keys, a missing `begin pstd`/`end` or a repeated key are tools::BadInput
// naming deck:line (with a did-you-mean for keys).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace tribex::pstd {

struct DeckArgs {
  std::vector<std::string> args;              // "--option", "value", ... in deck order
  std::map<std::string, std::string> where;   // option -> "deck:line", to locate errors in values
};

DeckArgs read_deck(const std::string& path);

/// The deck key table, for --help: "deck key  (option)" lines.
std::string deck_keys_help();

}  // namespace tribex::pstd
