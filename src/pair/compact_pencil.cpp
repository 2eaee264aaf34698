#include "pair/compact_pencil.hpp"

#include <gmp.h>

#include <array>
#include <utility>

#include "algebra/forms.hpp"
#include "algebra/pencil.hpp"

namespace relpos::detail {

CompactPencil::CompactPencil(const Matrix4& p, const Matrix4& e) {
  forms::MatrixOf<PooledInteger> pp, ep;
  std::array<mpz_ptr, 16> pz, ez;
  for (std::size_t i = 0; i < 16; ++i) pz[i] = pp.a[i].mpz(), ez[i] = ep.a[i].mpz();
  forms::to_compact_integers(p, e, pz, ez);
  f_ = characteristic_polynomial<PooledInteger>(pp, ep);
  s_ = special_polynomial<PooledInteger>(pp, ep);
}

const PooledInteger& CompactPencil::discriminant_times_27() const {
  if (!disc27_) disc27_.emplace(relpos::discriminant_times_27(f_));
  return *disc27_;
}

const SturmHabicht<PooledInteger>& CompactPencil::sturm_habicht() const {
  if (!sturm_habicht_) {
    discriminant_times_27();
    PooledInteger disc = std::move(*disc27_);  // not read again once the sequence holds Disc(f)
    disc27_.reset();
    mpz_divexact_ui(disc.mpz(), disc.mpz(), 27);  // Disc(f) itself, the sequence's g0: 80 products fewer
    sturm_habicht_.emplace(f_, std::move(disc));
  }
  return *sturm_habicht_;
}

Quartic<Integer> CompactPencil::f_integer() const {
  return {f_[0].to_integer(), f_[1].to_integer(), f_[2].to_integer(), f_[3].to_integer(), f_[4].to_integer()};
}

Quadratic<Integer> CompactPencil::s_integer() const {
  return {s_[0].to_integer(), s_[1].to_integer(), s_[2].to_integer()};
}

}  // namespace relpos::detail
