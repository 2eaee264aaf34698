// The second, independent method of math.md §8 (for tests): the position of an ellipsoid and an
// elliptic paraboloid of ANY size from the secular polynomial, in exact rational arithmetic only.
//
// Everything here is written from scratch (polynomials over Q as coefficient vectors, Euclid's gcd, Sturm
// sequences, evaluation in Q(sqrt d)); nothing of relpos is used but the Matrix4 / Ellipsoid / Paraboloid
// types and the number types. In particular none of relpos's pencil, Sturm, roots or classification code.
//
// With the sign-normalized matrices E = [[M, m], [m^T, e0]] and P = [[A, a], [a^T, p0]], in t = 1/lambda:
//   F(t) = det(P + tE)          (= t^4 f(1/t), a quartic; F(0) = det P < 0)
//   D(t) = det(A + tM)          (= t^3 s(1/t), a cubic with roots 0 and 1/(roots of s))
//   R(t) = F(t)/D(t) = p(x(t)) + t e(x(t)),  x(t) = -(A + tM)^-1 (a + tm)   (Schur complement)
//   S(t) = F'D - FD'            (degree 6; S = D^2 R' = D^2 e(x(t)))
// min over the solid ellipsoid of p = max_{t>0} R(t), reached at the unique root t+ of S in (0, inf), where
// D > 0: sign min p = sign F(t+). max p = inf_{t<tau} R(t), tau = the smallest root of D (A + tM < 0 for
// t < tau, D < 0 there): a root t- of S in the OPEN interval (-inf, tau) gives sign max p = -sign F(t-);
// none is the hard case, max p = lim_{t->tau} R = Ft(tau)/Dt(tau) with Ft/Dt = F/D reduced by gcd(F, D).
// E <=> min p > 0, TE <=> min p = 0, I <=> max p < 0, TI <=> max p = 0, C otherwise.
#pragma once

#include <cstddef>
#include <relpos/classify.hpp>
#include <relpos/numbers.hpp>
#include <relpos/quadric.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace relpos::testing {

