// The one exception the engine throws for bad input. It is thrown before any
// state changes, so a caller that catches it keeps a consistent world.
#pragma once

#include <stdexcept>
#include <string>

namespace gaphys {

class invalid_input : public std::invalid_argument {
 public:
  explicit invalid_input(const std::string& message) : std::invalid_argument(message) {}
};

}  // namespace gaphys
