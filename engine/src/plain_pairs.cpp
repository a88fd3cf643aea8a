// The plain sweeps of a double engine with SSE2 on pairs of contacts
// (plain_pairs.hpp): each part's contacts paired before the sweeps, solved
// two at a time in them, their impulses back into the constraints after.
#include "plain_pairs.hpp"

#include <algorithm>
#include <type_traits>

#include "contact_solver.hpp"

namespace gaphys {

bool contact_solver::pairs_plain_contacts() {
#if defined(__SSE2__)
  return std::is_same_v<real, double>;
#else
  return false;
#endif
}

// Each part's contacts, from its first slot on, in the order the sweeps
// solved them one by one: two contacts in a row of different runs into one
// pair, a contact without one into a pair of its own; contacts the sweeps
// leave out into none. Part p's pairs start where its slots do (it has no
// more pairs than slots).
void contact_solver::pair_plain_contacts() {
  const std::size_t count = constraints_.size();
  const auto spare = static_cast<std::uint32_t>(plain_bodies_.size() - 1);
  plain_pairs_.resize(count);
  pair_slots_.resize(count);
  part_pairs_.resize(colouring_.colours() * static_cast<std::size_t>(sweep_threads_) * 2);
  for_each_part([&](std::size_t part) {
    const auto [first_run, end_run] = part_runs(part);
    const std::size_t first = colouring_.run_starts[first_run];
    const std::size_t end = colouring_.run_starts[end_run];
    std::size_t out = first;
    // Lane `lane` of pair `out`: slot s's contact, or none (no_slot).
    const auto put = [&](int lane, std::uint32_t s) {
      detail::plain_pair& p = plain_pairs_[out];
      pair_slots_[out][lane] = s;
      if (s == no_slot) {
        p.normal_x[lane] = p.normal_y[lane] = p.normal_z[lane] = 0;
        p.target_speed[lane] = p.normal_mass[lane] = p.accumulated[lane] = 0;
        p.mass_inverse[lane] = 0;
        p.relaxation[lane] = 1;
        p.place_a[lane] = p.place_b[lane] = spare;
        return;
      }
      const constraint& k = constraints_[s];
      p.normal_x[lane] = k.normal.e1();
      p.normal_y[lane] = k.normal.e2();
      p.normal_z[lane] = k.normal.e3();
      p.target_speed[lane] = k.target_speed;
      p.relaxation[lane] = k.relaxation;
      p.normal_mass[lane] = k.normal_mass;
      p.accumulated[lane] = k.accumulated;
      p.mass_inverse[lane] = k.mass_inverse;
      p.place_a[lane] = k.place_a;
      p.place_b[lane] = k.place_b;
    };
    for (std::size_t s = first; s < end;) {
      const constraint& k0 = constraints_[s];
      if (left_out(k0)) {
        ++s;
        continue;
      }
      put(0, static_cast<std::uint32_t>(s));
      // (Contacts of one run share their bodies: one after the other.)
      const bool two =
          s + 1 < end && !left_out(constraints_[s + 1]) &&
          (constraints_[s + 1].place_a != k0.place_a || constraints_[s + 1].place_b != k0.place_b);
      put(1, two ? static_cast<std::uint32_t>(s + 1) : no_slot);
      s += two ? 2 : 1;
      ++out;
    }
    part_pairs_[part] = {first, out};
  });
}

// The pairs' impulses back into their constraints (store_impulses reads
// them there).
void contact_solver::store_paired_impulses() {
  for_each_part([&](std::size_t part) {
    const auto [first, end] = part_pairs_[part];
    for (std::size_t at = first; at < end; ++at) {
      for (int lane = 0; lane < 2; ++lane) {
        const std::uint32_t s = pair_slots_[at][lane];
        if (s != no_slot) constraints_[s].accumulated = plain_pairs_[at].accumulated[lane];
      }
    }
  });
}

// One sweep of part `part`'s pairs.
void contact_solver::solve_paired_part(std::size_t part, const sweep_kind& kind,
                                       sweep_result& result) {
  // (Past solver_iterations only contacts that turn a body are solved.)
  if (kind.turning_only) return;
  const auto [first, end] = part_pairs_[part];
  if (first == end) return;
  if (kind.last_of_all) {
    solve_pairs<true>(first, end, result);
  } else {
    solve_pairs<false>(first, end, result);
  }
}

template <bool last>
void contact_solver::solve_pairs(std::size_t first, std::size_t end, sweep_result& result) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<real, double>) {
    // (In locals: GCC read the arrays' addresses again for every pair, as
    // its stores might have changed them.)
    detail::plain_pair* const pairs = plain_pairs_.data();
    detail::plain_body* const at = plain_bodies_.data();
    // The largest change in either lane (the largest of numbers, none a
    // NaN, does not depend on the order they come in).
    __m128d largest = _mm_setzero_pd();
    for (std::size_t p = first; p < end; ++p) detail::solve_plain_pair<last>(pairs[p], at, largest);
    const __m128d larger = _mm_max_sd(largest, _mm_unpackhi_pd(largest, largest));
    result.any = true;
    result.largest_change =
        std::max(result.largest_change, static_cast<real>(_mm_cvtsd_f64(larger)));
  }
#endif
}

}  // namespace gaphys
