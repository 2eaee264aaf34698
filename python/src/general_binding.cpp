// The general pair in Python (doc/python.md, "Any real quadric"): relpos._relpos._classify_quadric_json
// and _verify_quadric, the compiled halves of relpos.classify and relpos.verify for a relpos.Quadric.
// The answer is the JSON text `relpos batch` writes for a line with "quadric" (the one answer writer,
// src/io/answer_json.hpp), and the certificate is read back and checked by the functions `relpos
// verify` calls, so both answers and verdicts are the CLI's.
#include <pybind11/stl.h>

#include <optional>
#include <relpos/general_classify.hpp>
#include <string>

#include "io/answer_json.hpp"
#include "io/general_io.hpp"
#include "io/json_tree.hpp"
#include "module.hpp"

namespace relpos_python {

namespace {

using namespace pybind11::literals;

/// The answer of `relpos batch` (full evidence) or `relpos batch --evidence minimal` for the line
/// {"ellipsoid": e, "quadric": q}, without "id", as text; the size limit as the line's (max_bits).
std::string classify_quadric_json(const relpos::Ellipsoid& e, const relpos::Quadric& q, bool full, int digits,
                                  std::size_t max_bits) {
  py::gil_scoped_release release;
  const std::size_t bits = relpos::detail::io::check_general_pair_size(e, q, relpos::SizeLimit{max_bits});
  if (full)
    return relpos::detail::io::answer_text(
        2048, relpos::detail::io::with_stack_for_general(bits, [&] { return relpos::classify(e, q); }), digits);
  return relpos::detail::io::answer_text(
      256, relpos::detail::io::with_stack_for_general(bits, [&] { return relpos::decide_position(e, q); }));
}

/// The verifier's reason why the certificate (JSON text) does not prove the position, or None.
std::optional<std::string> verify_quadric(const relpos::Ellipsoid& e, const relpos::Quadric& q,
                                          const std::string& position, const std::string& certificate) {
  const std::optional<relpos::QuadricPosition> p = relpos::detail::io::quadric_position_from_text(position);
  if (!p) throw relpos::InputError("position \"" + position + "\" is not one of I, TI, C, TE, E, O, TO, EQ");
  const relpos::QuadricCertificate c =
      relpos::detail::io::quadric_certificate_from_json(relpos::detail::io::parse_json_exact(certificate));
  py::gil_scoped_release release;
  return relpos::verify_certificate(e, q, *p, c);
}

}  // namespace

void bind_general(py::module_& m) {
  m.def("_classify_quadric_json", &classify_quadric_json, "e"_a, "q"_a, "full"_a = true, "digits"_a = 12,
        "max_bits"_a = relpos::kMaxNormalizedBits,
        "The JSON object of `relpos batch` (or `--evidence minimal`) for a line with \"quadric\", without \"id\", "
        "as text.");
  m.def("_verify_quadric", &verify_quadric, "e"_a, "q"_a, "position"_a, "certificate"_a,
        "The independent verifier's reason why the general certificate (JSON text) does not prove the position, "
        "or None.");
}

}  // namespace relpos_python
