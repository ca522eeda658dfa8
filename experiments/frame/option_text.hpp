// A driver parameter's value as text: as the output headers record it (to_text, numbers in their shortest
// round-trip form), as --help shows it (help_text), and the numbers a bound tests (numbers_of). Used by
// frame/driver.cpp only.
#pragma once

#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "io/run_info.hpp"

namespace sph::option_text {

template <class T>
std::string to_text(const T& v) {
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) return format_number(static_cast<double>(v));
  else if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
  else if constexpr (std::is_same_v<T, std::string>) return v;
  else {
    std::ostringstream s;
    bool first = true;
    for (const auto& x : v) { s << (first ? "" : " ") << to_text(x); first = false; }
    return s.str();
  }
}

template <class T>
constexpr bool is_text = std::is_same_v<T, std::string> || std::is_same_v<T, std::vector<std::string>>;

// The numbers a parameter holds (none for text): what a bound of DriverOption tests its default and quick value with.
template <class T>
std::vector<double> numbers_of(const T& v) {
  if constexpr (std::is_arithmetic_v<T>) return {static_cast<double>(v)};
  else if constexpr (std::is_same_v<T, std::string>) return {};
  else {
    std::vector<double> out;
    for (const auto& x : v)
      for (double y : numbers_of(x)) out.push_back(y);
    return out;
  }
}

// A value as --help shows it (numbers as CLI11 shows the defaults).
template <class T>
std::string help_text(const T& v) {
  if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
  else if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, std::string>) {
    std::ostringstream s;
    s << v;
    return s.str();
  } else {
    if (v.empty()) return "none";
    std::string out;
    for (const auto& x : v) out += (out.empty() ? "" : " ") + help_text(x);
    return out;
  }
}

}  // namespace sph::option_text
