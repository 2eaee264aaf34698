// Private JSON writing of the reports (io.cpp, batch.cpp, certificate_json.cpp): the one writer of
// a classification's and a certificate's JSON text. The text is appended directly instead of
// building an nlohmann tree and dumping it: the full report of a batch line holds a few dozen
// exact numbers, and the tree cost more than computing them (doc/performance.md). The trees of
// the public API are parsed back from this text, so there is one rendering.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "relpos/classify.hpp"
#include "relpos/io.hpp"
#include "relpos/numbers.hpp"

namespace relpos::io::detail {

/// Appends JSON values to a string; the caller writes the punctuation of objects and arrays.
class JsonWriter {
 public:
  explicit JsonWriter(std::string& out) : out_(out) {}

  void raw(std::string_view text) { out_.append(text); }
  void key(std::string_view name);      ///< "name": (name is plain ASCII)
  void member(std::string_view name) {  ///< ,"name": (a member after the first)
    out_ += ',';
    key(name);
  }
  void string(std::string_view s);  ///< escaped as dump_json escapes it
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

/// "position", "small" and "contact": the first members of the full and the minimal report, each
/// preceded by a comma.
void append_verdict_head(const Verdict& v, JsonWriter& w);

/// ,"rule":"<describe(r)>" and ,"stage":"<to_string(st)>", the reports' members for a verdict's rule
/// and stage (each text made once).
const std::string& rule_member(Rule r);
const std::string& stage_member(Stage st);

/// The members of the classification report, each preceded by a comma (the caller has written the
/// opening brace and the id), and the closing brace (classification_to_json describes them).
void append_classification(const Classification& c, const RenderOptions& options, JsonWriter& w);

/// The certificate's JSON value (certificate_to_json describes it).
void append_certificate(const Certificate& c, int digits, JsonWriter& w);

}  // namespace relpos::io::detail
