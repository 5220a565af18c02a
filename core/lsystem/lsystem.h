#pragma once
/// L-system engine shared by vessel painting (textures/) and vessel centre lines (templates/):
/// bracketed, parametric and stochastic productions (Prusinkiewicz & Lindenmayer 1990, "The
/// Algorithmic Beauty of Plants", ch. 1; seed 001 §3.3 "L-Systems … produce tree-like
/// structures"). Context-free: a module is rewritten from its own symbol and parameters.
///
/// Grammar text, one statement per line, `#` starts a comment:
///
///     const k = 0.8                       # named constant, usable in any later expression
///     axiom: A(1, 0.05)
///     A(l,w) : l > 0.1 -> F(l,w)[+(30)A(l*k, w*0.79)][-(25)A(l*k, w*0.63)] : 0.7
///     A(l,w) : l > 0.1 -> F(l,w)A(l*k, w)                                   : 0.3
///
/// A production is `PREDECESSOR [: CONDITION] -> SUCCESSOR [: WEIGHT]`. Among the productions
/// whose predecessor symbol and parameter count match a module and whose condition holds, one is
/// chosen with probability proportional to its weight; a module no production matches is copied.
/// Symbols are single characters other than `( ) , :` and white space.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/lsystem/lsystem_expression.h"
#include "core/random.h"

namespace viscera::core {

/// One module of an L-system string: a symbol with numeric parameters.
struct LsystemModule {
  char symbol = 0;
  std::vector<double> parameters;

  bool operator==(const LsystemModule&) const = default;
};

using LsystemString = std::vector<LsystemModule>;

/// A module of a successor: its arguments are expressions over the predecessor's parameters.
struct LsystemSuccessorModule {
  char symbol = 0;
  std::vector<LsystemExpression> arguments;
};

/// One production.
struct LsystemProduction {
  char predecessor = 0;
  std::vector<std::string> parameter_names;  ///< the predecessor's formal parameters
  bool has_condition = false;
  LsystemExpression condition;  ///< non-zero = applicable
  std::vector<LsystemSuccessorModule> successor;
  double weight = 1.0;  ///< relative probability, > 0
};

/// A grammar: axiom plus productions, rewritten in parallel generation by generation.
class Lsystem {
 public:
  Lsystem(LsystemString axiom, std::vector<LsystemProduction> productions);

  /// Parses grammar text (see the file comment). Throws InputError naming `what` and the line.
  static Lsystem parse(const std::string& text, const std::string& what = "L-system");

  /// The string after `generations` rewriting steps. Stochastic choices come from Rng(seed), so
  /// the same seed gives the same string. Throws UsageError when the string would exceed
  /// `max_modules` modules.
  LsystemString derive(int generations, std::uint64_t seed,
                       std::size_t max_modules = 4'000'000) const;
  /// One parallel rewriting step of `current`, drawing stochastic choices from `rng`.
  LsystemString rewrite(const LsystemString& current, Rng& rng,
                        std::size_t max_modules = 4'000'000) const;

  const LsystemString& axiom() const { return axiom_; }
  const std::vector<LsystemProduction>& productions() const { return productions_; }

 private:
  LsystemString axiom_;
  std::vector<LsystemProduction> productions_;
  std::array<std::vector<int>, 256> by_symbol_;  ///< production indices per predecessor symbol
};

/// Parses a module string with constant arguments, e.g. "F(1)[+F(0.5)]". Throws InputError.
LsystemString parse_lsystem_string(
    const std::string& text, const std::vector<std::pair<std::string, double>>& constants = {});
/// Writes a string back as text; parameters with up to 6 significant digits.
std::string to_string(const LsystemString& modules);

}  // namespace viscera::core
