#include "gaphys/detail/hidden_faces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

#include "prefetch.hpp"
#include "round_meet.hpp"
#include "vec3.hpp"

namespace gaphys::detail {

namespace {

constexpr std::size_t several = std::numeric_limits<std::size_t>::max();

// x's distance from a ball of radius r about c, and the way out of it.
real ball_distance(const vec3& c, real r, const vec3& x, vector& outward) {
  const vec3 away = x - c;
  const real length_away = length(away);
  // (At the very centre any way is out.)
  outward = length_away > 0 ? to_vector((1 / length_away) * away) : vector{0, 0, 1};
  return length_away - r;
}

// How far x is outside the shape (< 0 inside), and the outward normal of
// the surface nearest it. For boxes and hulls, the largest height above a
// face's plane: the distance where the nearest feature is a face (outside
// an edge or a corner, less than it). A point has no inside: +infinity.
real signed_distance(const placed_shape& s, const vector& x, vector& outward) {
  switch (s.kind) {
    case shape_kind::sphere:
      return ball_distance(to_vec3(s.center), s.radius, to_vec3(x), outward);
    case shape_kind::plane:
      outward = s.normal;
      return e3ga::scp(s.normal, x) - s.offset;
    case shape_kind::capsule: {
      const vec3 axis = to_vec3(s.axis), from_center = to_vec3(x - s.center);
      const real along = std::clamp(dot(from_center, axis), -s.half_height, s.half_height);
      return ball_distance(to_vec3(s.center) + along * axis, s.radius, to_vec3(x), outward);
    }
    case shape_kind::box:
    case shape_kind::convex_hull: {
      const rigid_frame frame = frame_of(s.attitude, s.center);
      const vec3 local = frame.to_local(to_vec3(x));
      real highest = -std::numeric_limits<real>::infinity();
      const polyhedron_face* nearest = nullptr;
      for (const polyhedron_face& face : s.polyhedron->faces) {
        const real height = dot(to_vec3(face.normal), local) - face.offset;
        if (height > highest) highest = height, nearest = &face;
      }
      outward = to_vector(frame.rotate(to_vec3(nearest->normal)));
      return highest;
    }
    case shape_kind::point:
      break;
  }
  outward = vector{0, 0, 1};
  return std::numeric_limits<real>::infinity();
}

// Whether the face of s through p with outward normal n is hidden there by
// `other` (hidden_by). The two surfaces must also be flush there, within
// the slop: s's end and the surface of `other` the same distance from p
// along that surface's normal (a tile 1.5 mm higher than the next is a
// step, and the lower one's edge holds what slides against it; a plate 2 mm
// thick on a floor does not hide the floor from what sinks into its edge).
bool face_hidden(const placed_shape& s, const vector& p, const vector& n, const placed_shape& other,
                 real slop) {
  const real step = 4 * slop;
  vector m;  // the other's surface normal
  const real in_other = signed_distance(other, p + step * n, m);
  if (!(in_other <= slop)) return false;
  vector unused;
  const real beyond_s = signed_distance(s, p + step * m, unused);
  if (!(beyond_s >= step / 2)) return false;
  // Along m from p, s ends at step - beyond_s, and the other's surface is
  // at step (n . m) - in_other (the test point is step n from p).
  const real s_ends = step - beyond_s, other_ends = step * e3ga::scp(n, m) - in_other;
  return std::fabs(s_ends - other_ends) <= slop;
}

// The shape's bounds along the world's axes, as lowest and highest
// corners; nothing for a plane, which reaches everywhere.
std::optional<std::pair<vec3, vec3>> bounds_of(const placed_shape& s) {
  const vec3 c = to_vec3(s.center);
  const auto around = [&c](const vec3& half) { return std::make_pair(c - half, c + half); };
  switch (s.kind) {
    case shape_kind::sphere:
      return around({s.radius, s.radius, s.radius});
    case shape_kind::capsule: {
      const vec3 a = to_vec3(s.axis);
      return around({s.half_height * std::fabs(a.x) + s.radius,
                     s.half_height * std::fabs(a.y) + s.radius,
                     s.half_height * std::fabs(a.z) + s.radius});
    }
    case shape_kind::box:
    case shape_kind::convex_hull: {
      const rigid_frame frame = frame_of(s.attitude, s.center);
      vec3 lo = c, hi = c;
      for (const vector& corner : s.polyhedron->vertices) {
        const vec3 x = frame.to_world(to_vec3(corner));
        lo = {std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
        hi = {std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z)};
      }
      return std::make_pair(lo, hi);
    }
    case shape_kind::point:
      return around({0, 0, 0});
    case shape_kind::plane:
      break;
  }
  return std::nullopt;
}

}  // namespace

bool hidden_by(const placed_shape& s, const vector& p, const vector& n, const placed_shape& other,
               real slop) {
  if (s.kind != shape_kind::box && s.kind != shape_kind::convex_hull) {
    return face_hidden(s, p, n, other, slop);
  }
  // A contact at an edge or a corner of a box or hull (a ball rolling over
  // a seam meets the next box's edge) has a normal between its faces': it
  // is hidden where one of the faces through p that it leans towards is.
  // (Leaning by more than rounding: a ball resting right above a seam
  // touches both boxes along their top faces' normal.)
  const rigid_frame frame = frame_of(s.attitude, s.center);
  const vec3 local = frame.to_local(to_vec3(p));
  for (const polyhedron_face& face : s.polyhedron->faces) {
    if (!(std::fabs(dot(to_vec3(face.normal), local) - face.offset) <= slop)) continue;
    const vector face_normal = to_vector(frame.rotate(to_vec3(face.normal)));
    if (!(e3ga::scp(n, face_normal) > real(1e-3))) continue;
    if (face_hidden(s, p, face_normal, other, slop)) return true;
  }
  return false;
}

void drop_hidden_contacts(const placed_shape* placed, const std::size_t* first_shape,
                          const std::vector<unsigned char>& is_static, real slop,
                          const static_contact* on_static, std::size_t static_count,
                          std::vector<contact>& contacts, hidden_face_lists& lists) {
  // Which body is the moving one of a contact with a static shape, and that
  // shape's index in `placed`; none for other contacts.
  struct sides {
    std::size_t moving, shape, moving_shape;
  };
  const auto sides_of = [&](const contact& c) -> std::optional<sides> {
    if (is_static[c.body_a] == is_static[c.body_b]) return std::nullopt;
    const std::size_t shape_a = first_shape[c.body_a] + c.shape_a;
    const std::size_t shape_b = first_shape[c.body_b] + c.shape_b;
    if (is_static[c.body_a]) return sides{c.body_b, shape_a, shape_b};
    return sides{c.body_a, shape_b, shape_a};
  };
  // The contact's point on the static shape: the meet of two round shapes
  // gives its round's centre (on a plane, the projected centre), found
  // again from the shape's distance; the convex narrow phase the point
  // midway between the surfaces, depth / 2 inside each.
  const auto surface_point = [&](const contact& c, const sides& at, const vector& n) {
    const placed_shape& s = placed[at.shape];
    if (is_round(s.kind) && is_round(placed[at.moving_shape].kind)) {
      vector unused;
      return c.geometry.point - signed_distance(s, c.geometry.point, unused) * n;
    }
    return c.geometry.point + (c.geometry.depth / 2) * n;
  };
  // Only a body touching two static shapes or more can have a hidden
  // contact; most touch one at most (a sphere on a floor), and the rest of
  // the pass is for the few that touch more.
  std::vector<std::size_t>& first = lists.first_partner;
  if (first.size() < is_static.size()) first.resize(is_static.size(), 0);
  lists.touched.clear();
  bool any = false;
  for (std::size_t k = 0; k < static_count; ++k) {
    const static_contact& at = on_static[k];
    std::size_t& seen = first[at.moving];
    if (seen == 0) {
      seen = at.shape + 1;
      lists.touched.push_back(at.moving);
    } else if (seen != at.shape + 1) {
      seen = several;
      any = true;
    }
  }
  if (any) {
    // Each such body's contacts with static shapes, together, in contact order.
    lists.entries.clear();
    for (std::size_t k = 0; k < static_count; ++k) {
      const static_contact& at = on_static[k];
      if (first[at.moving] == several) lists.entries.emplace_back(at.moving, at.contact);
    }
    std::stable_sort(lists.entries.begin(), lists.entries.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    // Their contacts asked for at once, ahead of the loop below, which reads
    // them one by one: many were written by another core. (Missed one at a
    // time, they were half of this pass, which runs on one thread: at 10,000
    // spheres on two threads, 0.067 ms a step, 0.04 so.)
    for (const auto& [moving, index] : lists.entries) {
      prefetch_bytes(&contacts[index], offsetof(contact, feature));
    }
    lists.dropped.assign(contacts.size(), 0);
    bool dropped_any = false;
    for (std::size_t begin = 0; begin < lists.entries.size();) {
      std::size_t end = begin + 1;
      while (end < lists.entries.size() && lists.entries[end].first == lists.entries[begin].first) {
        ++end;
      }
      // The static shapes this body touches, each once, by their bounds'
      // lowest x: each contact point looks only at those whose bounds it is
      // within reach of (a plank on a thousand small tiles touches all of
      // them, and each point is near a few). Planes, and shapes far wider
      // than most (a long kerb among tiles, which would widen every
      // point's window to its length), are looked at by every point.
      lists.partners.clear();
      lists.everywhere.clear();
      for (std::size_t e = begin; e < end; ++e) {
        const std::size_t shape = sides_of(contacts[lists.entries[e].second])->shape;
        if (const auto bounds = bounds_of(placed[shape])) {
          const auto& [lo, hi] = *bounds;
          lists.partners.push_back({{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}, shape});
        } else {
          lists.everywhere.push_back(shape);
        }
      }
      const auto by_x = [](const hidden_face_lists::partner& x,
                           const hidden_face_lists::partner& y) {
        return x.lo.x < y.lo.x || (x.lo.x == y.lo.x && x.shape < y.shape);
      };
      std::sort(lists.partners.begin(), lists.partners.end(), by_x);
      lists.partners.erase(
          std::unique(lists.partners.begin(), lists.partners.end(),
                      [](const auto& x, const auto& y) { return x.shape == y.shape; }),
          lists.partners.end());
      const auto width = [](const hidden_face_lists::partner& x) { return x.hi.x - x.lo.x; };
      lists.widths.clear();
      for (const hidden_face_lists::partner& x : lists.partners) lists.widths.push_back(width(x));
      real widest = 0;
      if (!lists.widths.empty()) {
        const auto middle = lists.widths.begin() + std::ptrdiff_t(lists.widths.size() / 2);
        std::nth_element(lists.widths.begin(), middle, lists.widths.end());
        const real wide = 4 * *middle + 10 * slop;
        for (const hidden_face_lists::partner& x : lists.partners) {
          if (width(x) > wide) lists.everywhere.push_back(x.shape);
        }
        lists.partners.erase(std::remove_if(lists.partners.begin(), lists.partners.end(),
                                            [&](const auto& x) { return width(x) > wide; }),
                             lists.partners.end());
        for (const hidden_face_lists::partner& x : lists.partners) {
          widest = std::max(widest, width(x));
        }
      }
      std::sort(lists.everywhere.begin(), lists.everywhere.end());
      lists.everywhere.erase(std::unique(lists.everywhere.begin(), lists.everywhere.end()),
                             lists.everywhere.end());
      // (The points a test looks at are within 4 slop of p, and count
      // within the slop of the other's surface.)
      const real reach = 5 * slop;
      for (std::size_t e = begin; e < end; ++e) {
        const contact& c = contacts[lists.entries[e].second];
        // A contact deeper than half the step's test is no seam's: a body
        // resting on a seam is within the slop of both surfaces. (Kept, it
        // holds what would else sink while each step hid it again.)
        if (c.geometry.depth > 2 * slop) continue;
        const sides at = *sides_of(c);
        const std::size_t own = at.shape;
        const placed_shape& s = placed[own];
        // The normal points from B to A: out of s where s is B's.
        const vector n = is_static[c.body_b] ? c.geometry.normal : -c.geometry.normal;
        const vector p = surface_point(c, at, n);
        const vec3 x = to_vec3(p);
        const auto hides = [&](std::size_t other) {
          return other != own && hidden_by(s, p, n, placed[other], slop);
        };
        bool hidden = std::any_of(lists.everywhere.begin(), lists.everywhere.end(), hides);
        hidden_face_lists::partner from{};
        from.lo.x = x.x - reach - widest;
        auto near = std::lower_bound(lists.partners.begin(), lists.partners.end(), from, by_x);
        for (; !hidden && near != lists.partners.end() && near->lo.x <= x.x + reach; ++near) {
          const bool within = near->lo.x - reach <= x.x && x.x <= near->hi.x + reach &&
                              near->lo.y - reach <= x.y && x.y <= near->hi.y + reach &&
                              near->lo.z - reach <= x.z && x.z <= near->hi.z + reach;
          if (within) hidden = hides(near->shape);
        }
        if (hidden) {
          lists.dropped[lists.entries[e].second] = 1;
          dropped_any = true;
        }
      }
      begin = end;
    }
    if (dropped_any) {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < contacts.size(); ++i) {
        if (!lists.dropped[i]) contacts[kept++] = contacts[i];
      }
      contacts.resize(kept);
    }
  }
  for (const std::size_t x : lists.touched) first[x] = 0;
}

}  // namespace gaphys::detail
