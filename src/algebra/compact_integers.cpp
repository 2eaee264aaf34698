#include "algebra/compact_integers.hpp"

#include "algebra/denominators.hpp"

namespace relpos::detail::forms {
namespace {

/// The scratch integers of to_compact_integers, one set per thread: they keep their limbs between
/// calls, so a warm thread converts a pair without malloc (a fresh mpz_t allocates on first write).
struct CompactScratch {
  mpz_t t[3], g, den, l, content, dens[16];
  CompactScratch() {
    for (auto& x : t) mpz_init(x);
    for (auto& x : dens) mpz_init(x);
    for (mpz_ptr x : {g, den, l, content}) mpz_init(x);
  }
  ~CompactScratch() {
    for (auto& x : t) mpz_clear(x);
    for (auto& x : dens) mpz_clear(x);
    for (mpz_ptr x : {g, den, l, content}) mpz_clear(x);
  }
  CompactScratch(const CompactScratch&) = delete;
  CompactScratch& operator=(const CompactScratch&) = delete;
};

/// The primitive integer form of D m D (D = diag(1, 1, 1, t), s.t[k] = t^k) into `out`.
void compact_form(const Matrix4& m, CompactScratch& s, const std::array<mpz_ptr, 16>& out) {
  // x t^k = (n t^k / g) / (d / g) with g = gcd(d, t^k): lowest terms (each prime divides only one
  // of d / g and t^k / g). The numerators go into `out`, the denominators' lcm into l.
  mpz_set_ui(s.l, 1);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const std::size_t at = static_cast<std::size_t>(4 * i + j);
      const mpq_srcptr x = m.a[at].mpq();
      const int k = (i == 3) + (j == 3);
      const mpz_ptr n = out[at], d = s.dens[at];
      if (k == 0 || mpz_cmp_ui(s.t[1], 1) == 0) {
        mpz_set(n, mpq_numref(x));
        mpz_set(d, mpq_denref(x));
      } else if (mpz_cmp_ui(mpq_denref(x), 1) == 0) {
        mpz_mul(n, mpq_numref(x), s.t[k]);
        mpz_set_ui(d, 1);
      } else {
        mpz_gcd(s.g, mpq_denref(x), s.t[k]);
        mpz_divexact(d, mpq_denref(x), s.g);
        mpz_divexact(n, s.t[k], s.g);
        mpz_mul(n, n, mpq_numref(x));
      }
      fold_lcm(s.l, d);
    }
  mpz_set_ui(s.content, 0);
  for (std::size_t i = 0; i < 16; ++i) {
    if (mpz_cmp(s.l, s.dens[i]) != 0) {
      mpz_divexact(s.den, s.l, s.dens[i]);
      mpz_mul(out[i], out[i], s.den);
    }
    if (mpz_cmp_ui(s.content, 1) != 0) mpz_gcd(s.content, s.content, out[i]);  // 1 stays 1
  }
  // Divided by its content (a positive factor): the primitive form, whatever the scale of the
  // input matrix, so that the size limit on normalized forms bounds what the exact stages see.
  if (mpz_cmp_ui(s.content, 1) > 0)
    for (mpz_ptr x : out) mpz_divexact(x, x, s.content);
}

}  // namespace

void to_compact_integers(const Matrix4& p, const Matrix4& e, const std::array<mpz_ptr, 16>& pz,
                         const std::array<mpz_ptr, 16>& ez) {
  // On mpz_t throughout, written into the caller's integers: the entries of D M D in lowest terms
  // without rational or Integer temporaries (their allocations were most of the cost on long
  // near-tangent inputs).
  thread_local CompactScratch scratch;
  mpz_set_ui(scratch.t[0], 1);
  mpz_set_ui(scratch.t[1], 1);
  for (const auto* m : {&p, &e})
    for (int i = 0; i < 3; ++i) fold_lcm(scratch.t[1], mpq_denref((*m)(i, 3).mpq()));
  mpz_mul(scratch.t[2], scratch.t[1], scratch.t[1]);
  compact_form(p, scratch, pz);
  compact_form(e, scratch, ez);
}

}  // namespace relpos::detail::forms
