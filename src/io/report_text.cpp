// The human-readable report of a classification (relpos classify without --json) and of a margin
// (--margin), and the texts they share with other reports: what a position and a stage mean, a
// polynomial with exact coefficients.
#include "io/report_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "algebra/polynomial_text.hpp"
#include "decide/stages.hpp"
#include "io/root_decimals.hpp"
#include "relpos/algebraic_real.hpp"
#include "relpos/io.hpp"
#include "relpos/margin.hpp"

namespace relpos::detail::io {

std::string position_meaning(Position p) {
  switch (p) {
    case Position::I:
      return "the ellipsoid lies inside the paraboloid, with no common point";
    case Position::TI:
      return "the ellipsoid lies inside the paraboloid and touches it (tangent from inside)";
    case Position::C:
      return "the surfaces cross: they meet, and not only tangentially";
    case Position::TE:
      return "the ellipsoid lies outside the paraboloid and touches it (tangent from outside)";
    case Position::E:
      return "the ellipsoid lies outside the paraboloid, with no common point";
  }
  return "?";
}

std::string rho_vs_one_text(int sign) { return sign < 0 ? "<1" : sign == 0 ? "=1" : ">1"; }

namespace {

std::string stage_meaning(Stage s) { return relpos::detail::stage_row(s).meaning; }

std::string double_text(double x, int digits) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits < 1 ? 1 : (digits > 15 ? 15 : digits), x);
  return buf;
}

std::string count_text(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// One line saying what the certificate is and why it proves the position (position.hpp).
std::string certificate_text(const Certificate& c) {
  switch (c.kind) {
    case Certificate::Kind::Definite:
      return "lambda = " + to_string(c.lambda) +
             ": lambda P + E is positive definite, so p has one sign on the "
             "solid ellipsoid";
    case Certificate::Kind::Tangent:
      return "lambda = " + to_string(c.lambda) + ": lambda P + E is positive semidefinite; contact point (" +
             to_string(c.contact[0]) + ", " + to_string(c.contact[1]) + ", " + to_string(c.contact[2]) + ")";
    case Certificate::Kind::HardTangent:
      return "lambda = lambda_s (hard case): contact along " +
             std::string(c.directions.empty()       ? "one point"
                         : c.directions.size() == 1 ? "two points"
                                                    : "a conic") +
             " (exact centre, directions and squared radius in the JSON output)";
    case Certificate::Kind::Crossing:
      return "inside point (" + to_string(c.inside[0]) + ", " + to_string(c.inside[1]) + ", " + to_string(c.inside[2]) +
             "), outside point (" + to_string(c.outside[0]) + ", " + to_string(c.outside[1]) + ", " +
             to_string(c.outside[2]) + ") of the solid ellipsoid";
    case Certificate::Kind::None:
      break;
  }
  return "none";
}

}  // namespace

std::string polynomial_to_text(const Rational* c, int size, const std::string& var) {
  return relpos::detail::polynomial_text(c, size < 0 ? 0 : static_cast<std::size_t>(size), var);
}

