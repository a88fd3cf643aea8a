#include "gaphys/world.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>

#include "contact_events.hpp"
#include "contact_solver.hpp"
#include "query_index.hpp"
#include "thread_count.hpp"
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
  // (At most a million sweeps each: more would never end a step, and the
  // solver adds the first two as ints.)
  constexpr int most_sweeps = 1'000'000;
  if (s.solver_iterations < 1 || s.solver_iterations > most_sweeps) {
    detail::reject("solver iterations must be in [1, 1000000] (got ", s.solver_iterations, ")");
  }
  if (s.turning_iterations < 0 || s.turning_iterations > most_sweeps) {
    detail::reject("turning iterations must be in [0, 1000000] (got ", s.turning_iterations, ")");
  }
  if (s.impact_iterations < 1 || s.impact_iterations > most_sweeps) {
    detail::reject("impact iterations must be in [1, 1000000] (got ", s.impact_iterations, ")");
  }
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
  detail::require_non_negative(s.sleep_linear_speed, "sleep linear speed");
  detail::require_non_negative(s.sleep_angular_speed, "sleep angular speed");
  detail::require_non_negative(s.time_to_sleep, "time to sleep");
  if (s.threads < 0 || s.threads > 1024) {
    detail::reject("threads must be in [0, 1024], 0 for every core (got ", s.threads, ")");
  }
  if (s.batch_contacts != contact_batching::automatic && s.batch_contacts != contact_batching::on &&
      s.batch_contacts != contact_batching::off) {
    detail::reject("batch_contacts must be automatic, on or off (got ",
                   static_cast<int>(s.batch_contacts), ")");
  }
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
      sleeping_contacts_(other.sleeping_contacts_),
      next_island_(other.next_island_),
      events_(other.events_),
      events_pending_(other.events_pending_),
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

// Merges `from` into the pair-sorted `into`; a pair's contacts are all in
// one of the two lists, so ordering by pair keeps them in the narrow
// phase's order.
void merge_by_pair(std::vector<contact>& into, const std::vector<contact>& from) {
  if (from.empty()) return;
  std::vector<contact> merged;
  merged.reserve(into.size() + from.size());
  std::merge(into.begin(), into.end(), from.begin(), from.end(), std::back_inserter(merged),
             [](const contact& x, const contact& y) {
               return std::tie(x.body_a, x.body_b) < std::tie(y.body_a, y.body_b);
             });
  into.swap(merged);
}

// Moves the contacts of `from` for which `moves(c)` holds into the
// pair-sorted `to`; both stay in pair order.
template <class Predicate>
void move_contacts(std::vector<contact>& from, std::vector<contact>& to, Predicate moves) {
  std::vector<contact> moving, staying;
  for (const contact& c : from) (moves(c) ? moving : staying).push_back(c);
  from.swap(staying);
  merge_by_pair(to, moving);
}

}  // namespace

body_id world::create_body(const body_definition& definition) {
  bodies_.emplace_back(definition);  // body's constructor validates, then nothing is added
  // A new body, even a static one, wakes the sleeping bodies it overlaps.
  bodies_.back().woken_ = true;
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
  return id_at(index);
}

body_id world::id_at(std::size_t index) const {
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
  settle_events();  // (before the lists and the indices change)
  contacts_solved_ = false;
  // What it touched, and its own island, wake: they may fall or slide now.
  std::vector<std::uint64_t> islands;
  if (bodies_[index].island_ != 0) islands.push_back(bodies_[index].island_);
  for (const contact& c : sleeping_contacts_) {
    if (c.body_a == index) islands.push_back(bodies_[c.body_b].island_);
    if (c.body_b == index) islands.push_back(bodies_[c.body_a].island_);
  }
  wake_islands(islands);
  for (const contact& c : contacts_) {
    if (c.body_a == index) bodies_[c.body_b].still_time_ = 0;
    if (c.body_b == index) bodies_[c.body_a].still_time_ = 0;
  }
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
  forget(sleeping_contacts_, index);
  merged_current_ = false;
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
  const bool changed = gravity.e1() != settings_.gravity.e1() ||
                       gravity.e2() != settings_.gravity.e2() ||
                       gravity.e3() != settings_.gravity.e3();
  settings_.gravity = gravity;
  if (changed) wake_all();
}

