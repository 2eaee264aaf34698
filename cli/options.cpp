#include "options.hpp"

#include <exception>
#include <utility>

#include "io/json_tree.hpp"
#include "relpos/error.hpp"
#include "relpos/io.hpp"
#include "relpos/quadric.hpp"

namespace relpos_cli {

bool Args::take(const char* name, std::string* out) {
  const std::string& a = args_[pos_];
  const std::string n(name);
  const bool with_equals = a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=';
  if (a != n && !with_equals) return false;
  if (!out && with_equals) throw UsageError{"option " + n + " takes no value"};
  if (!seen_.insert(n).second) throw UsageError{"option " + n + " given twice"};
  ++pos_;
  if (!out) return true;
  if (with_equals) {
    *out = a.substr(n.size() + 1);
    return true;
  }
  if (done()) throw UsageError{"option " + n + " needs a value"};
  *out = args_[pos_++];
  return true;
}

bool Args::help() { return take("--help", nullptr) || take("-h", nullptr); }

bool Args::flag(const char* name) { return take(name, nullptr); }

bool Args::value(const char* name, std::string& out) { return take(name, &out); }

void Args::unexpected() {
  const std::string a = next();
  throw UsageError{(a.size() > 1 && a[0] == '-' ? "unknown option '" : "unexpected argument '") + a + "'"};
}

unsigned long long parse_count(const std::string& text, const char* what, unsigned long long lo,
                               unsigned long long hi) {
  std::size_t used = 0;
  unsigned long long n = 0;
  try {
    if (!text.empty() && text[0] >= '0' && text[0] <= '9') n = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || n < lo || n > hi)
    throw UsageError{std::string(what) + " needs an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got " + relpos::detail::io::dump_json(relpos::detail::io::Json(text))};
  return n;
}

std::size_t parse_max_bits(const std::string& text) {
  return static_cast<std::size_t>(parse_count(text, "--max-bits", relpos::kMaxNormalizedBits, 1ULL << 32));
}

std::vector<relpos::Rational> comma_numbers(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<std::string> parts(1);
  for (char ch : text) {
    if (ch == ',')
      parts.emplace_back();
    else if (ch != ' ' && ch != '\t')
      parts.back() += ch;
  }
  if (parts.size() != count)
    throw relpos::InputError(what + ": expected " + std::to_string(count) + " comma-separated numbers, got " +
                             std::to_string(parts.size()) + " in " +
                             relpos::detail::io::dump_json(relpos::detail::io::Json(text)));
  std::vector<relpos::Rational> out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out.push_back(exact_option(parts[i], what + "[" + std::to_string(i) + "]"));
  return out;
}

relpos::Rational exact_option(const std::string& text, const std::string& name) {
  try {
    return relpos::parse_rational(text);
  } catch (const relpos::InputError& e) {
    throw relpos::InputError(name + ": " + e.what());
  }
}

relpos::detail::io::Json parse_inline(const std::string& text, const std::string& role) {
  try {
    return relpos::detail::io::parse_json_exact(text);
  } catch (const relpos::InputError& e) {
    throw relpos::InputError(role + ": " + e.what());
  }
}

bool ShapeOptions::take(Args& args) {
  const std::pair<const char*, std::optional<std::string>*> slots[] = {{"--ellipsoid", &ellipsoid},
                                                                       {"--sphere", &sphere},
                                                                       {"--paraboloid", &paraboloid},
                                                                       {"--standard-paraboloid", &standard}};
  std::string v;
  for (const auto& [name, slot] : slots)
    if (args.value(name, v)) {
      *slot = v;
      return true;
    }
  return false;
}

void ShapeOptions::check(bool need_ellipsoid) const {
  if (ellipsoid && sphere) throw UsageError{"give either --ellipsoid or --sphere, not both"};
  if (paraboloid && standard) throw UsageError{"give either --paraboloid or --standard-paraboloid, not both"};
  if (need_ellipsoid && !ellipsoid && !sphere)
    throw UsageError{"missing the ellipsoid (--ellipsoid Q or --sphere X,Y,Z,R)"};
  if (!need_ellipsoid && (ellipsoid || sphere)) throw UsageError{"this command takes no ellipsoid option"};
  if (!paraboloid && !standard)
    throw UsageError{"missing the paraboloid (--paraboloid Q or --standard-paraboloid A,B)"};
}

relpos::Ellipsoid ShapeOptions::make_ellipsoid() const {
  if (ellipsoid) return relpos::io::ellipsoid_from_json(*ellipsoid, "ellipsoid");
  const auto x = comma_numbers(*sphere, 4, "--sphere");
  try {
    return relpos::Ellipsoid::sphere({x[0], x[1], x[2]}, x[3]);
  } catch (const relpos::InputError& err) {
    throw relpos::InputError(std::string("ellipsoid: ") + err.what());
  }
}

std::vector<relpos::Rational> ShapeOptions::standard_axes() const {
  return comma_numbers(*standard, 2, "--standard-paraboloid");
}

relpos::Paraboloid ShapeOptions::make_paraboloid() const {
  if (paraboloid) return relpos::io::paraboloid_from_json(*paraboloid, "paraboloid");
  const auto x = standard_axes();
  try {
    const relpos::Rational zero(0);
    return relpos::Paraboloid::standard({zero, zero, zero}, x[0], x[1]);
  } catch (const relpos::InputError& err) {
    throw relpos::InputError(std::string("paraboloid: ") + err.what());
  }
}

}  // namespace relpos_cli
