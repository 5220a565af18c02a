#include "core/lsystem/lsystem_expression.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "core/error.h"

namespace viscera::core {
namespace {

enum Code : int {
  kPush,
  kLoad,
  kNeg,
  kNot,
  kAdd,
  kSub,
  kMul,
  kDiv,
  kPow,
  kLt,
  kLe,
  kGt,
  kGe,
  kEq,
  kNe,
  kAnd,
  kOr,
  kMin,
  kMax,
  kSqrt,
  kAbs,
  kSin,
  kCos,
  kFloor
};

/// Stack depth of the evaluator; deeper expressions are refused when compiled.
constexpr int kMaxStack = 32;

/// Recursive-descent compiler from infix text to a postfix program.
class Compiler {
 public:
  Compiler(const std::string& text, const std::vector<std::string>& parameters,
           const std::vector<std::pair<std::string, double>>& constants)
      : text_(text), parameters_(parameters), constants_(constants) {}

  std::vector<LsystemExpression::Op> compile() {
    parse_or();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    if (program_.empty()) fail("empty expression");
    return program_;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("bad L-system expression: " + why, {"", "", text_});
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool accept(const char* token) {
    skip_space();
    const std::string t(token);
    if (text_.compare(pos_, t.size(), t) != 0) return false;
    // "<" must not swallow the first half of "<=", nor "!" of "!=".
    if (t.size() == 1 && pos_ + 1 < text_.size() && text_[pos_ + 1] == '=' &&
        (t == "<" || t == ">" || t == "!")) {
      return false;
    }
    pos_ += t.size();
    return true;
  }
  void emit(int code, int index = 0, double value = 0.0) {
    program_.push_back({code, index, value});
    // Track the depth the evaluator will reach: pushes add one, binary operations remove one.
    if (code == kPush || code == kLoad) {
      if (++depth_ > kMaxStack) fail("too deeply nested");
    } else if (code != kNeg && code != kNot && code != kSqrt && code != kAbs && code != kSin &&
               code != kCos && code != kFloor) {
      --depth_;
    }
  }

  void parse_or() {
    parse_and();
    while (accept("||")) {
      parse_and();
      emit(kOr);
    }
  }
  void parse_and() {
    parse_comparison();
    while (accept("&&")) {
      parse_comparison();
      emit(kAnd);
    }
  }
  void parse_comparison() {
    parse_sum();
    static constexpr std::array<std::pair<const char*, int>, 6> kOps = {
        {{"<=", kLe}, {">=", kGe}, {"==", kEq}, {"!=", kNe}, {"<", kLt}, {">", kGt}}};
    for (const auto& [token, code] : kOps) {
      if (accept(token)) {
        parse_sum();
        emit(code);
        return;
      }
    }
  }
  void parse_sum() {
    parse_product();
    for (;;) {
      if (accept("+")) {
        parse_product();
        emit(kAdd);
      } else if (accept("-")) {
        parse_product();
        emit(kSub);
      } else
        return;
    }
  }
  void parse_product() {
    parse_unary();
    for (;;) {
      if (accept("*")) {
        parse_unary();
        emit(kMul);
      } else if (accept("/")) {
        parse_unary();
        emit(kDiv);
      } else
        return;
    }
  }
  void parse_unary() {
    if (accept("-")) {
      parse_unary();
      emit(kNeg);
      return;
    }
    if (accept("!")) {
      parse_unary();
      emit(kNot);
      return;
    }
    parse_power();
  }
  void parse_power() {
    parse_primary();
    if (accept("^")) {
      parse_unary();
      emit(kPow);
    }
  }
  void parse_primary() {
    skip_space();
    if (pos_ >= text_.size()) fail("unexpected end");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      parse_or();
      if (!accept(")")) fail("missing ')'");
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* begin = text_.c_str() + pos_;
      char* end = nullptr;
      const double value = std::strtod(begin, &end);
      if (end == begin) fail("bad number");
      pos_ += static_cast<std::size_t>(end - begin);
      emit(kPush, 0, value);
      return;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
        ++pos_;
      }
      const std::string name = text_.substr(start, pos_ - start);
      if (accept("(")) return parse_call(name);
      for (std::size_t i = 0; i < parameters_.size(); ++i) {
        if (parameters_[i] == name) return emit(kLoad, static_cast<int>(i));
      }
      for (const auto& [constant, value] : constants_) {
        if (constant == name) return emit(kPush, 0, value);
      }
      fail("unknown name \"" + name + "\"");
    }
    fail("unexpected '" + std::string(1, c) + "'");
  }
  void parse_call(const std::string& name) {
    static constexpr std::array<std::pair<const char*, int>, 5> kUnary = {
        {{"sqrt", kSqrt}, {"abs", kAbs}, {"sin", kSin}, {"cos", kCos}, {"floor", kFloor}}};
    for (const auto& [function, code] : kUnary) {
      if (name == function) {
        parse_or();
        if (!accept(")")) fail("missing ')' after argument of " + name);
        return emit(code);
      }
    }
    if (name == "min" || name == "max") {
      parse_or();
      if (!accept(",")) fail(name + " takes two arguments");
      parse_or();
      if (!accept(")")) fail("missing ')' after arguments of " + name);
      return emit(name == "min" ? kMin : kMax);
    }
    fail("unknown function \"" + name + "\"");
  }