void world::set_sleeping(bool sleeping) {
  settings_.sleeping = sleeping;
  if (!sleeping) wake_all();
}

const contact_events& world::events() const {
  settle_events();
  return events_;
}

void world::settle_events() const {
  if (!events_pending_) return;
  detail::find_events(previous_contacts_, contacts_, events_, step_threads_);
  // Contacts name bodies by index; the events by id.
  for (std::vector<contact_event>* list : {&events_.began, &events_.persisted, &events_.ended}) {
    detail::parallel_for(step_threads_, list->size(), 4096, [&](std::size_t i) {
      contact_event& e = (*list)[i];
      e.body_a = id_at(e.body_a), e.body_b = id_at(e.body_b);
    });
  }
  events_pending_ = false;
}

const std::vector<contact>& world::contacts() const {
  if (sleeping_contacts_.empty()) return contacts_;
  if (!merged_current_) {
    merged_contacts_ = contacts_;
    merge_by_pair(merged_contacts_, sleeping_contacts_);
    merged_current_ = true;
  }
  return merged_contacts_;
}

// Every body of the islands labelled in `labels` wakes, still for no time,
// and its island's contacts rejoin the awake ones (where the next solve
// warm starts from them). The bodies woken are listed in woken_bodies_.
void world::wake_islands(std::vector<std::uint64_t>& labels) {
  woken_bodies_.clear();
  labels.erase(std::remove(labels.begin(), labels.end(), std::uint64_t{0}), labels.end());
  if (labels.empty()) return;
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    body& b = bodies_[i];
    if (b.island_ == 0 || !std::binary_search(labels.begin(), labels.end(), b.island_)) continue;
    b.asleep_ = false;
    b.still_time_ = 0;
    b.island_ = 0;
    woken_bodies_.push_back(i);
  }
  settle_events();  // (before contacts_ changes)
  contacts_solved_ = false;
  move_contacts(sleeping_contacts_, contacts_, [this](const contact& c) {
    return !bodies_[c.body_a].asleep_ && !bodies_[c.body_b].asleep_;
  });
  merged_current_ = false;
}

