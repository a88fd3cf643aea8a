// Collision response: the thesis's impulse (eq. 3.20, in GA eq. 4.7) with the
// full inertia, Coulomb friction, rolling resistance and spinning friction,
// then a position correction that removes penetration without adding
// velocity. A step's response has two phases (docs/engine.md):
//
// 1. impacts: contacts that bounce exchange impulses as sequential pairwise
//    impacts would, each from the bodies' velocities as the earlier impacts
//    of the step left them, so an impact travels down a row of touching
//    balls (Newton's cradle) and no set of impacts can create energy;
// 2. contacts: sequential impulses on every contact at once (resting,
//    landing, sliding), warm started from the last step, friction in the
//    same sweeps as the normal impulse.
#pragma once

#include <omp.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "contact_batch.hpp"
#include "contact_colouring.hpp"
#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "gaphys/detail/cache_padded.hpp"
#include "gaphys/world.hpp"
#include "impulse_row.hpp"
#include "pair_cuts.hpp"
#include "plain_pairs.hpp"
#include "scratch_array.hpp"
#include "timed_impact.hpp"

namespace gaphys {

class contact_solver {
 public:
  // Changes velocities so that no contact still approaches, each bouncing
  // contact separates at e times its impact speed and every tangential
  // impulse stays within its friction cone, and stores each contact's
  // impulses in it. A bounce is timed inside the step (timed_impact.hpp)
  // from `start` (each body's velocities before this step's gravity and
  // forces) and the velocities after them; which contacts bounce, and how
  // fast, is read from `start` and the step's earlier impacts: taken after
  // gravity, a ball dropped with e = 1 would leave each bounce h g faster
  // than it came and climb 1.3% higher every time. Contacts between the
  // same two shapes in `previous` (the last step's, sorted by body pair like
  // `contacts`) with the same feature id, or else the nearest within 5% of
  // the smaller shape's size, start from their old resting impulses.
  //
  // A speculative contact (depth = -gap < 0) that does not bounce lets its
  // bodies close the gap in this step of h seconds but no more: its target
  // is -gap / h, so a landing body ends the step touching. One that would
  // bounce but meets only in a later step is left out.
  // `previous_solved`: `previous` is the list the last call solved, as it
  // left it (the world changed none of it since), whose keys it kept.
  void solve_velocities(const world_settings& settings, std::vector<body>& bodies,
                        const std::vector<body_velocity>& start, std::vector<contact>& contacts,
                        const std::vector<contact>& previous, bool previous_solved, real h);

  // After the positions moved by h v (and with the contacts of the last
  // solve_velocities): moves the bodies of a timed bounce by -t Δv (the
  // impulse came t into the step), and pushes other overlapping bodies apart
  // along the normal by a share of the depth beyond the slop.
  // Contacts that turn a body (off-centre ones: boxes, capsules, hulls,
  // compounds) are corrected together, moving and turning their bodies.
  void correct_positions(const world_settings& settings, std::vector<body>& bodies,
                         const std::vector<contact>& contacts, real h);

 private:
  using solver_body = detail::solver_body;
  using impulse_row = detail::impulse_row;
  using disk_block = detail::disk_block;

  // What every sweep reads of a contact, kept small: the sweeps walk all of
  // them, the rest of a contact's terms are looked up only where it has them.
  // Its normal row's arms, too, are apart (normal_arms_): a contact through
  // both centres (spheres, points, planes) has none, and with them inside,
  // 200 bytes a constraint, the sweeps over 10,000 spheres streamed twice
  // the memory.
  struct constraint {
    std::uint32_t body_a, body_b;    // the bodies' indices
    std::uint32_t place_a, place_b;  // their velocities' places (place_)
    vector normal;           // n, from B to A: the normal row's direction
    real mass_inverse = 0;   // the normal row's speed change per unit impulse; 0: left out
    real normal_mass = 0;    // 1 / mass_inverse (0 when left out)
    real target_speed = 0;   // normal separation speed wanted after the contact phase
    real relaxation = 1;     // settings' over-relaxation where the contact shares a body, else 1
    real accumulated = 0;    // the contact phase's normal impulse
    real restitution = 0;
    // m, > 0 for a speculative contact: its gap, and what its bodies' turning
    // read along the point's tangents overstates of how far their shapes
    // really come in the step (turning_overshoot), so the rows, which read
    // those tangents, close no more than the shapes can
    real gap = 0;
    int surface = -1;        // its friction and resistance terms in surfaces_, or -1: none
    bool turns = false;      // the normal row turns a body: its arms are normal_arms_[slot]
    bool bounces = false;    // approached faster than the threshold at the start of the step
    bool waits = false;      // a bounce whose surfaces meet only in a later step: left out
    bool struck = false;     // the impact phase gave it an impulse
  };

