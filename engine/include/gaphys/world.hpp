// World: the dynamics side (thesis 4.1). It owns the bodies and the space and
// advances them with step(h): semi-implicit Euler, the thesis's impulses, and a
// position correction so resting contacts neither sink nor jitter.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "gaphys/contact_events.hpp"
#include "gaphys/detail/thread_choice.hpp"
#include "gaphys/queries.hpp"
#include "gaphys/space.hpp"

namespace gaphys {

// Whether the contact sweeps run on SIMD batches (world_settings).
enum class contact_batching {
  automatic,  // where a batch holds 4 or more reals (AVX, or float with SSE2), for
              // contacts that turn a body or rub
  on,
  off,
};

struct world_settings {
  vector gravity{0, 0, -9.81};  // m/s^2
  // Damping rates (1/s, >= 0): each step scales v by 1 / (1 + h c).
  real linear_damping = 0;
  real angular_damping = 0;
  int solver_iterations = 20;  // most sequential impulse sweeps per step
  // More sweeps, after those, for the contacts that turn a body (boxes,
  // capsules, hulls, compounds: off-centre contacts). With them a tower of
  // ten boxes stands within 0.4 mm for 10 s; without, it walks 5 mm
  // (docs/engine.md). Spheres alone never pay for them.
  int turning_iterations = 10;
  // m/s: a sweep changing no normal speed more ends the solve (1e-6 in a
  // float engine, whose speeds of 1 m/s round to 1e-7).
  real solver_tolerance = sizeof(real) == 8 ? real(1e-9) : real(1e-6);
  // Over-relaxation (projected SOR), in (0, 2): each impulse is this multiple
  // of the one that would meet its contact's target. 1 is plain
  // Gauss-Seidel; above 1 converges faster along chains of contacts.
  real solver_relaxation = 1.3;
  real restitution_threshold = 0.5;  // m/s: slower approaches do not bounce
  // Most sweeps of the impact phase per step (docs/engine.md): a row of N
  // touching bodies struck against the order of the contact list needs N.
  int impact_iterations = 64;
  // How a contact combines its two shapes' material values (material.hpp).
  material_combine_rules material_combine{};
  real position_correction = 0.2;  // share of the excess depth removed per step
  real linear_slop = 0.0005;       // m of depth left uncorrected
  // m: boxes, capsules and hulls this close make (speculative) contacts, so
  // a resting face keeps its contact points, and their warm start, from
  // step to step even where the correction lifts it clear for a moment.
  real contact_margin = 0.001;
  // Candidate pairs: the grid (O(N)) or the thesis's all pairs (O(N^2)); the
  // simulation is the same to the bit.
  broad_phase_kind broad_phase = broad_phase_kind::uniform_grid;
  // Sleeping (docs/engine.md, "Sleeping"): bodies joined by contacts form
  // islands; an island whose bodies have all moved slower than these
  // speeds for time_to_sleep seconds sleeps: its velocities are zeroed and
  // it costs nothing per step until something wakes it.
  bool sleeping = true;
  real sleep_linear_speed = 0.01;   // m/s, of the centre of mass
  real sleep_angular_speed = 0.01;  // rad/s
  real time_to_sleep = 0.5;         // s
  // Threads a step runs on (at most 1024); 0: every core, or one where one
  // steps faster (the world times a step on the other count now and then:
  // detail/thread_choice.hpp). The step computes the same to the bit with
  // any number (docs/engine.md, "Threads"), so snapshots do not keep it: a
  // restored world keeps its own.
  int threads = 0;
  // The contact sweeps on SIMD batches, several contacts at once
  // (docs/engine.md, "Contact batches"). They pay where a batch holds 4 or
  // more reals, for contacts with friction or off-centre ones; 2 doubles
  // (SSE2 alone) do not pay for gathering their bodies. Like threads, it
  // changes the time, not the result (to the bit), so snapshots do not
  // keep it.
  contact_batching batch_contacts = contact_batching::automatic;
};

// Wall-clock seconds the last step spent in each phase, and how many candidate
// pairs the broad phase handed to the narrow phase.
struct step_timings {
  double integration = 0;   // waking, forces, velocities, positions, attitudes, islands
  double pairs = 0;         // candidate pairs (the broad phase)
  double narrow_phase = 0;  // meets
  double response = 0;      // impulses and position correction
  double events = 0;        // sensor overlaps named by id (contact events: world::events())
  std::size_t candidate_pairs = 0;
  // The threads the step asked for (for world_settings::threads 0, as
  // chosen); inside an application's parallel region without nesting,
  // OpenMP runs it on one.
  int threads = 0;
};

class contact_solver;
namespace detail {
class query_index;
struct snapshot_access;  // snapshot.cpp: reads and writes every field
}

class world {
 public:
  // Throws invalid_input for settings out of range.
  explicit world(const world_settings& settings = world_settings{});
  // A copy has the same bodies, contacts and settings, and steps as the
  // original would.
  world(const world& other);
  world& operator=(const world& other);
  world(world&&) noexcept;
  world& operator=(world&&) noexcept;
  ~world();

