#include "anysize/exact.hpp"

#include <CGAL/Interval_nt.h>
#include <gmp.h>

#include <cfloat>
#include <cmath>
#include <stdexcept>

#include "algebra/forms.hpp"

namespace relpos::detail::anysize {

Poly trimmed(Poly p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
  return p;
}

Poly derivative(const Poly& p) {
  Poly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * Rational(static_cast<long>(i)));
  return trimmed(std::move(d));
}

namespace {

/// a = q b + r with deg r < deg b.
void divide(const Poly& a, const Poly& b, Poly& q, Poly& r) {
  if (b.empty()) throw std::logic_error("polynomial division by zero");
  r = trimmed(a);
  q.assign(r.size() >= b.size() ? r.size() - b.size() + 1 : 0, Rational(0));
  while (!r.empty() && r.size() >= b.size()) {
    const std::size_t shift = r.size() - b.size();
    const Rational c = r.back() / b.back();
    q[shift] = c;
    for (std::size_t i = 0; i < b.size(); ++i) r[shift + i] -= c * b[i];
    r.pop_back();  // the leading term cancels exactly
    r = trimmed(std::move(r));
  }
  q = trimmed(std::move(q));
}

Poly monic(Poly p) {
  if (p.empty()) return p;
  const Rational lead = p.back();
  for (auto& c : p) c /= lead;
  return p;
}

Poly sub(const Poly& a, const Poly& b) {
  Poly r(std::max(a.size(), b.size()), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] -= b[i];
  return trimmed(std::move(r));
}

int sign_of_rational(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

}  // namespace

/// Sturm sequence of a square-free p: p, p', -rem(...), ...
std::vector<Poly> sturm_sequence(const Poly& p) {
  std::vector<Poly> seq{p, derivative(p)};
  while (seq.back().size() > 1) {
    Poly r = remainder(seq[seq.size() - 2], seq.back());
    if (r.empty()) break;
    for (auto& c : r) c = -c;
    seq.push_back(std::move(r));
  }
  return seq;
}

/// Sign changes of a sequence of signs, zeros dropped.
int variations(const std::vector<int>& signs) {
  int v = 0, last = 0;
  for (int s : signs) {
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

Poly remainder(const Poly& a, const Poly& b) {
  Poly q, r;
  divide(a, b, q, r);
  return r;
}

Poly quotient(const Poly& a, const Poly& b) {
  Poly q, r;
  divide(a, b, q, r);
  return q;
}

Poly monic_gcd(Poly a, Poly b) {
  a = trimmed(std::move(a));
  b = trimmed(std::move(b));
  while (!b.empty()) {
    Poly r = monic(remainder(a, b));
    a = std::move(b);
    b = std::move(r);
  }
  return monic(std::move(a));
}

std::vector<Poly> square_free_decomposition(const Poly& p) {
  // Yun's algorithm over Q (characteristic 0).
  std::vector<Poly> out;
  const Poly dp = derivative(p);
  Poly a = monic_gcd(p, dp);
  Poly b = quotient(p, a), c = quotient(dp, a);
  Poly d = sub(c, derivative(b));
  while (b.size() > 1) {
    Poly g = monic_gcd(b, d);
    out.push_back(g);
    b = quotient(b, g);
    c = quotient(d, g);
    d = sub(c, derivative(b));
  }
  while (!out.empty() && out.back().size() <= 1) out.pop_back();
  return out;
}

int LambdaS::sign(const QuadraticReal& x) const {
  const int sa = sign_of_rational(x.a), sb = d == 0 ? 0 : sign_of_rational(x.b);
  if (sb == 0) return sa;
  if (sa == 0) return sb;
  if (sa == sb) return sa;
  return sa * sign_of_rational(x.a * x.a - x.b * x.b * Rational(d));
}

QuadraticReal LambdaS::add(const QuadraticReal& x, const QuadraticReal& y) const { return {x.a + y.a, x.b + y.b}; }
QuadraticReal LambdaS::sub(const QuadraticReal& x, const QuadraticReal& y) const { return {x.a - y.a, x.b - y.b}; }
QuadraticReal LambdaS::mul(const QuadraticReal& x, const QuadraticReal& y) const {
  return {x.a * y.a + x.b * y.b * Rational(d), x.a * y.b + x.b * y.a};
}
QuadraticReal LambdaS::div(const QuadraticReal& x, const QuadraticReal& y) const {
  const Rational n = y.a * y.a - y.b * y.b * Rational(d);  // non-zero for y != 0 (d not a square)
  const QuadraticReal c = mul(x, {y.a, -y.b});
  return {c.a / n, c.b / n};
}

QuadraticReal LambdaS::at(const Poly& p) const {
  QuadraticReal acc{Rational(0), Rational(0)};
  for (std::size_t i = p.size(); i-- > 0;) acc = add(mul(acc, value()), {p[i], Rational(0)});
  return acc;
}

int LambdaS::compare(const Rational& q) const {
  const std::pair<double, double> x = forms::tight_interval(q);  // certified: decided without rationals
  if (x.second < lo) return -1;
  if (x.first > hi) return 1;
  const QuadraticReal& v = value();
  return sign({q - v.a, -v.b});
}

void LambdaS::settle() const {
  Rational a;  // fresh: written in place (value_.a may share its value with a copy's)
  mpq_div(a.mpq(), pending_->num.mpq(), pending_->den.mpq());
  mpq_neg(a.mpq(), a.mpq());
  value_.a = a;
  pending_.reset();
}

namespace {

/// Whether n 2^max(-k, 0) = m d 2^max(k, 0) modulo p = 2^31 - 1 (necessary for equality).
bool equal_modulo_mersenne_31(mpz_srcptr n, mpz_srcptr d, long long m, long k) {
  using U = unsigned long long;  // residues below 2^31: their products fit
  constexpr U p = (U{1} << 31) - 1;
  auto two_to = [](long j) { return U{1} << (j % 31); };  // 2^j mod p, as 2^31 = 1
  const U mm = m >= 0 ? static_cast<U>(m) % p : (p - static_cast<U>(-m) % p) % p;
  const U lhs = mpz_fdiv_ui(n, p) * two_to(k < 0 ? -k : 0) % p;  // fdiv: a residue in [0, p)
  const U rhs = mm * mpz_fdiv_ui(d, p) % p * two_to(k > 0 ? k : 0) % p;
  return lhs == rhs;
}

}  // namespace

std::pair<double, double> tight_interval_of_quotient(mpz_srcptr n, mpz_srcptr d) {
  // n / d as it is: mpq_get_d truncates the value, whatever fraction represents it (read only).
  const __mpq_struct q{*n, *d};
  const double t = mpq_get_d(&q);
  std::pair<double, double> out;
  if (!(std::fabs(t) >= DBL_MIN && std::fabs(t) < DBL_MAX)) {  // 0, subnormal, huge: reduced, the general way
    Rational r;                                                // fresh: written in place
    mpz_set(mpq_numref(r.mpq()), n);
    mpz_set(mpq_denref(r.mpq()), d);
    mpq_canonicalize(r.mpq());
    out = forms::tight_interval(r);
  } else {
    // n / d is the double t = m 2^k (m an integer) iff n 2^max(-k, 0) = m d 2^max(k, 0): first
    // modulo the prime 2^31 - 1 (no allocation; a difference there decides), then exactly.
    int e = 0;
    const double m = std::ldexp(std::frexp(t, &e), 53);
    const long k = static_cast<long>(e) - 53;
    if (!equal_modulo_mersenne_31(n, d, static_cast<long long>(m), k)) {
      const double away = std::nextafter(t, t < 0 ? -HUGE_VAL : HUGE_VAL);
      return t < 0 ? std::make_pair(away, t) : std::make_pair(t, away);
    }
    mpz_t lhs, rhs;
    mpz_init(lhs);
    mpz_init(rhs);
    mpz_mul_2exp(lhs, n, static_cast<mp_bitcnt_t>(k < 0 ? -k : 0));
    mpz_set_d(rhs, m);
    mpz_mul(rhs, rhs, d);
    mpz_mul_2exp(rhs, rhs, static_cast<mp_bitcnt_t>(k > 0 ? k : 0));
    if (mpz_cmp(lhs, rhs) == 0) {
      out = {t, t};
    } else {
      const double away = std::nextafter(t, t < 0 ? -HUGE_VAL : HUGE_VAL);
      out = t < 0 ? std::make_pair(away, t) : std::make_pair(t, away);
    }
    mpz_clear(lhs);
    mpz_clear(rhs);
  }
  return out;
}

namespace {

/// The enclosure of lambda_s = a + b sqrt(d) for compare(): interval arithmetic on certified
/// enclosures of a (forms::tight_interval(a), given), b and d (infinite bounds, hence no filtering,
/// beyond the double range).
void enclose(LambdaS& out, const QuadraticReal& value, std::pair<double, double> a) {
  using I = CGAL::Interval_nt<false>;
  const bool irrational = out.d != 0;
  const std::pair<double, double> b = irrational ? forms::tight_interval(value.b) : std::make_pair(0.0, 0.0);
  const std::pair<double, double> d = irrational ? CGAL::to_interval(out.d) : std::make_pair(0.0, 0.0);
  CGAL::Protect_FPU_rounding<true> guard;
  const I v = I(a) + (irrational ? I(b) * CGAL::sqrt(I(d)) : I(0));
  if (std::isfinite(v.inf()) && std::isfinite(v.sup())) {
    out.lo = v.inf();
    out.hi = v.sup();
  }
}

}  // namespace

LambdaS lambda_s_of(const Poly& s) {
  if (s.size() != 3 || !(s[2] > 0)) throw std::logic_error("s must be a quadratic with positive leading coefficient");
  // disc = s1^2 - 4 s2 s0 in lowest terms, from the integer form S = L s (L the lcm of the
  // denominators): disc = (S1^2 - 4 S2 S0) / L^2, reduced once (forms::divided_by_power) instead
  // of a canonicalization per rational operation.
  Integer l(1), num, g;  // fresh objects: written through mpz()
  forms::lcm_of_denominators(s.begin(), s.end(), l);
  Integer si[3];
  for (std::size_t i = 0; i < 3; ++i) forms::scaled_numerator(s[i], l, si[i].mpz());
  mpz_mul(num.mpz(), si[1].mpz(), si[1].mpz());
  mpz_mul(g.mpz(), si[2].mpz(), si[0].mpz());
  mpz_submul_ui(num.mpz(), g.mpz(), 4);
  return lambda_s_of(s, forms::divided_by_power(num, forms::split_scale(l), 2));
}

LambdaS LambdaS::blank() {
  thread_local const LambdaS prototype;
  return prototype;
}

LambdaS lambda_s_of(const Poly& s, const Rational& disc) {
  if (s.size() != 3 || !(s[2] > 0)) throw std::logic_error("s must be a quadratic with positive leading coefficient");
  if (disc < 0) throw std::logic_error("s has non-real roots");
  // d = 0 and value = 0 + 0 sqrt(d); each number written in place below is made fresh first.
  LambdaS out = LambdaS::blank();
  // disc = N / Den in lowest terms: sqrt(disc) = sqrt(N Den) / Den, rational iff N Den is a perfect
  // square.
  const mpz_srcptr den = mpq_denref(disc.mpq());
  std::pair<double, double> a_interval;
  mpz_t nd, tn, td;
  mpz_init(nd);
  mpz_init(tn);
  mpz_init(td);
  mpz_mul(nd, mpq_numref(disc.mpq()), den);
  Rational two_s2;  // fresh: written in place
  mpq_mul_2exp(two_s2.mpq(), s[2].mpq(), 1);
  if (mpz_perfect_square_p(nd)) {  // lambda_s = (-s1 + r / Den) / (2 s2)
    Rational t;                    // fresh: written in place
    mpz_sqrt(mpq_numref(t.mpq()), nd);
    mpz_set(mpq_denref(t.mpq()), den);
    mpq_canonicalize(t.mpq());
    mpq_sub(t.mpq(), t.mpq(), s[1].mpq());
    out.value_.a = Rational();
    mpq_div(out.value_.a.mpq(), t.mpq(), two_s2.mpq());
    a_interval = forms::tight_interval(out.value_.a);
  } else {  // lambda_s = -s1 / (2 s2) + sqrt(N Den) / (Den 2 s2)
    out.d = Integer();
    mpz_swap(out.d.mpz(), nd);
    // b = D2 / (Den N2) for 2 s2 = N2 / D2 (lowest terms, N2 > 0): in lowest terms after dividing
    // out g = gcd(Den, D2) alone, as gcd(D2, N2) = 1. One gcd of two denominators (powers of two
    // for doubles), where a rational product and inverse take two and reduce twice.
    out.value_.b = Rational();
    const mpz_ptr bn = mpq_numref(out.value_.b.mpq()), bd = mpq_denref(out.value_.b.mpq());
    const mpz_srcptr n2 = mpq_numref(two_s2.mpq()), d2 = mpq_denref(two_s2.mpq());
    mpz_gcd(tn, den, d2);
    mpz_divexact(bn, d2, tn);
    mpz_divexact(bd, den, tn);
    mpz_mul(bd, bd, n2);
    // a = -s1 / (2 s2) = -(n1 D2) / (d1 N2), reduced on first use (value()): its enclosure from
    // that fraction as it is.
    mpz_mul(tn, mpq_numref(s[1].mpq()), d2);
    mpz_neg(tn, tn);
    mpz_mul(td, mpq_denref(s[1].mpq()), n2);
    a_interval = tight_interval_of_quotient(tn, td);
    out.pending_ = LambdaS::Pending{s[1], two_s2};
  }
  mpz_clear(nd);
  mpz_clear(tn);
  mpz_clear(td);
  enclose(out, out.value_, a_interval);
  return out;
}

LambdaS rational_lambda_s(const Rational& value) {
  LambdaS out = LambdaS::blank();  // d = 0 and b = 0
  out.value_.a = value;
  enclose(out, out.value_, forms::tight_interval(value));
  return out;
}

AnySizeFacts any_size_facts(const Poly& f, const Poly& s) {
  AnySizeFacts x;
  const LambdaS ls = lambda_s_of(s);
  x.multiplicity_s = (s[1] * s[1] - 4 * s[2] * s[0]) == 0 ? 2 : 1;
  const std::vector<Poly> factors = square_free_decomposition(f);
  for (std::size_t k = 0; k < factors.size(); ++k) {
    Poly g = factors[k];
    if (g.size() <= 1) continue;
    const int mult = static_cast<int>(k) + 1;
    // Divide out lambda_s (and its conjugate when irrational) so the Sturm count at lambda_s needs
    // no convention for a root at the endpoint.
    if (ls.sign(ls.at(g)) == 0) {
      x.multiplicity_at_lambda_s = mult;
      g = quotient(g, ls.rational() ? Poly{-ls.value().a, Rational(1)} : monic(s));
    }
    if (g.size() <= 1) continue;
    const std::vector<Poly> seq = sturm_sequence(g);
    std::vector<int> at_ls, at_zero, at_inf;
    for (const Poly& q : seq) {
      at_ls.push_back(ls.sign(ls.at(q)));
      at_zero.push_back(sign_of_rational(q[0]));
      at_inf.push_back(sign_of_rational(q.back()));
    }
    const int positive = variations(at_zero) - variations(at_inf);
    const int gap = variations(at_ls) - variations(at_zero);
    (mult % 2 ? x.odd_positive : x.even_positive) += positive;
    (mult % 2 ? x.odd_gap : x.even_gap) += gap;
  }
  if (x.odd_positive > 0) {
    x.rule = 1;
  } else if (x.even_positive > 0) {
    x.rule = 2;
  } else if (x.odd_gap > 0) {
    x.rule = 3;
  } else if (x.even_gap > 0) {
    x.rule = 4;
  } else if (x.multiplicity_at_lambda_s > x.multiplicity_s) {
    x.rule = 4;
    x.hard = true;
  } else {
    x.rule = 5;
  }
  return x;
}

}  // namespace relpos::detail::anysize
