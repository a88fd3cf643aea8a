// The algebras the engine is written in: dynamics in e3ga, collision geometry
// in c3ga (thesis chapter 4). Which generated variant backs them (reference,
// instrumented, optimized) is chosen by the build; the engine's code is the same.
#pragma once

#include <c3ga/c3ga.hpp>
#include <e3ga/e3ga.hpp>

namespace gaphys {

using real = e3ga::real;
using vector = e3ga::vector;      // positions, velocities, forces (metres, m/s, N)
using bivector = e3ga::bivector;  // angular velocity, torque, angular momentum
using rotor = e3ga::rotor;        // attitude: x_world = R x_body ~R

}  // namespace gaphys
