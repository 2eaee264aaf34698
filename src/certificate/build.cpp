#include "certificate/build.hpp"

#include <CGAL/Interval_nt.h>
#include <flint/fmpz_poly.h>
#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "algebra/between.hpp"
#include "algebra/centre.hpp"
#include "algebra/cramer.hpp"
#include "algebra/double_sign.hpp"
#include "algebra/flint_thread.hpp"
#include "algebra/forms.hpp"
#include "algebra/pencil.hpp"
#include "anysize/exact.hpp"
#include "filters/checked_int.hpp"
#include "filters/pooled_integer.hpp"

namespace relpos::certificate {
namespace {

using anysize::LambdaS;
using anysize::Poly;
using anysize::QuadraticReal;
using detail::cramer;
using V3 = std::array<Rational, 3>;

int sgn(const Rational& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }

/// The entries of a matrix as doubles (CGAL::to_double), for the searches in doubles.
DoubleMatrix4 to_doubles(const Matrix4& m) {
  DoubleMatrix4 out;
  for (std::size_t i = 0; i < 16; ++i) out[i] = forms::truncated_double(m.a[i]);
  return out;
}

/// Exact signs of X^T Q X, X = (x, 1), on integers: Q times the positive lcm of its denominators,
/// x over the lcm D of its coordinates' denominators (D^2 X^T Q X = N^T Qz N, N = (D x, D)). No
/// rational canonicalisation (gcd) per operation, and every integer, temporaries included, is a
/// pooled one (no heap traffic once the thread's pool is warm).
class IntegerForm {
 public:
  /// From the integer form itself (forms::integer_form), when the caller has it.
  template <class Z>
  explicit IntegerForm(const forms::MatrixOf<Z>& z) {
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) mpz_set(z_[i][j].mpz(), z(i, j).mpz());
    double_off_diagonal();
  }
  /// From a matrix of exact doubles, written straight into the form (no Integer handles).
  explicit IntegerForm(const DoubleMatrix4& d) {
    PooledInteger lower[6];  // the entries below the diagonal, equal to those above
    std::array<mpz_ptr, 16> out;
    for (int i = 0, k = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) out[static_cast<std::size_t>(4 * i + j)] = (j >= i ? z_[i][j] : lower[k++]).mpz();
    Integer l;
    forms::integer_form(d, out, l);
    double_off_diagonal();
  }
  IntegerForm(const IntegerForm&) = delete;
  IntegerForm& operator=(const IntegerForm&) = delete;
  /// Numerators N = (D x, D) of a point, shared by every form evaluated at it.
  struct Point {
    PooledInteger n[4];
    explicit Point(const V3& x) {
      mpz_set_ui(n[3].mpz(), 1);
      for (int i = 0; i < 3; ++i) forms::fold_lcm(n[3].mpz(), mpq_denref(x[i].mpq()));
      for (int i = 0; i < 3; ++i) {
        mpz_divexact(n[i].mpz(), n[3].mpz(), mpq_denref(x[i].mpq()));
        mpz_mul(n[i].mpz(), n[i].mpz(), mpq_numref(x[i].mpq()));
      }
    }
    Point(const Point&) = delete;
    Point& operator=(const Point&) = delete;
  };
  /// sign(X^T Q X): Horner per row, N_i (sum_{j >= i} Qz_ij N_j).
  int sign(const Point& x) const {
    PooledInteger acc, row;
    for (int i = 0; i < 4; ++i) {
      mpz_set_ui(row.mpz(), 0);
      for (int j = i; j < 4; ++j) mpz_addmul(row.mpz(), z_[i][j].mpz(), x.n[j].mpz());
      mpz_addmul(acc.mpz(), row.mpz(), x.n[i].mpz());
    }
    return acc.sign();
  }

 private:
  void double_off_diagonal() {  // off-diagonal entries appear twice in X^T Q X
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) mpz_mul_2exp(z_[i][j].mpz(), z_[i][j].mpz(), 1);
  }
  PooledInteger z_[4][4];  // the upper triangle (j >= i) only
};

/// A positive multiple of a polynomial over Q with integer coefficients: exact signs at rationals by
/// sum z_k n^k d^(deg - k) for x = n / d, d > 0 (integer products only, where a rational Horner
/// scheme canonicalizes at every step).
class IntegerPoly {
 public:
  IntegerPoly() = default;
  /// From integer coefficients z[0..n) (a positive multiple of the polynomial: the same signs).
  IntegerPoly(const Integer* z, std::size_t n) : z_(z, z + n) {
    while (!z_.empty() && z_.back() == 0) z_.pop_back();
    for (const Integer& c : z_) bits_ = std::max(bits_, mpz_sizeinbase(c.mpz(), 2));
  }
  explicit IntegerPoly(const Poly& q) {
    Integer l(1);
    forms::lcm_of_denominators(q.begin(), q.end(), l);
    z_.resize(q.size());
    for (std::size_t k = 0; k < q.size(); ++k) {
      forms::scaled_numerator(q[k], l, z_[k].mpz());
      bits_ = std::max(bits_, mpz_sizeinbase(z_[k].mpz(), 2));
    }
  }
  int sign(const Rational& x) const {
    if (z_.empty()) return 0;
    PooledInteger acc_, dp_(1), t_;  // no Integer handles: one exact sign per candidate multiplier
    const mpz_ptr acc = acc_.mpz(), dp = dp_.mpz(), t = t_.mpz();
    mpz_set(acc, z_.back().mpz());
    for (std::size_t k = z_.size() - 1; k-- > 0;) {
      mpz_mul(dp, dp, mpq_denref(x.mpq()));
      mpz_mul(acc, acc, mpq_numref(x.mpq()));
      mpz_mul(t, z_[k].mpz(), dp);
      mpz_add(acc, acc, t);
    }
    return mpz_sgn(acc);
  }
  /// The Newton step t - q(t)/q'(t) from t = n/d rounded down to a multiple of 2^e, on integers
  /// (one division, no canonicalization); nullopt where q' vanishes.
  std::optional<Rational> newton_floor(const Rational& t, long e) const {
    if (z_.size() < 2) return std::nullopt;
    const mpz_srcptr n = mpq_numref(t.mpq()), d = mpq_denref(t.mpq());
    // v = d^deg q(t) and s = d^(deg - 1) q'(t) by Horner on the homogenized forms: v <- v n + z_k d^(deg - k)
    // and, differentiating the non-homogeneous step, s <- s n + v (the old v).
    Integer v, s, t1, dp(1);  // fresh objects: Gmpz shares its value on copy, mpz() does not unshare
    mpz_set(v.mpz(), z_.back().mpz());
    for (std::size_t k = z_.size() - 1; k-- > 0;) {
      mpz_mul(s.mpz(), s.mpz(), n);
      mpz_add(s.mpz(), s.mpz(), v.mpz());
      mpz_mul(dp.mpz(), dp.mpz(), d);
      mpz_mul(v.mpz(), v.mpz(), n);
      mpz_mul(t1.mpz(), z_[k].mpz(), dp.mpz());
      mpz_add(v.mpz(), v.mpz(), t1.mpz());
    }
    if (mpz_sgn(s.mpz()) == 0) return std::nullopt;
    // t - v / (s d) = (n s - v) / (s d), then divided by 2^e and floored.
    Integer num, den;
    mpz_mul(num.mpz(), n, s.mpz());
    mpz_sub(num.mpz(), num.mpz(), v.mpz());
    mpz_mul(den.mpz(), s.mpz(), d);
    if (mpz_sgn(den.mpz()) < 0) {
      mpz_neg(den.mpz(), den.mpz());
      mpz_neg(num.mpz(), num.mpz());
    }
    if (e >= 0)
      mpz_mul_2exp(den.mpz(), den.mpz(), static_cast<mp_bitcnt_t>(e));
    else
      mpz_mul_2exp(num.mpz(), num.mpz(), static_cast<mp_bitcnt_t>(-e));
    mpz_fdiv_q(num.mpz(), num.mpz(), den.mpz());
    Rational out(num);
    if (e >= 0)
      mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(e));
    else
      mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-e));
    return out;
  }
  /// From a FLINT polynomial's coefficients, kept as they are.
  explicit IntegerPoly(const fmpz_poly_t q) : z_(static_cast<std::size_t>(fmpz_poly_length(q))) {
    for (std::size_t k = 0; k < z_.size(); ++k) {
      fmpz_get_mpz(z_[k].mpz(), fmpz_poly_get_coeff_ptr(q, static_cast<slong>(k)));
      bits_ = std::max(bits_, mpz_sizeinbase(z_[k].mpz(), 2));
    }
  }
  /// The integer coefficients into a FLINT polynomial.
  void to_flint(fmpz_poly_t out) const {
    for (std::size_t k = 0; k < z_.size(); ++k) fmpz_poly_set_coeff_mpz(out, static_cast<slong>(k), z_[k].mpz());
  }
  std::size_t degree() const { return z_.empty() ? 0 : z_.size() - 1; }
  const Integer* data() const { return z_.data(); }
  std::size_t bits() const { return bits_; }  ///< the largest coefficient's bit length

 private:
  std::vector<Integer> z_;
  std::size_t bits_ = 0;
};

