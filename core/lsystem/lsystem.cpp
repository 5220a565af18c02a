#include "core/lsystem/lsystem.h"

#include <cctype>
#include <cstdio>
#include <sstream>

#include "core/error.h"

namespace viscera::core {
namespace {

using Constants = std::vector<std::pair<std::string, double>>;

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  const auto end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

/// Splits at `separator` outside parentheses.
std::vector<std::string> split_top_level(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (const char c : text) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == separator && depth == 0) {
      parts.emplace_back();
    } else {
      parts.back() += c;
    }
  }
  return parts;
}

bool is_symbol(char c) {
  return c != '(' && c != ')' && c != ',' && c != ':' &&
         !std::isspace(static_cast<unsigned char>(c)) &&
         std::isprint(static_cast<unsigned char>(c));
}

/// A module string whose arguments are expressions over `names`.
std::vector<LsystemSuccessorModule> parse_modules(const std::string& text,
                                                  const std::vector<std::string>& names,
                                                  const Constants& constants) {
  std::vector<LsystemSuccessorModule> modules;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (!is_symbol(c)) {
      throw InputError(std::string("unexpected '") + c + "' in module string", {"", "", text});
    }
    LsystemSuccessorModule module;
    module.symbol = c;
    ++i;
    std::size_t j = i;
    while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j])))
      ++j;
    if (j < text.size() && text[j] == '(') {
      int depth = 0;
      std::size_t k = j;
      for (; k < text.size(); ++k) {
        if (text[k] == '(') ++depth;
        if (text[k] == ')' && --depth == 0) break;
      }
      if (k == text.size()) throw InputError("missing ')' in module string", {"", "", text});
      for (const auto& argument : split_top_level(text.substr(j + 1, k - j - 1), ',')) {
        module.arguments.push_back(LsystemExpression::parse(trim(argument), names, constants));
      }
      i = k + 1;
    }
    modules.push_back(std::move(module));
  }
  return modules;
}

LsystemProduction parse_production(const std::string& line, const Constants& constants) {
  const auto arrow = line.find("->");
  LsystemProduction production;
  const auto left = split_top_level(line.substr(0, arrow), ':');
  if (left.size() > 2) throw InputError("more than one ':' before '->'");
  const std::string predecessor = trim(left[0]);
  if (predecessor.empty() || !is_symbol(predecessor[0])) {
    throw InputError("a production needs a predecessor symbol before '->'");
  }
  production.predecessor = predecessor[0];
  const std::string formal = trim(predecessor.substr(1));
  if (!formal.empty()) {
    if (formal.front() != '(' || formal.back() != ')') {
      throw InputError("the predecessor is one symbol with optional (names)");
    }
    for (const auto& name : split_top_level(formal.substr(1, formal.size() - 2), ',')) {
      const std::string n = trim(name);
      if (n.empty() || !(std::isalpha(static_cast<unsigned char>(n[0])) || n[0] == '_')) {
        throw InputError("bad parameter name \"" + n + "\"");
      }
      production.parameter_names.push_back(n);
    }
  }
  if (left.size() == 2) {
    production.has_condition = true;
    production.condition =
        LsystemExpression::parse(trim(left[1]), production.parameter_names, constants);
  }
  const auto right = split_top_level(line.substr(arrow + 2), ':');
  if (right.size() > 2) throw InputError("more than one ':' after '->'");
  production.successor = parse_modules(right[0], production.parameter_names, constants);
  if (right.size() == 2) {
    production.weight = LsystemExpression::parse(trim(right[1]), {}, constants).evaluate({});
    if (!(production.weight > 0.0)) throw InputError("a production weight must be positive");
  }
  return production;
}

}  // namespace

Lsystem::Lsystem(LsystemString axiom, std::vector<LsystemProduction> productions)
    : axiom_(std::move(axiom)), productions_(std::move(productions)) {
  for (std::size_t p = 0; p < productions_.size(); ++p) {
    if (!(productions_[p].weight > 0.0))
      throw UsageError("L-system production weights must be positive");
    by_symbol_[static_cast<unsigned char>(productions_[p].predecessor)].push_back(
        static_cast<int>(p));
  }
}

