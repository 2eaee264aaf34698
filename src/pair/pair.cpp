#include "pair/pair.hpp"

#include <CGAL/Interval_nt.h>
#include <gmp.h>

#include "algebra/decimal_recipe.hpp"

namespace relpos::detail {
namespace {

/// The entries of a quadric as intervals, without building its rationals when it has doubles or
/// stored enclosures (scaled by a power of two; rounding towards +inf).
template <class Q>
forms::MatrixOf<forms::Interval> interval_entries(const Q& q) {
  if (const std::optional<DoubleMatrix4> d = q.doubles()) return forms::to_intervals(*d);
  if (storage_of(q).enclosure()) return forms::to_intervals(*storage_of(q).enclosure());
  return forms::to_intervals(q.matrix());
}

/// The stored enclosures of a quadric read from text, degenerate ones of a matrix of doubles, else
/// certified ones of its rationals (for a pair of which one quadric was read from text).
template <class Q>
EnclosureMatrix4 enclosure_of(const Q& q) {
  if (storage_of(q).enclosure()) return *storage_of(q).enclosure();
  EnclosureMatrix4 out;
  if (const std::optional<DoubleMatrix4> d = q.doubles()) {
    out.lo = out.hi = *d;
    return out;
  }
  const Matrix4& m = q.matrix();
  for (std::size_t i = 0; i < 16; ++i) {
    const std::pair<double, double> b = CGAL::to_interval(m.a[i]);
    out.lo[i] = b.first;
    out.hi[i] = b.second;
  }
  return out;
}

/// The entries as doubles (CGAL::to_double, truncated) for the searches: the quadric's own doubles,
/// else those its recipe gives from the numbers read (a decimal sphere or axis paraboloid),
/// without building its rationals, else from the rationals.
template <class Q>
DoubleMatrix4 search_doubles(const Q& q) {
  if (const std::optional<DoubleMatrix4> d = q.doubles()) return *d;
  if (const DecimalRecipe* recipe = storage_of(q).recipe()) {
    DoubleMatrix4 out;
    if (truncated_doubles(*recipe, out)) return out;
  }
  DoubleMatrix4 out;
  const Matrix4& m = q.matrix();
  for (std::size_t i = 0; i < 16; ++i) out[i] = forms::truncated_double(m.a[i]);
  return out;
}

/// forms::integer_form of a quadric's matrix, from its doubles when it has them (no rational matrix).
template <class Q>
forms::MatrixOf<Integer> integer_form_of_quadric(const Q& q, Integer& l) {
  if (const std::optional<DoubleMatrix4> d = q.doubles()) return forms::integer_form(*d, l);
  return forms::integer_form(q.matrix(), l);
}

}  // namespace

const IntervalEntries& PairContext::intervals() const {
  Cold& c = cold();
  if (!c.intervals) c.intervals.emplace(IntervalEntries{interval_entries(p_), interval_entries(e_)});
  return *c.intervals;
}

const Enclosures& PairContext::enclosures() const {
  Cold& c = cold();
  if (!c.enclosures) c.enclosures.emplace(Enclosures{enclosure_of(p_), enclosure_of(e_)});
  return *c.enclosures;
}

const CompactPencil& PairContext::compact() const {
  Cold& c = cold();
  if (!c.compact) c.compact.emplace(p_.matrix(), e_.matrix());
  return *c.compact;
}

const EvidencePencil& PairContext::evidence() const {
  Cold& c = cold();
  if (!c.evidence) {
    c.scratch.emplace();
    c.evidence.emplace(e_, p_, c.certificate_reads_forms, **c.scratch);
  }
  return *c.evidence;
}

const RootStructure& PairContext::roots() const {
  Cold& c = cold();
  if (!c.roots) c.roots.emplace(exact_root_structure(f_multiple(), s_multiple(), c.sign_disc_f));
  return *c.roots;
}

void PairContext::move_evidence(Quartic<Rational>& f, Quadratic<Rational>& s, RootStructure& roots) {
  evidence();
  Cold& c = cold();
  for (std::size_t i = 0; i < 5; ++i) swap(f[i], c.evidence->f[i]);
  for (std::size_t i = 0; i < 3; ++i) swap(s[i], c.evidence->s[i]);
  this->roots();
  roots = std::move(*c.roots);
  c.roots.reset();
}

DoubleMatrix4 PairContext::e_search_doubles() const { return search_doubles(e_); }
DoubleMatrix4 PairContext::p_search_doubles() const { return search_doubles(p_); }

const IntegerForms& PairContext::integer_forms() const {
  Cold& c = cold();
  if (!c.forms) {
    c.forms.emplace();
    if (c.evidence && c.evidence->forms_written) {
      const EvidenceScratch& ws = **c.scratch;
      for (std::size_t i = 0; i < 16; ++i) {
        mpz_set(c.forms->ez.a[i].mpz(), ws.ez.a[i].mpz());  // fresh entries: written in place
        mpz_set(c.forms->pz.a[i].mpz(), ws.pz.a[i].mpz());
      }
      c.forms->le = ws.le;
      c.forms->lp = ws.lp;
    } else {
      c.forms->ez = integer_form_of_quadric(e_, c.forms->le);
      c.forms->pz = integer_form_of_quadric(p_, c.forms->lp);
    }
  }
  return *c.forms;
}

const PointForm& PairContext::e_point_form() const {
  Cold& c = cold();
  if (!c.e_point) {
    // The same form whichever source: the evidence's pooled integers, the doubles' bits (when the
    // integer forms with their scales are not built), or those forms.
    std::optional<DoubleMatrix4> d;
    if (c.evidence && c.evidence->forms_written) {
      c.e_point.emplace((*c.scratch)->ez);
      c.p_point.emplace((*c.scratch)->pz);
    } else if (!c.forms && (d = e_.doubles()) && p_.doubles()) {
      c.e_point.emplace(*d);
      c.p_point.emplace(*p_.doubles());
    } else {
      c.e_point.emplace(integer_forms().ez);
      c.p_point.emplace(integer_forms().pz);
    }
  }
  return *c.e_point;
}

const PointForm& PairContext::p_point_form() const {
  e_point_form();  // built together
  return *cold().p_point;
}

const anysize::Poly& PairContext::f_poly() const {
  Cold& c = cold();
  if (!c.f_poly) c.f_poly = anysize::to_poly(evidence().f.data(), 5);
  return *c.f_poly;
}

const anysize::Poly& PairContext::s_poly() const {
  Cold& c = cold();
  if (!c.s_poly) c.s_poly = anysize::to_poly(evidence().s.data(), 3);
  return *c.s_poly;
}

const IntegerPoly& PairContext::fz() const {
  Cold& c = cold();
  if (!c.fz) c.fz.emplace(f_poly());
  return *c.fz;
}

int PairContext::f_sign(const Rational& x) const {
  Cold& c = cold();
  if (!c.f_multiple) c.f_multiple.emplace(f_multiple().data(), 5);
  const IntegerPoly& q = *c.f_multiple;
  // At a double (the multipliers between isolating intervals are short dyadics), the roots' sign
  // at doubles: floating-point stages that answer only when certain, then the same exact sign.
  const std::pair<double, double> d = forms::tight_interval(x);
  if (d.first == d.second && q.degree() >= 1 && q.degree() <= 4) {
    if (!c.f_at_doubles) c.f_at_doubles.emplace(q.data(), static_cast<int>(q.degree()));
    return (*c.f_at_doubles)(d.first);
  }
  return q.sign(x);
}

}  // namespace relpos::detail
