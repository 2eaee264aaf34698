// recycled.hpp, the one per-thread free list: each live handle has its own object, a given-back
// object is the next one taken (its limbs kept), objects given back on other threads stay on those
// threads; PooledInteger through it: values computed with integers taken again from the list equal
// the same values computed with GMP's own integers.
#include <gmp.h>

#include <catch2/catch.hpp>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include "algebra/recycled.hpp"
#include "filters/pooled_integer.hpp"

namespace {

struct Limbs {
  mpz_t z;
  Limbs() { mpz_init(z); }
  ~Limbs() { mpz_clear(z); }
  Limbs(const Limbs&) = delete;
  Limbs& operator=(const Limbs&) = delete;
};

}  // namespace

TEST_CASE("Recycled: each live handle its own object, a given-back one reused", "[recycled]") {
  const int* first;
  {
    relpos::detail::Recycled<int> a, b;
    CHECK(&*a != &*b);
    *a = 7;
    first = &*a;
  }
  relpos::detail::Recycled<int> c, d;
  CHECK((&*c == first || &*d == first));  // both given back: one of them is the first again
}

TEST_CASE("Recycled: take and give keep the object and its limbs, per thread", "[recycled]") {
  using List = relpos::detail::Recycled<Limbs>;
  std::unique_ptr<Limbs> x = List::take();
  mpz_ui_pow_ui(x->z, 3, 500);  // about 800 bits
  const mp_limb_t* limbs = mpz_limbs_read(x->z);
  const std::size_t alloc = static_cast<std::size_t>(x->z->_mp_alloc);
  Limbs* kept = x.get();
  List::give(std::move(x));
  std::unique_ptr<Limbs> y = List::take();  // the last given back is the first taken
  CHECK(y.get() == kept);
  CHECK(static_cast<std::size_t>(y->z->_mp_alloc) == alloc);  // its limbs kept: no new allocation
  CHECK(mpz_limbs_read(y->z) == limbs);
  Limbs* other = nullptr;
  std::thread t([&] {
    std::unique_ptr<Limbs> z = List::take();  // another thread's list: never this thread's object
    other = z.get();
    List::give(std::move(z));
  });
  t.join();
  CHECK(other != kept);
  List::give(std::move(y));
}

TEST_CASE("PooledInteger: values through reused integers equal GMP's", "[recycled]") {
  std::mt19937_64 rng(20261207);
  for (int round = 0; round < 200; ++round) {
    const long a = static_cast<long>(rng() >> 2) - (1L << 60), b = static_cast<long>(rng() >> 40) - (1L << 22);
    // (a b + a)^3 - b^5 with PooledInteger: temporaries taken from and given back to the list
    const relpos::PooledInteger pa(a), pb(b);
    const relpos::PooledInteger t = pa * pb + pa;
    const relpos::PooledInteger lhs = t * t * t - pb * pb * pb * pb * pb;
    mpz_t za, zb, zt, zr, z5;
    mpz_inits(za, zb, zt, zr, z5, nullptr);
    mpz_set_si(za, a);
    mpz_set_si(zb, b);
    mpz_mul(zt, za, zb);
    mpz_add(zt, zt, za);
    mpz_pow_ui(zr, zt, 3);
    mpz_pow_ui(z5, zb, 5);
    mpz_sub(zr, zr, z5);
    CHECK(mpz_cmp(lhs.mpz(), zr) == 0);
    mpz_clears(za, zb, zt, zr, z5, nullptr);
  }
}
