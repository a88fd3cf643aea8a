// The algebras the engine is written in: dynamics in e3ga, collision geometry
// in c3ga (thesis chapter 4). Which generated variant backs them (reference,
// instrumented, optimized) is chosen by the build; the engine's code is the same.
#pragma once

#include <c3ga/c3ga.hpp>
#include <e3ga/e3ga.hpp>
#include <type_traits>

// The engine's scalar, set by the build (CMake's GAPHYS_REAL): double, or
// float for a single-precision engine. The generated kernels are templates
// on the scalar, so both are the same code.
#ifndef GAPHYS_REAL
#define GAPHYS_REAL double
#endif

namespace gaphys {

using real = GAPHYS_REAL;
static_assert(std::is_same_v<real, double> || std::is_same_v<real, float>,
              "GAPHYS_REAL must be double or float");

// A program compiled with another scalar than its engine library's would run
// on structs of another layout (a world built by a float library from a
// double program's settings read garbage). The library defines the one of
// these for its scalar (src/scalar_check.cpp); every file that includes this
// header refers to the one for its own, so such a program fails to link,
// naming the scalar it was compiled for: "undefined reference to
// gaphys::detail::engine_built_with_real_float".
#define GAPHYS_DETAIL_PASTE_(a, b) a##b
#define GAPHYS_DETAIL_PASTE(a, b) GAPHYS_DETAIL_PASTE_(a, b)
#define GAPHYS_DETAIL_SCALAR_CHECK GAPHYS_DETAIL_PASTE(engine_built_with_real_, GAPHYS_REAL)
namespace detail {
extern const int GAPHYS_DETAIL_SCALAR_CHECK;
#if defined(__GNUC__)
// (Kept by the compiler though unused: its reference is the point.)
[[maybe_unused]] __attribute__((used)) static const int* const scalar_check =
    &GAPHYS_DETAIL_SCALAR_CHECK;
#endif
}  // namespace detail

using vector = e3ga::basic_vector<real>;      // positions, velocities, forces (metres, m/s, N)
using bivector = e3ga::basic_bivector<real>;  // angular velocity, torque, angular momentum
using rotor = e3ga::basic_rotor<real>;        // attitude: x_world = R x_body ~R

// The conformal types of the narrow phase, in the engine's scalar.
namespace conformal {
using mv = c3ga::basic_mv<real>;
using normalized_point = c3ga::basic_normalized_point<real>;
using dual_sphere = c3ga::basic_dual_sphere<real>;
using dual_plane = c3ga::basic_dual_plane<real>;
using euclidean_vector = c3ga::basic_euclidean_vector<real>;
using rotor = c3ga::basic_rotor<real>;
using translator = c3ga::basic_translator<real>;
using motor = c3ga::basic_motor<real>;
}  // namespace conformal

}  // namespace gaphys