  // Throws invalid_input (see body) and then adds nothing.
  body_id create_body(const body_definition& definition);
  // Removes the body, its contacts and their warm-start data; the others
  // step on as if it had never been there. Its id, and every reference to
  // it, is dead: at() throws invalid_input for the id, and ids given later
  // never equal it. Events never name a dead id: the last step's events of
  // the body are dropped, and its touches end with no `ended` event (one
  // counting a sensor's or a plate's touches subtracts the removed body's
  // itself). Throws invalid_input for an id of no body. It edits
  // contacts(), events() and sensor_overlaps() in place: to remove the
  // bodies a list names, copy the list first (a loop over events().began
  // that removed body_b skipped every other event).
  void remove_body(body_id id);
  // The body of a live id; invalid_input for a removed or unknown one. A
  // reference stays valid until the next create_body or remove_body.
  // Change a body through its setters: a whole body assigned over it
  // (w.at(id) = other) leaves the world's sleeping contacts naming the old
  // body's shapes, and a snapshot of that world cannot be restored.
  body& at(body_id id);
  const body& at(body_id id) const;
  bool contains(body_id id) const;
  // The bodies in creation order, without the removed ones: bodies()[i] is
  // the body id_of(i); contacts name bodies by these indices.
  const std::vector<body>& bodies() const { return bodies_; }
  std::size_t body_count() const { return bodies_.size(); }
  body_id id_of(std::size_t index) const;

  const world_settings& settings() const { return settings_; }
  void set_gravity(const vector& gravity);
  void set_damping(real linear, real angular);
  void set_broad_phase(broad_phase_kind kind);
  // Applies from the next step's contacts on.
  void set_material_combine(const material_combine_rules& rules);
  // Off wakes every body. (A new gravity wakes every body too.)
  void set_sleeping(bool sleeping);
  void set_threads(int threads);
  void set_batch_contacts(contact_batching batching);

  // Advances by h seconds (finite, > 0; else invalid_input, nothing changes).
  // A body whose velocities after this step's forces, or h times them, would
  // overflow (body::set_velocity) is rejected the same way, naming its id.
  // Should a body's motion overflow within the step all the same (contact
  // impulses between bodies of absurd masses or speeds), it throws
  // numeric_overflow, the world as the step left it, rather than go on with
  // NaNs.
  void step(real h);

  // Seconds simulated, summed in double whatever the engine's scalar: summed
  // in float, 1/240 s steps would lose a step in 2,048 s.
  double time() const { return time_; }
  // Every contact, the sleeping islands' too (as they were when the island
  // fell asleep), in body pair order. With islands asleep the list is
  // merged on the first call after a change: like the queries, not safe to
  // call from two threads at once on one world.
  const std::vector<contact>& contacts() const;
  // The pairs that began touching in the last step, that touched in the
  // step before and still do, and that stopped (contact_events.hpp). Found
  // from the step's two contact lists on the first call after the step, so
  // a world whose events nobody reads does not pay for them (0.7 ms of a
  // 10,000-sphere step); like contacts(), not safe to call from two threads
  // at once on one world.
  const contact_events& events() const;
  // The sensor shapes and the shapes they overlap or touch, as the last
  // step's narrow phase found them (in body pair order).
  const std::vector<sensor_overlap>& sensor_overlaps() const { return sensor_overlaps_; }
  const step_timings& last_step_timings() const { return timings_; }

  // Spatial queries, against every body's shapes where they are now (after
  // the last step and any setter), through a grid of their bounds rebuilt
  // when bodies have moved (docs/engine.md, "Queries"); not safe to call
  // from two threads at once on one world. Directions need not
  // be unit; max_distance is finite or infinite and >= 0. A ray that starts
  // inside (or on) a solid hits it at distance 0 with the normal -direction;
  // point shapes are never hit. Throws invalid_input for a non-finite origin
  // or direction, a zero direction or a negative or NaN distance.
  // The nearest hit within max_distance (ties: the body created first, then
  // the lower shape index).
  std::optional<ray_hit> ray_cast(const vector& origin, const vector& direction,
                                  real max_distance) const;
  // Every shape the ray enters within max_distance, nearest first (one hit
  // per shape).
  std::vector<ray_hit> ray_cast_all(const vector& origin, const vector& direction,
                                    real max_distance) const;
  // The bodies, in creation order, with a shape that overlaps or touches the
  // solid sphere (radius finite, > 0), or the box at a pose (half extents
  // finite, > 0; attitude nonzero, normalized).
  std::vector<body_id> overlap_sphere(const vector& centre, real radius) const;
  std::vector<body_id> overlap_box(const vector& centre, const vector& half_extents,
                                   const rotor& attitude = rotor{1, 0, 0, 0}) const;