Lsystem Lsystem::parse(const std::string& text, const std::string& what) {
  Constants constants;
  LsystemString axiom;
  bool has_axiom = false;
  std::vector<LsystemProduction> productions;
  std::istringstream lines(text);
  std::string raw;
  int number = 0;
  while (std::getline(lines, raw)) {
    ++number;
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    const std::string where = "line " + std::to_string(number);
    try {
      if (line.rfind("const ", 0) == 0) {
        const auto equals = line.find('=');
        if (equals == std::string::npos) throw InputError("const needs '= value'");
        const std::string name = trim(line.substr(6, equals - 6));
        if (name.empty()) throw InputError("const needs a name");
        constants.emplace_back(
            name,
            LsystemExpression::parse(trim(line.substr(equals + 1)), {}, constants).evaluate({}));
      } else if (line.find("->") != std::string::npos) {
        productions.push_back(parse_production(line, constants));
      } else if (line.rfind("axiom", 0) == 0 && trim(line.substr(5)).rfind(':', 0) == 0) {
        axiom = parse_lsystem_string(trim(line.substr(line.find(':') + 1)), constants);
        has_axiom = true;
      } else {
        throw InputError("expected 'axiom: …', 'const name = value' or a production with '->'");
      }
    } catch (const InputError& e) {
      const std::string detail =
          e.location().element.empty() ? "" : " in \"" + e.location().element + "\"";
      throw InputError(e.reason() + detail, {what, "", where});
    }
  }
  if (!has_axiom) throw InputError("the grammar has no 'axiom:' line", {what, "", ""});
  return Lsystem(std::move(axiom), std::move(productions));
}

LsystemString Lsystem::rewrite(const LsystemString& current, Rng& rng,
                               std::size_t max_modules) const {
  LsystemString next;
  next.reserve(current.size() * 2);
  std::vector<int> applicable;
  for (const auto& module : current) {
    applicable.clear();
    double total_weight = 0.0;
    for (const int p : by_symbol_[static_cast<unsigned char>(module.symbol)]) {
      const auto& production = productions_[p];
      if (production.parameter_names.size() != module.parameters.size()) continue;
      if (production.has_condition && production.condition.evaluate(module.parameters) == 0.0) {
        continue;
      }
      applicable.push_back(p);
      total_weight += production.weight;
    }
    if (applicable.empty()) {
      next.push_back(module);
    } else {
      int chosen = applicable.front();
      // Draw only when there is a choice, so deterministic grammars consume no numbers.
      if (applicable.size() > 1) {
        double r = rng.uniform01() * total_weight;
        for (const int p : applicable) {
          chosen = p;
          r -= productions_[p].weight;
          if (r < 0.0) break;
        }
      }
      for (const auto& successor : productions_[chosen].successor) {
        LsystemModule produced;
        produced.symbol = successor.symbol;
        produced.parameters.reserve(successor.arguments.size());
        for (const auto& argument : successor.arguments) {
          produced.parameters.push_back(argument.evaluate(module.parameters));
        }
        next.push_back(std::move(produced));
      }
    }
    if (next.size() > max_modules) {
      throw UsageError("L-system string exceeds " + std::to_string(max_modules) +
                       " modules; use fewer generations");
    }
  }
  return next;
}

LsystemString Lsystem::derive(int generations, std::uint64_t seed, std::size_t max_modules) const {
  if (generations < 0) throw UsageError("L-system generations must be non-negative");
  Rng rng(seed);
  LsystemString current = axiom_;
  for (int g = 0; g < generations; ++g)
    current = rewrite(current, rng, max_modules);
  return current;
}

LsystemString parse_lsystem_string(const std::string& text, const Constants& constants) {
  LsystemString modules;
  for (const auto& m : parse_modules(text, {}, constants)) {
    LsystemModule module;
    module.symbol = m.symbol;
    for (const auto& argument : m.arguments)
      module.parameters.push_back(argument.evaluate({}));
    modules.push_back(std::move(module));
  }
  return modules;
}

std::string to_string(const LsystemString& modules) {
  std::string text;
  for (const auto& module : modules) {
    text += module.symbol;
    if (module.parameters.empty()) continue;
    text += '(';
    for (std::size_t i = 0; i < module.parameters.size(); ++i) {
      char number[32];
      std::snprintf(number, sizeof number, "%.6g", module.parameters[i]);
      text += (i ? "," : "") + std::string(number);
    }
    text += ')';
  }
  return text;
}

}  // namespace viscera::core
