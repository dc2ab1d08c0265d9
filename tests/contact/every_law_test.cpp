// SPDX-License-Identifier: MIT
// Every contact law of the list (contact/laws/contact_law.hpp `ContactLaw`): a typed test over the
// variant's alternatives, so a new law is covered with no edit here. What each must satisfy
// (contact/laws/README.md "What a law provides"):
//  - its keys are deck keys: lower-case words, a unit the deck parser reads (or "path"), help, and an
//    entry of the `begin interaction` schema whose help names the law;
//  - make() from its required keys alone: when check() accepts them the law is made (no throw), with
//    reach() >= 0 and finite and a run-log line; when it does not, check() says why (the builder
//    reports that deck);
//  - a two-flat normal pass (tests/contact/support.hpp: a 10 x 10 nm slave flat over a 12 x 12 nm
//    master, node to face) with energy balance, on the smallest key set check() accepts (the required
//    keys, then the fewest optional ones, each at a typical value of its unit): the slave flat moves
//    from beyond reach() to 0.01 nm penetration and back.
//      * beyond reach() the law applies no force;
//      * in penetration the net normal force pushes the flats apart;
//      * the work of the attraction the pass applies (compressive total minus the net normal force
//        on the slave, N) from beyond reach() to gap g equals the law's reported adhesion energy at g
//        (ContactTotals::adhesion_energy): trapezoid rule on a 0.005 z0 grid, tolerance 2e-4 of the
//        largest energy (the rule's error, (dg)^2/12 times the integral of |a''|, about
//        (0.005)^2/12 x 27 W = 5.6e-5 W for the Lennard-Jones traction; measured 3.5e-5, GTEST_LOG below);
//      * a law with the Lennard-Jones adhesion (adhesion_of) reports -W_captured A at contact and its
//        attraction does the work W_captured A on separation (docs/theory.md 6.3);
//      * the closing/opening cycle's work of the net normal force is zero (1e-9 of the work of one leg):
//        the normal law is conservative, whatever state the law keeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "inputs/schema.hpp"
#include "inputs/units.hpp"
#include "tests/contact/support.hpp"

