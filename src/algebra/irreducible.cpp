#include "algebra/irreducible.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/nmod_poly.h>
#include <flint/ulong_extras.h>

#include <bitset>

#include "algebra/flint_thread.hpp"

namespace relpos::detail {

bool proven_irreducible(const std::vector<Integer>& h) {
  std::size_t n = h.size();
  while (n > 0 && h[n - 1] == 0) --n;
  if (n < 2) return false;
  if (n == 2) return true;
  const std::size_t degree = n - 1;
  constexpr std::size_t kMaxDegree = 255;
  if (degree > kMaxDegree) return false;
  flint_thread_cleanup_at_exit();
  fmpz_poly_t z;
  fmpz_poly_init(z);
  fmpz_t c;
  fmpz_init(c);
  for (std::size_t i = 0; i < n; ++i) {
    fmpz_set_mpz(c, h[i].mpz());
    fmpz_poly_set_coeff_fmpz(z, static_cast<slong>(i), c);
  }
  fmpz_clear(c);
  // Bit d: a factor of degree d over Z is still possible (0 and deg h always are).
  std::bitset<kMaxDegree + 1> possible;
  for (std::size_t d = 0; d <= degree; ++d) possible.set(d);
  bool proven = false;
  ulong p = 1000;  // small primes: the distinct-degree factorisation takes about log p products
  for (int used = 0, tried = 0; used < 10 && tried < 16 && !proven; ++tried) {
    p = n_nextprime(p, 1);
    nmod_poly_t m;
    nmod_poly_init(m, p);
    fmpz_poly_get_nmod_poly(m, z);
    if (static_cast<std::size_t>(nmod_poly_degree(m)) == degree && nmod_poly_is_squarefree(m)) {
      ++used;
      // The distinct-degree factorisation: factor k is the product of the irreducible factors of
      // degree degs[k]; their number is its degree over degs[k].
      nmod_poly_factor_t f;
      nmod_poly_factor_init(f);
      slong* degs = static_cast<slong*>(flint_malloc(static_cast<std::size_t>(degree + 1) * sizeof(slong)));
      nmod_poly_factor_distinct_deg(f, m, &degs);
      std::bitset<kMaxDegree + 1> sums;
      sums.set(0);
      for (slong k = 0; k < f->num; ++k) {
        const slong count = nmod_poly_degree(f->p + k) / degs[k];
        for (slong j = 0; j < count; ++j) sums |= sums << static_cast<std::size_t>(degs[k]);
      }
      flint_free(degs);
      nmod_poly_factor_clear(f);
      possible &= sums;
      proven = true;
      for (std::size_t d = 1; d < degree; ++d) proven = proven && !possible.test(d);
    }
    nmod_poly_clear(m);
  }
  fmpz_poly_clear(z);
  return proven;
}

}  // namespace relpos::detail
