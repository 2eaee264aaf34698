// The decide floor's entry points (include/relpos/classify.hpp): decide_position, classify,
// classify_exact -- each a climb of the ladder (ladder.hpp) on the pair's one home (pair/pair.hpp),
// with the full evidence read off the same home (evidence.cpp).
#include "relpos/classify.hpp"

#include <optional>

#include "algebra/large_stack.hpp"
#include "algebra/pair_size.hpp"
#include "algebra/shape_filter.hpp"
#include "decide/evidence.hpp"
#include "decide/ladder.hpp"
#include "decide/unchecked.hpp"

namespace relpos {

std::string to_string(Stage s) { return detail::stage_row(s).name; }

namespace {

Classification classify_impl(const Ellipsoid& e, const Paraboloid& p, Evidence evidence, bool use_filter) {
  detail::PairContext pair(e, p);
  detail::Climb c(pair, use_filter);
  const Verdict& v = detail::climb(c);
  Classification out = detail::blank_classification();
  out.verdict = v;
  if (evidence == Evidence::Full) detail::fill_full_evidence(pair, v, out);
  return out;
}

/// f() directly, or, for a pair beyond the default size limit (a raised SizeLimit: `bits` from
/// check_normalized_pair_size), on a thread whose stack fits the exact root isolation's recursion,
/// whose depth grows with the numbers (algebra/large_stack.hpp).
template <class F>
auto with_stack_for(std::size_t bits, F f) -> decltype(f()) {
  if (bits <= kMaxNormalizedBits) return f();
  std::optional<decltype(f())> out;
  detail::run_on_large_stack(detail::stack_for_bits(bits), [&] { out.emplace(f()); });
  return std::move(*out);
}

}  // namespace

Verdict decide_position(const Ellipsoid& e, const Paraboloid& p, const SizeLimit& limit) {
  // Doubles and the fast reader's numbers are within the size limit: the check's own two flag
  // tests, without the call.
  std::size_t bits = 0;
  if (!storage_of(e).within_size_limit() || !storage_of(p).within_size_limit())
    bits = detail::check_normalized_pair_size(e, p, limit);
  return with_stack_for(bits, [&] {
    const detail::PairContext pair(e, p);
    detail::Climb c(pair, true);
    return detail::climb(c);
  });
}

Verdict decide_position(const DoubleMatrix4& e, const DoubleMatrix4& p) {
  // The objects from_doubles builds (normalized in place, the same orientation), with every shape
  // sign but the determinants certified; the ladder certifies those from the pencil or gives up.
  // Matrices of doubles are within the size limit (check_normalized_pair_size): no check. The
  // ellipsoid's signs assume round to nearest: the ladder certifies the determinants (clears
  // `pending`) only in that mode; in any other the two steps below decide.
  using detail::QuadricAccess;
  Ellipsoid ell = QuadricAccess::from_doubles_unchecked<Ellipsoid>(e);
  Paraboloid par = QuadricAccess::from_doubles_unchecked<Paraboloid>(p);
  detail::QuadricMatrix& em = QuadricAccess::storage(ell);
  detail::QuadricMatrix& pm = QuadricAccess::storage(par);
  const int oe = detail::shape_filter::ellipsoid_before_det_if_nearest(em.filter_doubles());
  const int op = oe != 0 ? detail::shape_filter::paraboloid_before_det(p, pm.filter_doubles()) : 0;
  if (op != 0) {
    if (oe < 0) em.negate_doubles();
    if (op < 0) pm.negate_doubles();
    bool pending = true;
    const detail::PairContext pair(ell, par);
    detail::Climb c(pair, true, &pending);
    const Verdict& v = detail::climb(c);
    if (!pending) return v;
  }
  // Anything uncertain, and every invalid input: the two steps themselves (their errors, the
  // ellipsoid's first: two statements, as the order of a call's arguments is unspecified).
  const Ellipsoid first = Ellipsoid::from_doubles(e);
  return decide_position(first, Paraboloid::from_doubles(p));
}

Classification classify(const Ellipsoid& e, const Paraboloid& p, Evidence evidence, const SizeLimit& limit) {
  return with_stack_for(detail::check_normalized_pair_size(e, p, limit),
                        [&] { return classify_impl(e, p, evidence, true); });
}

Classification classify_exact(const Ellipsoid& e, const Paraboloid& p, Evidence evidence, const SizeLimit& limit) {
  return with_stack_for(detail::check_normalized_pair_size(e, p, limit),
                        [&] { return classify_impl(e, p, evidence, false); });
}

Classification detail::classify_unchecked(const Ellipsoid& e, const Paraboloid& p, Evidence evidence) {
  return classify_impl(e, p, evidence, true);
}

}  // namespace relpos
