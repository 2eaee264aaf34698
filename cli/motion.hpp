// `relpos motion`: first contact and timeline of an ellipsoid moving by a polynomial rigid motion
// relative to a fixed paraboloid (doc/cli.md, "relpos motion"; math.md "Motion").
#pragma once

#include <string>
#include <vector>

namespace relpos_cli {

/// Runs `relpos motion` with the arguments after the command name; returns the exit code
/// (0 success, 1 input error, 2 usage error, 3 I/O error, 4 internal error).
int run_motion(const std::vector<std::string>& args);

}  // namespace relpos_cli
