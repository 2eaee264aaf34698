// Catch2 printers for relpos enums, so failures show names instead of integers.
#pragma once

#include <catch2/catch.hpp>
#include <relpos/classify.hpp>
#include <relpos/numbers.hpp>

namespace Catch {
template <>
struct StringMaker<relpos::Position> {
  static std::string convert(relpos::Position p) { return relpos::to_string(p); }
};
template <>
struct StringMaker<relpos::Stage> {
  static std::string convert(relpos::Stage s) { return relpos::to_string(s); }
};
template <>
struct StringMaker<relpos::Rational> {
  static std::string convert(const relpos::Rational& q) { return relpos::to_string(q); }
};
}  // namespace Catch
