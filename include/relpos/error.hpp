// The one exception type of relpos: input that is not what the theory covers, with a message that
// says what was found and where.
#pragma once

#include <stdexcept>
#include <string>

namespace relpos {

class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace relpos
