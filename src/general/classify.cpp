// The entry points of a general pair (include/relpos/general_classify.hpp): the filter, then the
// exact stage (math.md §17); the evidence and the certificate (math.md §18).
#include <stdexcept>

#include "general/certificate.hpp"
#include "general/exact.hpp"
#include "general/filter.hpp"
#include "general/integer_pencil.hpp"
#include "relpos/general_classify.hpp"

namespace relpos {

std::string to_string(QuadricStage s) {
  switch (s) {
    case QuadricStage::Filter:
      return "filter";
    case QuadricStage::Exact:
      return "exact";
  }
  return "unknown";
}

std::string describe(QuadricRule r) {
  switch (r) {
    case QuadricRule::OddRootAboveLo:
      return "f has a root of odd multiplicity above t_lo: q > 0 on the ellipsoid";
    case QuadricRule::EvenRootAboveLo:
      return "f has roots above t_lo, each of even multiplicity: min q = 0, a tangency";
    case QuadricRule::EndpointLo:
      return "f~ = f / gcd(f, D) vanishes at t_lo: min q = 0, a tangency in the hard case";
    case QuadricRule::OddRootBelowHi:
      return "f has a root of odd multiplicity below t_hi: q < 0 on the ellipsoid";
    case QuadricRule::EvenRootBelowHi:
      return "f has roots below t_hi, each of even multiplicity: max q = 0, a tangency";
    case QuadricRule::EndpointHi:
      return "f~ vanishes at t_hi: max q = 0, a tangency in the hard case";
    case QuadricRule::OddRootInner:
      return "f has a root of odd multiplicity in (r3, 0): e < 0 on the quadric's solid";
    case QuadricRule::EvenRootInner:
      return "f has roots in (r3, 0), each of even multiplicity: max e over the quadric's solid = 0";
    case QuadricRule::EndpointInner:
      return "f~ vanishes at r3: max e over the quadric's solid = 0, in the hard case";
    case QuadricRule::Equal:
      return "max q over the ellipsoid and max e over the quadric are both 0: the same ellipsoid";
    case QuadricRule::NoRoot:
      return "no root of f beyond the ends of the multipliers' intervals: the surfaces cross";
  }
  return "unknown rule";
}

QuadricVerdict decide_position_exact(const Ellipsoid& e, const Quadric& q) {
  const detail::general::IntegerPencil p = detail::general::integer_pencil(e.matrix(), q.matrix());
  QuadricVerdict v = detail::general::decide(detail::general::exact_facts(p, q.type() == QuadricType::Ellipsoid));
  v.type = q.type();
  v.stage = QuadricStage::Exact;
  return v;
}

QuadricVerdict decide_position(const Ellipsoid& e, const Quadric& q) {
  if (const std::optional<QuadricVerdict> v = detail::general::filtered_decision(e, q)) return *v;
  return decide_position_exact(e, q);
}

QuadricClassification classify(const Ellipsoid& e, const Quadric& q) {
  const QuadricVerdict decided = decide_position(e, q);
  const detail::general::IntegerPencil p = detail::general::integer_pencil(e.matrix(), q.matrix());
  const detail::general::ExactEvidence ev = detail::general::exact_evidence(p, q.type() == QuadricType::Ellipsoid);
  if (ev.verdict.position != decided.position)
    throw std::logic_error("relpos internal error: the filter and the exact stage disagree (" +
                           to_string(decided.position) + " / " + to_string(ev.verdict.position) + ")");
  QuadricClassification c;
  c.verdict = decided;
  c.verdict.rule = ev.verdict.rule;
  struct View {
    const Matrix4& m;
    const Rational& operator()(int i, int j) const { return m(i, j); }
  };
  const Quartic<Rational> f = detail::general::pencil_quartic<Rational>(View{e.matrix()}, View{q.matrix()});
  const detail::general::Cubic<Rational> d =
      detail::general::pencil_cubic<Rational>(View{e.matrix()}, View{q.matrix()});
  for (std::size_t i = 0; i < 5; ++i) c.f[i] = f[i];
  for (std::size_t i = 0; i < 4; ++i) c.d[i] = d[i];
  for (PencilRoot r : ev.roots) {
    r.lower *= p.scale;
    r.upper *= p.scale;
    if (r.exact) *r.exact *= p.scale;
    c.roots.push_back(r);
  }
  c.certificate = detail::general::build_certificate(e.matrix(), q.matrix(), ev, p.scale);
  return c;
}

}  // namespace relpos