  // FNV-1a over the bits of every body's position, velocity, attitude,
  // angular velocity and sleep state, and of the contact impulses (the next
  // step starts from them): equal states hash equal, on any run of the same
  // build.
  std::uint64_t state_hash() const;

  // Snapshots (docs/engine.md, "Snapshots"): the whole state of the world
  // (settings, bodies, ids, contacts and their warm-start impulses, events,
  // time) as bytes. A world restored from them steps on bit for bit as this
  // one does. restore_snapshot replaces everything in *this; for a
  // snapshot that is corrupt, truncated, of another build or inconsistent
  // it throws invalid_input (naming what is wrong and the byte offset) and
  // leaves *this untouched.
  std::vector<std::uint8_t> save_snapshot() const;
  void restore_snapshot(const std::vector<std::uint8_t>& bytes);
  // The same through a file. Saving writes a temporary file in the same
  // folder and renames it over `path` (over the file a symbolic link
  // names, keeping a replaced file's permissions), so a crash never leaves
  // half a snapshot there; errors (a folder that does not exist, a file
  // that cannot be read) are invalid_input naming the path.
  void save_snapshot_file(const std::string& path) const;
  void restore_snapshot_file(const std::string& path);

 private:
  friend struct detail::snapshot_access;
  void integrate_velocities(real h);
  void integrate_velocity(body& b, real h) const;
  bool steppable(const body& b, real h) const;
  void integrate_positions(real h);
  [[noreturn]] void report_overflow(std::size_t index) const;
  void wake_islands(std::vector<std::uint64_t>& labels);
  void wake_all();
  void fall_asleep(real h);
  std::vector<sensor_overlap> unchanged_sensor_overlaps() const;
  void merge_sensor_overlaps(const std::vector<sensor_overlap>& kept);

  world_settings settings_;
  std::size_t index_of(body_id id) const;  // or throws invalid_input
  body_id id_at(std::size_t index) const;  // id_of for an index known to be live

  std::vector<body> bodies_;
  // Ids: a slot (the low 32 bits) and its generation (the high 32), which
  // grows each time the slot's body is removed. Without removals the id is
  // the index.
  std::vector<std::size_t> slot_of_index_;
  std::vector<std::size_t> index_of_slot_;  // npos for a slot whose body was removed
  std::vector<std::uint32_t> generation_of_slot_;
  std::vector<std::size_t> free_slots_;
  gaphys::space space_;
  std::vector<body_pair> pairs_;
  std::vector<contact> contacts_;
  std::vector<contact> previous_contacts_;  // the last step's, for warm starting
  // contacts_ is the list the solver solved last, unchanged since (the
  // solver kept what its warm start reads of it); false after anything
  // that adds, drops or renumbers contacts between steps.
  bool contacts_solved_ = false;
  // The contacts of sleeping islands, in pair order, as they were when the
  // island fell asleep (contacts_ holds the awake ones); contacts() merges
  // the two into merged_contacts_ when there are sleeping ones.
  std::vector<contact> sleeping_contacts_;
  mutable std::vector<contact> merged_contacts_;
  mutable bool merged_current_ = false;
  std::uint64_t next_island_ = 1;  // the label the next island to fall asleep gets
  // Scratch of the islands' search and of waking (nothing a later step reads).
  std::vector<std::size_t> island_parent_;
  std::vector<real> island_still_;
  std::vector<std::uint64_t> island_label_;
  std::vector<std::size_t> woken_bodies_;
  // The last step's events, once found (events()); until then
  // events_pending_, and previous_contacts_ and contacts_ as the step left
  // them: whatever changes those lists or the bodies' indices finds the
  // events first (settle_events).
  mutable contact_events events_;
  mutable bool events_pending_ = false;
  void settle_events() const;
  std::vector<sensor_overlap> sensor_overlaps_;
  std::vector<body_velocity> start_velocities_;  // before this step's forces, for restitution
  step_timings timings_;
  double time_ = 0;
  // For world_settings::threads 0, the threads each step runs on; and the
  // count the last step ran on (the contact events found after it use it
  // too). Timing, not state: a copy or a restored world starts afresh.
  detail::thread_choice thread_choice_;
  int step_threads_ = 0;
  // The contact solver's working memory, kept from step to step (it holds
  // nothing a later step reads, so a copy of the world starts a fresh one).
  std::unique_ptr<contact_solver> solver_;
  // The queries' index of the shapes, built when a query finds it older than
  // the bodies' poses: geometry_version_ counts this world's steps, new
  // bodies and non-const at() (a body may be assigned through it); body
  // setters count their changes apart (pose_changes.hpp).
  mutable std::unique_ptr<detail::query_index> queries_;
  std::uint64_t geometry_version_ = 0;
};

}  // namespace gaphys