namespace secular_detail {

/// Coefficient i is that of t^i; no trailing zeros (the zero polynomial is empty).
using Poly = std::vector<Rational>;

inline int sign(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

inline Poly trimmed(Poly p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
  return p;
}

inline int degree(const Poly& p) { return static_cast<int>(p.size()) - 1; }

inline Poly add(const Poly& a, const Poly& b) {
  Poly out(std::max(a.size(), b.size()), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) out[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) out[i] += b[i];
  return trimmed(out);
}

inline Poly scale(const Poly& a, const Rational& k) {
  Poly out(a);
  for (auto& c : out) c *= k;
  return trimmed(out);
}

inline Poly sub(const Poly& a, const Poly& b) { return add(a, scale(b, Rational(-1))); }

inline Poly mul(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty()) return {};
  Poly out(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return trimmed(out);
}

inline Poly derivative(const Poly& a) {
  Poly out;
  for (std::size_t i = 1; i < a.size(); ++i) out.push_back(Rational(static_cast<long>(i)) * a[i]);
  return trimmed(out);
}

/// Quotient and remainder of a by b != 0 over Q.
inline std::pair<Poly, Poly> divmod(Poly a, const Poly& b) {
  if (b.empty()) throw std::logic_error("secular: division by the zero polynomial");
  a = trimmed(a);
  if (a.size() < b.size()) return {Poly{}, a};
  Poly q(a.size() - b.size() + 1, Rational(0));
  while (!a.empty() && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const Rational c = a.back() / b.back();
    q[shift] = c;
    for (std::size_t i = 0; i < b.size(); ++i) a[shift + i] -= c * b[i];
    a.back() = Rational(0);  // exactly cancelled
    a = trimmed(a);
  }
  return {trimmed(q), a};
}

inline Poly monic(const Poly& a) { return a.empty() ? a : scale(a, Rational(1) / a.back()); }

inline Poly gcd(Poly a, Poly b) {
  a = trimmed(a);
  b = trimmed(b);
  while (!b.empty()) {
    Poly r = divmod(a, b).second;
    a = std::move(b);
    b = std::move(r);
  }
  return monic(a);
}

/// a / b when b divides a (checked).
inline Poly exact_quotient(const Poly& a, const Poly& b) {
  auto qr = divmod(a, b);
  if (!qr.second.empty()) throw std::logic_error("secular: inexact polynomial division");
  return qr.first;
}

inline Poly square_free(const Poly& a) { return exact_quotient(a, gcd(a, derivative(a))); }

// ---- determinants of matrices of polynomials (Leibniz formula: independent of any elimination) ----

template <int N>
Poly poly_det(const Poly (&m)[N][N]) {
  int perm[N];
  for (int i = 0; i < N; ++i) perm[i] = i;
  Poly total;
  // Heap-free enumeration of all permutations with their parity (std::next_permutation order).
  for (;;) {
    int inversions = 0;
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j)
        if (perm[i] > perm[j]) ++inversions;
    Poly term{Rational(inversions % 2 ? -1 : 1)};
    for (int i = 0; i < N && !term.empty(); ++i) term = mul(term, m[i][perm[i]]);
    total = add(total, term);
    int k = N - 2;
    while (k >= 0 && perm[k] > perm[k + 1]) --k;
    if (k < 0) break;
    int l = N - 1;
    while (perm[l] < perm[k]) --l;
    std::swap(perm[k], perm[l]);
    for (int i = k + 1, j = N - 1; i < j; ++i, --j) std::swap(perm[i], perm[j]);
  }
  return total;
}

// ---- numbers u + v sqrt(d) of Q(sqrt d), d >= 0 fixed ----

struct Quad {
  Rational u, v;
};

struct Field {
  Rational d;
  Quad add(const Quad& x, const Quad& y) const { return {x.u + y.u, x.v + y.v}; }
  Quad mul(const Quad& x, const Quad& y) const { return {x.u * y.u + x.v * y.v * d, x.u * y.v + x.v * y.u}; }
  Quad mid(const Quad& x, const Quad& y) const { return {(x.u + y.u) / 2, (x.v + y.v) / 2}; }
  int sign(const Quad& x) const {
    const int su = secular_detail::sign(x.u), sv = d == 0 ? 0 : secular_detail::sign(x.v);
    if (sv == 0) return su;
    if (su == 0 || su == sv) return sv;
    // opposite signs: compare u^2 with v^2 d
    return su * secular_detail::sign(x.u * x.u - x.v * x.v * d);
  }
  Quad eval(const Poly& p, const Quad& x) const {
    Quad v{Rational(0), Rational(0)};
    for (std::size_t i = p.size(); i-- > 0;) v = add(mul(v, x), Quad{p[i], Rational(0)});
    return v;
  }
  int sign_at(const Poly& p, const Quad& x) const { return sign(eval(p, x)); }
};

/// Sturm sequence of a square-free polynomial: p, p', -rem, ...
struct Sturm {
  std::vector<Poly> seq;
  explicit Sturm(const Poly& p) {
    if (p.empty()) return;
    seq.push_back(p);
    Poly d = derivative(p);
    while (!d.empty()) {
      seq.push_back(d);
      Poly r = scale(divmod(seq[seq.size() - 2], seq.back()).second, Rational(-1));
      d = std::move(r);
    }
  }
  int variations(const Field& k, const Quad& x) const {
    int v = 0, last = 0;
    for (const auto& q : seq) {
      const int s = k.sign_at(q, x);
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    return v;
  }
  /// Distinct roots in the open interval (lo, hi), lo < hi (either may be a root).
  int count_open(const Field& k, const Quad& lo, const Quad& hi) const {
    if (seq.empty()) return 0;
    return variations(k, lo) - variations(k, hi) - (k.sign_at(seq[0], hi) == 0 ? 1 : 0);
  }
};

/// 1 + max |c_i / c_n|: every real root lies in (-bound, bound).
inline Rational cauchy_bound(const Poly& p) {
  Rational m(0);
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    Rational r = p[i] / p.back();
    if (r < 0) r = -r;
    if (r > m) m = r;
  }
  return m + 1;
}

/// The sign of F at the only root theta of the square-free s in the open interval (lo, hi).
inline int sign_at_unique_root(const Field& k, const Poly& s, const Poly& f, Quad lo, Quad hi) {
  const Sturm ss(s);
  if (ss.count_open(k, lo, hi) != 1) throw std::logic_error("secular: interval does not isolate one root");
  const Poly g = gcd(s, f);
  if (degree(g) >= 1 && Sturm(g).count_open(k, lo, hi) == 1) return 0;  // theta is a root of F
  const Sturm fs(square_free(f));
  for (int iter = 0; iter < 100000; ++iter) {
    const Quad m = k.mid(lo, hi);
    if (fs.count_open(k, lo, hi) == 0) return k.sign_at(f, m);  // F has constant sign on (lo, hi)
    if (k.sign_at(s, m) == 0) return k.sign_at(f, m);           // m is theta
    if (ss.count_open(k, lo, m) == 1)
      hi = m;
    else
      lo = m;
  }
  throw std::logic_error("secular: bisection did not separate the roots");
}

}  // namespace secular_detail

