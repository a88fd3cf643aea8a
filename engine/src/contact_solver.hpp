// Collision response: the thesis's impulse (eq. 3.20, in GA eq. 4.7) with the
// full inertia, solved by sequential impulses over all contacts, then a
// position correction that removes penetration without adding velocity.
#pragma once

#include <optional>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "gaphys/world.hpp"
#include "timed_impact.hpp"

namespace gaphys {

class contact_solver {
 public:
  explicit contact_solver(const world_settings& settings) : settings_(settings) {}

  // Changes velocities so that no contact still approaches and each
  // bouncing contact separates at e times its impact speed, and stores
  // each contact's total impulse in it. A bounce is timed inside the step
  // (timed_impact.hpp) from `start` (each body's velocities before this
  // step's gravity and forces) and the velocities after them; its impact
  // speed taken after them alone, a ball dropped with e = 1 would leave each
  // bounce h g faster than it came and climb 1.3% higher every time.
  // Contacts between the same two bodies in `previous` (the last step's,
  // sorted by body pair like `contacts`) start from their old impulse.
  //
  // A speculative contact (depth = -gap < 0) that does not bounce lets its
  // bodies close the gap in this step of h seconds but no more: its target
  // is -gap / h, so a landing body ends the step touching. One that would
  // bounce but meets only in a later step is left out.
  void solve_velocities(std::vector<body>& bodies, const std::vector<body_velocity>& start,
                        std::vector<contact>& contacts, const std::vector<contact>& previous,
                        real h);

  // After the positions moved by h v: moves the bodies of a timed bounce by
  // -t Δv (the impulse came t into the step), and pushes other overlapping
  // bodies apart along the normal by a share of the depth beyond the slop.
  void correct_positions(std::vector<body>& bodies, const std::vector<contact>& contacts,
                         real h) const;

 private:
  struct constraint {
    std::size_t body_a, body_b;
    vector normal;            // n, from B to A
    bivector arm_a, arm_b;    // n ∧ r for each body's offset r to the contact point
    bivector turn_a, turn_b;  // I⁻¹(r ∧ n): the change of Ω per unit impulse
    bool central = false;     // both arms zero: the impulse turns neither body
    real effective_mass_inverse;  // 0: the constraint is left out
    real target_speed;  // normal separation speed wanted after the impulses
    real relaxation = 1;  // settings' over-relaxation where the contact shares a body, else 1
    real accumulated = 0;
    bool timed = false;     // a bounce at impact_time into the step (timed_impact.hpp)
    real impact_time = 0;   // s; correct_positions moves the bodies by it
  };

  // What the sweeps read and change of each body, packed together: the
  // sweeps visit bodies in contact order, and whole body objects would
  // spread them over many cache lines.
  struct solver_body {
    vector velocity;
    bivector angular_velocity;
    real inverse_mass;
  };

  constraint make_constraint(const body& a, const body& b, const contact& c,
                             const body_velocity& start_a, const body_velocity& start_b,
                             real h) const;
  static std::optional<timed_impact> time_impact(const body& a, const body& b, const contact& c,
                                                 const body_velocity& start_a,
                                                 const body_velocity& start_b, real h);
  static real normal_speed(const solver_body& a, const solver_body& b, const constraint& k);
  static void apply_impulse(solver_body& a, solver_body& b, const constraint& k, real j);

  const world_settings& settings_;
  std::vector<constraint> constraints_;
  std::vector<int> contacts_per_body_;
  std::vector<solver_body> solver_bodies_;
};

}  // namespace gaphys