namespace {

/// The "small:" line's text: the smallness and rho, exactly when rational.
std::string smallness_text(const Classification& c, const relpos::io::RenderOptions& options) {
  std::string small =
      c.verdict.small ? "yes (the paper's smallness hypothesis holds): " : "no (the smallness hypothesis fails): ";
  const std::string compare = std::string("rho ") + (c.verdict.rho_vs_one < 0    ? "< 1"
                                                     : c.verdict.rho_vs_one == 0 ? "= 1"
                                                                                 : "> 1");
  if (c.rho) {
    const std::string exact = to_string(*c.rho), approx = to_decimal(*c.rho, options.digits);
    small += "rho = " + exact + (approx == exact ? "" : " ~ " + approx);
  } else if (c.has_full_evidence) {
    small += compare + ", rho ~ " + double_text(c.rho_approx, options.digits) + " (irrational; double precision)";
  } else {
    small += compare;
  }
  return small;
}

/// One line per real root of f: its certified decimal, its exact value, its multiplicities.
std::string root_lines(const Classification& c, const relpos::io::RenderOptions& options) {
  std::string t;
  const auto approx = root_decimals(c, options.digits, /*only_multiple=*/false);
  std::size_t width = 0;
  for (const auto& a : approx) width = std::max(width, a.size());
  for (std::size_t i = 0; i < c.roots.size(); ++i) {
    const auto& r = c.roots[i];
    std::string row = "  l = " + approx[i] + std::string(width - approx[i].size(), ' ');
    if (r.exact && to_string(*r.exact) != approx[i]) row += "  (exactly " + to_string(*r.exact) + ")";
    row += "  ";
    if (r.multiplicity_f == 1) {
      row += "simple";
      if (r.multiplicity_s > 0) row += "; also a root of s";
    } else {
      row +=
          "multiplicity " + std::to_string(r.multiplicity_f) + " in f, " + std::to_string(r.multiplicity_s) + " in s: ";
      row += r.tangency() ? "tangency (a multiple root of f~)"
                          : "special root of s (not a tangency; simple or absent in f~)";
    }
    t += row + "\n";
  }
  return t;
}

/// The polynomials, their discriminants' signs and the roots of f.
std::string polynomial_lines(const Classification& c, const relpos::io::RenderOptions& options) {
  std::string t;
  if (c.has_full_evidence) {
    t += "f(l) = det(l P + E) = " + polynomial_to_text(c.f.data(), 5) + "\n";
    t += "s(l) = det(l A + M) = " + polynomial_to_text(c.s.data(), 3) + "\n";
  }
  auto sign_text = [](int s) { return s < 0 ? std::string("< 0") : s == 0 ? "= 0" : "> 0"; };
  t += "Disc(f) " + sign_text(c.verdict.sign_disc_f) + ", Disc(f~) " + sign_text(c.verdict.sign_disc_ftilde);
  if (c.has_full_evidence) t += ", deg f~ = " + std::to_string(c.degree_ftilde);
  t += "   (f~ = f / gcd(f, s))\n";
  t += "real roots of f: " + count_text(c.verdict.real_roots, "distinct root", "distinct roots") + " (" +
       std::to_string(c.verdict.negative_roots) + " negative, " + std::to_string(c.verdict.positive_roots) +
       " positive)";
  if (c.has_full_evidence && !c.roots.empty())
    t += ", certified to " + std::to_string(options.digits) + " significant digits:\n" + root_lines(c, options);
  else
    t += "\n";
  t += "non-real roots of f: " + std::to_string(c.verdict.nonreal_roots) + " (with multiplicity)\n";
  return t;
}

}  // namespace

}  // namespace relpos::detail::io

namespace relpos::io {

std::string classification_to_text(const Classification& c, const RenderOptions& options) {
  std::string t;
  auto line = [&](const std::string& label, const std::string& text) {
    t += label;
    if (label.size() < 10) t += std::string(10 - label.size(), ' ');
    t += text + "\n";
  };
  line("position:", to_string(c.verdict.position) + " - " + detail::io::position_meaning(c.verdict.position));
  line("rule:", c.rule_text());
  line("small:", detail::io::smallness_text(c, options));
  line("contact:", contact_of(c.verdict.position) != Contact::None ? "yes" : "no");
  line("stage:", to_string(c.verdict.stage) + " (" + detail::io::stage_meaning(c.verdict.stage) + ")");
  if (c.has_full_evidence) line("proof:", detail::io::certificate_text(c.certificate));
  return t + "\n" + detail::io::polynomial_lines(c, options);
}

}  // namespace relpos::io

namespace relpos::detail::io {

std::string margin_to_text(const Margin& m, const relpos::io::RenderOptions& options) {
  const std::string pad(10, ' ');
  std::string t = "margin:   s* ";
  if (m.hi == 0) return t + "= 0: the ellipsoid's centre lies on the paraboloid (any scaling crosses it)\n";
  const bool rational = m.lo == m.hi;
  t += rational ? "= " + to_string(m.lo) + " exactly" : "~ " + m.value().decimals(options.digits);
  t += ": the factor by which the ellipsoid, scaled about its centre, first touches the paraboloid\n";
  t += pad + "minimal polynomial " + relpos::polynomial_text(m.polynomial) + "\n";
  if (rational) {
    t += pad + "proof: scaled by s* it is tangent (" +
         (m.at.lambda < 0 || m.at.kind == Certificate::Kind::HardTangent ? std::string("TI") : std::string("TE")) +
         " certificate)\n";
  } else {
    t += pad + "in [" + to_string(m.lo) + ", " + to_string(m.hi) + "]\n";
    t += pad + "proof: scaled by lo it is " + (m.below.lambda < 0 ? "I" : "E") +
         " (lambda = " + to_string(m.below.lambda) + "), scaled by hi it is C (two witness points)\n";
  }
  return t;
}

}  // namespace relpos::detail::io