  const std::string& text_;
  const std::vector<std::string>& parameters_;
  const std::vector<std::pair<std::string, double>>& constants_;
  std::vector<LsystemExpression::Op> program_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

double degrees_to_radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

}  // namespace

LsystemExpression::LsystemExpression() : program_{{kPush, 0, 0.0}} {}

LsystemExpression LsystemExpression::parse(
    const std::string& text, const std::vector<std::string>& parameters,
    const std::vector<std::pair<std::string, double>>& constants) {
  LsystemExpression expression;
  expression.program_ = Compiler(text, parameters, constants).compile();
  return expression;
}

LsystemExpression LsystemExpression::constant(double value) {
  LsystemExpression expression;
  expression.program_ = {{kPush, 0, value}};
  return expression;
}

bool LsystemExpression::is_constant() const {
  for (const auto& op : program_) {
    if (op.code == kLoad) return false;
  }
  return true;
}

double LsystemExpression::evaluate(std::span<const double> parameters) const {
  std::array<double, kMaxStack> stack{};
  int top = -1;
  for (const auto& op : program_) {
    switch (op.code) {
      case kPush:
        stack[++top] = op.value;
        continue;
      case kLoad:
        if (static_cast<std::size_t>(op.index) >= parameters.size()) {
          throw UsageError("L-system expression needs " + std::to_string(op.index + 1) +
                           " parameters, got " + std::to_string(parameters.size()));
        }
        stack[++top] = parameters[op.index];
        continue;
      case kNeg:
        stack[top] = -stack[top];
        continue;
      case kNot:
        stack[top] = stack[top] == 0.0 ? 1.0 : 0.0;
        continue;
      case kSqrt:
        stack[top] = std::sqrt(stack[top]);
        continue;
      case kAbs:
        stack[top] = std::abs(stack[top]);
        continue;
      case kSin:
        stack[top] = std::sin(degrees_to_radians(stack[top]));
        continue;
      case kCos:
        stack[top] = std::cos(degrees_to_radians(stack[top]));
        continue;
      case kFloor:
        stack[top] = std::floor(stack[top]);
        continue;
      default:
        break;
    }
    const double b = stack[top--];
    double& a = stack[top];
    switch (op.code) {
      case kAdd:
        a = a + b;
        break;
      case kSub:
        a = a - b;
        break;
      case kMul:
        a = a * b;
        break;
      case kDiv:
        a = a / b;
        break;
      case kPow:
        a = std::pow(a, b);
        break;
      case kLt:
        a = a < b ? 1.0 : 0.0;
        break;
      case kLe:
        a = a <= b ? 1.0 : 0.0;
        break;
      case kGt:
        a = a > b ? 1.0 : 0.0;
        break;
      case kGe:
        a = a >= b ? 1.0 : 0.0;
        break;
      case kEq:
        a = a == b ? 1.0 : 0.0;
        break;
      case kNe:
        a = a != b ? 1.0 : 0.0;
        break;
      case kAnd:
        a = (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
        break;
      case kOr:
        a = (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
        break;
      case kMin:
        a = std::fmin(a, b);
        break;
      case kMax:
        a = std::fmax(a, b);
        break;
      default:
        throw UsageError("corrupt L-system expression program");
    }
  }
  return stack[0];
}

}  // namespace viscera::core