/// A quadric's exact matrix, asked for on first use: the certificates of E and I with known roots
/// never read the matrices, so a quadric made from doubles builds no rationals for them.
template <class Quadric>
class LazyMatrix {
 public:
  explicit LazyMatrix(const Quadric& q) : q_(q) {}
  const Matrix4& get() const {
    if (!m_) m_ = &q_.matrix();
    return *m_;
  }
  operator const Matrix4&() const { return get(); }  // NOLINT: reads as the matrix it stands for
  const Rational& operator()(int i, int j) const { return get()(i, j); }
  /// The entries as doubles (CGAL::to_double of each): the quadric's own doubles when it has them,
  /// else those its recipe gives from the numbers read (a decimal sphere or axis
  /// paraboloid), without building its rationals.
  DoubleMatrix4 doubles() const {
    if (const std::optional<DoubleMatrix4> d = q_.doubles()) return *d;
    if (const detail::DecimalRecipe* recipe = storage_of(q_).recipe(); recipe && !m_) {
      DoubleMatrix4 out;
      if (detail::truncated_doubles(*recipe, out)) return out;
    }
    return to_doubles(get());
  }
  /// The quadric's own doubles (a copy), if it has them.
  std::optional<DoubleMatrix4> own_doubles() const { return q_.doubles(); }
  /// The enclosures of the entries stored by the reader of decimal text, if it has them.
  const detail::EnclosureMatrix4* enclosure() const { return storage_of(q_).enclosure(); }
  /// forms::integer_form of the matrix, from the doubles when the quadric has them.
  forms::MatrixOf<Integer> integer_form(Integer& l) const {
    if (const std::optional<DoubleMatrix4> d = q_.doubles()) return forms::integer_form(*d, l);
    return forms::integer_form(get(), l);
  }

 private:
  const Quadric& q_;
  mutable const Matrix4* m_ = nullptr;
};

/// The pair's blocks (E = [[M, m], [m^T, e0]], P = [[A, a], [a^T, p0]]), f, s and lambda_s.
struct Pair {
  LazyMatrix<Ellipsoid> E;
  LazyMatrix<Paraboloid> P;
  LambdaS ls;
  const forms::MatrixOf<PooledInteger>* ez_pooled = nullptr;  ///< Known::ez_pooled
  const forms::MatrixOf<PooledInteger>* pz_pooled = nullptr;  ///< Known::pz_pooled
  Pair(const Pair&) = delete;                                 // f_at_doubles_ points into f_multiple_ or fz_
  Pair& operator=(const Pair&) = delete;
  Pair(const Ellipsoid& e, const Paraboloid& p, const Known& known)
      : E(e), P(p), ls(known.f && known.s && known.lambda_s ? *known.lambda_s : LambdaS{}) {
    if (known.f && known.s) {
      known_f_ = known.f;
      known_s_ = known.s;
    } else {
      const Quartic<Rational> fq = characteristic_polynomial<Rational>(P.get(), E.get());
      const Quadratic<Rational> sq = special_polynomial<Rational>(P.get(), E.get());
      f_ = anysize::to_poly(fq.data(), 5);
      s_ = anysize::to_poly(sq.data(), 3);
    }
    if (!(known.f && known.s && known.lambda_s)) ls = anysize::lambda_s_of(s());
    if (known.forms) forms_ = *known.forms;
    ez_pooled = known.ez_pooled;
    pz_pooled = known.pz_pooled;
    if (ez_pooled && pz_pooled && known.le_pooled && known.lp_pooled) {
      le_pooled_ = known.le_pooled;
      lp_pooled_ = known.lp_pooled;
    }
    known_f_multiple_ = known.f_multiple;
  }
  /// f and s as polynomials over Q: the caller's, copied on first use (the certificates of E and I
  /// with known roots read neither).
  const Poly& f() const {
    if (!f_) f_ = anysize::to_poly(known_f_->data(), 5);
    return *f_;
  }
  const Poly& s() const {
    if (!s_) s_ = anysize::to_poly(known_s_->data(), 3);
    return *s_;
  }
  /// f times the lcm of its denominators (its size sets the searches' budgets), on first use.
  const IntegerPoly& fz() const {
    if (!fz_) fz_.emplace(f());
    return *fz_;
  }
  /// sign f(x), on the caller's integer multiple of f when it gave one (copied on first use: the
  /// crossings never evaluate f).
  int f_sign(const Rational& x) const {
    if (known_f_multiple_ && !f_multiple_) f_multiple_.emplace(known_f_multiple_->data(), 5);
    const IntegerPoly& q = f_multiple_ ? *f_multiple_ : fz();
    // At a double (the multipliers between isolating intervals are short dyadics), the roots' sign
    // at doubles: floating-point stages that answer only when certain, then the same exact sign.
    const std::pair<double, double> d = forms::tight_interval(x);
    if (d.first == d.second && q.degree() >= 1 && q.degree() <= 4) {
      if (!f_at_doubles_) f_at_doubles_.emplace(q.data(), static_cast<int>(q.degree()));
      return (*f_at_doubles_)(d.first);
    }
    return q.sign(x);
  }
  /// X^T Q X for X = (x, 1).
  static Rational form(const Matrix4& q, const V3& x) {
    Rational acc = q(3, 3);
    for (int i = 0; i < 3; ++i) {
      acc += 2 * q(i, 3) * x[i];
      for (int j = 0; j < 3; ++j) acc += x[i] * q(i, j) * x[j];
    }
    return acc;
  }
  Rational e_at(const V3& x) const { return form(E, x); }
  Rational p_at(const V3& x) const { return form(P, x); }
  /// x(lambda) = -(lambda A + M)^{-1} (lambda a + m): the stationary point of lambda p + e (math.md §8);
  /// nullopt when lambda A + M is singular. For lambda = n/d the system times d lp le (E = Ez/le,
  /// P = Pz/lp) has integer entries n le Pz + d lp Ez: Cramer's rule on integers, one rational
  /// canonicalisation per coordinate.
  std::optional<V3> x_of(const Rational& l) const {
    const IntegerForms& z = forms();
    const Integer pf = l.numerator() * z.le, ef = l.denominator() * z.lp;
    Integer k[3][4];  // [lambda A + M | -(lambda a + m)], scaled
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) {
        k[i][j] = pf * z.pz(i, j) + ef * z.ez(i, j);
        if (j == 3) k[i][j] = -k[i][j];
      }
    return detail::solve_integer_system(k);
  }

  bool has_forms() const { return forms_.has_value() || le_pooled_; }
  /// The integer forms of E and P with their scales: the caller's (copied from its pooled ones on
  /// first use), else computed on first use (from the quadrics' doubles when they have them: no
  /// rational matrix).
  const IntegerForms& forms() const {
    if (!forms_) {
      forms_.emplace();
      if (le_pooled_) {
        for (std::size_t i = 0; i < 16; ++i) {
          mpz_set(forms_->ez.a[i].mpz(), ez_pooled->a[i].mpz());  // fresh entries: written in place
          mpz_set(forms_->pz.a[i].mpz(), pz_pooled->a[i].mpz());
        }
        forms_->le = *le_pooled_;
        forms_->lp = *lp_pooled_;
      } else {
        forms_->ez = E.integer_form(forms_->le);
        forms_->pz = P.integer_form(forms_->lp);
      }
    }
    return *forms_;
  }

 private:
  const Quartic<Rational>* known_f_ = nullptr;
  const Quadratic<Rational>* known_s_ = nullptr;
  mutable std::optional<Poly> f_, s_;
  mutable std::optional<IntegerForms> forms_;
  const Integer* le_pooled_ = nullptr;  // Known::le_pooled and lp_pooled, with ez_pooled and pz_pooled
  const Integer* lp_pooled_ = nullptr;
  mutable std::optional<IntegerPoly> fz_;
  const Quartic<Integer>* known_f_multiple_ = nullptr;
  mutable std::optional<IntegerPoly> f_multiple_;
  mutable std::optional<detail::DoubleSign> f_at_doubles_;  // reads f_sign's IntegerPoly in place
};