void world::wake_all() {
  std::vector<std::uint64_t> labels;
  for (const body& b : bodies_) labels.push_back(b.island_);
  wake_islands(labels);
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

void world::set_threads(int threads) {
  world_settings changed = settings_;
  changed.threads = threads;
  settings_ = validated(changed);
}

void world::set_batch_contacts(contact_batching batching) {
  world_settings changed = settings_;
  changed.batch_contacts = batching;
  settings_ = validated(changed);
}

void world::set_material_combine(const material_combine_rules& rules) {
  world_settings changed = settings_;
  changed.material_combine = rules;
  settings_ = validated(changed);
}

// Whether every number in `values` is finite: 0 x is 0 for finite x and NaN
// for infinities and NaNs (a plain sum of large finite numbers could overflow).
static bool all_finite(std::initializer_list<real> values) {
  real zero = 0;
  for (const real x : values) zero += 0 * x;
  return zero == 0;
}

// Whether b's pose and velocities are all finite.
static bool finite_state(const body& b) {
  const vector& x = b.position();
  const vector& v = b.velocity();
  const rotor& r = b.attitude();
  const bivector& w = b.angular_velocity();
  return all_finite({x.c[0], x.c[1], x.c[2], v.c[0], v.c[1], v.c[2], r.c[0], r.c[1], r.c[2], r.c[3],
                     w.c[0], w.c[1], w.c[2]});
}

void world::step(real h) {
  detail::require_positive(h, "time step");
  // (The correction of a step divides depths by h.)
  if (!std::isfinite(1 / h))
    detail::reject("time step is too short: 1 / h overflows (got ", h, ")");
  if (!std::isfinite(time_ + h)) {
    detail::reject("time step ", h, " s would take the world's time (", time_,
                   " s) past the largest double");
  }
  const auto start = clock::now();
  // The threads this step runs on (settings_.threads, or for 0 every core
  // or one, as measured: detail/thread_choice.hpp), and the settings the
  // solver runs with, on them.
  step_threads_ = thread_choice_.next(settings_.threads, omp_get_num_procs());
  world_settings solver_settings = settings_;
  solver_settings.threads = step_threads_;
  // One pass over the bodies (on the threads, for many): the velocities
  // before this step's forces (waking changes none), whether any body may
  // meet another (else no pair at all), whether the user woke a sleeping
  // one, whether any sleeps, and the first that cannot be stepped.
  start_velocities_.resize(bodies_.size());
  bool any_moves = false, any_woken = false, any_asleep = false, any_fixed_woken = false;
  std::size_t unsteppable = no_index;
  {
    const int threads = detail::threads_for(step_threads_, bodies_.size(), 1024);
    const auto count = static_cast<std::ptrdiff_t>(bodies_.size());
    // clang-format off
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1) \
    reduction(|| : any_moves, any_woken, any_asleep, any_fixed_woken) reduction(min : unsteppable)
    // clang-format on
    for (std::ptrdiff_t i = 0; i < count; ++i) {
      const body& b = bodies_[static_cast<std::size_t>(i)];
      start_velocities_[static_cast<std::size_t>(i)] = {b.velocity_, b.angular_velocity_};
      const detail::motion m = detail::motion_of(b);
      const bool moves = m == detail::motion::awake || m == detail::motion::mover;
      any_moves = any_moves || moves;
      any_woken = any_woken || (b.woken_ && b.island_ != 0);
      any_fixed_woken = any_fixed_woken || (b.woken_ && !b.is_dynamic());
      any_asleep = any_asleep || b.asleep_;
      if (moves && !steppable(b, h)) {
        unsteppable = std::min(unsteppable, static_cast<std::size_t>(i));
      }
    }
  }
  if (unsteppable != no_index) {
    detail::reject("step: body ", id_at(unsteppable), " would move or turn too far in h = ", h,
                   " s (its velocities after this step's forces, or h times them, overflow)");
  }
  ++geometry_version_;
  merged_current_ = false;
  events_pending_ = false;  // (the last step's, unread: this step's replace them)
  // The islands of the bodies the user woke since the last step wake whole;
  // so do the sleeping islands resting on a static or kinematic body the
  // user moved or set going (its sleeping contacts name them, as they do
  // for remove_body): moved away, or down, it no longer reaches them, and a
  // box left asleep on a floor lowered by 30 cm floated where it was.
  std::vector<std::uint64_t> islands;
  if (any_woken) {
    for (const body& b : bodies_) {
      if (b.woken_ && b.island_ != 0) islands.push_back(b.island_);
    }
  }
  if (any_fixed_woken && any_asleep) {
    for (const contact& c : sleeping_contacts_) {
      const body& a = bodies_[c.body_a];
      const body& b = bodies_[c.body_b];
      if (a.woken_ && !a.is_dynamic()) islands.push_back(b.island_);
      if (b.woken_ && !b.is_dynamic()) islands.push_back(a.island_);
    }
  }
  wake_islands(islands);
  any_moves = any_moves || !woken_bodies_.empty();
  integrate_velocities(h);
  const auto integrated = clock::now();
  // Pairs that may touch by the end of the step: contacts up to h |v| apart
  // are speculative, so a landing body stops at the surface instead of
  // sinking in by up to h |v| first. A sleeping body that makes a contact
  // with a moving one wakes its island, whose bodies then take this step's
  // gravity and forces as if they had been awake, and the pairs are found
  // again with them.
  pairs_.clear();
  while (any_moves) {
    space_.candidate_pairs(bodies_, pairs_, h, settings_.contact_margin, step_threads_);
    if (!any_asleep) break;  // no island to wake
    islands.clear();
    for (const auto& [a, b] : pairs_) {
      const std::size_t sleeper = bodies_[a].asleep_ ? a : bodies_[b].asleep_ ? b : no_index;
      if (sleeper == no_index) continue;
      if (space_.make_contact(bodies_, a, b, h, settings_.contact_margin)) {
        islands.push_back(bodies_[sleeper].island_);
      }
    }
    wake_islands(islands);
    if (woken_bodies_.empty()) break;
    for (std::size_t i : woken_bodies_) integrate_velocity(bodies_[i], h);
  }
  const auto paired = clock::now();
  const bool previous_solved = contacts_solved_;
  previous_contacts_.swap(contacts_);
  std::vector<sensor_overlap> sleeping_overlaps = unchanged_sensor_overlaps();
  space_.find_contacts(bodies_, pairs_, contacts_, h, settings_.material_combine,
                       settings_.contact_margin, &sensor_overlaps_, step_threads_,
                       settings_.linear_slop);
  merge_sensor_overlaps(sleeping_overlaps);
  const auto met = clock::now();
  if (!solver_) solver_ = std::make_unique<contact_solver>();  // a moved-from world
  // (Without contacts the solver would copy every velocity out and back.)
  if (!contacts_.empty()) {
    solver_->solve_velocities(solver_settings, bodies_, start_velocities_, contacts_,
                              previous_contacts_, previous_solved, h);
  }
  contacts_solved_ = !contacts_.empty();
  const auto solved = clock::now();
  integrate_positions(h);
  const auto moved = clock::now();
  if (!contacts_.empty()) solver_->correct_positions(solver_settings, bodies_, contacts_, h);
  const auto corrected = clock::now();
  // The events are found when read (events()), or before the islands that
  // fall asleep set their contacts aside. Contacts name bodies by index; the
  // sensor overlaps by id.
  events_pending_ = true;
  for (sensor_overlap& o : sensor_overlaps_) o.sensor = id_of(o.sensor), o.other = id_of(o.other);
  const auto reported = clock::now();
  fall_asleep(h);
  // (On the threads for many bodies, as the step's first pass.)
  std::size_t overflowed = no_index;
  {
    const int threads = detail::threads_for(step_threads_, bodies_.size(), 1024);
    const auto count = static_cast<std::ptrdiff_t>(bodies_.size());
    // clang-format off
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1) \
    reduction(min : overflowed)
    // clang-format on
    for (std::ptrdiff_t i = 0; i < count; ++i) {
      body& b = bodies_[static_cast<std::size_t>(i)];
      b.woken_ = false;
      if (!finite_state(b)) overflowed = std::min(overflowed, static_cast<std::size_t>(i));
    }
  }
  const auto slept = clock::now();

  timings_.integration =
      seconds(start, integrated) + seconds(solved, moved) + seconds(reported, slept);
  timings_.pairs = seconds(integrated, paired);
  timings_.narrow_phase = seconds(paired, met);
  timings_.response = seconds(met, solved) + seconds(moved, corrected);
  timings_.events = seconds(corrected, reported);
  timings_.candidate_pairs = pairs_.size();
  timings_.threads = step_threads_;
  thread_choice_.record(seconds(start, slept));
  time_ += h;
  if (overflowed != no_index) report_overflow(overflowed);
}

