#include "margin/descartes.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "algebra/flint_poly.hpp"
#include "algebra/flint_thread.hpp"
#include "algebra/polynomial_sign.hpp"

namespace relpos::detail {
namespace {

/// An owned FLINT polynomial (movable, not copyable).
class ScratchPoly {
 public:
  ScratchPoly() { fmpz_poly_init(p_); }
  ScratchPoly(ScratchPoly&& o) noexcept {
    fmpz_poly_init(p_);
    fmpz_poly_swap(p_, o.p_);
  }
  ScratchPoly& operator=(ScratchPoly&& o) noexcept {
    fmpz_poly_swap(p_, o.p_);
    return *this;
  }
  ScratchPoly(const ScratchPoly&) = delete;
  ScratchPoly& operator=(const ScratchPoly&) = delete;
  ~ScratchPoly() { fmpz_poly_clear(p_); }
  fmpz_poly_struct* get() { return p_; }

 private:
  fmpz_poly_t p_;
};

/// x + y t.
void linear(fmpz_poly_t out, const Integer& x, const Integer& y) {
  fmpz_t c;
  fmpz_init(c);
  fmpz_poly_zero(out);
  fmpz_set_mpz(c, x.mpz());
  fmpz_poly_set_coeff_fmpz(out, 0, c);
  fmpz_set_mpz(c, y.mpz());
  fmpz_poly_set_coeff_fmpz(out, 1, c);
  fmpz_clear(c);
}

/// Sign variations of the coefficients, zeros skipped.
int variations(const fmpz_poly_t q) {
  int count = 0, last = 0;
  for (slong i = 0; i <= fmpz_poly_degree(q); ++i) {
    const int sg = fmpz_sgn(fmpz_poly_get_coeff_ptr(q, i));
    if (sg == 0) continue;
    if (last != 0 && sg != last) ++count;
    last = sg;
  }
  return count;
}

/// Descartes' bound for the roots of q in (0, 1): the variations of (1 + x)^n q(1 / (1 + x)), the
/// reversed polynomial shifted by 1 (`scratch` holds it).
int unit_bound(const fmpz_poly_struct* q, fmpz_poly_struct* scratch) {
  fmpz_t one;
  fmpz_init_set_ui(one, 1);
  fmpz_poly_reverse(scratch, q, fmpz_poly_length(q));
  fmpz_poly_taylor_shift(scratch, scratch, one);
  fmpz_clear(one);
  return variations(scratch);
}

/// q(x) -> 2^n q(x / 2), n = deg q: the left half of (0, 1) mapped onto (0, 1), in integers.
void halve(fmpz_poly_struct* q) {
  const slong n = fmpz_poly_degree(q);
  for (slong i = 0; i < n; ++i) fmpz_mul_2exp(q->coeffs + i, q->coeffs + i, static_cast<ulong>(n - i));
}

}  // namespace

int descartes_bound(const std::vector<Integer>& p, const Rational& a, const Rational& b) {
  flint_thread_cleanup_at_exit();
  std::size_t n = p.size();
  while (n > 0 && p[n - 1] == 0) --n;
  if (n == 0) throw std::logic_error("internal error: descartes_bound: the zero polynomial");
  // With a = a1 / a2, b = b1 / b2 and L = a2 b2: (a + b x) / (1 + x) = U / V, U = a1 b2 + b1 a2 x,
  // V = L (1 + x), and L^deg (1 + x)^deg p(U / V) = sum p_i U^i V^(deg - i) (Horner on U, powers of V).
  const Integer a1 = a.numerator(), a2 = a.denominator(), b1 = b.numerator(), b2 = b.denominator();
  fmpz_poly_t u, v, q, vpow, term;
  fmpz_poly_init(u);
  fmpz_poly_init(v);
  fmpz_poly_init(q);
  fmpz_poly_init(vpow);
  fmpz_poly_init(term);
  linear(u, a1 * b2, b1 * a2);
  const Integer l = a2 * b2;
  linear(v, l, l);
  fmpz_t c;
  fmpz_init(c);
  fmpz_set_mpz(c, p[n - 1].mpz());
  fmpz_poly_set_fmpz(q, c);
  fmpz_poly_one(vpow);
  for (std::size_t k = n - 1; k-- > 0;) {  // q = q U + p_k V^(deg - k)
    fmpz_poly_mul(q, q, u);
    fmpz_poly_mul(vpow, vpow, v);
    fmpz_set_mpz(c, p[k].mpz());
    fmpz_poly_scalar_mul_fmpz(term, vpow, c);
    fmpz_poly_add(q, q, term);
  }
  const int count = variations(q);
  fmpz_clear(c);
  fmpz_poly_clear(u);
  fmpz_poly_clear(v);
  fmpz_poly_clear(q);
  fmpz_poly_clear(vpow);
  fmpz_poly_clear(term);
  return count;
}

namespace {

/// An exponent e with every root of p (its first n coefficients, p_(n-1) != 0) below 2^e in
/// absolute value. Fujiwara's bound: every root has |x| <= 2 max_i |p_(n-i) / p_n|^(1/i) (deg n, the
/// last term halved), below 2^e with e = 1 + max_i ceil((B_i - b + 1) / i) for B_i the bits of
/// p_(n-i) and b those of p_n (|p_(n-i)| < 2^B_i, |p_n| >= 2^(b - 1)).
unsigned long fujiwara_exponent(const std::vector<Integer>& p, std::size_t n) {
  const long lead = static_cast<long>(mpz_sizeinbase(p[n - 1].mpz(), 2));
  long top = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const Integer& c = p[n - 1 - i];
    if (c == 0) continue;
    const long over = static_cast<long>(mpz_sizeinbase(c.mpz(), 2)) - lead + 1, k = static_cast<long>(i);
    top = std::max(top, over > 0 ? (over + k - 1) / k : 0);
  }
  return static_cast<unsigned long>(top + 1);
}

/// 2^e c / 2^k.
Rational dyadic(const Integer& c, unsigned long e, unsigned long k) {
  Integer num, den(1);  // fresh objects: written through their mpz_t (a copy of c would share c's)
  mpz_mul_2exp(num.mpz(), c.mpz(), e);
  mpz_mul_2exp(den.mpz(), den.mpz(), k);
  return Rational(num, den);
}

}  // namespace