/// floor(sqrt(x) 2^bits) / 2^bits for rational x >= 0.
Rational sqrt_below(const Rational& x, unsigned bits) {
  Integer nd = x.numerator() * x.denominator();
  mpz_mul_2exp(nd.mpz(), nd.mpz(), 2 * bits);
  Integer r;
  mpz_sqrt(r.mpz(), nd.mpz());
  Integer den = x.denominator();
  mpz_mul_2exp(den.mpz(), den.mpz(), bits);
  return Rational(r, den);
}

/// A rational within 2^-bits |b| of a + b sqrt(d), above it (up = true) or below it.
Rational approximate(const LambdaS& ls, const QuadraticReal& x, unsigned bits, bool up) {
  if (x.b == 0 || ls.d == 0) return x.a;
  const Rational lo = sqrt_below(Rational(ls.d), bits);
  Rational step(1);
  for (unsigned i = 0; i < bits; ++i) step /= 2;
  const Rational hi = lo + step;
  const bool b_positive = x.b > 0;
  return x.a + x.b * ((up == b_positive) ? hi : lo);
}

/// Rational roots of a polynomial of degree <= 2 (after removing repeated factors).
std::vector<Rational> rational_roots(const Poly& q) {
  std::vector<Rational> out;
  if (q.size() == 2) out.push_back(-q[0] / q[1]);
  if (q.size() == 3) {
    const Rational disc = q[1] * q[1] - 4 * q[2] * q[0];
    if (disc < 0) return out;
    Integer nd = disc.numerator() * disc.denominator();
    if (!mpz_perfect_square_p(nd.mpz())) return out;
    Integer r;
    mpz_sqrt(r.mpz(), nd.mpz());
    const Rational root = Rational(r) / Rational(disc.denominator());
    out.push_back((-q[1] - root) / (2 * q[2]));
    out.push_back((-q[1] + root) / (2 * q[2]));
  }
  return out;
}

/// The real roots of q (any degree <= 3 here) refined jointly: returns, level by level, dyadic
/// points converging to every real root; `accept` is tried on each and the first accepted is returned.
template <class Accept>
std::optional<Rational> search_near_roots(const Poly& q_in, Accept accept, std::size_t max_bits) {
  if (q_in.size() <= 1) return std::nullopt;
  const Poly q = anysize::quotient(q_in, anysize::monic_gcd(q_in, anysize::derivative(q_in)));  // square-free part
  if (q.size() <= 1) return std::nullopt;
  // Cauchy bound, as a power of two.
  Rational bound(1);
  for (std::size_t i = 0; i + 1 < q.size(); ++i) {
    const Rational r = q[i] / q.back();
    bound = std::max(bound, r > 0 ? r + 1 : 1 - r);
  }
  Rational b(1);
  while (b < bound) b *= 2;
  const std::vector<Poly> sturm = anysize::sturm_sequence(q);
  std::vector<int> signs(sturm.size());
  auto variations = [&](const Rational& x) {  // sign changes of the Sturm sequence at x
    for (std::size_t i = 0; i < sturm.size(); ++i) signs[i] = sgn(evaluate(sturm[i], x));
    return anysize::variations(signs);
  };
  struct Box {
    Rational lo, hi;
  };
  std::vector<Box> boxes{{-b, b}}, isolated;
  // Isolate (bisection on Sturm counts), then refine every isolating interval one bit per round.
  for (std::size_t round = 0; round < max_bits && !boxes.empty(); ++round) {
    std::vector<Box> next;
    for (const Box& box : boxes) {
      const Rational mid = (box.lo + box.hi) / 2;
      if (accept(mid)) return mid;
      for (const Box& half : {Box{box.lo, mid}, Box{mid, box.hi}}) {
        if (variations(half.lo) - variations(half.hi) > 0) next.push_back(half);
      }
    }
    boxes = std::move(next);
  }
  return std::nullopt;
}

/// Kernel basis and a particular solution of K x = r over Q(sqrt d) (3x3), by Gaussian elimination.
struct LinearSolution {
  std::array<QuadraticReal, 3> particular;
  std::vector<std::array<QuadraticReal, 3>> kernel;
  bool consistent = true;
};

LinearSolution solve3(const LambdaS& ls, std::array<std::array<QuadraticReal, 4>, 3> m) {
  const QuadraticReal zero{Rational(0), Rational(0)};
  int row = 0;
  std::array<int, 3> pivot_of_row{-1, -1, -1};
  std::array<bool, 3> is_pivot{false, false, false};
  for (int c = 0; c < 3 && row < 3; ++c) {
    int r = row;
    while (r < 3 && ls.sign(m[r][c]) == 0) ++r;
    if (r == 3) continue;
    std::swap(m[r], m[row]);
    const QuadraticReal inv = ls.div({Rational(1), Rational(0)}, m[row][c]);
    for (int j = 0; j < 4; ++j) m[row][j] = ls.mul(m[row][j], inv);
    for (int i = 0; i < 3; ++i) {
      if (i == row || ls.sign(m[i][c]) == 0) continue;
      const QuadraticReal factor = m[i][c];
      for (int j = 0; j < 4; ++j) m[i][j] = ls.sub(m[i][j], ls.mul(factor, m[row][j]));
    }
    pivot_of_row[row] = c;
    is_pivot[c] = true;
    ++row;
  }
  LinearSolution out;
  for (int i = row; i < 3; ++i)
    if (ls.sign(m[i][3]) != 0) out.consistent = false;
  out.particular = {zero, zero, zero};
  for (int r = 0; r < row; ++r) out.particular[pivot_of_row[r]] = m[r][3];
  for (int free = 0; free < 3; ++free) {
    if (is_pivot[free]) continue;
    std::array<QuadraticReal, 3> v{zero, zero, zero};
    v[free] = {Rational(1), Rational(0)};
    for (int r = 0; r < row; ++r) v[pivot_of_row[r]] = {-m[r][free].a, -m[r][free].b};
    out.kernel.push_back(v);
  }
  return out;
}

QuadraticReal q_of(const Rational& x) { return {x, Rational(0)}; }

/// e(x) = x^T M x + 2 m^T x + e0 over Q(sqrt d).
QuadraticReal e_at(const LambdaS& ls, const Matrix4& E, const std::array<QuadraticReal, 3>& x) {
  QuadraticReal acc = q_of(E(3, 3));
  for (int i = 0; i < 3; ++i) {
    acc = ls.add(acc, ls.mul(q_of(2 * E(i, 3)), x[i]));
    for (int j = 0; j < 3; ++j) acc = ls.add(acc, ls.mul(ls.mul(x[i], q_of(E(i, j))), x[j]));
  }
  return acc;
}

