// The one fixture every engine test uses: a small world builder with the
// shapes the tests need, a simulate() loop, and the closed-form helpers.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include "gaphys/gaphys.hpp"
#include "gaphys/scenes.hpp"

namespace gaphys::testing {

// A tolerance stated for each scalar the engine builds with: for a double
// engine, and for a float one (GAPHYS_REAL=float), whose rounding is 2^29
// times coarser. A test that states its float tolerances this way runs in
// both (tests/engine/CMakeLists.txt); the float value is the error measured
// in float with a margin, as the double value was.
constexpr real tolerance(double in_double, double in_float) {
  return sizeof(real) == 8 ? real(in_double) : real(in_float);
}

// A test input stated for each scalar, where double's would be lost in
// float: a gap below float's rounding, a magnitude beyond its range.
constexpr real for_scalar(double in_double, double in_float) {
  return sizeof(real) == 8 ? real(in_double) : real(in_float);
}

// Values the tests share.
constexpr real pi = 3.14159265358979323846;
constexpr real nan = std::numeric_limits<real>::quiet_NaN();
constexpr real inf = std::numeric_limits<real>::infinity();
inline const rotor identity{1, 0, 0, 0};  // no turn
inline const vector e1{1, 0, 0}, e2{0, 1, 0}, e3{0, 0, 1};
constexpr real g = 9.81;  // m/s², gravity in the tests' closed forms

// Components of vectors and bivectors, for readable assertions.
inline real x(const vector& v) { return v.e1(); }
inline real y(const vector& v) { return v.e2(); }
inline real z(const vector& v) { return v.e3(); }
inline real length(const vector& v) { return e3ga::norm(v); }
inline real length(const bivector& b) { return e3ga::norm(b); }
inline real dot(const vector& a, const vector& b) { return e3ga::scp(a, b); }

// The rotor turning by `angle` about the unit `axis` (right-handed).
inline rotor about(const vector& axis, real angle) {
  return e3ga::exp((-angle / 2) * bivector{z(axis), -y(axis), x(axis)});
}

inline ::testing::AssertionResult near(const vector& actual, const vector& expected, real tolerance) {
  const real error = length(actual - expected);
  if (error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "|" << e3ga::basic_mv<real>(actual) << " - " << e3ga::basic_mv<real>(expected)
         << "| = " << error << " > " << tolerance;
}

inline ::testing::AssertionResult near(const bivector& actual, const bivector& expected, real tolerance) {
  const real error = length(actual - expected);
  if (error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "|" << e3ga::basic_mv<real>(actual) << " - " << e3ga::basic_mv<real>(expected)
         << "| = " << error << " > " << tolerance;
}

// Runs `bad`, which must throw invalid_input whose message mentions `what`.
template <class Action>
::testing::AssertionResult rejects(Action&& bad, const std::string& what) {
  try {
    bad();
  } catch (const invalid_input& e) {
    const std::string message = e.what();
    if (message.find(what) == std::string::npos) {
      return ::testing::AssertionFailure()
             << "message \"" << message << "\" does not mention \"" << what << "\"";
    }
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw something else: " << e.what();
  }
  return ::testing::AssertionFailure() << "accepted input that should be rejected (" << what << ")";
}

class engine_test : public ::testing::Test {
 protected:
  static constexpr real h = scenes::time_step;

  world make_world(const vector& gravity = vector{0, 0, -9.81}) {
    world_settings settings;
    settings.gravity = gravity;
    return world(settings);
  }

  // A static floor: the half-space z <= height. Friction as the engine's
  // default unless given.
  static body_id add_floor(world& w, real height = 0, real restitution = 0,
                           real friction = material{}.friction) {
    body_definition floor;
    floor.is_static = true;
    floor.shape =
        shape::plane(vector{0, 0, 1}, height).with_restitution(restitution).with_friction(friction);
    return w.create_body(floor);
  }

  static body_id add_sphere(world& w, const vector& position, real radius, real mass = 1,
                            const vector& velocity = vector{}, real restitution = 0,
                            real friction = material{}.friction) {
    body_definition ball;
    ball.mass = mass;
    ball.position = position;
    ball.velocity = velocity;
    ball.shape = shape::sphere(radius).with_restitution(restitution).with_friction(friction);
    return w.create_body(ball);
  }

  static real kinetic_energy(const world& w) {
    real e = 0;
    for (const body& b : w.bodies()) e += b.kinetic_energy();
    return e;
  }

  // Steps the world `steps` times, calling after_step(step index) after each.
  static void simulate(world& w, int steps, const std::function<void(int)>& after_step = {}) {
    for (int i = 0; i < steps; ++i) {
      w.step(h);
      if (after_step) after_step(i);
    }
  }

  std::mt19937_64 random{20261122};
  real uniform(real low, real high) { return std::uniform_real_distribution<real>(low, high)(random); }
  vector random_unit_vector() {
    for (;;) {
      const vector v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const real l = length(v);
      if (l > real(0.1) && l <= 1) return v / l;
    }
  }
};

}  // namespace gaphys::testing
