// What the c3ga variant-agreement tests share: the reference variant beside
// the optimized one, and inputs for log, apply and inverse. The tests are
// split over several files (spec functions, groups of types, mixed and
// general) so that their thousands of instantiations compile in parallel.
#pragma once

#include <c3ga/c3ga.hpp>
#include <c3ga_ref/c3ga_ref.hpp>

#include "variants_agree.hpp"

namespace gaphys_test {

// Unit rotors, translators and motors for log, apply and inverse.
template <class T>
struct input_maker<c3ga::basic_rotor<T>> {
  static c3ga::basic_rotor<T> make(std::mt19937& rng, bool) {
    return c3ga::exp(random_named<c3ga::basic_euclidean_bivector<T>>(rng, T(-2), T(2)));
  }
};
template <class T>
struct input_maker<c3ga::basic_translator<T>> {
  static c3ga::basic_translator<T> make(std::mt19937& rng, bool) {
    auto x = random_named<c3ga::basic_translator<T>>(rng, T(-2), T(2));
    x.c[0] = 1;
    return x;
  }
};
template <class T>
struct input_maker<c3ga::basic_motor<T>> {
  static c3ga::basic_motor<T> make(std::mt19937& rng, bool) {
    return c3ga::exp(random_named<c3ga::basic_dual_line<T>>(rng, T(-2), T(2)));
  }
};

}  // namespace gaphys_test
