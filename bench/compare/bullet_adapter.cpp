#include "bullet_adapter.hpp"

#include <btBulletDynamicsCommon.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "matched_settings.hpp"
#include "number.hpp"

namespace gaphys_compare {

namespace {

using matched::position_correction;  // Bullet's erp2
using matched::restitution_threshold;
using matched::solver_iterations;

btVector3 to_bullet(const vec3& v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }
vec3 to_vec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

// Bullet combines two restitutions by their product, gaphys by their max.
// Giving every shape sqrt(e) makes each pair's product e when both shapes
// have the same e, which every scene here does (else the pair gets the
// geometric mean, sqrt(e_a e_b)).
btScalar restitution_of(double e) { return btScalar(std::sqrt(e)); }

// Friction combines by the product too (btManifoldResult::
// calculateCombinedFriction, capped at 10), so each shape gets sqrt(mu):
// sphere-plane and, in F5, sphere-sphere pairs then both get mu, where
// giving the planes 1 would leave sphere pairs mu^2.
btScalar friction_of(double mu) { return btScalar(std::sqrt(mu)); }

// Everything one scene needs, declared in the order it must be built; members
// are destroyed in reverse, so the world goes before the bodies, shapes and
// broadphase it refers to.
struct bullet_scene {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  std::map<double, std::unique_ptr<btSphereShape>> spheres;            // one shape per radius
  std::map<std::array<double, 3>, std::unique_ptr<btBoxShape>> boxes;  // one per size
  std::vector<std::unique_ptr<btCollisionShape>> other_shapes;
  std::vector<std::unique_ptr<btRigidBody>> bodies;  // planes first, then the scene's bodies
  std::unique_ptr<btDiscreteDynamicsWorld> world;
};

class bullet_adapter final : public engine_adapter {
 public:
  void build(const scene& s) override {
    scene_.reset();
    scene_ = std::make_unique<bullet_scene>();
    bullet_scene& b = *scene_;
    b.world = std::make_unique<btDiscreteDynamicsWorld>(&b.dispatcher, &b.broadphase, &b.solver,
                                                        &b.configuration);
    b.world->setGravity(to_bullet(s.gravity));
    btContactSolverInfo& info = b.world->getSolverInfo();
    info.m_numIterations = solver_iterations;
    info.m_restitutionVelocityThreshold = btScalar(restitution_threshold);
    // Split impulse for every penetration (by default only beyond 4 cm; a
    // velocity bias, which adds energy, below): the correction moves
    // positions without adding kinetic energy, as gaphys's does, at the same
    // 20% per step. m_linearSlop stays 0: Bullet also subtracts slop / h from
    // the contact's target velocity, which would cost every bounce
    // 0.0005 / h = 0.12 m/s, where gaphys's slop only limits the correction.
    info.m_splitImpulse = 1;
    info.m_splitImpulsePenetrationThreshold = 0;
    info.m_erp2 = btScalar(position_correction);

    for (const plane_description& p : s.planes) {
      b.other_shapes.push_back(
          std::make_unique<btStaticPlaneShape>(to_bullet(p.normal), btScalar(p.offset)));
      add_body(0, b.other_shapes.back().get(), {}, {}, {}, {}, p.restitution, p.friction);
    }
    first_body_ = s.planes.size();
    for (const body_description& d : s.bodies) {
      btCollisionShape* shape = nullptr;
      if (d.radius > 0) {
        auto& sphere = b.spheres[d.radius];
        if (!sphere) sphere = std::make_unique<btSphereShape>(btScalar(d.radius));
        shape = sphere.get();
      } else if (d.is_box()) {
        auto& box = b.boxes[{d.half_extents.x, d.half_extents.y, d.half_extents.z}];
        if (!box) box = std::make_unique<btBoxShape>(to_bullet(d.half_extents));
        shape = box.get();
      } else {
        // A body without a shape: Bullet needs one, the empty shape collides with nothing.
        b.other_shapes.push_back(std::make_unique<btEmptyShape>());
        shape = b.other_shapes.back().get();
      }
      add_body(d.is_static ? 0 : d.mass, shape, d.inertia, d.position, d.velocity,
               d.angular_velocity, d.restitution, d.friction, d.attitude);
    }
  }

  // maxSubSteps = 0: exactly one step of h. (h, 1, h) would accumulate h in
  // a btScalar clock and, in float, occasionally take no step.
  void step(double h) override { scene_->world->stepSimulation(btScalar(h), 0); }

  body_state state(std::size_t i) const override {
    const btRigidBody& body = *scene_->bodies[first_body_ + i];
    // Bullet keeps the attitude as a 3x3 matrix; getRotation converts it.
    const btQuaternion q = body.getWorldTransform().getRotation();
    return {to_vec3(body.getWorldTransform().getOrigin()),
            to_vec3(body.getLinearVelocity()),
            to_vec3(body.getAngularVelocity()),
            {q.w(), q.x(), q.y(), q.z()}};
  }

