// What the e3ga variant-agreement tests share: the reference variant beside
// the optimized one, and rotors for log, apply and inverse.
#pragma once

#include <e3ga/e3ga.hpp>
#include <e3ga_ref/e3ga_ref.hpp>

#include "variants_agree.hpp"

namespace gaphys_test {

// Rotors for log, apply and inverse: exp of a random bivector.
template <class T>
struct input_maker<e3ga::basic_rotor<T>> {
  static e3ga::basic_rotor<T> make(std::mt19937& rng, bool) {
    return e3ga::exp(random_named<e3ga::basic_bivector<T>>(rng, T(-2), T(2)));
  }
};

}  // namespace gaphys_test
