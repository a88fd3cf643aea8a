// Energies, momenta and contact slip computed from body states, one way for every
// engine: the engines' own energy reports (where they have one) differ in
// what they include, so the harness never asks for them.
#pragma once

#include <vector>

#include "engine_adapter.hpp"
#include "scene.hpp"

namespace gaphys_compare {

// World-frame angular momentum about the centre of mass: I_w ω with
// I_w = R I R^T, R from the normalized attitude.
vec3 angular_momentum(const body_description& body, const body_state& state);
// ½ m v² + ½ ω · I_w ω; zero for static bodies.
double kinetic_energy(const body_description& body, const body_state& state);

// Sums over the scene's dynamic bodies.
vec3 total_momentum(const scene& s, const std::vector<body_state>& states);
double total_kinetic_energy(const scene& s, const std::vector<body_state>& states);

// The velocity, in the plane's tangent plane, of the sphere's point nearest
// the (static) plane: v + ω × (-r n), its normal part removed. Zero when the
// sphere rolls without slipping; what friction acts against when it slides.
vec3 contact_slip(const body_description& sphere, const body_state& state,
                  const plane_description& plane);

// The horizontal part of v (gravity along -z in every friction scene).
inline vec3 horizontal(const vec3& v) { return {v.x, v.y, 0}; }

// Every body's state.
std::vector<body_state> states_of(const engine_adapter& adapter, const scene& s);

}  // namespace gaphys_compare
