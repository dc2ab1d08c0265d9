// SPDX-License-Identifier: MIT
// ContactManager state for restart files: everything compute_forces() reads from earlier steps.
#include <stdexcept>

#include "contact/contact_manager.hpp"

namespace tribex::contact {

ContactManager::State ContactManager::state() const {
  State s;
  for (const auto& p : passes_)
    s.passes.push_back({p.candidate_offset, p.candidates, p.last_face, p.x_at_search, p.gap, p.searched, p.stable_dt, p.law_state});
  s.traction = traction_;
  s.status = status_;
  s.total_searches = total_searches_;
  return s;
}

void ContactManager::restore(const State& s) {
  if (s.passes.size() != passes_.size() || s.traction.size() != traction_.size() || s.status.size() != status_.size())
    throw std::invalid_argument("contact state has " + std::to_string(s.passes.size()) + " passes, the deck " +
                                std::to_string(passes_.size()));
  for (std::size_t k = 0; k < passes_.size(); ++k) {
    Pass& p = passes_[k];
    const PassState& q = s.passes[k];
    if (q.x_at_search.size() != p.x_at_search.size())
      throw std::invalid_argument("contact pass " + std::to_string(k) + " has other surfaces than the deck");
    p.candidate_offset = q.candidate_offset;
    p.candidates = q.candidates;
    p.last_face = q.last_face;
    p.x_at_search = q.x_at_search;
    p.gap = q.gap;
    p.searched = q.searched;
    p.stable_dt = q.stable_dt;
    if (q.law_state.size() != p.law_state.size())
      throw std::invalid_argument("contact pass " + std::to_string(k) + " has another interaction law than the deck");
    p.law_state = q.law_state;
  }
  traction_ = s.traction;
  status_ = s.status;
  total_searches_ = s.total_searches;
}

void ContactManager::keep_projected_candidates() {
  if (projected_.empty()) return;  // one rank, or every slave node of the region computed here
  for (Pass& p : passes_) {
    const auto& nodes = surfaces_[p.slave].nodes;
    std::vector<int> offset{0}, kept;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (projected_[nodes[k]])
        kept.insert(kept.end(), p.candidates.begin() + p.candidate_offset[k], p.candidates.begin() + p.candidate_offset[k + 1]);
      offset.push_back(static_cast<int>(kept.size()));
    }
    p.candidate_offset = std::move(offset);
    p.candidates = std::move(kept);
  }
}

}  // namespace tribex::contact
