#pragma once
/// @file toml_text.hpp
/// Private helpers shared by covopt's two TOML readers (the materials catalog and scene
/// files) for their messages: where a node is ("file:line:column") and what type it has ("a
/// string"). Header-only and not installed (target covopt_text_internal); needs toml++.

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

#include "covopt/internal/toml.hpp"

namespace covopt::internal {

/// "source:line:column" of `position`.
inline std::string Where(std::string_view source, const toml::source_position& position) {
  return std::string(source) + ":" + std::to_string(position.line) + ":" +
         std::to_string(position.column);
}

/// "source:line:column" of where `region` begins.
inline std::string Where(std::string_view source, const toml::source_region& region) {
  return Where(source, region.begin);
}

/// The node's type for messages: "a string", "an integer", "a table", ...
inline std::string_view TypeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

/// The first key of `table` in file order that is not among `known` (a range of
/// std::string_view); nullptr when every key is known. Readers report that one.
template <class Keys>
const toml::key* FirstUnknownKey(const toml::table& table, const Keys& known) {
  const toml::key* first = nullptr;
  for (const auto& [key, node] : table) {
    if (std::find(std::begin(known), std::end(known), key.str()) != std::end(known)) continue;
    const auto& at = key.source().begin;
    if (first == nullptr || at.line < first->source().begin.line ||
        (at.line == first->source().begin.line && at.column < first->source().begin.column)) {
      first = &key;
    }
  }
  return first;
}

}  // namespace covopt::internal