  // Friction, rolling resistance and spinning friction of one contact, in
  // three parts: what every sweep reads (friction), what only contacts with
  // resistance have, and what only the warm start and the stored impulses
  // read (the frame). Kept apart, a sweep over a thousand boxes' contacts
  // streams half the memory.
  struct surface_terms {
    disk_block friction;            // along t1, t2; inactive without friction
    // How much a unit normal impulse changes the speeds friction's rows read
    // (disk_block::solve_after).
    std::array<real, 2> normal_coupling{};
    real friction_coefficient = 0;  // μ
    int resistance = -1;            // its rolling and spinning terms in resistances_, or -1
  };
  struct resistance_terms {
    std::array<bivector, 3> planes;  // n ∧ t1, n ∧ t2 (rolling) and t1 ∧ t2 (spin)
    disk_block rolling;              // turning in n ∧ t1 and n ∧ t2
    impulse_row spinning;            // turning in t1 ∧ t2, about the normal
    real spinning_accumulated = 0;
    real rolling_bound = 0;          // c_r ρ: the rolling impulse per unit normal impulse
    real spinning_bound = 0;         // c_s ρ
  };
  struct surface_frame {
    std::array<vector, 2> frame;           // t1, t2: unit tangents, (t1, t2, n) right-handed
    std::array<real, 2> impact_tangent{};  // the impact phase's friction impulse
  };

  // Nothing pushes and nothing is held: nothing to rub.
  bool holds_nothing(const surface_terms& t) const {
    if (t.friction.accumulated != std::array<real, 2>{}) return false;
    if (t.resistance < 0) return true;
    const resistance_terms& r = resistances_[t.resistance];
    return r.rolling.accumulated == std::array<real, 2>{} && r.spinning_accumulated == 0;
  }

  // What the impact phase knows and did of one contact.
  struct impact_terms {
    std::optional<timed_impact> timing;  // when and how fast, for a bounce within the step
    real normal = 0;                     // the impulse the impact phase gave
    bool timed = false;      // its first impact came at timing->time into the step
    vector timed_impulse{};  // and was this impulse (N s); correct_positions moves the bodies by it
    real approach_speed = 0;  // contact::approach_speed
  };

