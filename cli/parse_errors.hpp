#pragma once
/// @file parse_errors.hpp
/// CLI11's parse errors as covopt's one-line bad-input messages (exit code 2):
///
///     covopt optimize: error: unknown option '--max-thicknes'; did you mean '--max-thickness'?
///     covopt simulate: error: --max-steps: expected a whole number (got '1e99')
///     covopt simulate: error: --speed: missing value; expected SPEED
///     covopt simulate: error: --speed given twice ('1' and '2'); give it once
///
/// Each names the subcommand being parsed (so the help hint points at the right one), the
/// flag, the value and what is allowed. Header-only: used by app.cpp.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/internal/text.hpp"

namespace covopt::cli {
namespace parse_errors_detail {

using covopt::internal::EditDistance;

/// Every "--long" name of `app`'s options, help included.
inline std::vector<std::string> LongFlags(const CLI::App& app) {
  std::vector<std::string> flags;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) flags.push_back("--" + name);
  }
  return flags;
}

/// The flag `typed` was probably meant to be: a close spelling, else a flag that `typed`
/// ends with ("--covering-thickness" -> "--thickness") or that starts with it.
inline std::string SuggestFlag(const CLI::App& app, std::string_view typed) {
  const std::string_view word = typed.substr(0, typed.find('='));
  std::string best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  const std::vector<std::string> flags = LongFlags(app);
  // Words a new user reaches for that are not a spelling away from covopt's.
  static constexpr std::pair<std::string_view, std::string_view> kSynonyms[] = {
      {"--velocity", "--speed"},          {"--impact-speed", "--speed"},     {"--v", "--speed"},
      {"--mass", "--robot-mass"},         {"--reflected-mass", "--robot-mass"},
      {"--radius", "--robot-radius"},     {"--thickness", "--covering-thickness"},
      {"--modulus", "--covering-modulus"}, {"--youngs-modulus", "--covering-modulus"},
      {"--sf", "--safety-factor"},        {"--factor", "--safety-factor"}};
  for (const auto& [synonym, flag] : kSynonyms) {
    if (word == synonym && std::find(flags.begin(), flags.end(), flag) != flags.end()) return std::string(flag);
  }
  for (const std::string& flag : flags) {
    const std::size_t d = EditDistance(word, flag);
    if (d < best_distance) {
      best_distance = d;
      best = flag;
    }
  }
  if (!best.empty() && best_distance <= std::max<std::size_t>(2, word.size() / 4)) return best;
  for (const std::string& flag : flags) {
    const std::string_view bare = std::string_view(flag).substr(2);
    if (bare.size() >= 4 && word.size() > bare.size() &&
        word.substr(word.size() - bare.size()) == bare && word[word.size() - bare.size() - 1] == '-') {
      return flag;
    }
  }
  for (const std::string& flag : flags) {
    if (word.size() >= 4 && flag.size() > word.size() && flag.compare(0, word.size(), word) == 0) {
      return flag;
    }
  }
  return {};
}

inline std::vector<std::string> Words(std::string_view text) {
  std::istringstream in{std::string(text)};
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

inline bool IsIntegerType(std::string_view type_name) {
  return type_name == "INT" || type_name == "UINT" || type_name == "N" ||
         type_name == "SEED" || type_name == "COUNT";
}

}  // namespace parse_errors_detail

/// The innermost subcommand CLI11 was parsing when a parse error was thrown ("materials
/// find" gives `find`); null for the top level.
inline const CLI::App* ActiveSubcommand(const CLI::App& app) {
  const CLI::App* active = nullptr;
  for (auto parsed = app.get_subcommands(); !parsed.empty();
       parsed = parsed.front()->get_subcommands()) {
    active = parsed.front();
  }
  return active;
}