// The sensor overlaps of the last step (ids) whose two bodies cannot meet
// this step (asleep, or static against asleep): they stand as they were.
// Returned with body indices, in pair order.
std::vector<sensor_overlap> world::unchanged_sensor_overlaps() const {
  std::vector<sensor_overlap> kept;
  for (const sensor_overlap& o : sensor_overlaps_) {
    const std::size_t s = index_of(o.sensor), other = index_of(o.other);
    if (detail::may_meet(detail::motion_of(bodies_[s]), detail::motion_of(bodies_[other]))) {
      continue;
    }
    kept.push_back(sensor_overlap{s, o.sensor_shape, other, o.other_shape});
  }
  return kept;
}

void world::merge_sensor_overlaps(const std::vector<sensor_overlap>& kept) {
  if (kept.empty()) return;
  const auto pair_of = [](const sensor_overlap& o) {
    return std::make_pair(std::min(o.sensor, o.other), std::max(o.sensor, o.other));
  };
  std::vector<sensor_overlap> merged;
  merged.reserve(kept.size() + sensor_overlaps_.size());
  std::merge(sensor_overlaps_.begin(), sensor_overlaps_.end(), kept.begin(), kept.end(),
             std::back_inserter(merged), [&](const sensor_overlap& x, const sensor_overlap& y) {
               return pair_of(x) < pair_of(y);
             });
  sensor_overlaps_.swap(merged);
}

