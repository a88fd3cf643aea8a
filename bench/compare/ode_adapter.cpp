#include "ode_adapter.hpp"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "matched_settings.hpp"
#include "number.hpp"

namespace gaphys_compare {

namespace {

using matched::position_correction;            // ODE's ERP
using matched::restitution_threshold;          // ODE's bounce_vel
using matched::solver_iterations;              // QuickStep's sweeps
constexpr double linear_slop = 0.0005;         // m: ODE's contact surface layer
// CFM makes each contact slightly soft: an impulse j leaves a velocity error
// of about CFM j / h. ODE's double default, 1e-10, leaves ~1e-7 m/s in the
// M2 impacts; 1e-5 (the single-precision default) measured 0.6% of the
// energy lost in the head-on impact and 17% of the apex over 20 elastic
// bounces, so it would blur exactly what M2 and M3 measure.
constexpr double constraint_force_mixing = 1e-10;
// Contact points asked of dCollide per pair: a box's face on a face needs 4
// (dBoxBox finds up to 8 and, asked for fewer, keeps the deepest and others
// spread around it).
constexpr int max_contacts = 4;

// ODE prints solver trouble ("LCP internal error") as messages and carries
// on without the failed contact forces. They are counted here and reported
// once per scene by the adapter, so a run says where ODE's numbers are suspect.
int message_count = 0;
std::string last_message;

void count_message(int, const char* format, va_list arguments) {
  char text[256];
  std::vsnprintf(text, sizeof text, format, arguments);
  ++message_count;
  last_message = text;
}

// ODE wants dInitODE2 once per process before anything else.
void init_ode_once() {
  static const bool ready = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    dSetMessageHandler(count_message);
    return true;
  }();
  (void)ready;
}

class ode_adapter final : public engine_adapter {
 public:
  explicit ode_adapter(ode_stepper stepper) : stepper_(stepper) { init_ode_once(); }
  ~ode_adapter() override { clear(); }
  ode_adapter(const ode_adapter&) = delete;
  ode_adapter& operator=(const ode_adapter&) = delete;

  void build(const scene& s) override {
    clear();
    scene_name_ = s.name;
    // QuickStep reorders its constraints at random, from a generator shared
    // by the whole process; starting it from its initial seed (0) in every
    // scene makes ODE's numbers independent of which scenes ran before.
    dRandSetSeed(0);
    world_ = dWorldCreate();
    dWorldSetGravity(world_, s.gravity.x, s.gravity.y, s.gravity.z);
    dWorldSetERP(world_, position_correction);
    dWorldSetCFM(world_, constraint_force_mixing);
    dWorldSetContactSurfaceLayer(world_, linear_slop);
    dWorldSetAutoDisableFlag(world_, 0);  // no sleeping, as gaphys runs here
    dWorldSetQuickStepNumIterations(world_, solver_iterations);
    space_ = dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XYZ);
    contacts_ = dJointGroupCreate(0);

    // Each geom's data points at its surface; reserved up front, so the
    // pointers stay valid.
    surfaces_.clear();
    surfaces_.reserve(s.planes.size() + s.bodies.size());
    for (const plane_description& p : s.planes) {
      const dGeomID plane = dCreatePlane(space_, p.normal.x, p.normal.y, p.normal.z, p.offset);
      surfaces_.push_back({p.restitution, p.friction});
      dGeomSetData(plane, &surfaces_.back());
    }
    bodies_.clear();
    geoms_.clear();
    for (const body_description& d : s.bodies) add(d);
  }

  void step(double h) override {
    const int messages = message_count;
    dSpaceCollide(space_, this, &ode_adapter::near_callback);
    if (stepper_ == ode_stepper::quick) {
      dWorldQuickStep(world_, h);
    } else {
      dWorldStep(world_, h);
    }
    dJointGroupEmpty(contacts_);
    if (message_count != messages) ++troubled_steps_;
  }