/// The words that name the active subcommand after "covopt": "simulate", "materials find";
/// empty for the top level.
inline std::string ActiveCommandPath(const CLI::App& app) {
  std::string path;
  for (auto parsed = app.get_subcommands(); !parsed.empty();
       parsed = parsed.front()->get_subcommands()) {
    if (!path.empty()) path += ' ';
    path += parsed.front()->get_name();
  }
  return path;
}

/// One line, without the "covopt X: error: " prefix, for a CLI11 parse error.
inline std::string DescribeParseError(const CLI::App& app, const CLI::ParseError& error) {
  namespace d = parse_errors_detail;
  const CLI::App* sub = ActiveSubcommand(app);
  const CLI::App& scope = sub ? *sub : app;
  const std::string what = error.what();
  const std::string help =
      sub ? fmt::format("covopt {} --help", ActiveCommandPath(app)) : "covopt --help";

  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
    // "The following argument(s) was/were not expected: a b" (CLI11 lists them reversed).
    const auto colon = what.find(": ");
    std::vector<std::string> extras =
        d::Words(colon == std::string::npos ? std::string_view() : std::string_view(what).substr(colon + 2));
    std::reverse(extras.begin(), extras.end());
    const auto flag = std::find_if(extras.begin(), extras.end(),
                                   [](const std::string& w) { return w.size() > 1 && w[0] == '-'; });
    if (flag != extras.end()) {
      const std::string suggestion = d::SuggestFlag(scope, *flag);
      return fmt::format("unknown option '{}'; {}", *flag,
                         suggestion.empty() ? fmt::format("see '{}' for the options", help)
                                            : fmt::format("did you mean '{}'?", suggestion));
    }
    if (!extras.empty()) {
      return fmt::format("unexpected argument '{}' (values follow their flag, e.g. --speed 2m/s); "
                         "see '{}'",
                         extras.front(), help);
    }
  }
  if (dynamic_cast<const CLI::ConversionError*>(&error) != nullptr) {
    // "Could not convert: --top = abc"
    constexpr std::string_view kPrefix = "Could not convert: ";
    const auto eq = what.find(" = ");
    if (what.rfind(kPrefix, 0) == 0 && eq != std::string::npos) {
      const std::string name = what.substr(kPrefix.size(), eq - kPrefix.size());
      const std::string value = what.substr(eq + 3);
      const CLI::Option* option = scope.get_option_no_throw(name);
      const std::string type = option ? option->get_type_name() : std::string();
      return fmt::format("{}: expected {} (got '{}')", name,
                         d::IsIntegerType(type) ? std::string("a whole number")
                                                : (type.empty() ? std::string("a valid value") : type),
                         value);
    }
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    // "--speed: At Most 1 required but received 2": a single-value option given again. The
    // option still holds what was typed, in order.
    const auto colon = what.find(": ");
    if (colon != std::string::npos && what.find("At Most 1 required", colon) != std::string::npos) {
      const std::string name = what.substr(0, colon);
      const CLI::Option* option = scope.get_option_no_throw(name);
      if (option != nullptr && option->results().size() >= 2) {
        const std::vector<std::string>& typed = option->results();
        std::string values;
        for (std::size_t i = 0; i < typed.size(); ++i) {
          if (i > 0) values += i + 1 == typed.size() ? " and " : ", ";
          values += fmt::format("'{}'", typed[i]);
        }
        return fmt::format("{} given {} ({}); give it once", name,
                           typed.size() == 2 ? std::string("twice")
                                             : fmt::format("{} times", typed.size()),
                           values);
      }
    }
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    // "--speed: 1 required SPEED missing"
    const auto required = what.find(" required ");
    const auto missing = what.rfind(" missing");
    const auto colon = what.find(": ");
    if (required != std::string::npos && missing != std::string::npos && colon != std::string::npos &&
        missing > required) {
      return fmt::format("{}: missing value; expected {}", what.substr(0, colon),
                         what.substr(required + 10, missing - required - 10));
    }
  }
  return fmt::format("{}; see '{}'", what, help);
}

}  // namespace covopt::cli