// Islands: the awake dynamic bodies joined by contacts (static and
// kinematic bodies join nothing, or a floor would make one island of
// everything). An island sleeps when every body in it has been still
// (below both sleep speeds, and allowed to sleep) for time_to_sleep and
// none touches a moving kinematic body: velocities zeroed, its contacts
// set aside with their impulses for the warm start when it wakes.
void world::fall_asleep(real h) {
  if (!settings_.sleeping) return;
  const std::size_t n = bodies_.size();
  const auto awake = [this](std::size_t i) {
    return bodies_[i].is_dynamic() && !bodies_[i].asleep_;
  };
  bool any_awake = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!awake(i)) continue;
    any_awake = true;
    body& b = bodies_[i];
    const bool still = b.can_sleep_ && e3ga::norm(b.velocity_) <= settings_.sleep_linear_speed &&
                       e3ga::norm(b.angular_velocity_) <= settings_.sleep_angular_speed;
    b.still_time_ = still ? b.still_time_ + h : 0;
  }
  if (!any_awake) return;
  std::vector<std::size_t>& parent = island_parent_;
  parent.resize(n);
  for (std::size_t i = 0; i < n; ++i) parent[i] = i;
  const auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const contact& c : contacts_) {
    const bool awake_a = awake(c.body_a), awake_b = awake(c.body_b);
    if (awake_a && awake_b) {
      const std::size_t a = root(c.body_a), b = root(c.body_b);
      parent[std::max(a, b)] = std::min(a, b);
    } else if (awake_a && detail::motion_of(bodies_[c.body_b]) == detail::motion::mover) {
      bodies_[c.body_a].still_time_ = 0;
    } else if (awake_b && detail::motion_of(bodies_[c.body_a]) == detail::motion::mover) {
      bodies_[c.body_b].still_time_ = 0;
    }
  }
  std::vector<real>& least_still = island_still_;
  least_still.assign(n, std::numeric_limits<real>::infinity());
  for (std::size_t i = 0; i < n; ++i) {
    if (awake(i)) least_still[root(i)] = std::min(least_still[root(i)], bodies_[i].still_time_);
  }
  std::vector<std::uint64_t>& label = island_label_;
  label.assign(n, 0);
  bool any_asleep = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!awake(i) || !(least_still[root(i)] >= settings_.time_to_sleep)) continue;
    if (label[root(i)] == 0) label[root(i)] = next_island_++;
    body& b = bodies_[i];
    b.asleep_ = true;
    b.island_ = label[root(i)];
    b.velocity_ = vector{};
    b.angular_velocity_ = bivector{};
    any_asleep = true;
  }
  if (!any_asleep) return;
  settle_events();  // (before contacts_ changes: the pairs falling asleep persist)
  contacts_solved_ = false;
  move_contacts(contacts_, sleeping_contacts_, [this](const contact& c) {
    return bodies_[c.body_a].asleep_ || bodies_[c.body_b].asleep_;
  });
  merged_current_ = false;
}