  // What building a constraint reads of a body's shapes (summarize).
  struct shape_summary {
    bool central = false;      // central(): a sphere or point about its centre
    bool sphere = false;       // and it is a sphere
    bool plane = false;        // is_plane()
    real radius = 0;           // the central sphere's
    real rolling_radius = -1;  // its one shape's rolling radius; < 0: several shapes
  };
  // How many surface and resistance terms: a contact's own (0 or 1 each),
  // or where its own go in surfaces_ and resistances_.
  struct term_counts {
    std::size_t surfaces = 0, resistances = 0;
  };
  static shape_summary summarize(const body& b);
  static vector contact_offset(const body& x, const shape_summary& shapes, const contact& c,
                               const vector& n, real side);
  real rolling_radius(const body& a, const body& b, const contact& c) const;
  static term_counts terms_of(const body& a, const body& b, const contact& c);
  void build_constraint(const world_settings& settings, const body& a, const body& b,
                        const contact& c, const body_velocity& start_a,
                        const body_velocity& start_b, real h, std::size_t slot,
                        const term_counts& at);
  std::optional<timed_impact> time_impact(const body& a, const body& b, const contact& c,
                                          const body_velocity& start_a,
                                          const body_velocity& start_b, real h) const;
  // The same for any other contact, along its normal held fixed, from its
  // point's speeds (see build_constraint).
  std::optional<timed_impact> time_point_impact(const body& a, const body& b, const contact& c,
                                                real gap, const body_velocity& start_a,
                                                const body_velocity& start_b, real h) const;
  // A body's velocities through the step as a bounce's timing reads them:
  // after the step's forces, or, for a body that rests on a third (a box on
  // a floor struck by a ball), as the step began: what it rests on holds
  // its gravity, and timed as falling freely the ball struck it g t slower
  // than it came (an apex 24% low at 60 Hz with e = 0.5).
  body_velocity timing_velocity(const body& x, std::size_t index, std::size_t other,
                                const body_velocity& start) const;
  // The first two bodies each body rests on, for timing_velocity: touching
  // it, or nearly (within the contact margin), on the side the step's
  // forces press it towards (a floor under gravity, not a wall beside it);
  // `no_support` where it has fewer. From each contact's resting_sides
  // (rests_), in contact order.
  static constexpr std::size_t no_support = ~std::size_t{0};
  void find_supports(std::size_t bodies);
  std::vector<std::array<std::size_t, 2>> supports_;
  // Bit 1: A rests on B, bit 2: B on A (touching or within the margin, on
  // the side the forces press it towards), from forced_.
  unsigned char resting_sides(const world_settings& settings, const contact& c) const;
  std::vector<vector> forced_;        // per body: the velocity the step's forces gave it
  std::vector<vector> positions_;     // per body: its position (colour_contacts' slabs)
  std::vector<unsigned char> rests_;  // per contact: its resting_sides
  // Per contact: its terms_of (bit 1: surface terms, bit 2: resistance
  // terms), read in the same pass as rests_.
  std::vector<unsigned char> own_terms_;
  void count_contacts(std::size_t bodies, const std::vector<body_pair>& pairs);
  // The over-relaxation of a contact's normal row: settings' where it
  // shares a body with mass, 1 where it does not or the masses differ
  // (contact_solver.cpp).
  real relaxation_of(const world_settings& settings, const body& a, const body& b,
                     const contact& c) const;
  void resolve_impacts(const world_settings& settings, real h);
  bool impact(std::size_t index, real threshold, real h);
  void bounce(std::size_t index, real speed, bool timed_now);
  bool impact_run(std::size_t first, std::size_t end, real threshold, real h);
  std::optional<real> impact_speed(std::size_t index, real threshold, real h,
                                   bool& timed_now) const;
  void apply_impact_normal(std::size_t index, real j);
  void finish_impact(std::size_t index, real j, bool timed_now);
  // The warm start in two parts: which old contact each new one starts from
  // (matches_, in shares of both lists cut before the same pairs; needs
  // neither the colouring nor the constraints), then their impulses applied.
  void cut_for_matches(const std::vector<contact>& contacts, const std::vector<contact>& previous,
                       int shares);
  void match_share(int share, const std::vector<body>& bodies, const std::vector<contact>& contacts,
                   const std::vector<contact>& previous);
  std::size_t same_point(std::size_t i, std::size_t run, const std::vector<contact>& contacts,
                         const std::vector<contact>& previous,
                         const std::vector<body>& bodies) const;
  // What the warm start matches of a contact besides its bodies
  // (colouring_.pairs, previous_pairs_): this step's and the last step's.
  struct point_key {
    std::uint32_t shape_a, shape_b, feature;
  };
  static point_key key_of_point(const contact& c) { return {c.shape_a, c.shape_b, c.feature}; }
  std::vector<point_key> keys_, previous_keys_;
  std::vector<body_pair> previous_pairs_;
  void warm_start(const std::vector<contact>& previous);
  void warm_start_slots(std::size_t first, std::size_t end, const std::vector<contact>& previous);
  // What solve_velocities prepares from the bodies and contacts alone,
  // before the constraints: the rows' and shapes' summaries of the bodies
  // in contact, the solver's bodies, the warm start's matches. Sized and
  // marked on one thread first, then body by body and share by share.
  void mark_bodies_in_contact(const std::vector<body>& bodies);
  void prepare_body(std::size_t i, const std::vector<body>& bodies,
                    const std::vector<body_velocity>& start, bool velocities);
  void copy_velocities(std::size_t i, const std::vector<body>& bodies,
                       const std::vector<body_velocity>& start);
  void place_bodies(const std::vector<body>& bodies, const std::vector<body_velocity>& start);
  void prepare_bodies(const std::vector<body>& bodies, const std::vector<body_velocity>& start,
                      const std::vector<contact>& contacts, const std::vector<contact>& previous,
                      int threads);
  void colour_beside_preparation(const std::vector<body>& bodies,
                                 const std::vector<body_velocity>& start,
                                 const std::vector<contact>& contacts,
                                 const std::vector<contact>& previous);
  // Which contacts a sweep solves, and which of its sweeps are plain.
  struct sweep_kind {
    bool turning_only;     // past solver_iterations: only contacts that turn a body
    bool last_of_all;      // the last sweep of the contacts that do not turn a body
    bool last_of_turning;  // the last sweep of those that do
    std::uint64_t stamps;  // the stamp of the sweep's run r is stamps + r + 1
  };
  // A sweep's largest speed change, and whether it solved any contact.
  struct sweep_result {
    real largest_change = 0;
    bool any = false;
  };
  void solve_contacts(const world_settings& settings);
  // The sweeps on batches (contact_batch.hpp, contact_batches.cpp).
  struct batch_group;
  void pack_batches(const world_settings& settings);
  template <class Visit, class Ahead>
  void for_each_constraint(int threads, const Visit& visit, const Ahead& ahead) const;
  void find_slots(int threads);
  std::vector<std::uint16_t> owners_;  // per contact: its thread in the sweeps (find_slots)
  template <class Visit>
  void by_colours(const Visit& visit);
  // The slots of part p of block `block` of a colour (on one thread, part
  // own_runs of block 0 is the whole colour), and of the sequential group.
  std::pair<std::size_t, std::size_t> slots_of(std::size_t colour, std::size_t block,
                                               detail::contact_colouring::part p) const;
  std::pair<std::size_t, std::size_t> sequential_slots() const;
  template <class Solve, class Sequential, class Converged>
  void sweep_colours(int sweeps, const Solve& solve, const Sequential& sequential,
                     const Converged& converged);
  template <class Visit>
  void solve_in_parts(std::size_t colour, std::uint64_t count, std::size_t thread, std::size_t team,
                      const Visit& visit);
  void reset_shared_solved();
  void add_batch_group(const std::array<std::size_t, detail::contact_lanes>& runs, int filled);
  bool batchable(std::size_t run, contact_batching batching) const;
  // Part p of the sweeps: part p % 2 (contact_colouring::part) of block
  // p / 2, which is colour p / 2 / T, thread p / 2 % T of the sweep's T
  // threads (for one thread, the whole colour is part 1): part_index, and
  // its runs.
  std::size_t part_index(std::size_t colour, std::size_t thread,
                         detail::contact_colouring::part p) const {
    return 2 * (colour * static_cast<std::size_t>(sweep_threads_) + thread) + p;
  }
  std::pair<std::size_t, std::size_t> part_runs(std::size_t part) const;
  // Solves a part's batch groups, then its single runs.
  void solve_part(std::size_t part, const sweep_kind& kind, sweep_result& result);
  void solve_group(const batch_group& group, const sweep_kind& kind, sweep_result& result);
  void scatter_bodies(const std::array<std::size_t, detail::contact_lanes>& index, bool angular,
                      const detail::body_pack& x);
  void unpack_batches();
  // Whether a run is settled: its last solve changed no speed by more than
  // the tolerance, and the other runs on its bodies have changed them by no
  // more than that in all since. Solving it again would change next to
  // nothing, so the sweeps pass it by (in a pile of boxes coming to rest,
  // half the contact solves).
  bool settled_run(std::size_t run) const {
    if (!settling_) return false;
    const run_state& r = run_states_[run];
    return r.settled != 0 && body_disturbed_[r.body_a] <= r.settled &&
           body_disturbed_[r.body_b] <= r.settled;
  }
  // After run `run` was solved with stamp `stamp`, changing speeds by up to
  // `change`: it has settled, or its bodies are disturbed. Changes below the
  // tolerance add up on each body (its drift) until they disturb it: many
  // small ones move a body as far as one large one.
  void record_run(std::size_t run, std::uint64_t stamp, real change) {
    if (!settling_) return;
    run_state& r = run_states_[run];
    r.settled = change <= settle_tolerance_ ? stamp : 0;
    for (const std::size_t x : {r.body_a, r.body_b}) {
      if (!(solver_bodies_[x].inverse_mass > 0)) continue;
      body_drift_[x] += change;
      if (!(body_drift_[x] <= settle_tolerance_)) body_disturbed_[x] = stamp, body_drift_[x] = 0;
    }
  }
  void solve_runs(std::size_t first_run, std::size_t end_run, const sweep_kind& kind,
                  sweep_result& result);
  GAPHYS_ALWAYS_INLINE void solve_contact(std::size_t s, const sweep_kind& kind,
                                          sweep_result& result);
  template <class Body>
  void solve_plain_contacts(std::size_t first, std::size_t end, const sweep_kind& kind,
                            std::vector<Body>& bodies, sweep_result& result);
  // Whether the sweeps leave constraint k out: no mass to move, or a bounce
  // that waits for a later step.
  static bool left_out(const constraint& k) {
    return !(k.mass_inverse > 0) || (k.waits && !k.struck);
  }
  // One sweep's normal impulse of constraint k, whose row reads `speed`
  // (detail::row_speed), its total kept >= 0 and over-relaxed unless
  // `last`: accumulates it, raises largest_change by its speed change, and
  // returns it, not yet applied.
  static GAPHYS_ALWAYS_INLINE real normal_impulse(constraint& k, real speed, bool last,
                                                  real& largest_change) {
    const real relaxation = last ? real(1) : k.relaxation;
    const real wanted = relaxation * (k.target_speed - speed) * k.normal_mass;
    const real total = detail::at_least_zero(k.accumulated + wanted);
    const real j = total - k.accumulated;
    k.accumulated = total;
    largest_change = std::max(largest_change, std::fabs(j) * k.mass_inverse);
    return j;
  }
  // One sweep of plain constraint k (its row turns neither body): its
  // impulse, applied.
  template <class Body>
  static GAPHYS_ALWAYS_INLINE void solve_plain(constraint& k, Body& a, Body& b, bool last,
                                               real& largest_change) {
    const real j = normal_impulse(k, detail::row_speed(k.normal, a, b), last, largest_change);
    detail::row_apply(k.normal, a, b, j);
  }
  void store_impulses(std::vector<contact>& contacts, int threads) const;
  void correct_turning(const world_settings& settings, std::vector<body>& bodies,
                       const std::vector<contact>& contacts, real h);

