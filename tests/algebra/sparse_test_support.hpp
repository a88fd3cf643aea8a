// Comparisons on the sparse mv of algebras of more than 5 basis vectors
// (gaphys/ga/sparse_mv.hpp), shared by test_c4ga.cpp, test_ccga.cpp and
// test_qcga.cpp. Each file binds them to its algebra's mv.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace gaphys_test::sparse {

// x as the algebra's mv: a scalar, a named type or an mv.
template <class MV, class X>
MV widen(const X& x) {
  if constexpr (std::is_arithmetic_v<X>)
    return MV::from_blades({{0u, typename MV::scalar_type(x)}});
  else
    return MV(x);
}

template <class MV>
double largest(const MV& x) {
  double m = 0;
  for (const auto& t : x.terms) m = std::max(m, double(std::abs(t.value)));
  return m;
}

// Every coefficient of x and y within rel_tol times the larger of 1 and the
// largest coefficient of either; read through coefficient(), blade by blade.
template <class MV, class X, class Y>
::testing::AssertionResult near(const X& x_in, const Y& y_in, double rel_tol) {
  const MV x = widen<MV>(x_in), y = widen<MV>(y_in);
  const double bound = rel_tol * std::max({1.0, largest(x), largest(y)});
  std::vector<std::uint32_t> blades;
  for (const auto& t : x.terms) blades.push_back(t.blade);
  for (const auto& t : y.terms) blades.push_back(t.blade);
  for (const std::uint32_t b : blades) {
    const double d = std::abs(x.coefficient(b) - y.coefficient(b));
    if (!(d <= bound))
      return ::testing::AssertionFailure()
             << "blade 0x" << std::hex << b << std::dec << " differs by " << d << " > " << bound
             << "\n  lhs: " << x << "\n  rhs: " << y;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace gaphys_test::sparse
