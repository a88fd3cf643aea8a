// c3ga values from Euclidean data, shared by the c3ga tests.
#pragma once

#include <c3ga/c3ga.hpp>

#include "algebra_test_support.hpp"

namespace gaphys_test {

// no + x + 1/2 |x|^2 ni
template <class T>
c3ga::basic_normalized_point<T> point_of(const vec3& x) {
  return make_point<c3ga::basic_normalized_point<T>>(x);
}

// c - 1/2 r^2 ni around the normalized point c
template <class T>
c3ga::basic_dual_sphere<T> dual_sphere_of(const vec3& c, double r) {
  return make_dual_sphere<c3ga::basic_dual_sphere<T>>(c, r);
}

}  // namespace gaphys_test