/// Hard case (math.md §8): contact set x^ + {w in ker(lambda_s A + M): w^T M w = -e(x^)}, x^ the
/// minimiser of e on the solutions of (lambda_s A + M) x = -(lambda_s a + m).
bool hard_case(const Pair& pr, Certificate& c) {
  const LambdaS& ls = pr.ls;
  std::array<std::array<QuadraticReal, 4>, 3> m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i][j] = ls.add(ls.mul(ls.value(), q_of(pr.P(i, j))), q_of(pr.E(i, j)));
    const QuadraticReal r = ls.add(ls.mul(ls.value(), q_of(pr.P(i, 3))), q_of(pr.E(i, 3)));
    m[i][3] = {-r.a, -r.b};
  }
  const LinearSolution sol = solve3(ls, m);
  if (!sol.consistent) return false;  // not the hard case: x(lambda) leaves every bounded set
  std::array<QuadraticReal, 3> x = sol.particular;
  const auto& w = sol.kernel;
  // Gradient of e along the kernel: g_j = w_j^T (M x + m); Gram G_jk = w_j^T M w_k; solve G c = -g.
  auto Mv = [&](const std::array<QuadraticReal, 3>& v) {
    std::array<QuadraticReal, 3> out;
    for (int i = 0; i < 3; ++i) {
      QuadraticReal acc{Rational(0), Rational(0)};
      for (int j = 0; j < 3; ++j) acc = ls.add(acc, ls.mul(q_of(pr.E(i, j)), v[j]));
      out[i] = acc;
    }
    return out;
  };
  auto dot = [&](const std::array<QuadraticReal, 3>& u, const std::array<QuadraticReal, 3>& v) {
    QuadraticReal acc{Rational(0), Rational(0)};
    for (int i = 0; i < 3; ++i) acc = ls.add(acc, ls.mul(u[i], v[i]));
    return acc;
  };
  if (!w.empty()) {
    auto mx = Mv(x);
    for (int i = 0; i < 3; ++i) mx[i] = ls.add(mx[i], q_of(pr.E(i, 3)));
    const std::size_t n = w.size();
    std::array<std::array<QuadraticReal, 4>, 3> g;
    const QuadraticReal zero{Rational(0), Rational(0)};
    for (auto& row : g) row = {zero, zero, zero, zero};
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < n; ++k) g[j][k] = dot(w[j], Mv(w[k]));
      const QuadraticReal gj = dot(w[j], mx);
      g[j][3] = {-gj.a, -gj.b};
    }
    for (std::size_t j = n; j < 3; ++j) g[j][j] = {Rational(1), Rational(0)};  // pad to 3x3 identity
    const LinearSolution cs = solve3(ls, g);
    for (std::size_t j = 0; j < n; ++j)
      for (int i = 0; i < 3; ++i) x[i] = ls.add(x[i], ls.mul(cs.particular[j], w[j][i]));
  }
  const QuadraticReal ex = e_at(ls, pr.E, x);
  c.kind = Certificate::Kind::HardTangent;
  c.d = ls.d;
  c.lambda_q = {ls.value().a, ls.value().b};
  for (int i = 0; i < 3; ++i) c.centre[i] = {x[i].a, x[i].b};
  c.directions.clear();
  for (const auto& v : w) c.directions.push_back({QuadraticNumber{v[0].a, v[0].b}, {v[1].a, v[1].b}, {v[2].a, v[2].b}});
  c.radius2 = {-ex.a, -ex.b};
  return true;
}

/// lambda with f(lambda) > 0 in the domain: then lambda P + E is positive definite (lambda A + M is,
/// and det = f(lambda) > 0). The maximum of f over the domain is positive and attained at a root
/// of f', so points converging to the roots of f' find one.
template <class InDomain>
std::optional<Rational> definite_lambda(const Pair& pr, InDomain in_domain) {
  // The positive maximum of f sits at a root of f'; its margin, like a crossing's, needs at most a
  // multiple of the coefficient bits.
  return search_near_roots(
      anysize::derivative(pr.f()), [&](const Rational& l) { return in_domain(l) && pr.f_sign(l) > 0; },
      1024 + 16 * pr.fz().bits());
}

/// Tight enclosures of a point's coordinates (forms::tight_interval); nullopt beyond the double range.
using Enclosure3 = std::array<std::pair<double, double>, 3>;
std::optional<Enclosure3> enclosure(const V3& x) {
  Enclosure3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    out[i] = forms::tight_interval(x[i]);
    if (!std::isfinite(out[i].first) || !std::isfinite(out[i].second)) return std::nullopt;
  }
  return out;
}

/// The same for a point of finite doubles: the points themselves (tight_interval's answer for a
/// double; -0 taken as 0, as the rational it converts to).
Enclosure3 enclosure(const double x[3]) {
  Enclosure3 out;
  for (std::size_t i = 0; i < 3; ++i) out[i].first = out[i].second = x[i] == 0 ? 0.0 : x[i];
  return out;
}

/// The curve search of crossing_points first in doubles (a search only: every candidate is checked
/// exactly by `consider(point, its enclosure or null)`): bisection on lambda for e(x(lambda)) = 0,
/// lambda > 0 for the inside point and lambda in (lambda_s, 0) for the outside one; the point found,
/// and the same point pulled towards the centre (exact rationals), are tried. Most crossings end
/// here, without the exact bisection on rationals. Each bisection's last bracket (good end first:
/// e(x) <= 0 there in doubles) goes to `brackets` [0] for the inside point and [1] for the outside
/// one: a start for the exact search when the point itself is beyond doubles.
using DoubleBracket = std::optional<std::pair<double, double>>;

/// out = a - b 2^-shift in lowest terms (out distinct from a and b). The points of the double
/// search and their pulls are dyadic: then by shifts and one subtraction, where mpq_sub takes gcds.
void difference(mpq_ptr out, mpq_srcptr a, mpq_srcptr b, mp_bitcnt_t shift) {
  const long ka = forms::power_of_two_exponent(mpq_denref(a)), kb0 = forms::power_of_two_exponent(mpq_denref(b));
  if (ka < 0 || kb0 < 0) {
    mpq_div_2exp(out, b, shift);
    mpq_sub(out, a, out);
    return;
  }
  const unsigned long kb = static_cast<unsigned long>(kb0) + shift;
  const unsigned long top = std::max(static_cast<unsigned long>(ka), kb);
  const mpz_ptr num = mpq_numref(out), den = mpq_denref(out);
  if (top - static_cast<unsigned long>(ka) <= 63 && top - kb <= 63 && mpz_fits_slong_p(mpq_numref(a)) &&
      mpz_fits_slong_p(mpq_numref(b))) {  // the same on 128-bit words (both terms below 2^126)
    const Int128 one = 1, n = mpz_get_si(mpq_numref(a)) * (one << (top - static_cast<unsigned long>(ka))) -
                              mpz_get_si(mpq_numref(b)) * (one << (top - kb));
    const auto magnitude = static_cast<Int128>(n < 0 ? -n : n);
    const auto high = static_cast<unsigned long>(magnitude >> 64), low = static_cast<unsigned long>(magnitude);
    const unsigned long zeros = low != 0 ? static_cast<unsigned long>(__builtin_ctzl(low))
                                         : 64 + static_cast<unsigned long>(__builtin_ctzl(high | (1UL << 63)));
    const unsigned long twos = n == 0 ? top : std::min(zeros, top);
    const Int128 m = n == 0 ? 0 : magnitude >> twos;  // exact
    const unsigned long limbs[2] = {static_cast<unsigned long>(m), static_cast<unsigned long>(m >> 64)};
    mpz_import(num, 2, -1, sizeof(unsigned long), 0, 0, limbs);
    if (n < 0) mpz_neg(num, num);
    mpz_set_ui(den, 0);
    mpz_setbit(den, top - twos);
    return;
  }
  mpz_mul_2exp(den, mpq_numref(b), top - kb);  // den as a temporary
  mpz_mul_2exp(num, mpq_numref(a), top - static_cast<unsigned long>(ka));
  mpz_sub(num, num, den);
  const unsigned long twos = mpz_sgn(num) == 0 ? top : std::min<unsigned long>(mpz_scan1(num, 0), top);
  mpz_tdiv_q_2exp(num, num, twos);
  mpz_set_ui(den, 1);
  mpz_mul_2exp(den, den, top - twos);
}

