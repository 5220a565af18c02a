#pragma once
/// Arithmetic expressions of parametric L-systems (Prusinkiewicz & Lindenmayer 1990, "The
/// Algorithmic Beauty of Plants", ch. 1.10): module arguments such as `l*0.7` and conditions such
/// as `l > 0.01 && w > 0.002`, evaluated over the parameters of the rewritten module.

#include <span>
#include <string>
#include <vector>

namespace viscera::core {

/// A compiled expression over a fixed list of parameter names.
///
/// Syntax: numbers, parameter names, `+ - * / ^` (power, right-associative), unary `-` and `!`,
/// comparisons `< <= > >= == !=` (1 for true, 0 for false), `&&`, `||`, parentheses, and the
/// functions `min(a,b) max(a,b) sqrt(a) abs(a) sin(a) cos(a) floor(a)` (angles in degrees).
/// Names that are not parameters are looked up in the constants passed to parse() and folded in.
class LsystemExpression {
 public:
  /// The constant 0.
  LsystemExpression();

  /// Compiles `text`; `parameters` name the values passed to evaluate(), in order.
  /// Throws InputError (element = the text) on a syntax error or an unknown name.
  static LsystemExpression parse(const std::string& text,
                                 const std::vector<std::string>& parameters,
                                 const std::vector<std::pair<std::string, double>>& constants = {});
  /// An expression that always gives `value`.
  static LsystemExpression constant(double value);

  /// Value for the given parameter values (one per parameter name given to parse()).
  double evaluate(std::span<const double> parameters) const;
  /// True when the expression uses no parameter.
  bool is_constant() const;

  struct Op {
    int code = 0;        ///< operation; see the .cpp
    int index = 0;       ///< parameter index for a load
    double value = 0.0;  ///< literal for a push
  };

 private:
  std::vector<Op> program_;  ///< postfix program
};

}  // namespace viscera::core
