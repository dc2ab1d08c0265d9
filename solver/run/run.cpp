// SPDX-License-Identifier: MIT
#include "solver/run/run.hpp"

#include "solver/run/deck_run.hpp"

namespace tribex::solver {

RunSummary run_deck(const inputs::Deck& deck, const RunOptions& options) {
  DeckRun run(deck, options);
  return run.run();
}

}  // namespace tribex::solver