// Semi-implicit Euler, velocity half (thesis eqs. 3.12 and 4.4). The angular
// part integrates the world-frame angular momentum, L' = L + h τ, and reads Ω
// back through the inertia; the gyroscopic term is in integrate_positions.
// Each body's gravity is scaled by its gravity_scale and its damping rates
// are its own where set: a body with neither (scale 1 multiplies exactly)
// steps bit for bit as before they existed.
// Each body on its own: on several threads from 256 bodies a thread. (A
// sphere's velocity half takes about 20 ns, its position half about 35:
// each thread's part is then some microseconds, a few times what starting
// and joining the threads costs. From 2,048 a thread, both halves ran on
// one thread at 1,000 spheres: about 50 us of a step on two threads.)
void world::integrate_velocities(real h) {
  detail::parallel_for(step_threads_, bodies_.size(), 256, [&](std::size_t i) {
    body& b = bodies_[i];
    if (!b.asleep_) integrate_velocity(b, h);
  });
}

void world::integrate_velocity(body& b, real h) const {
  if (b.is_dynamic()) {
    const auto decay = [h](real rate) { return 1 / (1 + h * rate); };
    const real linear = decay(b.linear_damping_.value_or(settings_.linear_damping));
    const real angular = decay(b.angular_damping_.value_or(settings_.angular_damping));
    const vector gravity = b.gravity_scale_ * settings_.gravity;
    b.velocity_ = linear * (b.velocity_ + h * (gravity + b.inverse_mass_ * b.force_));
    const bivector momentum = b.world_inertia(b.angular_velocity_) + h * b.torque_;
    b.angular_velocity_ = angular * b.world_inverse_inertia(momentum);
  }
  b.force_ = vector{};
  b.torque_ = bivector{};
}

// Whether b, moving in this step, can: its velocities after this step's
// gravity and forces (damping only slows them), and h times them, square to
// finite numbers, and its next position is finite. (The step squares
// speeds in every norm it takes; past that it would make NaNs.)
bool world::steppable(const body& b, real h) const {
  vector v = b.velocity_;
  bivector w = b.angular_velocity_;
  if (b.is_dynamic()) {
    v = v + h * (b.gravity_scale_ * settings_.gravity + b.inverse_mass_ * b.force_);
    if (b.torque_.c != bivector{}.c) w = w + h * b.world_inverse_inertia(b.torque_);
  }
  // (|v| and h |v|, whichever is larger.)
  const real longer = std::max(real(1), h);
  const vector moved = b.position_ + h * v;
  return all_finite(
      {e3ga::norm2(longer * v), e3ga::norm2(longer * w), moved.e1(), moved.e2(), moved.e3()});
}

// What steppable() cannot foresee (contact impulses between bodies of
// absurd masses or speeds, say) is caught at the end of the step, which
// throws then rather than hand on NaNs that would poison every later step.
void world::report_overflow(std::size_t index) const {
  throw numeric_overflow("gaphys: step: the motion of body " + std::to_string(id_at(index)) +
                         " overflowed in this step (its masses, speeds or forces are too large "
                         "for real numbers); the world is left as the step left it");
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
  // (Each body on its own, as integrate_velocities.)
  detail::parallel_for(step_threads_, bodies_.size(), 256, [&](std::size_t i) {
    body& b = bodies_[i];
    // Sleeping bodies and kinematic ones at rest stay exactly where they are.
    if (b.is_static_ || b.asleep_ || detail::motion_of(b) == detail::motion::fixed) return;
    b.position_ = b.position_ + h * b.velocity_;
    if (b.is_kinematic_) {  // turns as it is told
      const rotor attitude = e3ga::gp(e3ga::exp((-h / 2) * b.angular_velocity_), b.attitude_);
      b.attitude_ = attitude / e3ga::norm(attitude);
      return;
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
  });
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
    // When it falls asleep, too.
    mix(std::array<real, 2>{b.still_time_, real(b.asleep_ ? 1 : 0)});
  }
  // The last impulses too: the next step starts from them.
  for (const contact& c : contacts()) {
    for (const contact_impulse& i : {c.impulse, c.resting}) {
      mix(std::array<real, 1>{i.normal});
      mix(i.tangent.c);
      mix(i.angular.c);
    }
  }
  return hash;
}

}  // namespace gaphys
