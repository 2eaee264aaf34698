// Private JSON writing of the answers (answer_json.cpp, certificate_json.cpp): JSON values appended
// to a string, the punctuation of objects and arrays left to the caller. The text is appended
// directly instead of building an nlohmann tree and dumping it: the full report of a batch line
// holds a few dozen exact numbers, and the tree cost more than computing them (doc/performance.md).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "relpos/numbers.hpp"

namespace relpos::detail::io {

/// Appends JSON values to a string; the caller writes the punctuation of objects and arrays.
class JsonWriter {
 public:
  explicit JsonWriter(std::string& out) : out_(out) {}

  void raw(std::string_view text) { out_.append(text); }
  void raw(char c) { out_ += c; }
  void key(std::string_view name);      ///< "name": (name is plain ASCII)
  void member(std::string_view name) {  ///< ,"name": (a member after the first)
    out_ += ',';
    key(name);
  }
  void string(std::string_view s);  ///< escaped as dump_json (json_tree.hpp) escapes it
  void integer(long n);
  void boolean(bool b) { out_ += b ? "true" : "false"; }
  void null() { out_ += "null"; }
  template <class T, class Write>
  void or_null(const std::optional<T>& x, Write write) {  ///< write(*x), or null
    if (x)
      write(*x);
    else
      null();
  }
  void number(double x);                             ///< as dump_json writes a double (the shortest round trip)
  void rational(const Rational& q);                  ///< "p/q" or "p": to_string(q) as a JSON string
  void rationals(const Rational* q, std::size_t n);  ///< [q0, q1, ...] as strings

 private:
  std::string& out_;
};

}  // namespace relpos::detail::io