std::vector<RootInterval> positive_roots(const std::vector<Integer>& p) {
  flint_thread_cleanup_at_exit();
  std::size_t n = p.size();
  while (n > 0 && p[n - 1] == 0) --n;
  if (n < 2) throw std::logic_error("internal error: positive_roots: a constant polynomial");
  const unsigned long e = fujiwara_exponent(p, n);
  auto at = [e](const Integer& c, unsigned long k) { return dyadic(c, e, k); };
  // The Collins-Akritas bisection on (0, 1) for q(x) = p(2^e x): a node (c, k) stands for the interval
  // (c / 2^k, (c + 1) / 2^k) and holds 2^(k deg) q((c + x) / 2^k), whose roots in (0, 1) are those.
  struct Node {
    Integer c;
    unsigned long k;
    ScratchPoly q;
  };
  std::vector<Node> pending(1);
  pending[0].c = Integer(0);
  pending[0].k = 0;
  to_flint(pending[0].q.get(), std::vector<Integer>(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(n)));
  for (slong i = 1; i < static_cast<slong>(n); ++i)
    fmpz_mul_2exp(pending[0].q.get()->coeffs + i, pending[0].q.get()->coeffs + i, e * static_cast<ulong>(i));
  std::vector<RootInterval> out;
  ScratchPoly scratch;
  fmpz_t one;
  fmpz_init_set_ui(one, 1);
  for (int nodes = 0; !pending.empty(); ++nodes) {
    if (nodes > 100000) {
      fmpz_clear(one);
      throw std::logic_error("internal error: positive_roots: no isolation (not square-free?)");
    }
    Node node = std::move(pending.back());
    pending.pop_back();
    const int v = unit_bound(node.q.get(), scratch.get());
    if (v == 1) out.push_back({at(node.c, node.k), at(node.c + 1, node.k)});
    if (v <= 1) continue;
    const Integer c2 = 2 * node.c;
    halve(node.q.get());  // the left child: 2^deg q(x / 2)
    Node right{c2 + 1, node.k + 1, ScratchPoly()};
    fmpz_poly_taylor_shift(right.q.get(), node.q.get(), one);  // the right child: the left one at x + 1
    if (fmpz_is_zero(right.q.get()->coeffs)) {  // the midpoint is a root: kept, and divided out on the right
      out.push_back({at(c2 + 1, node.k + 1), at(c2 + 1, node.k + 1)});
      fmpz_poly_shift_right(right.q.get(), right.q.get(), 1);
    }
    pending.push_back(std::move(right));
    pending.push_back({c2, node.k + 1, std::move(node.q)});
  }
  fmpz_clear(one);
  std::sort(out.begin(), out.end(),
            [](const RootInterval& x, const RootInterval& y) { return x.lo < y.lo || (x.lo == y.lo && x.hi < y.hi); });
  return out;
}

bool isolates(const std::vector<Integer>& pi, const std::vector<Integer>& f, const Rational& a, const Rational& b) {
  flint_thread_cleanup_at_exit();
  if (descartes_bound(f, a, b) != 1) return false;
  fmpz_poly_t rest, divisor, quotient;
  fmpz_poly_init(rest);
  fmpz_poly_init(divisor);
  fmpz_poly_init(quotient);
  to_flint(rest, pi);
  to_flint(divisor, f);
  int divisions = 0;
  while (!fmpz_poly_is_zero(rest) && fmpz_poly_degree(rest) >= fmpz_poly_degree(divisor) &&
         fmpz_poly_divides(quotient, rest, divisor)) {
    fmpz_poly_swap(rest, quotient);
    ++divisions;
  }
  bool ok = divisions > 0 && !fmpz_poly_is_zero(rest);
  if (ok && fmpz_poly_degree(rest) >= 1) ok = descartes_bound(from_flint(rest), a, b) == 0;
  fmpz_poly_clear(rest);
  fmpz_poly_clear(divisor);
  fmpz_poly_clear(quotient);
  return ok;
}

void bisect(const std::vector<Integer>& p, RootInterval& r) {
  if (r.lo == r.hi) return;
  Rational m = (r.lo + r.hi) / 2;
  const int sm = sign_of_value(p, m);
  if (sm == 0) {
    r.lo = r.hi = m;
  } else if (sm == sign_of_value(p, r.lo)) {
    r.lo = std::move(m);
  } else {
    r.hi = std::move(m);
  }
}

}  // namespace relpos::detail
