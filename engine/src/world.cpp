#include "gaphys/world.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <limits>

#include "contact_events.hpp"
#include "contact_solver.hpp"
#include "query_index.hpp"
#include "validate.hpp"

namespace gaphys {

namespace {

void require_rule(combine_rule rule, const char* what) {
  switch (rule) {
    case combine_rule::geometric_mean:
    case combine_rule::average:
    case combine_rule::min:
    case combine_rule::max:
    case combine_rule::multiply:
      return;
  }
  detail::reject(what, " must be geometric_mean, average, min, max or multiply (got ",
                 static_cast<int>(rule), ")");
}

const world_settings& validated(const world_settings& s) {
  detail::require_finite(s.gravity, "gravity");
  detail::require_non_negative(s.linear_damping, "linear damping");
  detail::require_non_negative(s.angular_damping, "angular damping");
  if (s.solver_iterations < 1) detail::reject("solver iterations must be >= 1");
  if (s.turning_iterations < 0) detail::reject("turning iterations must be >= 0");
  if (s.impact_iterations < 1) detail::reject("impact iterations must be >= 1");
  detail::require_non_negative(s.solver_tolerance, "solver tolerance");
  if (!(s.solver_relaxation > 0 && s.solver_relaxation < 2)) {
    detail::reject("solver relaxation must be in (0, 2) (got ", s.solver_relaxation, ")");
  }
  detail::require_non_negative(s.restitution_threshold, "restitution threshold");
  require_rule(s.material_combine.restitution, "restitution combine rule");
  require_rule(s.material_combine.friction, "friction combine rule");
  require_rule(s.material_combine.rolling_resistance, "rolling resistance combine rule");
  require_rule(s.material_combine.spinning_friction, "spinning friction combine rule");
  if (!(s.position_correction >= 0 && s.position_correction <= 1)) {
    detail::reject("position correction must be in [0, 1] (got ", s.position_correction, ")");
  }
  detail::require_non_negative(s.linear_slop, "linear slop");
  detail::require_non_negative(s.contact_margin, "contact margin");
  if (s.broad_phase != broad_phase_kind::uniform_grid &&
      s.broad_phase != broad_phase_kind::all_pairs) {
    detail::reject("broad phase must be uniform_grid or all_pairs");
  }
  return s;
}

using clock = std::chrono::steady_clock;

double seconds(clock::time_point from, clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

world::world(const world_settings& settings)
    : settings_(validated(settings)),
      space_(settings.broad_phase),
      solver_(std::make_unique<contact_solver>()) {}

world::world(const world& other)
    : settings_(other.settings_),
      bodies_(other.bodies_),
      slot_of_index_(other.slot_of_index_),
      index_of_slot_(other.index_of_slot_),
      generation_of_slot_(other.generation_of_slot_),
      free_slots_(other.free_slots_),
      space_(other.space_),
      pairs_(other.pairs_),
      contacts_(other.contacts_),
      previous_contacts_(other.previous_contacts_),
      events_(other.events_),
      sensor_overlaps_(other.sensor_overlaps_),
      start_velocities_(other.start_velocities_),
      timings_(other.timings_),
      time_(other.time_),
      solver_(std::make_unique<contact_solver>()) {}

world& world::operator=(const world& other) {
  if (this != &other) *this = world(other);
  return *this;
}

world::world(world&&) noexcept = default;
world& world::operator=(world&&) noexcept = default;
world::~world() = default;

namespace {

constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();
constexpr std::size_t slot_bits = 32;
constexpr std::size_t slot_mask = (std::size_t{1} << slot_bits) - 1;
static_assert(sizeof(std::size_t) >= 8, "body ids pack a slot and a generation into 64 bits");

// Drops a removed body's contacts from a pair-sorted list and renumbers
// the bodies after it; the order stays sorted.
void forget(std::vector<contact>& contacts, std::size_t index) {
  std::vector<contact> kept;
  kept.reserve(contacts.size());
  for (contact c : contacts) {
    if (c.body_a == index || c.body_b == index) continue;
    if (c.body_a > index) --c.body_a;
    if (c.body_b > index) --c.body_b;
    kept.push_back(c);
  }
  contacts.swap(kept);
}

}  // namespace

body_id world::create_body(const body_definition& definition) {
  bodies_.emplace_back(definition);  // body's constructor validates, then nothing is added
  ++geometry_version_;
  const std::size_t index = bodies_.size() - 1;
  std::size_t slot;
  if (!free_slots_.empty()) {
    slot = free_slots_.back();
    free_slots_.pop_back();
    index_of_slot_[slot] = index;
  } else {
    slot = index_of_slot_.size();
    index_of_slot_.push_back(index);
    generation_of_slot_.push_back(0);
  }
  slot_of_index_.push_back(slot);
  if (bodies_.back().shape()) space_.add(index);
  return id_of(index);
}

body_id world::id_of(std::size_t index) const {
  if (index >= bodies_.size()) detail::reject("no body at index ", index);
  const std::size_t slot = slot_of_index_[index];
  return slot | (static_cast<std::size_t>(generation_of_slot_[slot]) << slot_bits);
}

std::size_t world::index_of(body_id id) const {
  const std::size_t slot = id & slot_mask;
  const std::size_t generation = id >> slot_bits;
  if (slot >= index_of_slot_.size() || generation_of_slot_[slot] != generation ||
      index_of_slot_[slot] == no_index) {
    detail::reject("no body with id ", id, " (removed, or never created)");
  }
  return index_of_slot_[slot];
}

bool world::contains(body_id id) const {
  const std::size_t slot = id & slot_mask;
  return slot < index_of_slot_.size() && generation_of_slot_[slot] == id >> slot_bits &&
         index_of_slot_[slot] != no_index;
}

void world::remove_body(body_id id) {
  const std::size_t index = index_of(id);
  const std::size_t slot = slot_of_index_[index];
  bodies_.erase(bodies_.begin() + static_cast<std::ptrdiff_t>(index));
  slot_of_index_.erase(slot_of_index_.begin() + static_cast<std::ptrdiff_t>(index));
  index_of_slot_[slot] = no_index;
  for (std::size_t& i : index_of_slot_) {
    if (i != no_index && i > index) --i;
  }
  // A slot whose generation would wrap is retired, so no id ever comes back.
  if (generation_of_slot_[slot] < std::numeric_limits<std::uint32_t>::max()) {
    ++generation_of_slot_[slot];
    free_slots_.push_back(slot);
  }
  space_.remove(index);
  forget(contacts_, index);
  forget(previous_contacts_, index);
  const auto names_it = [id](const contact_event& e) { return e.body_a == id || e.body_b == id; };
  for (std::vector<contact_event>* list : {&events_.began, &events_.persisted, &events_.ended}) {
    list->erase(std::remove_if(list->begin(), list->end(), names_it), list->end());
  }
  sensor_overlaps_.erase(
      std::remove_if(sensor_overlaps_.begin(), sensor_overlaps_.end(),
                     [id](const sensor_overlap& o) { return o.sensor == id || o.other == id; }),
      sensor_overlaps_.end());
  ++geometry_version_;
}

body& world::at(body_id id) {
  const std::size_t index = index_of(id);
  ++geometry_version_;  // the caller may assign a whole body through it
  return bodies_[index];
}

const body& world::at(body_id id) const { return bodies_[index_of(id)]; }

void world::set_gravity(const vector& gravity) {
  detail::require_finite(gravity, "gravity");
  settings_.gravity = gravity;
}

void world::set_damping(real linear, real angular) {
  detail::require_non_negative(linear, "linear damping");
  detail::require_non_negative(angular, "angular damping");
  settings_.linear_damping = linear;
  settings_.angular_damping = angular;
}

void world::set_broad_phase(broad_phase_kind kind) {
  world_settings changed = settings_;
  changed.broad_phase = kind;
  settings_ = validated(changed);
  space_.set_broad_phase(kind);
}

void world::set_material_combine(const material_combine_rules& rules) {
  world_settings changed = settings_;
  changed.material_combine = rules;
  settings_ = validated(changed);
}

void world::step(real h) {
  detail::require_positive(h, "time step");
  ++geometry_version_;
  const auto start = clock::now();
  start_velocities_.clear();
  for (const body& b : bodies_) start_velocities_.push_back({b.velocity_, b.angular_velocity_});
  integrate_velocities(h);
  const auto integrated = clock::now();
  // Pairs that may touch by the end of the step: contacts up to h |v| apart
  // are speculative, so a landing body stops at the surface instead of
  // sinking in by up to h |v| first.
  space_.candidate_pairs(bodies_, pairs_, h, settings_.contact_margin);
  const auto paired = clock::now();
  previous_contacts_.swap(contacts_);
  space_.find_contacts(bodies_, pairs_, contacts_, h, settings_.material_combine,
                       settings_.contact_margin, &sensor_overlaps_);
  const auto met = clock::now();
  if (!solver_) solver_ = std::make_unique<contact_solver>();  // a moved-from world
  solver_->solve_velocities(settings_, bodies_, start_velocities_, contacts_, previous_contacts_,
                            h);
  const auto solved = clock::now();
  integrate_positions(h);
  const auto moved = clock::now();
  solver_->correct_positions(settings_, bodies_, contacts_, h);
  const auto corrected = clock::now();

  timings_.integration = seconds(start, integrated) + seconds(solved, moved);
  timings_.pairs = seconds(integrated, paired);
  timings_.narrow_phase = seconds(paired, met);
  timings_.response = seconds(met, solved) + seconds(moved, corrected);
  timings_.candidate_pairs = pairs_.size();
  detail::find_events(previous_contacts_, contacts_, events_);
  // Contacts name bodies by index; the events and sensor overlaps by id.
  for (std::vector<contact_event>* list : {&events_.began, &events_.persisted, &events_.ended}) {
    for (contact_event& e : *list) e.body_a = id_of(e.body_a), e.body_b = id_of(e.body_b);
  }
  for (sensor_overlap& o : sensor_overlaps_) o.sensor = id_of(o.sensor), o.other = id_of(o.other);
  time_ += h;
}

// Semi-implicit Euler, velocity half (thesis eqs. 3.12 and 4.4). The angular
// part integrates the world-frame angular momentum, L' = L + h τ, and reads Ω
// back through the inertia; the gyroscopic term is in integrate_positions.
// Each body's gravity is scaled by its gravity_scale and its damping rates
// are its own where set: a body with neither (scale 1 multiplies exactly)
// steps bit for bit as before they existed.
void world::integrate_velocities(real h) {
  const auto decay = [h](real rate) { return 1 / (1 + h * rate); };
  const real linear_decay = decay(settings_.linear_damping);
  const real angular_decay = decay(settings_.angular_damping);
  for (body& b : bodies_) {
    if (b.is_dynamic()) {
      const real linear = b.linear_damping_ ? decay(*b.linear_damping_) : linear_decay;
      const real angular = b.angular_damping_ ? decay(*b.angular_damping_) : angular_decay;
      const vector gravity = b.gravity_scale_ * settings_.gravity;
      b.velocity_ = linear * (b.velocity_ + h * (gravity + b.inverse_mass_ * b.force_));
      const bivector momentum = b.world_inertia(b.angular_velocity_) + h * b.torque_;
      b.angular_velocity_ = angular * b.world_inverse_inertia(momentum);
    }
    b.force_ = vector{};
    b.torque_ = bivector{};
  }
}

// Position half (thesis eqs. 3.13, 4.5, 4.6): x' = x + h v and
// R' = exp(-h Ω / 2) R, renormalized.
//
// Without torque the world-frame angular momentum L = I_w(Ω) is constant, but
// I_w turns with the body, so Ω does not: that is the gyroscopic term of
// Euler's equations (I Ω̇ = τ - Ω × I Ω). We keep L fixed over the turn and
// read Ω from it through the inertia at the turn's midpoint, found by a few
// fixed-point sweeps (the implicit midpoint rule on the rotation). Taking Ω
// at the start of the turn instead (explicit Euler) conserves L as well but
// pumps energy in: +93% over 10,000 steps of 1/240 s for the 1:2:3 body.
void world::integrate_positions(real h) {
  constexpr int midpoint_sweeps = 4;
  for (body& b : bodies_) {
    if (b.is_static_) continue;
    b.position_ = b.position_ + h * b.velocity_;
    if (b.is_kinematic_) {  // turns as it is told
      const rotor attitude = e3ga::gp(e3ga::exp((-h / 2) * b.angular_velocity_), b.attitude_);
      b.attitude_ = attitude / e3ga::norm(attitude);
      continue;
    }
    const bivector momentum = b.world_inertia(b.angular_velocity_);
    const rotor start = b.attitude_;
    bivector omega = b.angular_velocity_;
    // An isotropic body's Ω is fixed with L: no midpoint to look for.
    const int sweeps = b.inertia_.is_isotropic() ? 0 : midpoint_sweeps;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      const rotor midpoint = e3ga::gp(e3ga::exp((-h / 4) * omega), start);
      b.attitude_ = midpoint / e3ga::norm(midpoint);
      omega = b.world_inverse_inertia(momentum);
    }
    const rotor attitude = e3ga::gp(e3ga::exp((-h / 2) * omega), start);
    b.attitude_ = attitude / e3ga::norm(attitude);
    if (sweeps > 0) b.angular_velocity_ = b.world_inverse_inertia(momentum);
  }
}

std::uint64_t world::state_hash() const {
  std::uint64_t hash = 14695981039346656037ull;
  const auto mix = [&hash](const auto& coordinates) {
    for (real x : coordinates) {
      unsigned char bytes[sizeof(real)];
      std::memcpy(bytes, &x, sizeof(real));
      for (unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
    }
  };
  for (const body& b : bodies_) {
    mix(b.position_.c);
    mix(b.velocity_.c);
    mix(b.attitude_.c);
    mix(b.angular_velocity_.c);
  }
  // The last impulses too: the next step starts from them.
  for (const contact& c : contacts_) {
    for (const contact_impulse& i : {c.impulse, c.resting}) {
      mix(std::array<real, 1>{i.normal});
      mix(i.tangent.c);
      mix(i.angular.c);
    }
  }
  return hash;
}

}  // namespace gaphys