template <class Consider>
void double_curve_search(const DoubleMatrix4& em, const DoubleMatrix4& pm, const LambdaS& lambda_s, const V3& centre,
                         const std::optional<V3>& inside, const std::optional<V3>& outside, const Consider& consider,
                         DoubleBracket (&brackets)[2]) {
  double E[4][4], P[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      E[i][j] = em[static_cast<std::size_t>(4 * i + j)];
      P[i][j] = pm[static_cast<std::size_t>(4 * i + j)];
      if (!std::isfinite(E[i][j]) || !std::isfinite(P[i][j])) return;
    }
  auto x_of = [&](double l, double x[3]) {
    double k[3][3], r[3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) k[i][j] = l * P[i][j] + E[i][j];
      r[i] = -(l * P[i][3] + E[i][3]);
    }
    const double det = k[0][0] * (k[1][1] * k[2][2] - k[1][2] * k[2][1]) -
                       k[0][1] * (k[1][0] * k[2][2] - k[1][2] * k[2][0]) +
                       k[0][2] * (k[1][0] * k[2][1] - k[1][1] * k[2][0]);
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
    for (int c = 0; c < 3; ++c) {
      double m[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = j == c ? r[i] : k[i][j];
      x[c] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
              m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
             det;
    }
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(x[c])) return false;
    return true;
  };
  auto e_of = [&](const double x[3]) {
    double acc = E[3][3];
    for (int i = 0; i < 3; ++i) {
      acc += 2 * E[i][3] * x[i];
      for (int j = 0; j < 3; ++j) acc += x[i] * E[i][j] * x[j];
    }
    return acc;
  };
  // `wanted`: the point a search is for (inside or outside); the pulls stop once it is found.
  auto try_point = [&](const double x[3], const std::optional<V3>& wanted) {
    // Each point a fresh V3 written in place (`consider` may keep it: its values are then shared).
    V3 q;
    for (int i = 0; i < 3; ++i) forms::set_double(q[i].mpq(), x[i]);  // exact: x is finite
    const std::optional<Enclosure3> at = enclosure(x);
    consider(q, &at);
    if (wanted) return;
    mpq_t diff[3];  // never shared: reused
    for (auto& v : diff) mpq_init(v);
    for (int i = 0; i < 3; ++i) difference(diff[i], q[i].mpq(), centre[i].mpq(), 0);
    for (int k : {40, 20, 10, 4, 1}) {  // pulled towards the centre: inside the solid when x is not
      V3 y;                             // centre + (1 - 2^-k)(q - centre) = q - 2^-k (q - centre)
      for (int i = 0; i < 3; ++i) difference(y[i].mpq(), q[i].mpq(), diff[i], static_cast<mp_bitcnt_t>(k));
      consider(y, nullptr);
      if (wanted) break;
    }
    for (auto& v : diff) mpq_clear(v);
  };
  // lo: e(x(lo)) <= 0 side; hi: e(x(hi)) > 0 side (either order on the line). Regula falsi with
  // the Illinois modification (the end that stays has its value halved), bisection when the
  // interpolated point is not strictly inside; down to a bracket of one or two doubles, as plain
  // bisection would, in a fraction of the steps.
  auto bisect = [&](double lo, double hi, const std::optional<V3>& wanted, DoubleBracket& bracket) {
    double x[3], best[3];
    bool have = false;
    double glo = 0, ghi = 0;
    if (!x_of(lo, x) || !x_of(hi, best)) return;
    glo = e_of(x);
    ghi = e_of(best);
    if (!(glo <= 0 && ghi > 0)) glo = ghi = 0;  // no usable values: bisection only
    int side = 0;
    for (int i = 0; i < 200; ++i) {
      const double half = lo + (hi - lo) / 2;
      if (!(half != lo && half != hi)) break;
      double mid = glo < 0 && ghi > 0 ? (lo * ghi - hi * glo) / (ghi - glo) : half;
      if (!(mid > std::min(lo, hi) && mid < std::max(lo, hi))) mid = half;
      if (!x_of(mid, x)) return;
      const double g = e_of(x);
      if (g <= 0) {
        lo = mid;
        glo = g;
        if (side == -1) ghi /= 2;
        side = -1;
        std::copy(x, x + 3, best);
        have = true;
      } else {
        hi = mid;
        ghi = g;
        if (side == 1) glo /= 2;
        side = 1;
      }
    }
    if (have) {
      bracket.emplace(lo, hi);
      try_point(best, wanted);
    }
  };
  double x[3];
  if (!inside) {
    double hi = 1;
    for (int k = 0; k < 2000; ++k, hi *= 2) {
      if (!std::isfinite(hi)) return;
      if (x_of(hi, x) && e_of(x) > 0) break;
    }
    bisect(0, hi, inside, brackets[0]);
  }
  if (!outside) {
    // lambda_s from above: the upper end of its stored enclosure (a search needs no more), else a
    // rational approximation.
    const double ls = std::isfinite(lambda_s.hi) && lambda_s.hi - lambda_s.lo <= 0x1p-40 * std::fabs(lambda_s.hi)
                          ? lambda_s.hi
                          : CGAL::to_double(approximate(lambda_s, lambda_s.value(), 64, true));
    if (std::isfinite(ls) && ls < 0) {
      // approach lambda_s from 0: the first lambda with e(x(lambda)) > 0
      for (double l = ls / 2, step = ls / 4; l > ls && l < 0; l += step, step /= 2) {
        if (x_of(l, x) && e_of(x) > 0) {
          bisect(0, l, outside, brackets[1]);
          break;
        }
        if (step > ls * 1e-15) break;  // step is negative: stop once it is negligible
      }
    }
  }
}

/// The centre -M^{-1} m solved in doubles (Cramer's rule), as exact rationals (the doubles
/// themselves into `doubles`); nullopt when it is not finite. An approximation: the caller checks
/// it exactly.
std::optional<V3> approximate_centre(const DoubleMatrix4& e, double doubles[3]) {
  double k[3][4];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) k[i][j] = e[static_cast<std::size_t>(4 * i + j)] * (j == 3 ? -1 : 1);
  const std::array<double, 4> d = cramer(k);
  V3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    const double x = d[i + 1] / d[0];
    if (!std::isfinite(x)) return std::nullopt;
    doubles[i] = x == 0 ? 0.0 : x;       // the rational's double (no -0)
    forms::set_double(out[i].mpq(), x);  // exact; a fresh value, written in place
  }
  return out;
}

std::logic_error internal_error(const std::string& what) {
  return std::logic_error("relpos internal error: " + what + " (please report the input)");
}

/// The signs of e and p along the curve x(lambda), lambda in (lambda_s, oo), from two polynomials
/// (math.md §8): lambda p + e is f/s at x(lambda), and its derivative in lambda is p(x(lambda))
/// (the envelope theorem), so with s > 0 there
///   p(x(lambda)) s^2 = f' s - f s'   and   e(x(lambda)) s^2 = f s - lambda (f' s - f s').
/// e(x(lambda)) increases on (0, oo) and decreases on (lambda_s, 0) while p(x(lambda)) decreases on
/// both (f/s is concave): the optimisers of p over the solid are x(lambda*) at the root lambda* of
/// the second polynomial, or the limit at lambda_s in the hard case. Only their signs are used, so
/// f and s are taken as positive integer multiples (FLINT's integer products: no rational
/// canonicalisation).
struct Secular {
  IntegerPoly e, p;
  /// The most bisection steps or approximation bits a witness may take before the search is
  /// declared broken: the margin of p at its optimiser and the distance of lambda* to the other
  /// polynomial's roots are algebraic numbers whose size the coefficients bound (root separation),
  /// so a crossing never needs more than a multiple of the coefficient bits.
  std::size_t budget;
  explicit Secular(const Pair& pr) {
    detail::flint_thread_cleanup_at_exit();
    fmpz_poly_t f, s, d, gp, ge;  // gp = f' s - f s', ge = f s - lambda gp (d: scratch)
    for (auto* q : {f, s, d, gp, ge}) fmpz_poly_init(q);
    pr.fz().to_flint(f);
    IntegerPoly(pr.s()).to_flint(s);
    fmpz_poly_derivative(d, f);
    fmpz_poly_mul(gp, d, s);
    fmpz_poly_derivative(d, s);
    fmpz_poly_mul(d, f, d);
    fmpz_poly_sub(gp, gp, d);
    fmpz_poly_mul(ge, f, s);
    fmpz_poly_shift_left(d, gp, 1);
    fmpz_poly_sub(ge, ge, d);
    e = IntegerPoly(ge);
    p = IntegerPoly(gp);
    for (auto* q : {f, s, d, gp, ge}) fmpz_poly_clear(q);
    budget = 1024 + 16 * (e.bits() + p.bits() + pr.fz().bits());
  }
};