  // In the sweeps' order (contact_colouring.hpp), not the contacts':
  // contact i is constraints_[slot_[i]].
  detail::contact_colouring colouring_;
  std::vector<std::size_t> slot_;
  // Per constraint: where its optional terms go (filled where any has some).
  std::vector<term_counts> terms_at_;
  std::vector<constraint> constraints_;
  std::vector<detail::row_arms> normal_arms_;  // per constraint, where it turns a body
  // Constraint s's normal arms, or null where its normal row turns nothing.
  GAPHYS_ALWAYS_INLINE const detail::row_arms* normal_arms(std::size_t s) const {
    return constraints_[s].turns ? &normal_arms_[s] : nullptr;
  }
  real normal_speed(std::size_t s, const solver_body& a, const solver_body& b) const {
    return detail::row_speed(constraints_[s].normal, normal_arms(s), a, b);
  }
  void apply_normal(std::size_t s, solver_body& a, solver_body& b, real j) const {
    detail::row_apply(constraints_[s].normal, normal_arms(s), a, b, j);
  }
  // The whole row (its arms zero where it turns nothing), for the batches.
  impulse_row normal_row(std::size_t s) const {
    const constraint& k = constraints_[s];
    impulse_row row;
    if (const detail::row_arms* arms = normal_arms(s)) static_cast<detail::row_arms&>(row) = *arms;
    row.linear = k.normal;
    row.turns = k.turns;
    row.mass_inverse = k.mass_inverse;
    return row;
  }
  std::vector<impact_terms> impacts_;        // one per constraint
  // Per constraint (in the sweeps' order, written by build_constraint):
  // resolve_impacts' first test.
  struct impact_filter {
    bool can_bounce;  // restitution, and a normal impulse that moves something
    bool starts;      // bounces from the start velocities (and meets within the step)
  };
  std::vector<impact_filter> impact_filters_;
  // Per run (colouring_.run_begins, contact order): its bodies, whether a
  // contact of it can bounce, and whether one bounces by itself.
  struct impact_run_filter {
    std::uint32_t body_a, body_b;
    bool starts, can_bounce;
  };
  std::vector<impact_run_filter> impact_runs_;
  // impact_run's scratch: the run's bouncing contacts.
  struct run_bounce {
    std::size_t index;  // the constraint
    real speed;         // its approach speed (impact_speed)
    real target;        // the normal speed wanted: about e times the approach speed
    real total;         // the run's impulse so far
    bool timed;
  };
  std::vector<run_bounce> run_bounces_;
  std::vector<surface_terms> surfaces_;      // for the constraints that have them
  std::vector<surface_frame> frames_;        // one per surface
  std::vector<resistance_terms> resistances_;  // for the surfaces that have them
  std::vector<int> contacts_per_body_;
  // Body i's velocities are solver_bodies_[place_[i]] and
  // impact_bodies_[place_[i]] (place_bodies); body_at_ is the inverse.
  std::vector<std::uint32_t> place_;
  std::vector<std::size_t> body_at_, owner_starts_, place_scratch_;
  std::vector<solver_body> solver_bodies_;  // the velocities after the step's forces, as solved
  // Where every contact is plain and none goes on batches (plain_sweeps_),
  // the sweeps change plain_bodies_ instead (by place too), copied from
  // solver_bodies_ before them and back after.
  std::vector<detail::plain_body> plain_bodies_;
  bool plain_sweeps_ = false;
  void copy_to_plain_bodies();
  void copy_from_plain_bodies();
  // Plain sweeps in double on x86-64 (plain_lanes_, from plain_lanes: 2,
  // or 4 with AVX, 8 with AVX-512; 0 elsewhere) solve each part's contacts
  // that many at a time (plain_pairs.hpp): part p's records are
  // plain_pairs_ (plain_quads_, plain_octets_) [part_records_[p].first ..
  // part_records_[p].second), from its first slot on, and lane_slots_ holds
  // each record's slots, W a record (no_slot for an empty lane). Past the
  // bodies' places, plain_bodies_ holds the empty lanes' spare, without
  // mass (spare_place).
  static constexpr std::uint32_t no_slot = ~std::uint32_t{0};
  detail::scratch_array<detail::plain_pair> plain_pairs_;
  detail::scratch_array<detail::plain_quad> plain_quads_;
  detail::scratch_array<detail::plain_octet> plain_octets_;
  detail::scratch_array<std::uint32_t> lane_slots_;
  std::vector<std::pair<std::size_t, std::size_t>> part_records_;
  int plain_lanes_ = 0;
  std::uint32_t spare_place() const { return static_cast<std::uint32_t>(solver_bodies_.size()); }
  static int plain_lanes();
  template <class Visit>
  void with_plain_records(const Visit& visit);
  void put_plain_contacts();
  template <int W>
  void put_in_lanes(detail::scratch_array<detail::plain_lanes<W>>& records);
  void store_plain_impulses();
  void solve_plain_part(std::size_t part, const sweep_kind& kind, sweep_result& result);
  template <bool last>
  void solve_plain_records(std::size_t first, std::size_t end, sweep_result& result);
  // visit(part) for every part of the sweeps, each on the thread whose sweeps
  // solve it (its rows come to that core).
  template <class Visit>
  void for_each_part(const Visit& visit) {
    const auto threads = static_cast<std::size_t>(sweep_threads_);
    const std::size_t parts = colouring_.colours() * threads * 2;
#pragma omp parallel num_threads(sweep_threads_) if (sweep_threads_ > 1)
    {
      const auto thread = static_cast<std::size_t>(omp_get_thread_num());
      const auto team = static_cast<std::size_t>(omp_get_num_threads());
      for (std::size_t part = 0; part < parts; ++part) {
        if (part / 2 % threads % team == thread) visit(part);
      }
    }
  }
  template <class Visit>
  void for_each_place(const Visit& visit);
  // Per body, for the bodies in contact (in_contact_): what building the
  // rows reads (row_body), and what building a constraint reads of its
  // shapes (summarize): read once per body, not once per contact
  // (in a pile each body has several, and its shapes lie elsewhere in memory).
  std::vector<detail::row_body> row_bodies_;
  std::vector<shape_summary> shape_summaries_;
  std::vector<char> in_contact_;
  std::vector<solver_body> impact_bodies_;  // the start velocities plus the impact phase's impulses
  std::vector<char> impacted_;              // bodies the impact phase has changed
  std::vector<char> previous_used_;         // the last step's contacts already warm starting one
  std::vector<std::size_t> matches_;        // per contact, the last step's it starts from (or none)
  detail::pair_cuts warm_cuts_;             // the warm start's shares of both lists
  std::vector<solver_body> pseudo_bodies_;  // correct_turning's pseudo velocities, by place_
  std::vector<real> pseudo_targets_, pseudo_accumulated_;  // per slot
  std::vector<char> pseudo_taking_part_;                   // per slot
  std::vector<char> pseudo_pushed_;           // per body: a dynamic body a deep contact pushes
  std::vector<sweep_result> thread_results_;  // per thread of the sweeps, in two rows
  // Per thread of the sweeps, how many colours' shared runs it has solved
  // in this contact phase, counted on across sweeps (solve_in_parts).
  std::unique_ptr<detail::cache_padded<std::atomic<std::uint64_t>>[]> shared_solved_;
  int shared_solved_count_ = 0;

