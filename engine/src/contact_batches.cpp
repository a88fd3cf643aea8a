// The contact phase's sweeps on batches (contact_batch.hpp): which runs go
// into which batch, their packs, and a sweep over them.
#include <omp.h>

#include <algorithm>
#include <numeric>
#include <utility>

#include "contact_solver.hpp"

namespace gaphys {

namespace {
constexpr int lanes = detail::contact_lanes;
}  // namespace

// Whether a run goes into a batch (detail::batches_take): never if one of
// its contacts has rolling or spinning resistance, which the packs leave out
// (few contacts have it): the scalar solve takes those.
bool contact_solver::batchable(std::size_t run, contact_batching batching) const {
  // (Where not even a run that turns a body would go, none goes: no need
  // to walk the run.)
  if (!detail::batches_take(batching, false)) return false;
  bool plain = true;
  for (std::size_t i = colouring_.run_starts[run]; i < colouring_.run_starts[run + 1]; ++i) {
    const constraint& k = constraints_[i];
    if (k.surface >= 0 && surfaces_[k.surface].resistance >= 0) return false;
    if (k.turns || (k.surface >= 0 && surfaces_[k.surface].friction.active())) plain = false;
  }
  return detail::batches_take(batching, plain);
}

// Each part's runs (part_runs), in order, into batches of `lanes` (the
// last one maybe short) and single runs; then the packs, from the
// constraints as the impact phase and the warm start left them.
void contact_solver::pack_batches(const world_settings& settings) {
  const std::size_t threads = static_cast<std::size_t>(sweep_threads_);
  const std::size_t parts = colouring_.colours() * threads * 2;
  groups_.clear();
  single_runs_.clear();
  normal_packs_.clear();
  friction_packs_.clear();
  pack_slots_.clear();
  part_groups_.assign(1, 0);
  part_singles_.assign(1, 0);
  if (!detail::batches_take(settings.batch_contacts, false)) {
    // No run goes on batches (the default build's two doubles): each part
    // is one stretch of single runs, written by the thread that solves it.
    // (Run by run on one thread, 0.1 ms of a 10,000-sphere step.)
    part_groups_.assign(parts + 1, 0);
    part_singles_.resize(parts + 1);
    for (std::size_t part = 0; part < parts; ++part) {
      const auto [first, end] = part_runs(part);
      part_singles_[part + 1] = part_singles_[part] + (end - first);
    }
    single_runs_.resize(part_singles_.back());
    stretch_ends_.resize(part_singles_.back());
    for_each_part([&](std::size_t part) {
      const std::size_t at = part_singles_[part], stop = part_singles_[part + 1];
      std::iota(single_runs_.begin() + std::ptrdiff_t(at),
                single_runs_.begin() + std::ptrdiff_t(stop), part_runs(part).first);
      std::fill(stretch_ends_.begin() + std::ptrdiff_t(at),
                stretch_ends_.begin() + std::ptrdiff_t(stop), stop);
    });
    return;
  }
  for (std::size_t part = 0; part < parts; ++part) {
    const auto [first, end] = part_runs(part);
    std::array<std::size_t, lanes> runs{};
    int filled = 0;
    for (std::size_t run = first; run < end; ++run) {
      if (!batchable(run, settings.batch_contacts)) {
        single_runs_.push_back(run);
        continue;
      }
      runs[filled++] = run;
      if (filled == lanes) add_batch_group(runs, filled), filled = 0;
    }
    if (filled > 0) add_batch_group(runs, filled);
    part_groups_.push_back(groups_.size());
    // Where each single run's stretch of consecutive ones ends (without
    // batches, the whole part is one).
    const std::size_t begin = part_singles_.back(), stop = single_runs_.size();
    stretch_ends_.resize(stop);
    for (std::size_t at = stop; at-- > begin;) {
      const bool joins = at + 1 < stop && single_runs_[at + 1] == single_runs_[at] + 1;
      stretch_ends_[at] = joins ? stretch_ends_[at + 1] : at + 1;
    }
    part_singles_.push_back(stop);
  }
}

std::pair<std::size_t, std::size_t> contact_solver::part_runs(std::size_t part) const {
  const auto threads = static_cast<std::size_t>(sweep_threads_);
  const std::size_t block = part / 2;
  return colouring_.runs_of(block / threads, block % threads, threads,
                            static_cast<detail::contact_colouring::part>(part % 2));
}

// Contact s of each lane's run into pack group.first + s; a lane whose run
// is shorter, or that has no run, is left empty (nothing to solve, no body).
void contact_solver::add_batch_group(const std::array<std::size_t, lanes>& runs, int filled) {
  batch_group group;
  group.first = normal_packs_.size();
  group.body_a.fill(batch_group::no_body);
  group.body_b.fill(batch_group::no_body);
  group.runs.fill(batch_group::no_run);
  for (int lane = 0; lane < filled; ++lane) {
    group.runs[lane] = runs[lane];
    const std::size_t begin = colouring_.run_starts[runs[lane]];
    const std::size_t length = colouring_.run_starts[runs[lane] + 1] - begin;
    group.count = std::max(group.count, length);
    group.body_a[lane] = constraints_[begin].place_a;
    group.body_b[lane] = constraints_[begin].place_b;
  }
  for (std::size_t s = 0; s < group.count; ++s) {
    detail::normal_pack normal;
    detail::friction_pack friction;
    std::array<std::ptrdiff_t, lanes> slots;
    slots.fill(-1);
    bool rubs = false;
    for (int lane = 0; lane < filled; ++lane) {
      const std::size_t i = colouring_.run_starts[runs[lane]] + s;
      if (i >= colouring_.run_starts[runs[lane] + 1]) continue;
      const constraint& k = constraints_[i];
      slots[lane] = static_cast<std::ptrdiff_t>(i);
      normal.row.set_lane(lane, normal_row(i));
      normal.normal_mass[lane] = k.normal_mass;
      normal.target_speed[lane] = k.target_speed;
      normal.relaxation[lane] = k.relaxation;
      normal.accumulated[lane] = k.accumulated;
      normal.solvable[lane] = k.mass_inverse > 0 && !(k.waits && !k.struck);
      normal.turns[lane] = k.turns;
      group.angular = group.angular || k.turns;
      if (k.surface < 0 || !surfaces_[k.surface].friction.active()) continue;
      const surface_terms& t = surfaces_[k.surface];
      friction.set_lane(lane, t.friction, t.friction_coefficient, t.normal_coupling);
      rubs = true;
    }
    if (rubs) {
      // (Friction's rows turn the bodies.)
      group.angular = true;
      normal.friction = static_cast<int>(friction_packs_.size());
      friction_packs_.push_back(friction);
    }
    normal_packs_.push_back(normal);
    pack_slots_.push_back(slots);
  }
  groups_.push_back(group);
}

// Back into the bodies with mass (static and kinematic ones, only read, may
// be in several lanes and in other threads' batches).
void contact_solver::scatter_bodies(const std::array<std::size_t, lanes>& index, bool angular,
                                    const detail::body_pack& x) {
  for (int lane = 0; lane < lanes; ++lane) {
    if (index[lane] == batch_group::no_body || !x.moves[lane]) continue;
    solver_body& to = solver_bodies_[index[lane]];
    to.velocity = ga::lane(x.velocity, lane);
    if (angular) to.angular_velocity = ga::lane(x.angular_velocity, lane);
  }
}

void contact_solver::solve_group(const batch_group& group, const sweep_kind& kind,
                                 sweep_result& result) {
  // The lanes whose runs are not settled (settled_run), as the scalar solve
  // passes them by.
  detail::pack_mask open(false);
  for (int lane = 0; lane < lanes; ++lane) {
    const std::size_t run = group.runs[lane];
    open[lane] = run != batch_group::no_run && !settled_run(run);
  }
  if (none_of(open)) return;
  static const solver_body none{};
  std::array<const solver_body*, lanes> from_a, from_b;
  for (int lane = 0; lane < lanes; ++lane) {
    const std::size_t a = group.body_a[lane], b = group.body_b[lane];
    from_a[lane] = a == batch_group::no_body ? &none : &solver_bodies_[a];
    from_b[lane] = b == batch_group::no_body ? &none : &solver_bodies_[b];
  }
  detail::body_pack a = detail::body_pack::gather(from_a.data());
  detail::body_pack b = detail::body_pack::gather(from_b.data());
  const detail::sweep_lanes lanes_kind{kind.turning_only, kind.last_of_all, kind.last_of_turning};
  detail::pack largest(0);
  bool any = false;
  for (std::size_t s = group.first; s < group.first + group.count; ++s) {
    detail::normal_pack& k = normal_packs_[s];
    detail::friction_pack* friction = k.friction >= 0 ? &friction_packs_[k.friction] : nullptr;
    any = detail::solve_lanes(k, friction, a, b, lanes_kind, open, largest) || any;
  }
  for (int lane = 0; lane < lanes; ++lane) {
    if (!open[lane]) continue;
    const std::size_t run = group.runs[lane];
    record_run(run, kind.stamps + run + 1, real(largest[lane]));
  }
  if (!any) return;  // nothing solved, nothing changed
  scatter_bodies(group.body_a, group.angular, a);
  scatter_bodies(group.body_b, group.angular, b);
  result.any = true;
  for (int lane = 0; lane < lanes; ++lane) {
    result.largest_change = std::max(result.largest_change, real(largest[lane]));
  }
}

void contact_solver::solve_part(std::size_t part, const sweep_kind& kind, sweep_result& result) {
  if (plain_lanes_ > 0) {  // (then nothing goes on batches)
    solve_plain_part(part, kind, result);
    return;
  }
  for (std::size_t g = part_groups_[part]; g < part_groups_[part + 1]; ++g) {
    solve_group(groups_[g], kind, result);
  }
  // The single runs a stretch of consecutive ones at a time: solve_runs per
  // run cost a call and its set-up per contact, a third of the instructions
  // of a plain contact's solve.
  for (std::size_t at = part_singles_[part]; at < part_singles_[part + 1];) {
    const std::size_t stop = stretch_ends_[at];
    solve_runs(single_runs_[at], single_runs_[at] + (stop - at), kind, result);
    at = stop;
  }
}

// The packs' impulses back into their constraints, for store_impulses.
void contact_solver::unpack_batches() {
  for (std::size_t p = 0; p < normal_packs_.size(); ++p) {
    const detail::normal_pack& normal = normal_packs_[p];
    for (int lane = 0; lane < lanes; ++lane) {
      if (pack_slots_[p][lane] < 0) continue;
      constraint& k = constraints_[pack_slots_[p][lane]];
      k.accumulated = normal.accumulated[lane];
      if (normal.friction < 0 || k.surface < 0) continue;
      const detail::friction_pack& friction = friction_packs_[normal.friction];
      if (!friction.present[lane]) continue;
      detail::disk_block& block = surfaces_[k.surface].friction;
      block.accumulated = {friction.accumulated[0][lane], friction.accumulated[1][lane]};
      block.slip_rate = friction.slip_rate[lane];
    }
  }
}

}  // namespace gaphys