Rational power_of_two(long k) {
  Rational r(1);
  if (k >= 0)
    mpq_mul_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(k));
  else
    mpq_div_2exp(r.mpq(), r.mpq(), static_cast<mp_bitcnt_t>(-k));
  return r;
}

/// floor(log2 |x|) up to one, for x != 0.
long log2_of(const Rational& x) {
  return static_cast<long>(mpz_sizeinbase(mpq_numref(x.mpq()), 2)) -
         static_cast<long>(mpz_sizeinbase(mpq_denref(x.mpq()), 2));
}

/// x rounded down to a multiple of 2^e.
Rational floor_to(const Rational& x, long e) {
  Rational scaled = x;
  if (e >= 0)
    mpq_div_2exp(scaled.mpq(), scaled.mpq(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_mul_2exp(scaled.mpq(), scaled.mpq(), static_cast<mp_bitcnt_t>(-e));
  Integer n;
  mpz_fdiv_q(n.mpz(), mpq_numref(scaled.mpq()), mpq_denref(scaled.mpq()));
  return Rational(n) * power_of_two(e);
}

/// Shrinks the bracket of the one sign change of q between `good` (q <= 0) and `bad` (q > 0),
/// calling `accept` at every new good end until it returns true; false after `budget` rounds or
/// once the bracket is `budget` bits below the scale of `bad`.
/// Each round takes a Newton step from the midpoint (exact) and probes a dyadic neighbourhood of
/// width |bad - good| 2^-k around it: when the probes bracket the sign change, the bracket becomes
/// that neighbourhood and k doubles (quadratic convergence at a simple root), otherwise k halves
/// and a bisection keeps the bracket at least halving. A root wanted to b bits costs O(log b)
/// rounds near a simple root, and never more than b. `k` is the first round's: a bracket already
/// narrow (from doubles) starts with long steps.
template <class Accept>
bool refine_root(const IntegerPoly& q, Rational good, Rational bad, Accept accept, std::size_t budget, long k = 2) {
  if (accept(good)) return true;
  auto inside = [&](const Rational& x) { return good < bad ? good < x && x < bad : bad < x && x < good; };
  auto step = [&](const Rational& x) {  // moves one end to x (inside the bracket); true if `good` moved
    if (q.sign(x) <= 0) {
      good = x;
      return true;
    }
    bad = x;
    return false;
  };
  const long top = log2_of(bad);  // bad != 0 (good may be 0): the scale the budget counts bits from
  for (std::size_t round = 0; round < budget; ++round) {
    const Rational width = good < bad ? bad - good : good - bad;
    if (log2_of(width) < top - static_cast<long>(budget)) return false;  // as many bits as allowed
    const Rational mid = (good + bad) / 2;
    const long e = log2_of(width) - k;
    const Rational delta = power_of_two(e);
    std::optional<Rational> x0 = q.newton_floor(mid, e);
    if (!x0 || !inside(*x0)) x0 = floor_to(mid, e);
    // The probes in the order from good to bad.
    Rational a = *x0 - delta, b = *x0 + 2 * delta;
    if (bad < good) std::swap(a, b);
    bool moved = false, bracketed = false;
    if (inside(a)) {
      moved = step(a);
      if (moved && inside(b)) bracketed = !step(b), moved = true;
    }
    if (moved && accept(good)) return true;
    const Rational now = good < bad ? bad - good : good - bad;
    k = bracketed ? 2 * k : std::max(2L, k / 2);
    if (2 * now > width && step((good + bad) / 2) && accept(good)) return true;
  }
  return false;
}

/// What refine_root accepts on the curve: a good end lambda where p(x(lambda)) has the sign `want`
/// gives its point to `consider`; true once `found` holds a point.
auto curve_accept(const Pair& pr, const Secular& sec, int want, const std::optional<V3>& found,
                  const std::function<void(const V3&)>& consider) {
  return [&pr, &sec, want, &found, &consider](const Rational& l) {
    if (sec.p.sign(l) == want)
      if (const auto x = pr.x_of(l)) consider(*x);
    return found.has_value();
  };
}

/// The exact search for the point with p of sign `want` (-1: min side, lambda > 0; 1: max side,
/// lambda in (lambda_s, 0)) from the double search's last bracket of lambda*, its ends taken exactly
/// and checked (doubles only suggested them). Steps start long: the bracket is a double's width,
/// where Newton's step is good to about twice as many bits. False when the bracket does not hold.
bool refine_from_doubles(const Pair& pr, const Secular& sec, const DoubleBracket& bracket, int want,
                         std::optional<V3>& found, const std::function<void(const V3&)>& consider) {
  if (!bracket) return false;
  Rational good = exact_rational(bracket->first), bad = exact_rational(bracket->second);
  // At a double's width the doubles' signs are rounding noise: each end moves away from the other
  // by growing multiples of the width until its exact sign holds.
  const Rational width = bad - good;  // signed: from good towards bad
  Rational step = width;
  for (int i = 0; i < 6 && sec.e.sign(good) > 0; ++i, step *= 256) good -= step;
  step = width;
  for (int i = 0; i < 6 && sec.e.sign(bad) <= 0; ++i, step *= 256) bad += step;
  // good past 0 becomes 0 (x(0) is the centre, e < 0 there); bad strictly on the side searched.
  if (want < 0 ? good < 0 : good > 0) good = 0;
  const bool side = want < 0 ? bad > 0 : bad < 0 && pr.ls.compare(bad) > 0;
  if (!side || sec.e.sign(good) > 0 || sec.e.sign(bad) <= 0) return false;
  return refine_root(sec.e, good, bad, curve_accept(pr, sec, want, found, consider), sec.budget, 32);
}

/// The point of the solid with p < 0 from the min side (lambda > 0). x(0) is the centre; else the
/// minimiser x(lambda*) lies on the surface, lambda* > 0 the root of e(x(lambda)). Its bracket is
/// found on powers of two (galloping exponents: a body of size 2^-k costs O(log k) steps to reach
/// its scale), then bisected; every lower end lambda has e(x(lambda)) <= 0, and as it tends to
/// lambda* p(x(lambda)) tends to min p < 0, so the first lower end with p(x(lambda)) < 0 gives the
/// point, exactly on the curve and inside the solid, after as many bits as the margin of p needs.
void min_side_point(const Pair& pr, const Secular& sec, std::optional<V3>& found,
                    const std::function<void(const V3&)>& consider) {
  auto try_lambda = [&](const Rational& l) {
    if (sec.e.sign(l) <= 0 && sec.p.sign(l) < 0)
      if (const auto x = pr.x_of(l)) consider(*x);
  };
  try_lambda(Rational(0));
  if (found) return;
  // lo, hi > 0 with e(x(lo)) <= 0 < e(x(hi)).
  const int up = sec.e.sign(Rational(1)) <= 0 ? 1 : -1;
  long k = 0, prev = 0;
  for (long step = 1; (sec.e.sign(power_of_two(k)) <= 0) == (up > 0); step *= 2) {
    if (static_cast<std::size_t>(step) > sec.budget) throw internal_error("no bracket of the minimiser's multiplier");
    prev = k;
    k = up * step;
  }
  // Down to one binade: binary search on the exponent between prev and k.
  long lo_exp = std::min(prev, k), hi_exp = std::max(prev, k);
  while (hi_exp - lo_exp > 1) {
    const long mid = lo_exp + (hi_exp - lo_exp) / 2;
    (sec.e.sign(power_of_two(mid)) <= 0 ? lo_exp : hi_exp) = mid;
  }
  refine_root(sec.e, power_of_two(lo_exp), power_of_two(hi_exp), curve_accept(pr, sec, -1, found, consider),
              sec.budget);
}

/// A rational in (lambda_s, 0) within about 2^-bits of lambda_s (relative to lambda_s, or to the
/// irrational part's coefficient); nullopt while the approximation is too coarse.
std::optional<Rational> above_lambda_s(const LambdaS& ls, unsigned bits) {
  Rational l = approximate(ls, ls.value(), bits, true);
  if (ls.rational()) {
    Rational step = l < 0 ? -l : l;
    mpq_div_2exp(step.mpq(), step.mpq(), bits);
    l += step;
  }
  if (!(l < 0) || ls.compare(l) <= 0) return std::nullopt;
  return l;
}

/// Hard case of the max side: the maximisers are x^ + w, w in the kernel of lambda_s A + M with
/// w^T M w = -e(x^) (hard_case); x^ and the kernel's basis are rounded to `bits` and the point
/// x0 + t w0 taken with t a rational just inside the roots of e(x0 + t w0) = 0 (exact).
void kernel_walk(const Pair& pr, const Certificate& hard, unsigned bits,
                 const std::function<void(const V3&)>& consider) {
  V3 x0;
  for (int i = 0; i < 3; ++i) x0[i] = approximate(pr.ls, {hard.centre[i].a, hard.centre[i].b}, bits, true);
  for (const auto& dir : hard.directions) {
    V3 w;
    for (int i = 0; i < 3; ++i) w[i] = approximate(pr.ls, {dir[i].a, dir[i].b}, bits, true);
    // e(x0 + t w) = e(x0) + 2 t w^T (M x0 + m) + t^2 w^T M w <= 0 between its roots.
    Rational mw(0), g(0);
    for (int i = 0; i < 3; ++i) {
      Rational mi = pr.E(i, 3), wi(0);
      for (int j = 0; j < 3; ++j) {
        mi += pr.E(i, j) * x0[j];
        wi += pr.E(i, j) * w[j];
      }
      g += w[i] * mi;
      mw += w[i] * wi;
    }
    const Rational disc = g * g - mw * pr.e_at(x0);
    if (disc < 0 || mw == 0) continue;
    const Rational r = sqrt_below(disc, bits);
    for (int sign : {1, -1}) {
      V3 x;
      const Rational t = (-g + sign * r) / mw;  // |r| <= sqrt(disc): inside the roots
      for (int i = 0; i < 3; ++i) x[i] = x0[i] + t * w[i];
      consider(x);
    }
  }
}

/// The point of the solid with p > 0 from the max side (lambda in (lambda_s, 0)), as the min side
/// with the order reversed: lambda* in (lambda_s, 0) is bracketed by 0 and rationals approaching
/// lambda_s from above with doubling precision. When e(x(lambda)) stays <= 0 up to lambda_s (the
/// hard case), the maximiser is a limit point: the approach itself reaches it when p > 0 at
/// x^ = lim x(lambda), and the walk along the kernel of lambda_s A + M otherwise; both are tried
/// at every precision, so the search ends whichever case holds.
void max_side_point(const Pair& pr, const Secular& sec, std::optional<V3>& found,
                    const std::function<void(const V3&)>& consider) {
  auto try_lambda = [&](const Rational& l) {
    if (sec.e.sign(l) <= 0 && sec.p.sign(l) > 0)
      if (const auto x = pr.x_of(l)) consider(*x);
  };
  try_lambda(Rational(0));
  if (found) return;
  std::optional<Rational> lo;
  std::optional<Certificate> hard;
  for (unsigned bits = 4; bits <= sec.budget && !found && !lo; bits *= 2) {
    const std::optional<Rational> l = above_lambda_s(pr.ls, bits);
    if (!l) continue;
    if (sec.e.sign(*l) > 0) {
      lo = l;
      break;
    }
    try_lambda(*l);
    if (found) return;
    if (!hard) {
      hard.emplace();
      if (!hard_case(pr, *hard)) hard->directions.clear();
    }
    kernel_walk(pr, *hard, bits, consider);
  }
  if (!lo) return;
  refine_root(sec.e, Rational(0), *lo, curve_accept(pr, sec, 1, found, consider), sec.budget);
}

/// Whether the body is below 2^-20 of its distance to the origin (or its size is not a finite
/// double): then doubles around its centre cannot resolve it, and the search runs in its frame.
bool small_for_doubles(const DoubleMatrix4& em, const double c[3]) {
  auto e = [&](int i, int j) { return em[static_cast<std::size_t>(4 * i + j)]; };
  double least = HUGE_VAL, far = 0, r2 = e(3, 3);
  for (int i = 0; i < 3; ++i) {
    r2 += 2 * e(i, 3) * c[i];
    for (int j = 0; j < 3; ++j) r2 += c[i] * e(i, j) * c[j];
    least = std::min(least, e(i, i));
    far = std::max(far, std::fabs(c[i]));
  }
  const double size = std::sqrt(-r2 / least);  // -e(c) = r2 up to rounding
  return !(std::isfinite(size) && size > 0x1p-20 * far);
}

/// Q in the frame x = c + s u: H^T Q H for H = [[s I, c], [0, 1]].
Matrix4 in_frame(const Matrix4& q, const V3& c, const Rational& s) {
  Matrix4 out;
  std::array<Rational, 3> g;  // Q's block times c plus its last column: half the gradient at c
  for (int i = 0; i < 3; ++i) {
    g[i] = q(i, 3);
    for (int j = 0; j < 3; ++j) g[i] += q(i, j) * c[j];
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out(i, j) = s * s * q(i, j);
    out(i, 3) = out(3, i) = s * g[i];
  }
  out(3, 3) = Pair::form(q, c);
  return out;
}

/// A power of two near the body's largest semi-axis, sqrt(-e(c) / min_i M_ii) (bit lengths only).
Rational body_scale(const Matrix4& e, const Rational& e_at_centre) {
  long least = 0;
  for (int i = 0; i < 3; ++i) least = i == 0 ? log2_of(e(0, 0)) : std::min(least, log2_of(e(i, i)));
  return power_of_two((log2_of(-e_at_centre) - least) / 2);
}

/// sign(X^T Q X), X = (x, 1), for every matrix Q within the entries' enclosures (exact doubles:
/// lo = hi) and x in the point's, when interval arithmetic decides it; 0 when it does not (an
/// enclosure containing 0, overflow or NaN).
int interval_sign(const detail::EnclosureMatrix4& q, const Enclosure3& x) {
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> guard;
  auto entry = [&q](std::size_t k) { return I(q.lo[k], q.hi[k]); };
  I acc = entry(15);
  for (std::size_t i = 0; i < 3; ++i) {
    I row = entry(4 * i + 3) * 2;  // off-diagonal entries appear twice
    for (std::size_t j = 0; j < 3; ++j) row += entry(4 * i + j) * I(x[j]);
    acc += row * I(x[i]);
  }
  if (acc.inf() > 0) return 1;
  if (acc.sup() < 0) return -1;
  return 0;
}

/// Two points of the solid ellipsoid with p < 0 and p > 0 (position C).
void crossing_points(const Pair& pr, Certificate& c) {
  std::optional<V3> inside, outside;
  DoubleBracket brackets[2];
  const std::optional<DoubleMatrix4> ed_own = pr.E.own_doubles();
  const std::optional<DoubleMatrix4> pd_own = ed_own ? pr.P.own_doubles() : std::nullopt;
  // Exact signs of e and p at the candidates, built on first use: with the quadrics' doubles the
  // interval signs decide most pairs' every candidate.
  std::optional<IntegerForm> ez_form, pz_form;
  auto exact_forms = [&]() -> std::pair<const IntegerForm&, const IntegerForm&> {
    if (!ez_form) {
      if (pr.ez_pooled && pr.pz_pooled) {
        ez_form.emplace(*pr.ez_pooled);
        pz_form.emplace(*pr.pz_pooled);
      } else if (ed_own && pd_own && !pr.has_forms()) {  // the integer forms with their scales are not needed
        ez_form.emplace(*ed_own);
        pz_form.emplace(*pd_own);
      } else {
        ez_form.emplace(pr.forms().ez);
        pz_form.emplace(pr.forms().pz);
      }
    }
    return {*ez_form, *pz_form};
  };
  // The signs in interval arithmetic on the quadrics' entries first (0: undecided, then the exact
  // sign on integers decides): most candidates are far enough from both surfaces. The entries are
  // the quadric's exact doubles, else the enclosures the reader of decimal text stored.
  auto entries = [](const std::optional<DoubleMatrix4>& own, const detail::EnclosureMatrix4* stored) {
    if (own) return std::optional<detail::EnclosureMatrix4>({*own, *own});
    return stored ? std::optional<detail::EnclosureMatrix4>(*stored) : std::nullopt;
  };
  const std::optional<detail::EnclosureMatrix4> e_entries = entries(ed_own, pr.E.enclosure()),
                                                p_entries = entries(pr.P.own_doubles(), pr.P.enclosure());
  auto filtered = [](const std::optional<detail::EnclosureMatrix4>& q, const std::optional<Enclosure3>& x) {
    return q && x ? interval_sign(*q, *x) : 0;
  };
  // `known`: the point's enclosure when the caller has it (a point of doubles), else null.
  auto consider_at = [&](const V3& x, const std::optional<Enclosure3>* known) {
    const std::optional<Enclosure3> at = !(e_entries && p_entries) ? std::nullopt : known ? *known : enclosure(x);
    const int se = filtered(e_entries, at);
    if (se > 0) return;
    int sp = filtered(p_entries, at);
    if (se == 0 || sp == 0) {
      const IntegerForm::Point xz(x);
      const auto [ez, pz] = exact_forms();
      if (se == 0 && ez.sign(xz) > 0) return;
      if (sp == 0) sp = pz.sign(xz);
    }
    if (sp < 0 && !inside) inside = x;
    if (sp > 0 && !outside) outside = x;
  };
  auto consider = [&](const V3& x) { consider_at(x, nullptr); };
  // Candidates are pulled towards a dyadic centre (short exact arithmetic): the centre solved in
  // doubles, taken exactly, when it is strictly inside the solid (almost always); else the exact
  // centre (Cramer's rule on integers, several times dearer).
  const DoubleMatrix4 ed = pr.E.doubles();
  double pull_doubles[3];
  std::optional<V3> pull = approximate_centre(ed, pull_doubles);
  const std::optional<Enclosure3> pull_at = pull ? std::optional<Enclosure3>(enclosure(pull_doubles)) : std::nullopt;
  auto pull_e_sign = [&]() {
    const int s = filtered(e_entries, pull_at);
    return s != 0 ? s : exact_forms().first.sign(IntegerForm::Point(*pull));
  };
  if (pull && pull_e_sign() < 0 && !small_for_doubles(ed, pull_doubles)) {
    consider_at(*pull, &pull_at);
    double_curve_search(ed, pr.P.doubles(), pr.ls, *pull, inside, outside, consider_at, brackets);
  } else if (const std::optional<V3> ctr = detail::centre_of(pr.E)) {
    // A body too small or too far for doubles: the same search in the body's frame x = c + 2^k u
    // (an exact congruence; lambda and lambda_s unchanged), the body of unit size at the origin;
    // the points found are mapped back exactly.
    const V3& at = *ctr;
    consider(at);
    const Rational scale = body_scale(pr.E, pr.e_at(at));
    auto mapped = [&](const V3& u, const std::optional<Enclosure3>*) {  // u's enclosure is not x's
      V3 x;
      for (int i = 0; i < 3; ++i) x[i] = at[i] + scale * u[i];
      consider(x);
    };
    double_curve_search(to_doubles(in_frame(pr.E, at, scale)), to_doubles(in_frame(pr.P, at, scale)), pr.ls, V3{},
                        inside, outside, mapped, brackets);
  }
  // What the double search missed, the exact optimisers give (they always exist in a crossing).
  if (!inside || !outside) {
    const Secular sec(pr);
    const std::function<void(const V3&)> consider_fn = consider;
    if (!inside && !refine_from_doubles(pr, sec, brackets[0], -1, inside, consider_fn))
      min_side_point(pr, sec, inside, consider_fn);
    if (!outside && !refine_from_doubles(pr, sec, brackets[1], 1, outside, consider_fn))
      max_side_point(pr, sec, outside, consider_fn);
  }
  if (!inside || !outside)
    throw internal_error(std::string("no point of the solid ellipsoid with p ") + (inside ? "> 0" : "< 0") +
                         " for a pair classified C");
  c.kind = Certificate::Kind::Crossing;
  c.inside = *inside;
  c.outside = *outside;
}

/// A lambda in the domain with f(lambda) > 0 from the isolating intervals of f's real roots: f has
/// one sign between consecutive intervals, so one exact evaluation per gap decides. `below_domain`
/// (x at or below the domain's lower end) skips the gaps whose every point is outside.
template <class InDomain, class BelowDomain>
std::optional<Rational> lambda_between_roots(const Pair& pr, const std::vector<RealRoot>& roots, InDomain in_domain,
                                             BelowDomain below_domain) {
  for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
    const Rational& lo = roots[i].exact ? *roots[i].exact : roots[i].upper;
    const Rational& hi = roots[i + 1].exact ? *roots[i + 1].exact : roots[i + 1].lower;
    if (!(lo < hi) || below_domain(hi)) continue;
    const Rational l = detail::rational_inside(lo, hi, detail::Shortest::Bits);
    if (in_domain(l) && pr.f_sign(l) > 0) return l;
  }
  return std::nullopt;
}

}  // namespace

