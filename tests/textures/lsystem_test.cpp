// The L-system engine lives in core/lsystem; its tests sit with the textures that paint with it,
// since tests/core is kept by the foundation issue.

#include "core/lsystem/lsystem.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/lsystem/turtle.h"

namespace viscera::core {
namespace {

std::string derive(const std::string& grammar, int generations, std::uint64_t seed = 1) {
  return to_string(Lsystem::parse(grammar).derive(generations, seed));
}

TEST(Lsystem, rewrites_lindenmayers_algae_into_fibonacci_strings) {
  const std::string algae = "axiom: A\nA -> AB\nB -> A\n";
  EXPECT_EQ(derive(algae, 0), "A");
  EXPECT_EQ(derive(algae, 1), "AB");
  EXPECT_EQ(derive(algae, 2), "ABA");
  EXPECT_EQ(derive(algae, 3), "ABAAB");
  EXPECT_EQ(derive(algae, 4), "ABAABABA");
  std::size_t a = 1, b = 1;  // lengths follow Fibonacci numbers
  for (int n = 1; n <= 15; ++n) {
    std::tie(a, b) = std::pair(b, a + b);
    EXPECT_EQ(Lsystem::parse(algae).derive(n, 0).size(), b) << n;
  }
}

TEST(Lsystem, rewrites_the_quadratic_koch_island_in_parallel) {
  const auto modules = Lsystem::parse("axiom: F-F-F-F\nF -> F-F+F+FF-F-F+F\n").derive(2, 0);
  EXPECT_EQ(
      std::count_if(modules.begin(), modules.end(), [](const auto& m) { return m.symbol == 'F'; }),
      4 * 8 * 8);
}

TEST(Lsystem, follows_the_parametric_derivation_of_abop_figure_1_31) {
  const std::string grammar =
      "axiom: B(2)A(4,4)\n"
      "A(x,y) : y <= 3 -> A(x*2, x+y)\n"
      "A(x,y) : y > 3 -> B(x)A(x/y, 0)\n"
      "B(x) : x < 1 -> C\n"
      "B(x) : x >= 1 -> B(x-1)\n";
  EXPECT_EQ(derive(grammar, 1), "B(1)B(4)A(1,0)");
  EXPECT_EQ(derive(grammar, 2), "B(0)B(3)A(2,1)");
  EXPECT_EQ(derive(grammar, 3), "CB(2)A(4,3)");
  EXPECT_EQ(derive(grammar, 4), "CB(1)A(8,7)");
  EXPECT_EQ(derive(grammar, 5), "CB(0)B(8)A(1.14286,0)");
}

TEST(Lsystem, constants_functions_and_logic_in_expressions) {
  const std::string grammar =
      "const k = 2 ^ 3      # 8\n"
      "axiom: X(1, 4)\n"
      "X(a,b) : a < b && !(a == 3) -> X(a + 1, b) Y(max(a, k) - sqrt(b), -a)\n";
  EXPECT_EQ(derive(grammar, 1), "X(2,4)Y(6,-1)");
}

TEST(Lsystem, stochastic_choices_follow_the_weights_and_the_seed) {
  std::string axiom = "axiom: ";
  for (int i = 0; i < 30000; ++i)
    axiom += 'F';
  const std::string grammar = axiom + "\nF -> F[+F]F : 1\nF -> F[-F]F : 1\nF -> FF : 2\n";
  const auto modules = Lsystem::parse(grammar).derive(1, 42);
  const auto plus =
      std::count_if(modules.begin(), modules.end(), [](const auto& m) { return m.symbol == '+'; });
  const auto minus =
      std::count_if(modules.begin(), modules.end(), [](const auto& m) { return m.symbol == '-'; });
  // Expected 7500 each; five standard deviations is about 375.
  EXPECT_NEAR(static_cast<double>(plus), 7500.0, 375.0);
  EXPECT_NEAR(static_cast<double>(minus), 7500.0, 375.0);
  EXPECT_EQ(Lsystem::parse(grammar).derive(1, 42), modules);
  EXPECT_NE(Lsystem::parse(grammar).derive(1, 43), modules);
}

TEST(Lsystem, reports_grammar_errors_with_their_line) {
  try {
    Lsystem::parse("axiom: F\nF(l) -> F(l * q)\n", "vessels.lsys");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location().file, "vessels.lsys");
    EXPECT_EQ(e.location().element, "line 2");
    EXPECT_NE(std::string(e.what()).find("unknown name \"q\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(Lsystem::parse("F -> FF\n"), InputError);               // no axiom
  EXPECT_THROW(Lsystem::parse("axiom: F(1\n"), InputError);            // missing ')'
  EXPECT_THROW(Lsystem::parse("axiom: F\nF -> F : 0\n"), InputError);  // zero weight
  EXPECT_THROW(Lsystem::parse("axiom: F\nF\n"), InputError);           // not a statement
}

TEST(Lsystem, refuses_strings_beyond_the_module_limit) {
  EXPECT_THROW(Lsystem::parse("axiom: F\nF -> FF\n").derive(30, 0, 1000), UsageError);
}

TEST(Turtle, closes_a_square_and_links_branches_to_their_parents) {
  TurtleOptions options;
  options.angle = 90.0;
  const auto square = interpret_turtle(parse_lsystem_string("F+F+F+F"), options);
  ASSERT_EQ(square.size(), 4u);
  EXPECT_LT((square.back().end - options.origin).norm(), 1e-12);
  EXPECT_NEAR(square[0].end.y(), 1.0, 1e-12);
  EXPECT_NEAR(square[1].end.x(), -1.0, 1e-12);  // '+' turns left, towards -x

  const auto tree = interpret_turtle(parse_lsystem_string("F[+F[-F]]F"), options);
  ASSERT_EQ(tree.size(), 4u);
  EXPECT_EQ(tree[0].parent, -1);
  EXPECT_EQ(tree[1].parent, 0);
  EXPECT_EQ(tree[1].order, 1);
  EXPECT_EQ(tree[2].parent, 1);
  EXPECT_EQ(tree[2].order, 2);
  EXPECT_EQ(tree[3].parent, 0);
  EXPECT_EQ(tree[3].order, 0);
  EXPECT_TRUE(tree[3].start.isApprox(tree[0].end));
}

TEST(Turtle, tapers_widths_and_tracks_depth) {
  TurtleOptions options;
  options.width = 2.0;
  options.taper = 0.25;  // a quarter of the width per unit length
  options.depth_step = 0.4;
  const auto s = interpret_turtle(parse_lsystem_string("F(1)F(2)'F!(0.5)F"), options);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(s[0].start_width, 2.0);
  EXPECT_DOUBLE_EQ(s[0].end_width, 1.5);
  EXPECT_DOUBLE_EQ(s[1].start_width, 1.5);
  EXPECT_DOUBLE_EQ(s[1].end_width, 0.75);
  EXPECT_DOUBLE_EQ(s[2].depth, 0.4);
  EXPECT_DOUBLE_EQ(s[3].start_width, 0.5);
}

TEST(Turtle, pitches_out_of_the_plane_in_three_dimensions) {
  TurtleOptions options;
  options.angle = 90.0;
  const auto s = interpret_turtle(parse_lsystem_string("&F^^F"), options);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(std::abs((s[0].end - s[0].start).z()), 1.0, 1e-12);
  EXPECT_NEAR((s[1].end - s[1].start).dot(s[0].end - s[0].start), -1.0, 1e-12);
  EXPECT_THROW(interpret_turtle(parse_lsystem_string("F]")), InputError);
  EXPECT_THROW(interpret_turtle(parse_lsystem_string("[F")), InputError);
}

TEST(Turtle, jitter_is_seeded) {
  TurtleOptions options;
  options.angle_jitter = 10.0;
  options.seed = 5;
  const auto modules = parse_lsystem_string("F+F+F-F");
  const auto a = interpret_turtle(modules, options);
  const auto b = interpret_turtle(modules, options);
  EXPECT_TRUE(a.back().end == b.back().end);
  options.seed = 6;
  EXPECT_FALSE(interpret_turtle(modules, options).back().end == a.back().end);
}

}  // namespace
}  // namespace viscera::core
