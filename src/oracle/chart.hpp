// The judge's chart: error rate against eps on a log axis (eps = 0, the exact tangencies, on a tick
// of its own at the left), one curve for all the families together, one per family, and the float
// baselines' curves (all families), as a PNG written with no dependency (raster.hpp, png.hpp).
#pragma once

#include <string>

#include "oracle/judge.hpp"

namespace relpos::detail::oracle {

/// The PNG file of the chart of r.curves.
std::string chart_png(const JudgeReport& r);

}  // namespace relpos::detail::oracle
