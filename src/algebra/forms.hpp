// Exact forms of a quadric's matrix, computed once for every caller: the one matrix view the
// generic formulas read, and the conversions every stage needs -- double enclosures for the interval
// stage, each matrix's own integer form for the reported evidence (with its scale split along 2, 5
// and the rest, and the reduction by powers of it), the closed forms of a decimal sphere and
// standard paraboloid, and the compact integer form of the exact decisions (math.md §11). One
// header per job; this one gathers them for the stages that read several.
#pragma once

#include "algebra/closed_evidence.hpp"
#include "algebra/compact_integers.hpp"
#include "algebra/decimal_recipe.hpp"
#include "algebra/denominators.hpp"
#include "algebra/divided_by_powers.hpp"
#include "algebra/enclosures.hpp"
#include "algebra/exact_doubles.hpp"
#include "algebra/integer_form.hpp"
#include "algebra/matrix_view.hpp"
#include "algebra/power_of_five.hpp"
#include "algebra/split_scale.hpp"
