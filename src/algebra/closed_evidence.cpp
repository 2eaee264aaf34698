#include "algebra/closed_evidence.hpp"

#include <gmp.h>

#include <algorithm>
#include <initializer_list>
#include <stdexcept>

#include "algebra/power_of_five.hpp"
#include "algebra/word_arithmetic.hpp"

namespace relpos::detail::forms {
namespace {

using detail::Decimal;
using detail::DecimalRecipe;
using detail::word_gcd;

/// The scratch integers of sphere_standard_evidence, one set per thread: warm limbs, no malloc.
struct ClosedScratch {
  static constexpr std::size_t kCount = 27;
  mpz_t t[kCount];
  ClosedScratch() {
    for (auto& x : t) mpz_init(x);
  }
  ~ClosedScratch() {
    for (auto& x : t) mpz_clear(x);
  }
  ClosedScratch(const ClosedScratch&) = delete;
  ClosedScratch& operator=(const ClosedScratch&) = delete;
};

/// A standard paraboloid's 1/a^2 = 2^p 5^q / R^2, R the part of a's mantissa prime to 10.
struct InverseSquare {
  std::uint64_t rest = 1;
  long p = 0, q = 0;
};
InverseSquare inverse_square_of(const Decimal& a) {
  InverseSquare out;
  std::uint64_t m = a.m;  // a > 0: m != 0
  const int twos = __builtin_ctzll(m);
  m >>= twos;
  long fives = 0;
  for (; m % 5 == 0; m /= 5) ++fives;
  out.rest = m;
  out.p = -2L * (a.e + twos);
  out.q = -2L * (a.e + fives);
  return out;
}

/// out = (-1)^neg m 10^(e - low) (e >= low).
void set_scaled(mpz_ptr out, const Decimal& x, int low) {
  mpz_set_ui(out, x.m);
  if (x.m == 0) return;
  const auto k = static_cast<unsigned long>(x.e - low);
  times_power_of_five(out, out, k);
  mpz_mul_2exp(out, out, k);
  if (x.neg) mpz_neg(out, out);
}

/// One term c 2^u 5^v of a sum (c may be zero).
struct Term {
  mpz_srcptr c;
  long u, v;
};

/// sum = sum of c 2^(u - u0) 5^(v - v0) over the terms, u0 and v0 the smallest exponents: the sum is
/// sum 2^u0 5^v0. `t` is scratch.
void sum_terms(std::initializer_list<Term> terms, mpz_ptr sum, long& u0, long& v0, mpz_ptr t) {
  u0 = v0 = 0;
  bool any = false;
  for (const Term& x : terms) {
    if (mpz_sgn(x.c) == 0) continue;
    u0 = any ? std::min(u0, x.u) : x.u;
    v0 = any ? std::min(v0, x.v) : x.v;
    any = true;
  }
  mpz_set_ui(sum, 0);
  for (const Term& x : terms) {
    if (mpz_sgn(x.c) == 0) continue;
    if (x.u == u0 && x.v == v0) {
      mpz_add(sum, sum, x.c);
      continue;
    }
    times_power_of_five(t, x.c, static_cast<unsigned long>(x.v - v0));
    mpz_mul_2exp(t, t, static_cast<unsigned long>(x.u - u0));
    mpz_add(sum, sum, t);
  }
}

/// The rests R_a and R_b of a and b, their squares and the product of the squares.
struct Rests {
  std::uint64_t a, b;
  mpz_srcptr a2, b2, both;
};

/// Where reduce_all writes S^k times a coefficient: S = 2^twos 5^fives rest, and
/// q[k] = S's rest^k / (R_a^2 R_b^2) for k = 3, 4 (q[0] = rest^4, for a coefficient without R).
struct Multiples {
  unsigned long twos, fives;
  mpz_srcptr q[5];
};

/// A coefficient n 2^e2 5^e5 / (R_a^ja R_b^jb) on its way to lowest terms (R_a, R_b prime to 10;
/// ja, jb in {0, 2}), written into `out` (a fresh mpq) by reduce_all.
struct Pending {
  mpz_ptr n;  // its own integer: overwritten
  long e2 = 0, e5 = 0;
  int ja = 2, jb = 2;
  mpq_ptr out = nullptr;
  mpz_ptr multiple = nullptr;  // S^k times the coefficient, or nullptr
  unsigned long k = 4;
};

constexpr std::size_t kMostPending = 8;

/// Each n's factors 2 and 5 moved into its exponents.
void strip_twos_and_fives(Pending* p, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    if (mpz_sgn(p[i].n) == 0) continue;
    const mp_bitcnt_t twos = mpz_scan1(p[i].n, 0);
    mpz_tdiv_q_2exp(p[i].n, p[i].n, twos);
    p[i].e2 += static_cast<long>(twos);
    p[i].e5 += static_cast<long>(remove_fives(p[i].n, ~0UL));
  }
}

/// shared[i] = {gcd(n_i, R_a), gcd(n_i, R_b)} (0 for 1) where one can be more than 1: for each R,
/// g = gcd(prod (n mod R), R) over the coefficients with R in their denominator is one word gcd;
/// gcd(n, R) divides g, so g = 1 clears every n, and else gcd(n, R) = gcd(n mod R, g), a gcd with
/// the short g (the residues are taken before any division by a factor of R_a: a divisor of a
/// number prime to R_b is prime to R_b).
void shared_with_rests(const Pending* p, std::size_t count, const Rests& r, std::uint64_t (*shared)[2]) {
  for (int side = 0; side < 2; ++side) {
    const std::uint64_t base = side ? r.b : r.a;
    if (base == 1) continue;
    std::uint64_t residue[kMostPending] = {};
    __extension__ unsigned __int128 product = 1;  // residues below 2^64: no overflow
    auto takes = [&](const Pending& x) {
      return mpz_sgn(x.n) != 0 && mpz_cmpabs_ui(x.n, 1) != 0 && (side ? x.jb : x.ja) > 0;
    };
    for (std::size_t i = 0; i < count; ++i)
      if (takes(p[i])) {
        residue[i] = mpz_fdiv_ui(p[i].n, base);
        product = product * residue[i] % base;
      }
    const std::uint64_t g = word_gcd(static_cast<std::uint64_t>(product), base);  // gcd(0, R) = R
    if (g == 1) continue;
    for (std::size_t i = 0; i < count; ++i)
      if (takes(p[i])) shared[i][side] = word_gcd(residue[i] % g, g);
  }
}

/// S^k n 2^e2 5^e5 / (R_a^ja R_b^jb), n prime to 10: an integer, so both exponents are >= 0.
void write_multiple(const Pending& x, const Multiples& m) {
  const long twos = static_cast<long>(x.k * m.twos) + x.e2, fives = static_cast<long>(x.k * m.fives) + x.e5;
  if (twos < 0 || fives < 0 || x.ja != x.jb)
    throw std::logic_error("relpos internal error: S^k times a closed-form coefficient is not an integer");
  const mpz_srcptr q = m.q[x.ja ? x.k : 0];
  // Sized once (5 < 2^3), not regrown by each product: a caller's integer is fresh.
  mpz_realloc2(x.multiple, mpz_sizeinbase(x.n, 2) + mpz_sizeinbase(q, 2) + 3 * static_cast<unsigned long>(fives) +
                               static_cast<unsigned long>(twos) + 64);
  mpz_mul(x.multiple, x.n, q);
  times_power_of_five(x.multiple, x.multiple, static_cast<unsigned long>(fives));
  mpz_mul_2exp(x.multiple, x.multiple, static_cast<unsigned long>(twos));
}

/// The coefficient in lowest terms into x.out: the common factor of n with R_a^ja R_b^jb found by at
/// most ja gcds with R_a, then jb with R_b, each taking min(v_p(n), v_p(R)) more of every prime p
/// (as in divided_by_powers: the caps add up whether R_a and R_b share primes or not). Each next
/// step's factor divides the previous one: gcd(n / c, R) = gcd(n / c, c) for c = gcd(n, R) (a prime
/// of R dividing n / c divides c with the power it has in R), and gcd(n', R) = gcd(n', c) for a
/// divisor n' of n.
void write_reduced(const Pending& x, const std::uint64_t (&shared)[2], const Rests& r, mpz_ptr common) {
  const mpz_ptr num = mpq_numref(x.out), den = mpq_denref(x.out);
  mpz_set_ui(common, 1);
  for (int side = 0; side < 2; ++side) {
    std::uint64_t c = shared[side];  // gcd(n, R) of the undivided n
    if (c <= 1) continue;
    for (int step = 0; step < (side ? x.jb : x.ja); ++step) {
      if (step > 0 || mpz_cmp_ui(common, 1) != 0) c = mpz_gcd_ui(nullptr, x.n, c);
      if (c == 1) break;
      mpz_divexact_ui(x.n, x.n, c);
      mpz_mul_ui(common, common, c);
    }
  }
  const mpz_srcptr rest = x.ja && x.jb ? r.both : x.ja ? r.a2 : x.jb ? r.b2 : nullptr;
  const auto n5 = static_cast<unsigned long>(std::max(0L, x.e5)), n2 = static_cast<unsigned long>(std::max(0L, x.e2)),
             d5 = static_cast<unsigned long>(std::max(0L, -x.e5)), d2 = static_cast<unsigned long>(std::max(0L, -x.e2));
  // Each part sized once (5 < 2^3): the caller's rational is fresh.
  mpz_realloc2(num, mpz_sizeinbase(x.n, 2) + 3 * n5 + n2 + 64);
  mpz_realloc2(den, (rest ? mpz_sizeinbase(rest, 2) : 0) + 3 * d5 + d2 + 64);
  times_power_of_five(num, x.n, n5);
  mpz_mul_2exp(num, num, n2);
  set_power_of_five(den, d5);
  mpz_mul_2exp(den, den, d2);
  if (!rest) return;
  if (mpz_cmp_ui(common, 1) != 0) {
    mpz_divexact(common, rest, common);
    mpz_mul(den, den, common);
  } else {
    mpz_mul(den, den, rest);
  }
}

/// The pending coefficients in lowest terms, and their multiples by S^k where asked.
void reduce_all(Pending* p, std::size_t count, const Rests& r, const Multiples& m, mpz_ptr common) {
  std::uint64_t shared[kMostPending][2] = {};  // gcd(n, R_a), gcd(n, R_b) of the n before any division (0: 1)
  strip_twos_and_fives(p, count);
  shared_with_rests(p, count, r, shared);
  for (std::size_t i = 0; i < count; ++i) {
    const Pending& x = p[i];
    if (mpz_sgn(x.n) == 0) {
      mpq_set_ui(x.out, 0, 1);
      if (x.multiple) mpz_set_ui(x.multiple, 0);
      continue;
    }
    if (x.multiple) write_multiple(x, m);
    write_reduced(x, shared[i], r, common);
  }
}

/// The closed forms' state: the thread's scratch integers by name, the pending coefficients.
struct Closed {
  mpz_t* t;
  Pending pending[kMostPending];
  InverseSquare A, B;
  /// The coefficient k: the sum of the terms into n, to be written into `to`.
  void coefficient(std::size_t k, mpz_ptr n, std::initializer_list<Term> terms, mpq_ptr to) {
    sum_terms(terms, n, pending[k].e2, pending[k].e5, t[8]);
    pending[k].n = n;
    pending[k].out = to;
  }
};

/// f0 .. f4, s0 .. s2 as pending coefficients (math.md §2, §5; the closed forms of
/// sphere_standard_evidence), over 2^u 5^v R_a^2 R_b^2 (f1 to f4, s1, s2; A = 2^pa 5^qa R_b^2 /
/// (R_a^2 R_b^2), and so on) or 2^u 5^v (f0 = -r^2), each in its own integer; the sphere's numbers
/// and the vertex's are read as integers over 10^low. A vertex off the axis moves both bodies by
/// (-v_x, -v_y, 0): a congruence of determinant 1, so f and s are those of the centre (x - v_x,
/// y - v_y, z) and the vertex on the axis (math.md §2).
void pending_coefficients(const DecimalRecipe& sphere, const DecimalRecipe& paraboloid, Closed& c,
                          const ClosedEvidence& out) {
  mpz_t* t = c.t;
  const Decimal &x = sphere.n[0], &y = sphere.n[1], &z = sphere.n[2], &r = sphere.n[3];
  const Decimal &vx = paraboloid.n[0], &vy = paraboloid.n[1], &vz = paraboloid.n[2];
  int low = 0;
  for (const Decimal* d : {&x, &y, &z, &r, &vx, &vy, &vz})
    if (d->m != 0) low = std::min(low, d->e);
  const mpz_ptr X2 = t[0], Y2 = t[1], R2 = t[2], W = t[3], P1 = t[4], P2 = t[5], Q0 = t[6], sum = t[7], tmp = t[8],
                a2 = t[10], b2 = t[11], both = t[12], ra_w = t[13], rb_w = t[14];
  set_scaled(X2, x, low);  // (x - v_x) 10^(-low)
  if (vx.m != 0) {
    set_scaled(tmp, vx, low);
    mpz_sub(X2, X2, tmp);
  }
  mpz_mul(X2, X2, X2);
  set_scaled(Y2, y, low);
  if (vy.m != 0) {
    set_scaled(tmp, vy, low);
    mpz_sub(Y2, Y2, tmp);
  }
  mpz_mul(Y2, Y2, Y2);
  set_scaled(R2, r, low);
  mpz_mul(R2, R2, R2);
  set_scaled(W, vz, low);  // w = vz - z = W 10^low
  set_scaled(tmp, z, low);
  mpz_sub(W, W, tmp);
  mpz_sub(P1, X2, R2);  // (x^2 - r^2) 10^(-2 low)
  mpz_sub(P2, Y2, R2);  // (y^2 - r^2) 10^(-2 low)
  mpz_add(Q0, P1, Y2);  // (x^2 + y^2 - r^2) 10^(-2 low)
  const InverseSquare &A = c.A, &B = c.B;
  const long l1 = low, l2 = 2L * low, pab = A.p + B.p, qab = A.q + B.q;
  const mpz_ptr f0 = t[15], f1 = t[16], f2 = t[17], f3 = t[18], f4 = t[19], s1 = t[20], s2 = t[21];
  mpz_neg(f0, R2);
  c.pending[0] = {f0, l2, l2, 0, 0, out.f[0].mpq(), nullptr, 4};
  mpz_mul(ra_w, a2, P2);  // R_a^2 (y^2 - r^2)
  mpz_mul(rb_w, b2, P1);  // R_b^2 (x^2 - r^2)
  mpz_mul(sum, both, W);  // R_a^2 R_b^2 w
  c.coefficient(1, f1, {{rb_w, A.p + l2, A.q + l2}, {ra_w, B.p + l2, B.q + l2}, {sum, l1, l1}}, out.f[1].mpq());
  mpz_mul(ra_w, a2, W);  // R_a^2 w
  mpz_mul(rb_w, b2, W);  // R_b^2 w
  mpz_neg(sum, both);    // -R_a^2 R_b^2
  c.coefficient(2, f2, {{Q0, pab + l2, qab + l2}, {rb_w, A.p + l1, A.q + l1}, {ra_w, B.p + l1, B.q + l1}, {sum, -2, 0}},
                out.f[2].mpq());
  mpz_neg(ra_w, a2);
  mpz_neg(rb_w, b2);
  c.coefficient(3, f3, {{W, pab + l1, qab + l1}, {rb_w, A.p - 2, A.q}, {ra_w, B.p - 2, B.q}}, out.f[3].mpq());
  mpz_set_si(sum, -1);
  c.coefficient(4, f4, {{sum, pab - 2, qab}}, out.f[4].mpq());
  mpq_set_ui(out.s[0].mpq(), 1, 1);
  c.coefficient(5, s1, {{b2, A.p, A.q}, {a2, B.p, B.q}}, out.s[1].mpq());
  mpz_set_ui(sum, 1);
  c.coefficient(6, s2, {{sum, pab, qab}}, out.s[2].mpq());
}

/// lambda_s = -min(a, b)^2 = -1 / max(A, B) into out.lambda_s, and rho = (2 r / min(a, b)^2)^2 as
/// the pending 2 r 2^p 5^q / R^2 (squared once reduced: coprime parts stay coprime).
void lambda_s_and_rho(const DecimalRecipe& sphere, const DecimalRecipe& paraboloid, Closed& c,
                      const ClosedEvidence& out) {
  mpz_t* t = c.t;
  // a <= b compared as integers over 10^min(ea, eb).
  const Decimal &a = paraboloid.n[3], &b = paraboloid.n[4];
  const int e0 = std::min(a.e, b.e);
  set_scaled(t[4], a, e0);
  set_scaled(t[5], b, e0);
  const bool a_smaller = mpz_cmp(t[4], t[5]) <= 0;
  const InverseSquare& m = a_smaller ? c.A : c.B;
  // -R^2 2^-p 5^-q: R is prime to 10, so this is in lowest terms.
  const mpz_ptr ln = mpq_numref(out.lambda_s.mpq()), ld = mpq_denref(out.lambda_s.mpq());
  times_power_of_five(ln, a_smaller ? t[10] : t[11], static_cast<unsigned long>(std::max(0L, -m.q)));
  mpz_mul_2exp(ln, ln, static_cast<unsigned long>(std::max(0L, -m.p)));
  mpz_neg(ln, ln);
  set_power_of_five(ld, static_cast<unsigned long>(std::max(0L, m.q)));
  mpz_mul_2exp(ld, ld, static_cast<unsigned long>(std::max(0L, m.p)));
  const Decimal& r = sphere.n[3];
  const mpz_ptr rho = t[22];
  mpz_set_ui(rho, r.m);
  c.pending[7] = {rho,          1L + r.e + m.p, static_cast<long>(r.e) + m.q, a_smaller ? 2 : 0, a_smaller ? 0 : 2,
                  out.rho.mpq()};
}

/// S^4 f and S^3 s: S's rest is lcm(R_a^2, R_b^2) = (R_a R_b / g)^2; q[k] = rest^(k-1) / g^2. Sets
/// S^3 s0 = S^3 and the multiples the pending coefficients write.
Multiples multiples(Closed& c, const ClosedEvidence& out) {
  mpz_t* t = c.t;
  const std::uint64_t g = word_gcd(c.A.rest, c.B.rest);
  const mpz_ptr rest = t[23], q3 = t[24], q4 = t[25], rest4 = t[26];
  mpz_set_ui(rest, c.A.rest / g);
  mpz_mul_ui(rest, rest, c.B.rest);
  mpz_mul(rest, rest, rest);
  mpz_mul(q3, rest, rest);  // rest^2
  mpz_mul(q4, q3, rest);    // rest^3
  mpz_mul(rest4, q4, rest);
  const mpz_ptr s0 = out.s_multiple[0].mpz();  // S^3 s0 = S^3
  times_power_of_five(s0, q4, 3 * out.s_fives);
  mpz_mul_2exp(s0, s0, 3 * out.s_twos);
  for (int i = 0; g > 1 && i < 2; ++i) {  // g divides R_a R_b / g, so g^2 divides rest
    mpz_divexact_ui(q3, q3, g);
    mpz_divexact_ui(q4, q4, g);
  }
  for (std::size_t k = 0; k < 5; ++k) c.pending[k].multiple = out.f_multiple[k].mpz();
  for (std::size_t k = 5; k < 7; ++k) {
    c.pending[k].multiple = out.s_multiple[k - 4].mpz();
    c.pending[k].k = 3;
  }
  return {out.s_twos, out.s_fives, {rest4, nullptr, nullptr, q3, q4}};
}

}  // namespace