/// The three polynomials in t of the header comment, for the sign-normalized matrices of e and p.
struct SecularPolynomials {
  secular_detail::Poly F, D, S;
};

inline SecularPolynomials secular_polynomials(const Ellipsoid& e, const Paraboloid& p) {
  using namespace secular_detail;
  const Matrix4 &em = e.matrix(), &pm = p.matrix();
  Poly pe[4][4], am[3][3];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) pe[i][j] = trimmed(Poly{pm(i, j), em(i, j)});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) am[i][j] = pe[i][j];
  SecularPolynomials out;
  out.F = poly_det<4>(pe);
  out.D = poly_det<3>(am);
  out.S = sub(mul(derivative(out.F), out.D), mul(out.F, derivative(out.D)));
  return out;
}

/// Signs of min and max of p(x) = X^T P X over the solid ellipsoid (first = min, second = max), by the
/// secular method. Throws std::logic_error when a structural claim of math.md §8 fails (a finding).
/// *hard_case (if given) tells whether the max side was the hard case (no root of S in (-inf, tau)).
inline std::pair<int, int> secular_extreme_signs(const Ellipsoid& e, const Paraboloid& p, bool* hard_case = nullptr) {
  using namespace secular_detail;
  const SecularPolynomials sp = secular_polynomials(e, p);
  const Poly &F = sp.F, &D = sp.D, &S = sp.S;
  if (degree(F) != 4 || degree(D) != 3 || degree(S) != 6 || D[0] != 0)
    throw std::logic_error("secular: unexpected degrees (not an ellipsoid and a paraboloid?)");
  const Poly ssf = square_free(S);
  Rational bound = cauchy_bound(ssf);
  if (cauchy_bound(D) > bound) bound = cauchy_bound(D);
  const Rational zero(0);

  // tau = smaller root of D(t)/t = D3 t^2 + D2 t + D1 (D3 = det M > 0).
  const Rational &d1 = D[1], &d2 = D[2], &d3 = D[3];
  const Field k{d2 * d2 - 4 * d3 * d1};
  if (k.d < 0 || d3 <= 0) throw std::logic_error("secular: D/t has no real roots or det M <= 0");
  const Quad tau{-d2 / (2 * d3), Rational(-1) / (2 * d3)};
  if (k.sign(tau) >= 0) throw std::logic_error("secular: tau is not negative");

  // Min side: exactly one root of S in (0, inf); D > 0 there.
  const Sturm ss(ssf);
  const Quad q0{zero, zero}, qhi{bound, zero}, qlo{-bound, zero};
  if (ss.count_open(k, q0, qhi) != 1) throw std::logic_error("secular: S has not exactly one root in (0, inf)");
  const int smin = sign_at_unique_root(k, ssf, F, q0, qhi);

  // Max side: at most one root of S in the open interval (-inf, tau); D < 0 there.
  const int n = ss.count_open(k, qlo, tau);
  if (n > 1) throw std::logic_error("secular: S has several roots in (-inf, tau)");
  int smax = 0;
  if (hard_case) *hard_case = n == 0;
  if (n == 1) {
    smax = -sign_at_unique_root(k, ssf, F, qlo, tau);
  } else {  // hard case: the limit of F/D at tau after cancelling gcd(F, D)
    const Poly g = gcd(F, D);
    const Poly ft = exact_quotient(F, g), dt = exact_quotient(D, g);
    const int sd = k.sign_at(dt, tau);
    if (sd == 0) throw std::logic_error("secular: hard case with an infinite limit at tau");
    smax = k.sign_at(ft, tau) * sd;
  }
  return {smin, smax};
}

inline Position position_from_extreme_signs(int smin, int smax) {
  if (smin > 0) return Position::E;
  if (smin == 0) return Position::TE;
  if (smax < 0) return Position::I;
  if (smax == 0) return Position::TI;
  return Position::C;
}

/// The relative position by the secular method (math.md §8, second method): I, TI, C, TE or E.
inline Position secular_position(const Ellipsoid& e, const Paraboloid& p) {
  const auto s = secular_extreme_signs(e, p);
  return position_from_extreme_signs(s.first, s.second);
}

}  // namespace relpos::testing
