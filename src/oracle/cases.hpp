// `relpos cases` and relpos.testing.cases (doc/oracle.md): the constructed pairs of families.hpp with
// the three truths of each (the construction, relpos on the doubles of the parameters, relpos on the
// float code's matrices) written as JSON Lines that `relpos batch` reads and `relpos judge` judges.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "oracle/families.hpp"
#include "oracle/float_matrices.hpp"
#include "relpos/margin.hpp"
#include "relpos/position.hpp"

namespace relpos::detail::oracle {

/// The default epsilons of `relpos cases`.
inline const char* const kDefaultEps = "1e-2,1e-4,1e-6,1e-8,1e-10,1e-12,0";

struct CaseOptions {
  std::vector<std::string> families;  ///< names, or "all"
  std::size_t n = 100;                ///< cases per family and eps
  std::vector<std::string> eps;       ///< exact numbers in [0, 1); empty: kDefaultEps
  std::uint64_t seed = 1;
  unsigned threads = 0;  ///< 0: every core (the labels cost a classification each)
};

struct Case {
  std::string id;  ///< "family/eps/index"
  const Family* family = nullptr;
  std::string eps_text;  ///< as given
  Rational eps;
  std::uint64_t index = 0;
  Construction construction;
  DoubleParameters doubles;
  DoubleMatrix4 e_matrix{}, p_matrix{};     ///< the float code's matrices (float_matrices.hpp)
  Position exact_position = Position::I;    ///< the construction's, or relpos's for the random family
  Position double_position = Position::I;   ///< relpos on the doubles of the parameters
  std::optional<Position> matrix_position;  ///< relpos on the matrices' upper triangles, if they are a pair
  std::string matrix_error;                 ///< why not, otherwise
  /// s* with its proof (margin.hpp) of the exact pair and of the doubles of the parameters: the
  /// judge's tolerance reads them (doc/oracle.md, "Tolerance").
  std::optional<Margin> margin, double_margin;
};

/// Every case of the options, family by family, eps by eps, index by index. Throws InputError for an
/// unknown family or an eps outside [0, 1).
std::vector<Case> make_cases(const CaseOptions& options);

/// What a line's "ellipsoid" and "paraboloid" members hold: the exact parameters (strings "p/q"),
/// their doubles (JSON numbers, for `relpos batch --numbers double`) or the float code's matrices.
enum class Form { Exact, Double, Matrix };

/// The JSON line of a case (doc/oracle.md, "Case lines"), without a newline.
std::string case_line(const Case& c, Form form);

}  // namespace relpos::detail::oracle