 private:
  void add_body(double mass, btCollisionShape* shape, const vec3& inertia, const vec3& position,
                const vec3& velocity, const vec3& angular_velocity, double restitution,
                double friction, const quat& attitude = {}) {
    btRigidBody::btRigidBodyConstructionInfo info(
        btScalar(mass), nullptr, shape, mass > 0 ? to_bullet(inertia) : btVector3(0, 0, 0));
    info.m_startWorldTransform.setIdentity();
    info.m_startWorldTransform.setOrigin(to_bullet(position));
    info.m_startWorldTransform.setRotation(btQuaternion(
        btScalar(attitude.x), btScalar(attitude.y), btScalar(attitude.z), btScalar(attitude.w)));
    // Sliding friction as the scene says (0 unless an F scene sets it; Bullet's
    // default would be 0.5); rolling and spinning friction never.
    info.m_friction = friction_of(friction);
    info.m_rollingFriction = 0;
    info.m_spinningFriction = 0;
    info.m_restitution = restitution_of(restitution);
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    auto body = std::make_unique<btRigidBody>(info);
    body->setLinearVelocity(to_bullet(velocity));
    body->setAngularVelocity(to_bullet(angular_velocity));
    // No sleeping: gaphys never puts bodies to sleep.
    body->setActivationState(DISABLE_DEACTIVATION);
    // Bullet's default since 2.83, stated because M1 depends on it.
    body->setFlags(body->getFlags() | BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
    scene_->world->addRigidBody(body.get());
    scene_->bodies.push_back(std::move(body));
  }

  std::unique_ptr<bullet_scene> scene_;
  std::size_t first_body_ = 0;
};

}  // namespace

engine bullet_engine() {
  const btSphereShape sphere(btScalar(0.1));
  const btStaticPlaneShape plane(btVector3(0, 0, 1), 0);
  const btBoxShape box(btVector3(btScalar(0.5), btScalar(0.5), btScalar(0.5)));
  const btContactSolverInfo defaults;
  const btRigidBody::btRigidBodyConstructionInfo default_body(1, nullptr, nullptr);
  const double default_friction = default_body.m_friction;
  const int version = btGetVersion();
  return {
      "bullet",
      number(version / 100) + "." + number(version % 100),
      btIsDoublePrecision() ? "double (BT_USE_DOUBLE_PRECISION)" : "float (btScalar = float)",
      {{"world", "btDiscreteDynamicsWorld, btDbvtBroadphase, btSequentialImpulseConstraintSolver",
        "the standard single-threaded pipeline"},
       {"step", "stepSimulation(h, 0)", "one fixed step of h per call, no interpolation"},
       {"solver iterations", number(solver_iterations),
        "gaphys's 20 sweeps (it gives turning contacts 10 more; Bullet default " +
            number(defaults.m_numIterations) + ")"},
       {"restitution", "sqrt(e) per shape; Bullet multiplies the pair's values",
        "product = e = gaphys's max(e, e) (all shapes of a scene share e)"},
       {"restitution threshold", number(restitution_threshold) + " m/s",
        "gaphys's (Bullet default " + number(defaults.m_restitutionVelocityThreshold) + ")"},
       {"penetration",
        "split impulse at every depth, erp2 " + number(position_correction) + ", slop 0",
        "positions-only correction like gaphys's (Bullet default: split impulse beyond " +
            number(-defaults.m_splitImpulsePenetrationThreshold) +
            " m only); slop 0 as Bullet's slop also lowers the rebound velocity"},
       {"friction",
        "sqrt(mu) per shape (0 in M1-M6, Bullet default " + number(default_friction) +
            "); Bullet multiplies the pair's values",
        "product = mu for every pair in F1-F5 and B1-B5 (all shapes of a scene share mu), as "
        "gaphys's geometric mean gives"},
       {"friction model",
        "one friction row per contact point, along its slip before the solve (below sqrt("
        "SIMD_EPSILON) = " +
            number(std::sqrt(double(SIMD_EPSILON)), 3) +
            " m/s: a fixed tangent), bounded by mu times the point's normal impulse; warm started",
        "Bullet's default solver mode (no SOLVER_USE_2_FRICTION_DIRECTIONS)"},
       {"rolling / spinning friction", "0 / 0", "the F scenes measure sliding friction only"},
       {"damping / sleeping", "0 / DISABLE_DEACTIVATION", "gaphys: none / sleeping off"},
       {"gyroscopic", "BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY", "Bullet's default, for M1"},
       {"margins",
        "sphere " + number(sphere.getMargin()) + " m (= r: the whole sphere is margin), plane " +
            number(plane.getMargin()) + " m, box " + number(box.getMargin()) +
            " m inside its half extents (the box keeps its size; its edges and corners are "
            "rounded by the margin where Bullet uses support points, as against planes)",
        "shape defaults; btBoxShape(half extents)"},
       {"warm starting", "factor " + number(defaults.m_warmstartingFactor), "default"},
       {"CCD", "off", "default; gaphys and ODE have none"}},
      [] { return std::make_unique<bullet_adapter>(); }};
}

}  // namespace gaphys_compare