namespace tribex::contact {
namespace {

template <class V>
struct TypesOf;
template <class... L>
struct TypesOf<std::variant<L...>> {
  using type = ::testing::Types<L...>;
};
struct DeckName {
  template <class L>
  static std::string GetName(int) {
    std::string name(L::deck_name);
    std::replace(name.begin(), name.end(), ' ', '_');
    return name;
  }
};

template <class L>
class EveryLaw : public ::testing::Test {};
TYPED_TEST_SUITE(EveryLaw, TypesOf<ContactLaw>::type, DeckName);

/// A typical value of a key of this unit at the scale of the two flats (nm gaps, GPa moduli).
double typical(std::string_view unit) {
  if (unit == "Pa") return 1e9;
  if (unit == "m") return 0.3e-9;
  if (unit == "J/m^2") return 0.1;
  if (unit == "m/s") return 0.1;
  if (unit == "1/m^2") return 1e17;
  if (unit == "m^2") return 1e-16;
  return 0.5;  // a pure number (a friction coefficient)
}
void give(KeyValues& v, const KeyDecl& k) { v.numbers[std::string(k.key)] = typical(k.unit); }

template <class L>
KeyValues required_values() {
  KeyValues v;
  for (const KeyDecl& k : L::keys)
    if (k.required) give(v, k);
  return v;
}

/// The required keys plus the fewest optional ones (no paths, at most three) that check() accepts.
template <class L>
std::optional<KeyValues> smallest_accepted() {
  std::vector<KeyDecl> optional;
  for (const KeyDecl& k : L::keys)
    if (!k.required && k.unit != "path") optional.push_back(k);
  const int n = static_cast<int>(optional.size());
  for (int size = 0; size <= std::min(3, n); ++size)
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
      if (__builtin_popcount(mask) != size) continue;
      KeyValues v = required_values<L>();
      for (int i = 0; i < n; ++i)
        if (mask & (1u << i)) give(v, optional[static_cast<std::size_t>(i)]);
      if (!L::check(v)) return v;
    }
  return std::nullopt;
}

TYPED_TEST(EveryLaw, KeysAreDeckKeysOfTheInteraction) {
  using L = TypeParam;
  const inputs::BlockSchema* interaction = inputs::find_block_schema("interaction");
  ASSERT_NE(interaction, nullptr);
  for (const KeyDecl& k : L::keys) {
    const std::string key(k.key);
    EXPECT_FALSE(k.help.empty()) << key;
    EXPECT_EQ(key.find("  "), std::string::npos) << key;
    for (char c : key) EXPECT_TRUE((c >= 'a' && c <= 'z') || c == ' ' || c == '_' || (c >= '0' && c <= '9')) << key;
    if (!k.unit.empty() && k.unit != "path") {
      std::string why;
      EXPECT_TRUE(inputs::parse_unit(k.unit, &why)) << key << ": " << why;
    }
    const auto s = std::find_if(interaction->keys.begin(), interaction->keys.end(),
                                [&](const inputs::KeySchema& e) { return e.name == key; });
    ASSERT_NE(s, interaction->keys.end()) << key;
    EXPECT_NE(s->help.find(std::string(L::deck_name)), std::string::npos) << key << ": " << s->help;
  }
  EXPECT_EQ(law_index(L::deck_name) >= 0, true);
}

TYPED_TEST(EveryLaw, MakeFromTheRequiredKeysAlone) {
  using L = TypeParam;
  const KeyValues v = required_values<L>();
  if (const auto problem = L::check(v)) {
    EXPECT_FALSE(problem->message.empty()) << "check() rejects the required keys alone without saying why";
    GTEST_LOG_(INFO) << L::deck_name << ": the required keys alone are not a law: " << problem->message;
    return;
  }
  std::optional<L> law;
  ASSERT_NO_THROW(law = L::make(v)) << "check() accepted the required keys alone, so make() must work";
  EXPECT_GE(law->reach(), 0.0);
  EXPECT_TRUE(std::isfinite(law->reach()));
  EXPECT_FALSE(law->describe().empty());
}

/// The two flats at gap g along a closing/opening path, with the totals and the slave's net force.
struct Sample {
  double gap, force_z, compressive, adhesion_energy;
};

template <class L>
std::vector<Sample> closing_and_opening(const L& law, const std::vector<double>& gaps) {
  mesh::Mesh m = test::two_flats({.gap = 0.0});
  std::vector<double> mass(static_cast<std::size_t>(m.node_count()), 1e-20);
  InteractionSettings s;
  s.law = law;
  s.search_margin = std::max(2.0 * law.reach(), 1e-9);
  ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", s, mass, 1e-15);
  const auto& upper = m.node_sets.at("upper_all");
  const auto& slave = m.node_sets.at("upper_zmin");
  std::vector<Sample> out;
  std::vector<double> x(m.coordinates), force(m.coordinates.size());
  for (double g : gaps) {
    for (int node : upper) x[3 * node + 2] = m.coordinates[3 * node + 2] + g;
    std::fill(force.begin(), force.end(), 0.0);
    const ContactTotals t = manager.compute_forces(x.data(), nullptr, force.data(), nullptr, 1e-15);
    out.push_back({g, test::force_sum(force, slave, 2), t.compressive_force, t.adhesion_energy});
  }
  return out;
}

TYPED_TEST(EveryLaw, TwoFlatNormalPassBalancesItsEnergy) {
  using L = TypeParam;
  const auto values = smallest_accepted<L>();
  ASSERT_TRUE(values) << "no set of the required keys and at most three optional ones passes check()";
  const L law = L::make(*values);
  // Gaps: from beyond reach() to contact (g = 0 on the grid) in steps of 0.005 z0 (z0 = 0.3 nm), on to
  // the overlap, and back.
  const double reach = law.reach(), top = reach + 0.3e-9, bottom = -0.01e-9;
  const int steps = static_cast<int>(std::ceil(top / 0.0015e-9));
  std::vector<double> gaps;
  for (int i = 0; i <= steps; ++i) gaps.push_back(top * (1.0 - static_cast<double>(i) / steps));
  for (int i = 1; i <= 5; ++i) gaps.push_back(bottom * i / 5.0);
  for (int i = static_cast<int>(gaps.size()) - 2; i >= 0; --i) gaps.push_back(gaps[static_cast<std::size_t>(i)]);
  const std::vector<Sample> path = closing_and_opening(law, gaps);
  const std::size_t half = path.size() / 2;  // path[half] is the deepest point

  EXPECT_EQ(path.front().force_z, 0.0) << "a force beyond reach() = " << reach << " m";
  EXPECT_EQ(path.front().adhesion_energy, 0.0) << "an energy beyond reach()";
  EXPECT_GT(path[half].force_z, 0.0) << "the flats overlap by 0.01 nm and are not pushed apart";

  // The attraction the pass applied, a = compressive - net (>= 0), and its work from the top.
  double work = 0.0, largest = 0.0, worst = 0.0, work_at_contact = 0.0, energy_at_contact = 0.0;
  for (std::size_t i = 0; i <= half; ++i) {
    if (i > 0) {
      const double a0 = path[i - 1].compressive - path[i - 1].force_z, a1 = path[i].compressive - path[i].force_z;
      work -= 0.5 * (a0 + a1) * (path[i - 1].gap - path[i].gap);  // dE = a dg, closing: dg < 0
    }
    largest = std::max({largest, std::abs(work), std::abs(path[i].adhesion_energy)});
    worst = std::max(worst, std::abs(work - path[i].adhesion_energy));
    if (path[i].gap >= 0.0) work_at_contact = work, energy_at_contact = path[i].adhesion_energy;
  }
  EXPECT_LE(worst, 2e-4 * largest) << "the attraction's work and the reported adhesion energy differ by " << worst
                                   << " J (largest " << largest << " J)";
  GTEST_LOG_(INFO) << L::deck_name << ": |work - energy| <= " << worst << " J of " << largest << " J";
  const ContactLaw as_variant = law;
  if (const Adhesion* adhesion = adhesion_of(as_variant)) {
    const double area = 100e-18, W = captured_work(adhesion->lj) * area;  // the 10 x 10 nm slave flat
    EXPECT_NEAR(energy_at_contact, -W, 1e-9 * W) << "the energy at contact is not -W_captured A";
    EXPECT_NEAR(work_at_contact, -W, 2e-4 * W) << "the attraction's work of separation is not W_captured A";
  }
  // The cycle: the net force's work closing and opening.
  double closing = 0.0, opening = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double w = 0.5 * (path[i - 1].force_z + path[i].force_z) * (path[i].gap - path[i - 1].gap);
    (i <= half ? closing : opening) += w;
  }
  EXPECT_NEAR(closing + opening, 0.0, 1e-9 * std::abs(closing)) << "closing " << closing << " J, opening " << opening;
}

}  // namespace
}  // namespace tribex::contact