  body_state state(std::size_t i) const override {
    const dBodyID body = bodies_[i];
    if (!body) {  // a static sphere: a geom without a body
      const dReal* p = dGeomGetPosition(geoms_[i]);
      return {{p[0], p[1], p[2]}, {}, {}, {}};
    }
    const dReal* p = dBodyGetPosition(body);
    const dReal* v = dBodyGetLinearVel(body);
    const dReal* w = dBodyGetAngularVel(body);
    const dReal* q = dBodyGetQuaternion(body);  // (w, x, y, z)
    return {{p[0], p[1], p[2]}, {v[0], v[1], v[2]}, {w[0], w[1], w[2]}, {q[0], q[1], q[2], q[3]}};
  }

 private:
  void add(const body_description& d) {
    dBodyID body = nullptr;
    if (!d.is_static) {
      body = dBodyCreate(world_);
      dMass mass;
      dMassSetParameters(&mass, d.mass, 0, 0, 0, d.inertia.x, d.inertia.y, d.inertia.z, 0, 0, 0);
      dBodySetMass(body, &mass);
      dBodySetPosition(body, d.position.x, d.position.y, d.position.z);
      const dQuaternion attitude{d.attitude.w, d.attitude.x, d.attitude.y, d.attitude.z};
      dBodySetQuaternion(body, attitude);
      dBodySetLinearVel(body, d.velocity.x, d.velocity.y, d.velocity.z);
      dBodySetAngularVel(body, d.angular_velocity.x, d.angular_velocity.y, d.angular_velocity.z);
      dBodySetAutoDisableFlag(body, 0);
      dBodySetGyroscopicMode(body, 1);  // ODE 0.16's default, stated because M1 depends on it
    }
    dGeomID geom = nullptr;
    if (d.has_shape()) {
      // dCreateBox takes the full side lengths.
      geom = d.is_box() ? dCreateBox(space_, 2 * d.half_extents.x, 2 * d.half_extents.y,
                                     2 * d.half_extents.z)
                        : dCreateSphere(space_, d.radius);
      surfaces_.push_back({d.restitution, d.friction});
      dGeomSetData(geom, &surfaces_.back());
      if (body) {
        dGeomSetBody(geom, body);
      } else {
        dGeomSetPosition(geom, d.position.x, d.position.y, d.position.z);
        const dQuaternion attitude{d.attitude.w, d.attitude.x, d.attitude.y, d.attitude.z};
        dGeomSetQuaternion(geom, attitude);
      }
    }
    bodies_.push_back(body);
    geoms_.push_back(geom);
  }

  // Bouncing contacts, e = the larger of the two geoms' values (gaphys's
  // rule), bouncing only above the threshold, as in gaphys. Friction mu is
  // the geometric mean of the two (gaphys's rule), and dContactApprox1 bounds
  // each of ODE's two friction rows by mu times the contact's normal force,
  // ODE's nearest to Coulomb: a pyramid on ODE's own tangent axes (no
  // dContactFDir1), not a cone. mu 0 adds no friction rows, so M1-M6 stay
  // frictionless.
  static void near_callback(void* data, dGeomID a, dGeomID b) {
    auto& self = *static_cast<ode_adapter*>(data);
    const dBodyID body_a = dGeomGetBody(a), body_b = dGeomGetBody(b);
    if (!body_a && !body_b) return;
    dContact contact[max_contacts];
    const int count = dCollide(a, b, max_contacts, &contact[0].geom, sizeof(dContact));
    const geom_surface& sa = *static_cast<const geom_surface*>(dGeomGetData(a));
    const geom_surface& sb = *static_cast<const geom_surface*>(dGeomGetData(b));
    const double e = std::max(sa.restitution, sb.restitution);
    const double mu = std::sqrt(sa.friction * sb.friction);
    for (int i = 0; i < count; ++i) {
      contact[i].surface.mode = dContactBounce | dContactApprox1;
      contact[i].surface.mu = mu;
      contact[i].surface.bounce = e;
      contact[i].surface.bounce_vel = restitution_threshold;
      const dJointID joint = dJointCreateContact(self.world_, self.contacts_, &contact[i]);
      dJointAttach(joint, body_a, body_b);
    }
  }

  void clear() {
    if (troubled_steps_ > 0) {
      std::cerr << "  " << (stepper_ == ode_stepper::quick ? "ode-quick" : "ode-lcp") << ", "
                << scene_name_ << ": ODE reported trouble in " << troubled_steps_
                << " steps (last: " << last_message << ")\n";
    }
    troubled_steps_ = 0;
    if (contacts_) dJointGroupDestroy(contacts_);
    if (space_) dSpaceDestroy(space_);  // destroys its geoms
    if (world_) dWorldDestroy(world_);  // destroys its bodies
    contacts_ = nullptr;
    space_ = nullptr;
    world_ = nullptr;
  }

