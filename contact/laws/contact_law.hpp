// SPDX-License-Identifier: MIT
// The interaction law of a contact pair: a std::variant of small value types, and the one list of
// them (`ContactLaw` below) from which the deck schema (`model =` choices and the interaction's keys),
// the deck builder's checks, the set-up and the key reference are made. The node-to-face pass visits
// the variant once per pass and runs a loop templated on the law (node_to_face/node_to_face_pass.cpp),
// so there is no dispatch per node.
//
// Every law provides (README.md, "Adding a contact law"):
//   static constexpr std::string_view deck_name;            // `model = ...`
//   static constexpr std::array<KeyDecl, N> keys;            // its deck keys (law_key.hpp)
//   static constexpr bool penalty;                          // penalty normal contact for g < 0
//   static constexpr bool mortar;                           // also with enforcement = mortar
//   static constexpr int state_size;                        // doubles of state per slave node (restart carries them)
//   static std::optional<LawProblem> check(const KeyValues&);   // rules between its keys (deck check time)
//   static L make(const KeyValues&);                        // defaults filled in; may throw LawError
//   std::string describe() const;                           // one line for the run log
//   double reach() const;                                   // largest gap it acts at (the search margin covers it), m
// and optionally the hooks of the node-to-face pass (node_to_face/pass_view.hpp):
//   void at_point(const ContactPoint&, PassView&) const;    // every projected node: g >= 0, or after its penalty
//   void end_pass(PassView&) const;                         // after the pass's normal forces (tangential pairs)
//   static constexpr bool area_from_shares;                 // the law counts the contact area itself
//   const Adhesion* adhesion_part() const;                  // the Lennard-Jones adhesion it applies, if any
#pragma once

#include <span>
#include <string>
#include <variant>
#include <vector>

#include "contact/laws/adhesion.hpp"
#include "contact/laws/coulomb.hpp"
#include "contact/laws/frictionless.hpp"
#include "contact/laws/junction.hpp"
#include "contact/laws/rough_surface.hpp"

namespace tribex::contact {

/// Every contact law; a new one is a header and one entry here.
using ContactLaw = std::variant<Frictionless, Adhesion, Junction, RoughSurface, Coulomb>;

inline constexpr int law_count = static_cast<int>(std::variant_size_v<ContactLaw>);

/// f(std::type_identity<L>{}, index) for every law L of the list, in order.
template <class F>
void for_each_law(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::type_identity<std::variant_alternative_t<I, ContactLaw>>{}, static_cast<int>(I)), ...);
  }(std::make_index_sequence<std::variant_size_v<ContactLaw>>{});
}

/// What the deck side needs of law `index`: its name, keys, whether it runs with mortar and whether
/// its normal contact is the penalty (the set-up's slave/master order depends on it).
struct LawInfo {
  std::string_view deck_name;
  std::span<const KeyDecl> keys;
  bool mortar = false;
  bool penalty = false;
};
inline LawInfo law_info(int index) {
  LawInfo info;
  for_each_law([&](auto l, int i) {
    using L = typename decltype(l)::type;
    if (i == index) info = {L::deck_name, L::keys, L::mortar, L::penalty};
  });
  return info;
}
/// Deck names of the laws, in the list's order.
inline std::vector<std::string> law_names() {
  std::vector<std::string> names;
  for (int i = 0; i < law_count; ++i) names.emplace_back(law_info(i).deck_name);
  return names;
}
/// Index of the law with this deck name, or -1.
inline int law_index(std::string_view name) {
  for (int i = 0; i < law_count; ++i)
    if (law_info(i).deck_name == name) return i;
  return -1;
}
inline std::span<const KeyDecl> law_keys(int index) { return law_info(index).keys; }
inline bool law_supports_mortar(int index) { return law_info(index).mortar; }
/// "" when law `index` runs with the mortar enforcement, else why not and what to do (the deck
/// builder and the manager both ask here: the pairing is decided in one place).
inline std::string mortar_problem(int index) {
  if (law_supports_mortar(index)) return "";
  std::vector<std::string> with_mortar;
  for (int i = 0; i < law_count; ++i)
    if (law_supports_mortar(i)) with_mortar.push_back("'model = " + law_names()[static_cast<std::size_t>(i)] + "'");
  std::string list;
  for (std::size_t i = 0; i < with_mortar.size(); ++i)
    list += (i == 0 ? "" : i + 1 == with_mortar.size() ? " and " : ", ") + with_mortar[i];
  return "'enforcement = mortar' supports " + list + "; use 'enforcement = node to face' for 'model = " +
         law_names()[static_cast<std::size_t>(index)] + "'";
}
inline std::optional<LawProblem> check_law(int index, const KeyValues& values) {
  std::optional<LawProblem> problem;
  for_each_law([&](auto l, int i) {
    if (i == index) problem = decltype(l)::type::check(values);
  });
  return problem;
}
/// Law `index` from the deck's values (defaults filled in); throws LawError.
inline ContactLaw make_law(int index, const KeyValues& values) {
  ContactLaw made;
  for_each_law([&](auto l, int i) {
    if (i == index) made = decltype(l)::type::make(values);
  });
  return made;
}

inline std::string_view law_name(const ContactLaw& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::deck_name; }, law);
}
inline std::string describe(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.describe(); }, law);
}
inline double law_reach(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.reach(); }, law);
}
inline bool uses_penalty(const ContactLaw& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::penalty; }, law);
}
inline bool supports_mortar(const ContactLaw& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::mortar; }, law);
}
inline int law_state_size(const ContactLaw& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::state_size; }, law);
}
/// The Lennard-Jones adhesion of the law, if it has one (a law that adheres provides
/// `const Adhesion* adhesion_part() const`).
inline const Adhesion* adhesion_of(const ContactLaw& law) {
  return std::visit(
      [](const auto& l) -> const Adhesion* {
        if constexpr (requires { l.adhesion_part(); })
          return l.adhesion_part();
        else
          return nullptr;
      },
      law);
}
/// Whether the law reads the velocities of its nodes (PassView::v): every law that does not declare
/// `static constexpr bool reads_velocity = false`. A distributed run sends its ghost nodes' velocities
/// only for such laws (ContactManager::ghost_fields).
inline bool reads_velocity(const ContactLaw& law) {
  return std::visit(
      [](const auto& l) {
        using L = std::decay_t<decltype(l)>;
        if constexpr (requires { L::reads_velocity; })
          return L::reads_velocity;
        else
          return true;
      },
      law);
}
/// Whether the law records tangential pairs (has an end_pass hook).
inline bool has_tangential_pairs(const ContactLaw& law) {
  return std::visit([](const auto& l) { return requires(PassView& view) { l.end_pass(view); }; }, law);
}

}  // namespace tribex::contact
