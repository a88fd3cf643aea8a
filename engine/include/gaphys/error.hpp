// The exceptions the engine throws. invalid_input, for bad input, is thrown
// before any state changes, so a caller that catches it keeps a consistent
// world.
#pragma once

#include <stdexcept>
#include <string>

namespace gaphys {

class invalid_input : public std::invalid_argument {
 public:
  explicit invalid_input(const std::string& message) : std::invalid_argument(message) {}
};

// Thrown by world::step when a body's motion overflowed within the step
// though its inputs were steppable (contact impulses between bodies of
// absurd masses or speeds, say): rather than hand on NaNs, which would
// poison every later step. Unlike invalid_input it comes after the step
// changed the world: restore a snapshot taken before it.
class numeric_overflow : public std::runtime_error {
 public:
  explicit numeric_overflow(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace gaphys
