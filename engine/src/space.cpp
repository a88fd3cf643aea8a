#include "gaphys/space.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <new>
#include <optional>
#include <tuple>
#include <type_traits>

#include "convex_contact.hpp"
#include "huge_pages.hpp"
#include "prefetch.hpp"
#include "round_meet.hpp"
#include "thread_count.hpp"
#include "turning_reach.hpp"

namespace gaphys {

void space::candidate_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs,
                            real lookahead, real margin, int threads) {
  // The grid declines coordinates too far out for integer cells.
  if (kind_ == broad_phase_kind::uniform_grid &&
      grid_.find_pairs(bodies, shaped_bodies_, lookahead, margin, pairs, threads)) {
    return;
  }
  all_pairs(bodies, pairs, lookahead, margin);
}

// The thesis's candidates: every two shaped bodies, each pair tested as the
// grid tests its candidates (bounds that overlap, and that may meet: not
// both static, say), so that both broad phases hand the narrow phase the
// same pairs. (Which bodies have a moving body near them, `jostled`, is read
// off the pairs: untested, every body had one.)
void space::all_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs,
                      real lookahead, real margin) const {
  pairs.clear();
  std::vector<detail::uniform_grid::bound> bounds;
  bounds.reserve(shaped_bodies_.size());
  for (const std::size_t a : shaped_bodies_) {
    bounds.push_back(detail::uniform_grid::bound_of(bodies[a], a, lookahead, margin));
  }
  for (std::size_t i = 0; i < shaped_bodies_.size(); ++i) {
    const std::size_t a = shaped_bodies_[i];
    for (std::size_t j = i + 1; j < shaped_bodies_.size(); ++j) {
      const std::size_t b = shaped_bodies_[j];
      if (!detail::uniform_grid::pairs_bounds(bounds[i], bounds[j], bodies[a], bodies[b], margin)) {
        continue;
      }
      pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
}

// How far apart two bodies' surfaces may be for their shapes to make a
// (speculative) contact: what their speeds, including each turning about
// its centre, can close within the lookahead, plus `margin`.
static real turning_speed(const body& x) {
  // (A static body does not turn; a plane's bound is infinite.)
  return x.is_static() ? 0 : e3ga::norm(x.angular_velocity()) * x.bounding_radius();
}

static real closing_reach(const body& a, const body& b, real lookahead, real margin) {
  const real turning = turning_speed(a) + turning_speed(b);
  return margin + lookahead * (e3ga::norm(a.velocity()) + e3ga::norm(b.velocity()) + turning);
}

// How far the bodies' shapes can close along the normal n (from B towards
// A) within the lookahead: each body's own speed towards the other, -n . v_A
// and n . v_B where positive (not their relative speed: two boxes falling
// together close once a floor stops the lower one, as round pairs' contacts
// reason, docs/engine.md), and what their turning adds to each shape's
// support (turning_reach.hpp). `exact` false: the turning bounded by each
// body's bounding sphere, as closing_reach does.
static real closing_along(const body& a, const body& b, const placed_shape& shape_a,
                          const placed_shape& shape_b, const vector& n, real lookahead,
                          bool exact) {
  const real speed = std::max(real(0), -e3ga::scp(a.velocity(), n)) +
                     std::max(real(0), e3ga::scp(b.velocity(), n));
  if (!exact) return lookahead * (speed + turning_speed(a) + turning_speed(b));
  return lookahead * speed +
         detail::turning_approach(shape_a, a.position(), a.angular_velocity(), lookahead, -n) +
         detail::turning_approach(shape_b, b.position(), b.angular_velocity(), lookahead, n);
}

// Shape s of body b where its velocities take it in `time` seconds: moved by
// time v, turned by exp(-time Ω / 2) about its centre (as a step moves it).
static placed_shape placed_after(const body& b, const attached_shape& s, real time) {
  return space::placed(s, b.position() + time * b.velocity(),
                       e3ga::gp(e3ga::exp((-time / 2) * b.angular_velocity()), b.attitude()));
}

// Whether shape i of a dynamic body, moving on at its velocities, comes
// within `margin` of a static body's shape within the lookahead, by
// conservative advancement: apart by d along the unit normal n of their
// nearest points (from the static shape), the shapes' separation along n
// shrinks no faster than the body's speed against n plus its turning,
// -v . n + |Ω| r, so it may advance by d over that. (A box corner's normal at
// the start says where the static shape's face plane is, not where the face
// ends: a ball flying past a pillar's edge 2 cm off bounced off the face's
// plane beyond the edge.)
static bool sweeps_into(const body& mover, std::size_t i, const placed_shape& fixed, real lookahead,
                        real margin) {
  const attached_shape& s = mover.shapes()[i];
  real t = 0;
  for (int round = 0; round < 64; ++round) {
    const detail::separation apart = detail::convex_separation(placed_after(mover, s, t), fixed);
    if (apart.distance <= margin) return true;
    const real closing =
        std::max(real(0), -e3ga::scp(mover.velocity(), apart.normal)) + turning_speed(mover);
    if (!(closing > 0)) return false;
    t += apart.distance / closing;
    if (t > lookahead) return false;
  }
  return true;  // still closing in after 64 rounds: kept
}

// Leaves out the points of a manifold that its bodies cannot reach within
// the lookahead: those on a normal along which the nearest of them is more
// than `margin` plus closing_along apart. (The nearest, not each: a body
// turning towards the other may bring a farther corner in first.) A
// spinning body's speculative contacts with something its corners never
// reach would otherwise stop its linearised corner speeds, and throw it.
static void keep_reachable(const body& a, const body& b, std::size_t i, std::size_t j,
                           const placed_shape& shape_a, const placed_shape& shape_b, real lookahead,
                           real margin, contact_manifold& manifold) {
  std::array<bool, std::tuple_size_v<decltype(manifold.points)>> reached{};
  for (int k = 0; k < manifold.count; ++k) {
    const vector& n = manifold.points[k].geometry.normal;
    // The nearest point on this normal, and whether one before it decided.
    real gap = -manifold.points[k].geometry.depth;
    bool decided = false;
    for (int other = 0; other < manifold.count; ++other) {
      const contact_geometry& g = manifold.points[other].geometry;
      if (g.normal.c != n.c) continue;
      if (other < k) {
        reached[k] = reached[other];
        decided = true;
        break;
      }
      gap = std::min(gap, -g.depth);
    }
    if (decided) continue;
    const real beyond = gap - margin;
    reached[k] =
        beyond <= 0 || (beyond <= closing_along(a, b, shape_a, shape_b, n, lookahead, false) &&
                        beyond <= closing_along(a, b, shape_a, shape_b, n, lookahead, true));
    // A dynamic body apart from a static box, hull or capsule (a plane's
    // normal holds everywhere; round pairs are timed from their centres):
    // its path must bring it within the margin in this step.
    if (reached[k] && beyond > 0 &&
        !(detail::is_round(shape_a.kind) && detail::is_round(shape_b.kind)) &&
        shape_a.kind != shape_kind::plane && shape_b.kind != shape_kind::plane) {
      if (a.is_dynamic() && b.is_static()) {
        reached[k] = sweeps_into(a, i, shape_b, lookahead, margin);
      } else if (b.is_dynamic() && a.is_static()) {
        reached[k] = sweeps_into(b, j, shape_a, lookahead, margin);
      }
    }
  }
  int kept = 0;
  for (int k = 0; k < manifold.count; ++k) {
    if (reached[k]) manifold.points[kept++] = manifold.points[k];
  }
  manifold.count = kept;
}

// Only the bodies of some pair: with most bodies asleep, the others are not
// placed at all.
void space::place_shapes(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                         int threads) {
  // Each body's kind and number of shapes, read once on the threads: read
  // for both bodies of every pair, and the numbers for each body, serially,
  // these scattered reads of the large bodies took 0.1-0.2 ms of 10,000
  // spheres. Then where each body's shapes go; then the pairs mark their
  // bodies (mark_pairs).
  const std::size_t count = bodies.size();
  static_.resize(count);
  dynamic_.resize(count);
  first_shape_.resize(count + 1);
  first_shape_[0] = 0;
  detail::parallel_for(threads, count, 4096, [&](std::size_t i) {
    const body& b = bodies[i];
    static_[i] = b.is_static();
    dynamic_[i] = b.is_dynamic();
    first_shape_[i + 1] = b.shapes().size();
  });
  for (std::size_t i = 0; i < count; ++i) first_shape_[i + 1] += first_shape_[i];
  placed_.resize(first_shape_.back());
  mark_pairs(pairs, threads);
  singles_.resize(bodies.size());
  // Each body's shapes on their own: on the threads for many bodies.
  detail::parallel_for(threads, shaped_bodies_.size(), 256, [&](std::size_t at) {
    const std::size_t index = shaped_bodies_[at];
    if (!(body_marks_[index] & in_a_pair)) return;
    const body& b = bodies[index];
    // (Each made in its place, here and below: assigned from a copy made
    // aside, the bytes were read back as soon as they were written, wider
    // than written, and each read waited; two fifths of this loop.)
    static_assert(std::is_trivially_destructible_v<placed_shape>, "made anew over the old");
    placed_shape* out = &placed_[first_shape_[index]];
    for (const attached_shape& s : b.shapes())
      ::new (static_cast<void*>(out++)) placed_shape(placed(b, s));
    single_shape_facts& facts = singles_[index];
    facts.plain = b.shapes().size() == 1 && !b.shapes()[0].shape.is_sensor();
    if (facts.plain) {
      const shape& only = b.shapes()[0].shape;
      facts.velocity = b.velocity();
      facts.surface = only.material();
      facts.filter = only.filter();
    }
  });
}

// Each body's marks (body_marks_): each thread marks the bodies of its
// share of the pairs in a list of its own, then adds every list's marks to
// the first for its share of the bodies. (Marked by all threads in one
// list, the two cores wrote bytes of the same lines at random and took the
// lines from each other: at 10,000 spheres on two threads whose round trip
// is 400 ns, the marks and the placing of the shapes that reads them took
// 427 us, 324 so. A mark is written whatever it was: a branch on it went
// either way at random.)
void space::mark_pairs(const std::vector<body_pair>& pairs, int threads) {
  const std::size_t count = static_.size();
  const int markers = detail::threads_for(threads, pairs.size(), 8192);
  if (more_marks_.size() + 1 < static_cast<std::size_t>(markers)) more_marks_.resize(markers - 1);
#pragma omp parallel num_threads(markers) if (markers > 1)
  {
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<unsigned char>& marks = thread == 0 ? body_marks_ : more_marks_[thread - 1].value;
    marks.assign(count, 0);
    const std::size_t first = pairs.size() * thread / team;
    const std::size_t end = pairs.size() * (thread + 1) / team;
    for (std::size_t k = first; k < end; ++k) {
      const auto [a, b] = pairs[k];
      marks[a] |=
          static_cast<unsigned char>(in_a_pair | (dynamic_[a] && !static_[b] ? jostled : 0));
      marks[b] |=
          static_cast<unsigned char>(in_a_pair | (dynamic_[b] && !static_[a] ? jostled : 0));
    }
    if (team > 1) {
#pragma omp barrier
      const std::size_t from = count * thread / team, upto = count * (thread + 1) / team;
      for (std::size_t t = 1; t < team; ++t) {
        const unsigned char* more = more_marks_[t - 1].value.data();
        for (std::size_t i = from; i < upto; ++i) body_marks_[i] |= more[i];
      }
    }
  }
}

placed_shape space::placed(const body& b, const attached_shape& s) {
  return placed(s, b.position(), b.attitude());
}

placed_shape space::placed(const attached_shape& s, const vector& position, const rotor& attitude) {
  const bool centred = s.offset.e1() == 0 && s.offset.e2() == 0 && s.offset.e3() == 0;
  const vector at = centred ? position : position + e3ga::apply(attitude, s.offset);
  const bool turned = s.attitude.c[1] != 0 || s.attitude.c[2] != 0 || s.attitude.c[3] != 0;
  return place(s.shape, at, turned ? e3ga::gp(attitude, s.attitude) : attitude);
}

// Shape i of A against shape j of B, as find_contacts meets them: culled
// by their bounds in a compound, by their filters, a sensor's overlap, or
// the contact manifold (count 0: none).
space::met space::meet(const body& body_a, const body& body_b, std::size_t i, std::size_t j,
                       const placed_shape& shape_a, const placed_shape& shape_b, real lookahead,
                       real reach, real margin, bool alone, contact_manifold& manifold) {
  const attached_shape& attached_a = body_a.shapes()[i];
  const attached_shape& attached_b = body_b.shapes()[j];
  const bool compound = body_a.shapes().size() > 1 || body_b.shapes().size() > 1;
  // The broad phase bounded whole bodies; a compound's parts are
  // bounded again here, each by its own sphere.
  if (compound && shape_a.kind != shape_kind::plane && shape_b.kind != shape_kind::plane) {
    const real apart = e3ga::norm(shape_a.center - shape_b.center) -
                       attached_a.shape.bounding_radius() - attached_b.shape.bounding_radius();
    if (apart > reach) return met::nothing;
  }
  if (!attached_a.shape.filter().meets(attached_b.shape.filter())) return met::nothing;
  if (attached_a.shape.is_sensor() || attached_b.shape.is_sensor()) {
    return touching(shape_a, shape_b, manifold) ? met::sensed : met::nothing;
  }
  gaphys::find_contacts(shape_a, shape_b, lookahead, body_a.velocity(), body_b.velocity(), reach,
                        manifold);
  if (alone) keep_reachable(body_a, body_b, i, j, shape_a, shape_b, lookahead, margin, manifold);
  return manifold.count > 0 ? met::contacts : met::nothing;
}

bool space::make_contact(const std::vector<body>& bodies, std::size_t a, std::size_t b,
                         real lookahead, real margin) const {
  const body& body_a = bodies[a];
  const body& body_b = bodies[b];
  const real reach = closing_reach(body_a, body_b, lookahead, margin);
  contact_manifold manifold;
  for (std::size_t i = 0; i < body_a.shapes().size(); ++i) {
    const placed_shape shape_a = placed(body_a, body_a.shapes()[i]);
    for (std::size_t j = 0; j < body_b.shapes().size(); ++j) {
      const placed_shape shape_b = placed(body_b, body_b.shapes()[j]);
      if (meet(body_a, body_b, i, j, shape_a, shape_b, lookahead, reach, margin, false, manifold) ==
          met::contacts) {
        return true;
      }
    }
  }
  return false;
}

void space::remove(std::size_t body_index) {
  std::vector<std::size_t> kept;
  for (const std::size_t index : shaped_bodies_) {
    if (index != body_index) kept.push_back(index > body_index ? index - 1 : index);
  }
  shaped_bodies_.swap(kept);
}

void space::find_contacts(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                          std::vector<contact>& contacts, real lookahead,
                          const material_combine_rules& rules, real margin,
                          std::vector<sensor_overlap>* sensors, int threads, real slop) {
  place_shapes(bodies, pairs, threads);
  meet_all(bodies, pairs, contacts, lookahead, rules, margin, sensors, threads);
  if (slop > 0) {
    detail::drop_hidden_contacts(placed_.data(), first_shape_.data(), static_, slop,
                                 on_static_.data(), static_count_, contacts, hidden_);
  }
}

void space::meet_all(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                     std::vector<contact>& contacts, real lookahead,
                     const material_combine_rules& rules, real margin,
                     std::vector<sensor_overlap>* sensors, int threads) {
  if (sensors) sensors->clear();
  // (A few hundred pairs per thread: a box pair takes about a microsecond.)
  const int shares = detail::threads_for(threads, pairs.size(), 256);
  // Room for at least a contact per pair (grown_room: a quarter more, at
  // least twice the old room): a list that outgrows its room is copied
  // whole to a new one whose pages are then faulted in (5.7 MB at 10,000
  // spheres; in a pile still filling up, 0.08 ms a step on average). What
  // it holds (the list of two steps ago) is written over below: emptied
  // first, it is not copied.
  detail::reserve_over_in_huge_pages(contacts, pairs.size());
  if (shares == 1) {
    on_static_.clear();
    contacts.resize(meet_pairs(bodies, pairs.data(), pairs.data() + pairs.size(), contacts, 0,
                               lookahead, rules, margin, sensors, on_static_));
    static_count_ = on_static_.size();
    return;
  }
  // The pairs in contiguous shares, four per thread, each thread taking its
  // own four first (detail::visit_parts: the shapes of the bodies of its
  // pairs, mostly of its own part of the bodies, are where it placed them)
  // and then what the others have left (a core slowed by other programs
  // takes fewer). Joined in share order, the shares' contacts are what one
  // thread makes. The thread that takes share 0 meets it straight into
  // `contacts`, and so every next share it takes while it has met all
  // those before it (its own part, unless another thread took some of it):
  // their places are known. The other shares are met into lists of their
  // own, then copied to their places, the copying shared evenly by the
  // threads. (Each share met into its own list, and copied by the thread
  // that completed the shares before it, one thread copied most of the
  // contacts of 10,000 spheres on two threads, 0.30 ms a step, while the
  // other waited.)
  const auto share_count = static_cast<std::size_t>(4 * shares);
  shares_.resize(share_count);
  const std::unique_ptr<detail::part_progress[]> progress(
      new detail::part_progress[static_cast<std::size_t>(shares)]);
#pragma omp parallel num_threads(shares)
  {
    // This thread's shares met in place so far: [0, next_in_place), ending at in_place_end.
    std::size_t next_in_place = 0, in_place_end = 0;
    detail::visit_parts(
        static_cast<std::size_t>(omp_get_num_threads()),
        static_cast<std::size_t>(omp_get_thread_num()), share_count, 1, progress.get(),
        [&](std::size_t at) {
          const body_pair* first = pairs.data() + pairs.size() * at / share_count;
          const body_pair* end = pairs.data() + pairs.size() * (at + 1) / share_count;
          share_lists& lists = shares_[at].value;
          lists.sensors.clear();
          lists.on_static.clear();
          std::vector<sensor_overlap>* sensed = sensors ? &lists.sensors : nullptr;
          lists.in_place = at == next_in_place;
          if (lists.in_place) {
            lists.made = meet_pairs(bodies, first, end, contacts, in_place_end, lookahead, rules,
                                    margin, sensed, lists.on_static);
            in_place_end += lists.made;
            ++next_in_place;
          } else {
            // (Room for a contact a pair, as for the step's list above.)
            detail::reserve_over_in_huge_pages(lists.contacts,
                                               static_cast<std::size_t>(end - first));
            lists.made = meet_pairs(bodies, first, end, lists.contacts, 0, lookahead, rules, margin,
                                    sensed, lists.on_static);
          }
        });
  }
  // Each share's start in the lists, and the contacts to copy: the shares
  // not met in place, one after another (copy_starts_: where each begins).
  share_starts_.resize(share_count + 1);
  copy_starts_.resize(share_count + 1);
  share_starts_[0] = {};
  copy_starts_[0] = 0;
  for (std::size_t at = 0; at < share_count; ++at) {
    const share_lists& lists = shares_[at].value;
    share_starts_[at + 1] = {share_starts_[at].contacts + lists.made,
                             share_starts_[at].on_static + lists.on_static.size()};
    copy_starts_[at + 1] = copy_starts_[at] + (lists.in_place ? 0 : lists.made);
  }
  const share_start total = share_starts_.back();
  detail::reserve_in_huge_pages(contacts, total.contacts);
  // (Longer than this step's where it holds the list from two steps ago:
  // only the end is cut. Made longer, the new contacts are zeroed first.)
  contacts.resize(total.contacts);
  if (on_static_.size() < total.on_static) on_static_.resize(total.on_static + total.on_static / 4);
  static_count_ = total.on_static;
  for (std::size_t at = 0; at < share_count; ++at) {
    const share_lists& lists = shares_[at].value;
    const share_start& start = share_starts_[at];
    for (std::size_t k = 0; k < lists.on_static.size(); ++k) {
      detail::static_contact c = lists.on_static[k];
      c.contact += start.contacts;
      on_static_[start.on_static + k] = c;
    }
  }
  // The contacts to copy, in pieces of equal length, shared by the threads.
  constexpr std::size_t piece = 512;
  const std::size_t copied = copy_starts_.back();
  detail::parallel_for(threads, (copied + piece - 1) / piece, 2, [&](std::size_t p) {
    const std::size_t from = p * piece, upto = std::min(copied, from + piece);
    // The first share this piece reaches into, then each one after it.
    std::size_t at =
        static_cast<std::size_t>(std::upper_bound(copy_starts_.begin(), copy_starts_.end(), from) -
                                 copy_starts_.begin() - 1);
    for (std::size_t i = from; i < upto; ++at) {
      const std::size_t share_end = copy_starts_[at + 1];
      if (share_end <= i) continue;  // (a share met in place: nothing to copy)
      const std::size_t count = std::min(upto, share_end) - i;
      const auto in_share = static_cast<std::ptrdiff_t>(i - copy_starts_[at]);
      const std::vector<contact>& met = shares_[at].value.contacts;
      std::copy(
          met.begin() + in_share, met.begin() + in_share + static_cast<std::ptrdiff_t>(count),
          contacts.begin() + static_cast<std::ptrdiff_t>(share_starts_[at].contacts) + in_share);
      i += count;
    }
  });
  if (sensors) {
    for (const auto& share : shares_) {
      sensors->insert(sensors->end(), share.value.sensors.begin(), share.value.sensors.end());
    }
  }
}

// Whether the pair is one of single round shapes whose meet runs on
// batches (detail::batched_readings), and whose contact find_contacts would
// look for (no sensor, filters that meet).
template <class Facts>
static bool meets_on_batches(const Facts& a, const Facts& b, const placed_shape* shape_a,
                             const placed_shape* shape_b) {
  return a.plain && b.plain && detail::meets_on_batches(shape_a->kind, shape_b->kind) &&
         a.filter.meets(b.filter);
}

std::size_t space::meet_pairs(const std::vector<body>& bodies, const body_pair* first,
                              const body_pair* end, std::vector<contact>& contacts,
                              std::size_t start, real lookahead,
                              const material_combine_rules& rules, real margin,
                              std::vector<sensor_overlap>* sensors,
                              std::vector<detail::static_contact>& on_static) const {
  // The meets of single spheres and planes first, their algebra on batches
  // of pairs; then every pair in order, those from their terms.
  constexpr std::size_t none = ~std::size_t{0};
  // (Each thread's lists, kept from call to call: allocated anew, they cost
  // a page fault every few pairs.)
  struct scratch_lists {
    std::vector<std::pair<const placed_shape*, const placed_shape*>> round_pairs;
    std::vector<std::size_t> round_slot;
    std::vector<detail::round_reading<real>> readings;
  };
  static thread_local scratch_lists scratch;
  std::vector<std::pair<const placed_shape*, const placed_shape*>>& round_pairs =
      scratch.round_pairs;
  std::vector<std::size_t>& round_slot = scratch.round_slot;
  round_pairs.clear();
  round_slot.assign(static_cast<std::size_t>(end - first), none);
  for (const body_pair* pair = first; pair != end; ++pair) {
    // (The pairs come by their first body; their second ones are scattered:
    // prefetch.hpp.)
    if (static_cast<std::size_t>(end - pair) > detail::prefetch_distance) {
      const std::size_t ahead = pair[detail::prefetch_distance].second;
      detail::prefetch(&singles_[ahead]);
      detail::prefetch(&placed_[first_shape_[ahead]]);
    }
    const auto [a, b] = *pair;
    const placed_shape* shape_a = placed_.data() + first_shape_[a];
    const placed_shape* shape_b = placed_.data() + first_shape_[b];
    if (!meets_on_batches(singles_[a], singles_[b], shape_a, shape_b)) continue;
    round_slot[static_cast<std::size_t>(pair - first)] = round_pairs.size();
    round_pairs.emplace_back(shape_a, shape_b);
  }
  std::vector<detail::round_reading<real>>& readings = scratch.readings;
  readings.resize(round_pairs.size());
  detail::batched_readings(round_pairs.data(), round_pairs.size(), readings.data());

  contact_manifold manifold;
  // The contact at a point of shape i of body a and shape j of body b, made
  // in its place in the list. (Made aside and copied in, through a manifold
  // for the pairs met on batches too, its bytes were copied three times.)
  // And which contacts have a static body on one side only, for the seams'
  // pass: listed here, it reads those instead of the whole list again.
  // The list comes as an earlier step left it: its contacts are written
  // over, field by field, and the caller cuts it to its length. (Each
  // made anew, 248 bytes were zeroed and most of them written again: 1.6%
  // of a 1,000-sphere step.)
  std::size_t made = 0;
  const auto add = [&](bool across, std::size_t a, std::size_t b, std::size_t i, std::size_t j,
                       const contact_geometry& geometry, std::uint32_t feature, const material& m) {
    if (across) {
      const bool a_static = static_[a] != 0;
      on_static.push_back(
          {made, a_static ? b : a, a_static ? first_shape_[a] + i : first_shape_[b] + j});
    }
    // (Made in its place and filled in: made whole aside and copied in,
    // meet_pairs ran 9% fewer instructions but took a third longer, its
    // loads of the copy waiting for the narrower stores that made it.)
    contact& c = start + made < contacts.size() ? contacts[start + made] : contacts.emplace_back();
    ++made;
    c.body_a = a;
    c.body_b = b;
    c.geometry = geometry;
    c.shape_a = static_cast<std::uint32_t>(i);
    c.shape_b = static_cast<std::uint32_t>(j);
    c.feature = feature;
    c.material = m;
    c.impulse = {};
    c.resting = {};
    c.approach_speed = 0;
  };
  for (const body_pair* pair = first; pair != end; ++pair) {
    const auto [a, b] = *pair;
    const bool across = static_[a] != static_[b];
    const std::size_t slot = round_slot[static_cast<std::size_t>(pair - first)];
    if (slot != none) {
      // One shape each, met on batches: from the placed shapes and the facts alone.
      const single_shape_facts& facts_a = singles_[a];
      const single_shape_facts& facts_b = singles_[b];
      const placed_shape& shape_a = placed_[first_shape_[a]];
      const placed_shape& shape_b = placed_[first_shape_[b]];
      const std::optional<contact_geometry> geometry = detail::contact_from(
          shape_a, shape_b, readings[slot], detail::meet_origin(shape_a, shape_b), lookahead,
          facts_a.velocity, facts_b.velocity);
      if (geometry) {
        add(across, a, b, 0, 0, *geometry, 0, combine(rules, facts_a.surface, facts_b.surface));
      }
      continue;
    }
    const body& body_a = bodies[a];
    const body& body_b = bodies[b];
    const std::size_t shapes_a = body_a.shapes().size(), shapes_b = body_b.shapes().size();
    const real reach = closing_reach(body_a, body_b, lookahead, margin);
    const bool alone = ((body_marks_[a] | body_marks_[b]) & jostled) == 0;
    for (std::size_t i = 0; i < shapes_a; ++i) {
      const placed_shape& shape_a = placed_[first_shape_[a] + i];
      const attached_shape& attached_a = body_a.shapes()[i];
      for (std::size_t j = 0; j < shapes_b; ++j) {
        const placed_shape& shape_b = placed_[first_shape_[b] + j];
        const attached_shape& attached_b = body_b.shapes()[j];
        const met what =
            meet(body_a, body_b, i, j, shape_a, shape_b, lookahead, reach, margin, alone, manifold);
        if (what == met::sensed && sensors) {
          const bool a_senses = attached_a.shape.is_sensor();
          sensors->push_back(a_senses ? sensor_overlap{a, i, b, j} : sensor_overlap{b, j, a, i});
        }
        if (what != met::contacts) continue;
        const material m = combine(rules, attached_a.shape.material(), attached_b.shape.material());
        for (int k = 0; k < manifold.count; ++k) {
          add(across, a, b, i, j, manifold.points[k].geometry, manifold.points[k].feature, m);
        }
      }
    }
  }
  return made;
}

}  // namespace gaphys
