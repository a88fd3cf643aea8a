// Numbers as short text (printf's %g), for labels and parameter values.
#pragma once

#include <cstdio>
#include <string>

namespace gaphys_compare {

inline std::string number(double value, int digits = 6) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace gaphys_compare