  // The sweeps' batches. Part p (part_runs) has the runs of groups_[part_groups_[p] ..
  // part_groups_[p + 1]), up to contact_lanes runs each, and the runs
  // solved one by one, single_runs_[part_singles_[p] .. part_singles_[p + 1]).
  struct batch_group {
    static constexpr std::size_t no_body = ~std::size_t{0}, no_run = ~std::size_t{0};
    std::array<std::size_t, detail::contact_lanes> runs;            // per lane, or no_run
    // Per lane, its bodies' places (place_), or no_body.
    std::array<std::size_t, detail::contact_lanes> body_a, body_b;
    std::size_t first = 0, count = 0;  // its contacts: normal_packs_[first .. first + count)
    bool angular = false;              // some lane's impulses turn a body
  };
  std::vector<batch_group> groups_;
  std::vector<std::size_t> single_runs_, part_groups_, part_singles_;
  // Per single run (as single_runs_), one past the last single run of its
  // part that follows it without a gap: single_runs_ from it to there are
  // consecutive runs.
  std::vector<std::size_t> stretch_ends_;
  std::vector<detail::normal_pack> normal_packs_;
  std::vector<detail::friction_pack> friction_packs_;
  // Per normal pack, each lane's constraint (index into constraints_), or -1.
  std::vector<std::array<std::ptrdiff_t, detail::contact_lanes>> pack_slots_;
  int sweep_threads_ = 1;  // the contact phase's threads in this step
  // Per run, its bodies' places and the stamp of its last solve if it
  // settled there, else 0 (kept apart from the constraints: a settled run is
  // passed by without reading them); per body (by place), the stamp of the run solve after
  // which its changes passed settle_tolerance_ (settled_run, record_run).
  // The stamps of sweep s are s * runs + run + 1: a body's runs are solved
  // in that order.
  struct run_state {
    std::uint64_t settled = 0;
    std::size_t body_a = 0, body_b = 0;
  };
  std::vector<run_state> run_states_;
  std::vector<std::uint64_t> body_disturbed_;
  std::vector<real> body_drift_;  // per body: the changes below the tolerance since disturbed
  real settle_tolerance_ = 0;
  bool settling_ = false;  // this step passes settled runs by: some run turns a body or rubs
};

}  // namespace gaphys
