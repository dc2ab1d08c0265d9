// SPDX-License-Identifier: MIT
// Deck parameters (inputs/parameters.hpp, inputs/expression.hpp; inputs/README.md "Parameters"):
// arithmetic with units, definitions and uses, --set, the resolved text, the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "inputs/diagnostics.hpp"
#include "inputs/expression.hpp"
#include "inputs/parameters.hpp"

using namespace tribex::inputs;

namespace {

Quantity eval(const std::string& text, const Quantity* r = nullptr) {
  std::string error;
  const auto q = evaluate_expression(text, [&](std::string_view n) { return n == "R" ? r : nullptr; }, &error);
  EXPECT_TRUE(q.has_value()) << text << ": " << error;
  return q.value_or(Quantity{NAN, dim::none});
}

std::string eval_error(const std::string& text) {
  std::string error;
  const Quantity r{1e-9, dim::length};
  const auto q = evaluate_expression(text, [&](std::string_view n) { return n == "R" ? &r : nullptr; }, &error);
  EXPECT_FALSE(q.has_value()) << text << " evaluated to " << (q ? q->value : 0.0);
  return error;
}

// The deck of tests/bad_decks/good/minimal.i with a head of definitions and uses in three keys.
std::string deck(const std::string& head, const std::string& density = "7850", const std::string& size = "1 1 1 mm") {
  return head + "\nbegin sierra p\n  begin property specification for material steel\n    density = " + density +
         "\n    begin parameters for model elastic\n      youngs modulus = 200e9\n      poissons ratio = 0.3\n    end\n"
         "  end\n  begin solid section sec\n  end\n  begin finite element model m\n    begin generated box cube\n"
         "      size = " + size + "\n      intervals = 2 2 2\n    end\n    begin parameters for block cube\n"
         "      material = steel\n      section = sec\n    end\n  end\n  begin presto procedure p\n"
         "    begin time control\n      termination time = 1 us\n    end\n    begin presto region r\n"
         "      use finite element model = m\n    end\n  end\nend\n";
}

std::string errors_of(const std::string& text, const std::vector<ParameterSetting>& set = {}) {
  try {
    parse_deck_string(text, "/tmp/p.i", set);
  } catch (const DeckError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parsed without error:\n" << text;
  return "";
}

}  // namespace

TEST(Expression, ArithmeticPrecedenceAndUnits) {
  EXPECT_DOUBLE_EQ(eval("2*(3+4)^2").value, 98.0);
  EXPECT_DOUBLE_EQ(eval("-2^2").value, -4.0);        // unary minus below ^, as in APREPRO and Fortran
  EXPECT_DOUBLE_EQ(eval("2^3^2").value, 512.0);      // right-associative
  EXPECT_DOUBLE_EQ(eval("7 - 2 - 1").value, 4.0);    // left-associative
  EXPECT_DOUBLE_EQ(eval("1e-3 * 4 / 8").value, 5e-4);
  const Quantity w = eval("0.05 J/m^2");
  EXPECT_DOUBLE_EQ(w.value, 0.05);
  EXPECT_EQ(w.dimension, dim::energy_per_area);
  const Quantity half = eval("15nm/2");              // a unit glued to its number, then an operator
  EXPECT_DOUBLE_EQ(half.value, 7.5e-9);
  EXPECT_EQ(half.dimension, dim::length);
  const Quantity area = eval("1 mm * 2 mm");
  EXPECT_DOUBLE_EQ(area.value, 2e-6);
  EXPECT_EQ(area.dimension, dim::area);
  const Quantity v = eval("(4 m^2/s^2)^(1/2)");      // half powers that leave integer unit powers
  EXPECT_DOUBLE_EQ(v.value, 2.0);
  EXPECT_EQ(v.dimension, dim::velocity);
  const Quantity r{27e-9, dim::length};
  const Quantity f = eval("2 * 3.14159 * R * 0.05 J/m^2", &r);
  EXPECT_DOUBLE_EQ(f.value, 2 * 3.14159 * 27e-9 * 0.05);
  EXPECT_EQ(f.dimension, dim::force);
}

TEST(Expression, ErrorsNameTheProblemAndTheFix) {
  EXPECT_NE(eval_error("R + 1").find("cannot add a dimensionless number to a length (m)"), std::string::npos);
  EXPECT_NE(eval_error("R^0.5").find("has no unit with integer powers"), std::string::npos);
  EXPECT_NE(eval_error("2^R").find("an exponent must be dimensionless"), std::string::npos);
  EXPECT_NE(eval_error("1/0").find("not finite"), std::string::npos);
  EXPECT_NE(eval_error("2 *").find("ends where a number, a name or '(' is expected"), std::string::npos);
  EXPECT_NE(eval_error("(2 + 3").find("missing ')'"), std::string::npos);
  EXPECT_NE(eval_error("2 3").find("unexpected '3' at character 3"), std::string::npos);
  EXPECT_NE(eval_error("X * 2").find("'X' is not defined; define it above on a line of its own, {X = VALUE}"),
            std::string::npos);
  EXPECT_NE(eval_error("2 furlong").find("unknown unit 'furlong'"), std::string::npos);
}

TEST(Expression, SiUnitTextReadsBack) {
  for (const Dimension d : {dim::length, dim::energy_per_area, dim::density, dim::rate, Dimension{1, -1, -1}}) {
    std::string error;
    const auto u = parse_unit(si_unit_text(d), &error);
    ASSERT_TRUE(u) << si_unit_text(d) << ": " << error;
    EXPECT_EQ(u->dimension, d) << si_unit_text(d);
    EXPECT_DOUBLE_EQ(u->value, 1.0) << si_unit_text(d);
  }
  EXPECT_EQ(si_unit_text(dim::none), "");
  EXPECT_EQ(si_unit_text(Dimension{1, -1, -1}), "kg*m^-1*s^-1");
}

TEST(Parameters, DefinitionsAndUsesGiveTheValuesInSi) {
  const Deck d = parse_deck_string(deck("{rho = 7850 kg/m^3 * 1000}\n{L = 2 mm}", "{rho / 1000}", "{L} {L} {L/2}"),
                                   "/tmp/p.i");
  EXPECT_DOUBLE_EQ(d.materials.at(0).density, 7850.0);
  ASSERT_EQ(d.parameters.size(), 2u);
  EXPECT_EQ(d.parameters[0].name, "rho");
  EXPECT_DOUBLE_EQ(d.parameters[0].value, 7.85e6);
  EXPECT_EQ(d.parameters[0].unit, "kg/m^3");
  EXPECT_EQ(d.parameters[1].unit, "m");
  EXPECT_EQ(d.parameters[1].where.line, 2);
  EXPECT_FALSE(d.parameters[1].set_on_command_line);
  EXPECT_NE(d.resolved_text.find("size = 0.002 0.002 0.001"), std::string::npos) << d.resolved_text;
  // The resolved text holds the definitions in SI (below its first comment line) and reads back to itself.
  EXPECT_NE(d.resolved_text.find("\n# parameters in SI, --set values applied\n{rho = 7850000 kg/m^3}\n{L = 0.002 m}\n"),
            std::string::npos) << d.resolved_text;
  EXPECT_EQ(parse_deck_string(d.resolved_text, "/tmp/p.i").resolved_text, d.resolved_text);
}

TEST(Parameters, SetReplacesTheDeckValue) {
  const std::string text = deck("{L = 2 mm}\n{H = L / 2}", "7850", "{L} {L} {H}");
  const Deck a = parse_deck_string(text, "/tmp/p.i", {{"L", "3 mm"}});
  EXPECT_DOUBLE_EQ(a.parameters[0].value, 3e-3);
  EXPECT_TRUE(a.parameters[0].set_on_command_line);
  EXPECT_DOUBLE_EQ(a.parameters[1].value, 1.5e-3);  // a later definition follows the new value
  EXPECT_FALSE(a.parameters[1].set_on_command_line);
  EXPECT_NE(a.resolved_text.find("size = 0.003 0.003 0.0015"), std::string::npos) << a.resolved_text;
  // A plain number is SI of the definition's dimension (as plain numbers in a deck are SI of their key).
  const Deck b = parse_deck_string(text, "/tmp/p.i", {{"L", "0.004"}});
  EXPECT_DOUBLE_EQ(b.parameters[0].value, 4e-3);
  EXPECT_EQ(b.parameters[0].unit, "m");
}

TEST(Parameters, SetErrorsAreOneLineEachNamingTheFix) {
  const std::string text = deck("{L = 2 mm}\n{n = 2}", "7850", "{L} {L} {L}");
  EXPECT_NE(errors_of(text, {{"W", "0.06"}})
                .find("/tmp/p.i:0:0: error: --set W=0.06: the deck defines no parameter 'W'; it defines: L, n"),
            std::string::npos);
  EXPECT_NE(errors_of(text, {{"L", "2 GPa"}})
                .find("/tmp/p.i:1:1: error: --set L=2 GPa: 'L' is a length (m) here, got a pressure (Pa)"),
            std::string::npos);
  EXPECT_NE(errors_of(text, {{"n", "2", }, {"n", "3"}}).find("--set n is given twice"), std::string::npos);
  std::string error;
  EXPECT_FALSE(parse_parameter_setting("W", &error));
  EXPECT_NE(error.find("--set expects NAME=VALUE"), std::string::npos);
  EXPECT_FALSE(parse_parameter_setting("2W=1", &error));
  const auto ok = parse_parameter_setting("R = 20 nm", &error);
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->name, "R");
  EXPECT_EQ(ok->expression, "20 nm");
}

TEST(Parameters, DeckErrorsAreReportedOnceEach) {
  // A bad definition is reported at its line; its uses stay quiet (no cascade).
  const std::string bad = errors_of(deck("{L = 2 mm +}", "7850", "{L} {L} {L}"));
  EXPECT_NE(bad.find("/tmp/p.i:1:1: error: '{L = 2 mm +}': the expression ends"), std::string::npos) << bad;
  EXPECT_EQ(bad.find("'L' is not defined"), std::string::npos) << bad;
  EXPECT_NE(errors_of(deck("{L = 1}\n{L = 2}")).find("/tmp/p.i:2:1: error: parameter 'L' is already defined at /tmp/p.i:1:1"),
            std::string::npos);
  EXPECT_NE(errors_of(deck("{2L = 1}")).find("'2L' is not a parameter name"), std::string::npos);
  EXPECT_NE(errors_of(deck("", "{rho = 7850}")).find("a definition {NAME = VALUE} must be a line of its own"),
            std::string::npos);
  EXPECT_NE(errors_of(deck("", "7850}")).find("'}' without its '{'"), std::string::npos);
  EXPECT_NE(errors_of(deck("", "{{7850}}")).find("expressions do not nest"), std::string::npos);
}
