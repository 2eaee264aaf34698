// The one argument model of the relpos CLI (doc/cli.md): options, usage errors and the shape
// options --ellipsoid/--sphere/--paraboloid/--standard-paraboloid shared by classify, scene and motion.
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "io/json_tree.hpp"
#include "relpos/numbers.hpp"
#include "relpos/quadric.hpp"

namespace relpos_cli {

/// A command line that cannot be used (exit code 2).
struct UsageError {
  std::string message;
};

/// The options of one command: "--name value" or "--name=value"; flags take no value. Every option
/// may be given once: a second --json is the same error as a second --sphere.
class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}
  bool done() const { return pos_ >= args_.size(); }
  const std::string& peek() const { return args_[pos_]; }
  std::string next() { return args_[pos_++]; }
  /// --help or -h.
  bool help();
  /// If the next argument is flag `name`, consume it.
  bool flag(const char* name);
  /// The same, setting `set` to true.
  bool flag(const char* name, bool& set) { return flag(name) && (set = true); }
  /// If the next argument is option `name`, consume it and its value.
  bool value(const char* name, std::string& out);
  /// The next argument is neither a known option nor an accepted operand.
  [[noreturn]] void unexpected();

 private:
  bool take(const char* name, std::string* out);
  std::vector<std::string> args_;
  std::size_t pos_ = 0;
  std::set<std::string> seen_;
};

/// "N" as an integer in [lo, hi] for option `what` (UsageError otherwise).
unsigned long long parse_count(const std::string& text, const char* what, unsigned long long lo, unsigned long long hi);

/// --max-bits N of classify, batch and scene: the pair size limit, from kMaxNormalizedBits (the
/// default) to 2^32 (UsageError otherwise; doc/cli.md, Limits).
std::size_t parse_max_bits(const std::string& text);

/// "a,b,c" -> `count` exact numbers; `what` names the option in InputError messages.
std::vector<relpos::Rational> comma_numbers(const std::string& text, std::size_t count, const std::string& what);

/// One exact number given as an option's value; InputError "<name>: ..." otherwise.
relpos::Rational exact_option(const std::string& text, const std::string& name);

/// Inline JSON of an option, numbers exact; InputError "<role>: invalid JSON ..." otherwise.
relpos::detail::io::Json parse_inline(const std::string& text, const std::string& role);

/// The ellipsoid and paraboloid options of classify, scene and motion.
struct ShapeOptions {
  std::optional<std::string> ellipsoid, sphere, paraboloid, standard;
  /// Consume one of the four options if it is next.
  bool take(Args& args);
  /// UsageError when both forms of a shape are given, or a needed one is missing.
  void check(bool need_ellipsoid) const;
  /// The shapes (InputError "ellipsoid: ..." / "paraboloid: ..." when they cannot be built).
  relpos::Ellipsoid make_ellipsoid() const;
  relpos::Paraboloid make_paraboloid() const;
  /// A and B of --standard-paraboloid.
  std::vector<relpos::Rational> standard_axes() const;
};

}  // namespace relpos_cli
