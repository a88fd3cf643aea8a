#include "gaphys/space.hpp"

#include <algorithm>
#include <cstdint>

namespace gaphys {

void space::candidate_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs,
                            real lookahead, real margin) {
  // The grid declines coordinates too far out for integer cells.
  if (kind_ == broad_phase_kind::uniform_grid &&
      grid_.find_pairs(bodies, shaped_bodies_, lookahead, margin, pairs)) {
    return;
  }
  all_pairs(bodies, pairs);
}

// The thesis's candidates: every two shaped bodies not both static.
void space::all_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs) const {
  pairs.clear();
  for (std::size_t i = 0; i < shaped_bodies_.size(); ++i) {
    const std::size_t a = shaped_bodies_[i];
    for (std::size_t j = i + 1; j < shaped_bodies_.size(); ++j) {
      const std::size_t b = shaped_bodies_[j];
      // Neither can move the other.
      if (!bodies[a].is_dynamic() && !bodies[b].is_dynamic()) continue;
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

void space::place_shapes(const std::vector<body>& bodies) {
  first_shape_.assign(bodies.size() + 1, 0);
  for (std::size_t index : shaped_bodies_) first_shape_[index + 1] = bodies[index].shapes().size();
  for (std::size_t i = 0; i < bodies.size(); ++i) first_shape_[i + 1] += first_shape_[i];
  placed_.resize(first_shape_.back());
  for (std::size_t index : shaped_bodies_) {
    const body& b = bodies[index];
    placed_shape* out = &placed_[first_shape_[index]];
    for (const attached_shape& s : b.shapes()) {
      const bool centred = s.offset.e1() == 0 && s.offset.e2() == 0 && s.offset.e3() == 0;
      const vector position = centred ? b.position() : b.to_world(s.offset);
      const bool turned = s.attitude.c[1] != 0 || s.attitude.c[2] != 0 || s.attitude.c[3] != 0;
      const rotor attitude = turned ? e3ga::gp(b.attitude(), s.attitude) : b.attitude();
      *out++ = place(s.shape, position, attitude);
    }
  }
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
                          std::vector<sensor_overlap>* sensors) {
  place_shapes(bodies);
  contacts.clear();
  if (sensors) sensors->clear();
  contact_manifold manifold;
  for (const auto& [a, b] : pairs) {
    const body& body_a = bodies[a];
    const body& body_b = bodies[b];
    const std::size_t shapes_a = body_a.shapes().size(), shapes_b = body_b.shapes().size();
    const bool compound = shapes_a > 1 || shapes_b > 1;
    const real reach = closing_reach(body_a, body_b, lookahead, margin);
    for (std::size_t i = 0; i < shapes_a; ++i) {
      const placed_shape& shape_a = placed_[first_shape_[a] + i];
      const attached_shape& attached_a = body_a.shapes()[i];
      for (std::size_t j = 0; j < shapes_b; ++j) {
        const placed_shape& shape_b = placed_[first_shape_[b] + j];
        const attached_shape& attached_b = body_b.shapes()[j];
        // The broad phase bounded whole bodies; a compound's parts are
        // bounded again here, each by its own sphere.
        if (compound && shape_a.kind != shape_kind::plane && shape_b.kind != shape_kind::plane) {
          const real apart = e3ga::norm(shape_a.center - shape_b.center) -
                             attached_a.shape.bounding_radius() -
                             attached_b.shape.bounding_radius();
          if (apart > reach) continue;
        }
        if (!attached_a.shape.filter().meets(attached_b.shape.filter())) continue;
        if (attached_a.shape.is_sensor() || attached_b.shape.is_sensor()) {
          if (sensors && touching(shape_a, shape_b, manifold)) {
            const bool a_senses = attached_a.shape.is_sensor();
            sensors->push_back(a_senses ? sensor_overlap{a, i, b, j} : sensor_overlap{b, j, a, i});
          }
          continue;
        }
        gaphys::find_contacts(shape_a, shape_b, lookahead, body_a.velocity(), body_b.velocity(),
                              reach, manifold);
        if (manifold.count == 0) continue;
        const material m = combine(rules, attached_a.shape.material(), attached_b.shape.material());
        for (int k = 0; k < manifold.count; ++k) {
          contact c{};
          c.body_a = a;
          c.body_b = b;
          c.geometry = manifold.points[k].geometry;
          c.shape_a = static_cast<std::uint32_t>(i);
          c.shape_b = static_cast<std::uint32_t>(j);
          c.feature = manifold.points[k].feature;
          c.material = m;
          contacts.push_back(c);
        }
      }
    }
  }
}

}  // namespace gaphys