  ode_stepper stepper_;
  std::string scene_name_;
  int troubled_steps_ = 0;  // steps in which ODE printed a message
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  struct geom_surface {
    double restitution;
    double friction;
  };
  std::vector<geom_surface> surfaces_;  // per geom: the planes', then the bodies'
  std::vector<dBodyID> bodies_;         // per scene body; null for static ones
  std::vector<dGeomID> geoms_;          // per scene body; null without a shape
};

}  // namespace

engine ode_engine(ode_stepper stepper) {
  init_ode_once();
  const dWorldID defaults = dWorldCreate();
  const double default_cfm = dWorldGetCFM(defaults);
  const double sor = dWorldGetQuickStepW(defaults);
  dWorldDestroy(defaults);
  const bool quick = stepper == ode_stepper::quick;
  std::string precision = dCheckConfiguration("ODE_double_precision") ? "double" : "single";
  precision += std::string(" (dReal of ") + (sizeof(dReal) == 8 ? "8" : "4") + " bytes; " +
               dGetConfiguration() + ")";
  std::vector<parameter> parameters = {
      {"stepper",
       quick ? "dWorldQuickStep, " + number(solver_iterations) + " iterations, SOR w " + number(sor)
             : "dWorldStep (direct LCP per island)",
       quick ? "the iterative stepper applications use; 20 = gaphys's sweeps (+10 on its turning contacts)"
             : "exact LCP solve, for reference; cost grows as n^3"},
      {"space", "dSweepAndPruneSpaceCreate(XYZ)", "a broad phase for M6 and B5"},
      {"shapes",
       "dCreateSphere, dCreateBox (full side lengths), dCreatePlane; mass and principal inertia "
       "by dMassSetParameters (a box's equal dMassSetBox's); at most " +
           number(max_contacts) + " contact points per pair",
       "the scene's shapes; 4 points hold a face on a face"},
      {"contacts",
       "dContactBounce | dContactApprox1, bounce = max(e_a, e_b), bounce_vel " +
           number(restitution_threshold) + " m/s",
       "gaphys's restitution rule and threshold"},
      {"friction",
       "mu = sqrt(mu_a mu_b) set in the near callback: 0 in M1-M6 (no friction rows), the "
       "scene's mu in F1-F5 and B1-B5",
       "gaphys's geometric mean; both geoms get the scene's mu, so every pair gets mu"},
      {"friction model",
       "dContactApprox1: two rows along ODE's own tangent axes (dPlaneSpace of the normal; no "
       "dContactFDir1), each bounded by mu times the normal force: a pyramid, up to sqrt(2) mu "
       "along a diagonal",
       "ODE's closest Coulomb law (without Approx1 mu bounds a force, whatever the load); ODE "
       "has no cone; left as ODE gives it"},
      {"rolling friction", "off (no dContactRolling)",
       "the F scenes measure sliding friction only"},
      {"random seed", "dRandSetSeed(0) as each scene is built",
       "QuickStep shuffles constraints with ODE's process-wide generator: the same numbers "
       "whatever ran before"},
      {"ERP / surface layer", number(position_correction) + " / " + number(linear_slop) + " m",
       "gaphys's 20% per step beyond 0.5 mm; ODE corrects through velocity (adds energy)"},
      {"CFM", number(constraint_force_mixing),
       "ODE's double default (" + number(default_cfm) + "); 1e-5 loses energy in M2 and M3"},
      {"gyroscopic / finite rotation", "on / off (defaults)",
       "ODE 0.16 defaults; the infinitesimal attitude update is ODE's default"},
      {"damping / auto-disable", "0 / off", "gaphys has neither"}};
  const std::string name = quick ? "ode-quick" : "ode-lcp";
  return {name, GAPHYS_COMPARE_ODE_VERSION, precision, parameters,
          [stepper] { return std::make_unique<ode_adapter>(stepper); }};
}

}  // namespace gaphys_compare