Certificate build(const Ellipsoid& e, const Paraboloid& p, Position position) { return build(e, p, position, Known{}); }

Certificate build(const Ellipsoid& e, const Paraboloid& p, Position position, const Known& known) {
  Certificate c;
  build(e, p, position, known, c);
  return c;
}

void build(const Ellipsoid& e, const Paraboloid& p, Position position, const Known& known, Certificate& c) {
  const Pair pr(e, p, known);
  const std::string name = to_string(position);
  auto in_gap = [&](const Rational& l) { return l < 0 && pr.ls.compare(l) > 0; };
  switch (position) {
    case Position::E:
    case Position::I: {
      const bool ext = position == Position::E;
      auto positive = [](const Rational& x) { return x > 0; };
      auto not_positive = [](const Rational& x) { return CGAL::sign(x) <= 0; };
      auto not_above_lambda_s = [&](const Rational& x) { return pr.ls.compare(x) <= 0; };
      std::optional<Rational> l;
      if (known.roots)
        l = ext ? lambda_between_roots(pr, *known.roots, positive, not_positive)
                : lambda_between_roots(pr, *known.roots, in_gap, not_above_lambda_s);
      if (!l) l = ext ? definite_lambda(pr, positive) : definite_lambda(pr, in_gap);
      if (!l) throw internal_error("no multiplier lambda with lambda P + E definite for a pair classified " + name);
      c.kind = Certificate::Kind::Definite;
      c.lambda = *l;
      return;
    }
    case Position::TE:
    case Position::TI: {
      // The double root lambda* of f is rational (math.md §8), and (x(lambda*), 1) spans the kernel.
      const Poly g = anysize::monic_gcd(pr.f(), anysize::derivative(pr.f()));
      const Poly q = anysize::quotient(g, anysize::monic_gcd(g, anysize::derivative(g)));
      for (const Rational& l : rational_roots(q)) {
        const bool ok = position == Position::TE ? l > 0 : in_gap(l);
        if (!ok) continue;
        const auto x = pr.x_of(l);
        if (!x || pr.e_at(*x) != 0 || pr.p_at(*x) != 0) continue;
        c.kind = Certificate::Kind::Tangent;
        c.lambda = l;
        c.contact = *x;
        return;
      }
      // The hard case's contact set exists whenever its linear system is consistent; only the
      // semidefiniteness at lambda_s makes it a tangency, which the verifier's check decides (rare).
      if (position == Position::TI && hard_case(pr, c) && !verify_certificate(e, p, position, c)) return;
      throw internal_error("no contact point for a pair classified " + name);
    }
    case Position::C:
      crossing_points(pr, c);
      return;
  }
  throw internal_error("no certificate for a pair classified " + name);
}

}  // namespace relpos::certificate