bool has_closed_evidence(const DecimalRecipe& sphere, const DecimalRecipe& paraboloid) {
  // The vertex anywhere: f and s do not see a translation of both bodies (pending_coefficients).
  return sphere.form == DecimalRecipe::Form::Sphere && paraboloid.form == DecimalRecipe::Form::Standard &&
         detail::has_closed_form(sphere) && !paraboloid.doubles;
}

void sphere_standard_evidence(const DecimalRecipe& sphere, const DecimalRecipe& paraboloid, const ClosedEvidence& out) {
  thread_local ClosedScratch scratch;
  Closed c{scratch.t, {}, inverse_square_of(paraboloid.n[3]), inverse_square_of(paraboloid.n[4])};
  mpz_t* t = scratch.t;
  // A = 2^pa 5^qa / R_a^2, B = 2^pb 5^qb / R_b^2.
  const mpz_ptr a2 = t[10], b2 = t[11], both = t[12];
  mpz_set_ui(a2, c.A.rest);
  mpz_mul(a2, a2, a2);
  mpz_set_ui(b2, c.B.rest);
  mpz_mul(b2, b2, b2);
  mpz_mul(both, a2, b2);
  const Rests rests{c.A.rest, c.B.rest, a2, b2, both};
  pending_coefficients(sphere, paraboloid, c, out);
  lambda_s_and_rho(sphere, paraboloid, c, out);
  const Multiples m = multiples(c, out);
  reduce_all(c.pending, kMostPending, rests, m, t[9]);
  mpz_mul(mpq_numref(out.rho.mpq()), mpq_numref(out.rho.mpq()), mpq_numref(out.rho.mpq()));
  mpz_mul(mpq_denref(out.rho.mpq()), mpq_denref(out.rho.mpq()), mpq_denref(out.rho.mpq()));
}

}  // namespace relpos::detail::forms
