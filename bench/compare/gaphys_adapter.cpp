#include "gaphys_adapter.hpp"

#include <optional>
#include <string>

#include "gaphys/world.hpp"
#include "gaphys_conversions.hpp"
#include "number.hpp"

namespace gaphys_compare {

namespace {

// A shape with the scene's surface values. Every value is set, so a change of
// gaphys's defaults (friction 0.5) cannot leak into the frictionless scenes;
// rolling resistance and spinning friction stay 0 in every scene.
gaphys::shape with_surface(const gaphys::shape& shape, double restitution, double friction) {
  return shape.with_restitution(restitution)
      .with_friction(friction)
      .with_rolling_resistance(0)
      .with_spinning_friction(0);
}

class gaphys_adapter final : public engine_adapter {
 public:
  gaphys_adapter(int threads, gaphys::contact_batching batches, int turning_sweeps)
      : threads_(threads), batches_(batches), turning_sweeps_(turning_sweeps) {}

  void build(const scene& s) override {
    gaphys::world_settings settings;  // defaults: 20 sweeps (+10 for turning contacts), threshold 0.5 m/s
    settings.gravity = to_gaphys(s.gravity);
    settings.sleeping = false;  // as Bullet and ODE run here: every body steps every step
    settings.threads = threads_;
    settings.batch_contacts = batches_;
    if (turning_sweeps_ >= 0) settings.turning_iterations = turning_sweeps_;
    world_.emplace(settings);
    for (const plane_description& p : s.planes) {
      gaphys::body_definition plane;
      plane.is_static = true;
      plane.shape = with_surface(gaphys::shape::plane(to_gaphys(p.normal), p.offset), p.restitution,
                                 p.friction);
      world_->create_body(plane);
    }
    first_body_ = s.planes.size();
    for (const body_description& b : s.bodies) {
      gaphys::body_definition d;
      d.is_static = b.is_static;
      d.mass = b.is_static ? 1 : b.mass;
      if (!b.is_static) {  // static bodies take their sphere's default
        d.inertia = gaphys::inertia::principal(b.inertia.x, b.inertia.y, b.inertia.z);
      }
      d.position = to_gaphys(b.position);
      d.attitude = to_rotor(b.attitude);
      d.velocity = to_gaphys(b.velocity);
      d.angular_velocity = to_bivector(b.angular_velocity);
      if (b.radius > 0) {
        d.shape = with_surface(gaphys::shape::sphere(b.radius), b.restitution, b.friction);
      } else if (b.is_box()) {
        d.shape =
            with_surface(gaphys::shape::box(to_gaphys(b.half_extents)), b.restitution, b.friction);
      }
      world_->create_body(d);
    }
  }

  void step(double h) override { world_->step(h); }

  body_state state(std::size_t i) const override {
    const gaphys::body& b = world_->at(first_body_ + i);
    return {to_vec3(b.position()), to_vec3(b.velocity()), axis_of(b.angular_velocity()),
            to_quat(b.attitude())};
  }

 private:
  int threads_;
  gaphys::contact_batching batches_;
  int turning_sweeps_;
  std::optional<gaphys::world> world_;
  std::size_t first_body_ = 0;
};

std::string rule_name(gaphys::combine_rule rule) {
  switch (rule) {
    case gaphys::combine_rule::geometric_mean:
      return "geometric mean";
    case gaphys::combine_rule::average:
      return "average";
    case gaphys::combine_rule::min:
      return "min";
    case gaphys::combine_rule::max:
      return "max";
    case gaphys::combine_rule::multiply:
      return "product";
  }
  return "rule " + std::to_string(static_cast<int>(rule));
}

}  // namespace

engine gaphys_engine(int threads, gaphys::contact_batching batches, int turning_sweeps) {
  const gaphys::world_settings defaults;
  const int turning = turning_sweeps >= 0 ? turning_sweeps : defaults.turning_iterations;
  return {
      "gaphys",
      "this tree",
      sizeof(gaphys::real) == 8 ? "double" : "float (GAPHYS_REAL=float)",
      {{"world", "gaphys::world, default world_settings but sleeping off",
        "the engine as documented; no engine sleeps here"},
       {"threads", threads == 0 ? std::string("every core") : std::to_string(threads),
        "--gaphys-threads; the results are the same with any number, only the time changes"},
       {"contact batches",
        batches == gaphys::contact_batching::automatic ? "auto"
        : batches == gaphys::contact_batching::on      ? "on"
                                                       : "off",
        "--gaphys-batches; the sweeps on SIMD batches or one by one, the same results"},
       {"solver sweeps",
        std::to_string(defaults.solver_iterations) + " (+" + std::to_string(turning) +
            " for contacts that turn a body)",
        turning_sweeps >= 0 ? "--gaphys-turning-sweeps" : "default"},
       {"restitution",
        "max(e_a, e_b) per contact, threshold " + number(defaults.restitution_threshold) + " m/s",
        "default; the scenes give every shape the same e"},
       {"position correction",
        number(100 * defaults.position_correction) + "% of depth beyond " +
            number(1000 * defaults.linear_slop) + " mm per step, positions only",
        "default; adds no kinetic energy"},
       {"shapes",
        "shape::sphere, shape::box(half extents), shape::plane; the inertia of each body is "
        "given (the solid's, which is also gaphys's default)",
        "the scene's shapes, no margin"},
       {"friction",
        "with_friction(mu) on every shape and plane: 0 in M1-M6, the scene's mu in F1-F5 and "
        "B1-B5; a pair's mu is the " +
            rule_name(defaults.material_combine.friction) +
            " of its shapes'; Coulomb cone |impulse_t| <= mu impulse_n (material.hpp)",
        "default combine rule; both shapes get the scene's mu, so every pair gets mu"},
       {"rolling resistance / spinning friction", "0 / 0 on every shape",
        "the F scenes measure sliding friction only; set explicitly, as are friction and e"},
       {"damping", "0", "default"},
       {"attitude", "rotor, |q| = sqrt(R ~R)", "read as a quaternion for the harness"}},
      [threads, batches, turning_sweeps] {
        return std::make_unique<gaphys_adapter>(threads, batches, turning_sweeps);
      }};
}

}  // namespace gaphys_compare
