#include "timed_impact.hpp"

#include <cmath>

namespace gaphys {

namespace {

// Both pieces of the motion's parabola p(t) = offset + w t + a t^2 / 2.
vector start_velocity(const relative_motion& m) { return real(0.5) * (m.velocity_start + m.velocity_now); }
vector acceleration(const relative_motion& m, real h) { return (1 / h) * (m.velocity_now - m.velocity_start); }

bool within_step(real time, real h) { return time >= -h && time <= h; }

// The smaller root of a t^2 + 2 b t + c = 0 on the approaching branch, written
// c / (sqrt(b^2 - a c) - b) so that it stays exact as a -> 0; nothing if
// there is no such root.
std::optional<real> approaching_root(real a, real b, real c) {
  const real discriminant = b * b - a * c;
  if (!(discriminant >= 0)) return std::nullopt;
  const real denominator = std::sqrt(discriminant) - b;
  if (!(denominator > 0)) return std::nullopt;
  return c / denominator;
}

}  // namespace

std::optional<timed_impact> impact_across_plane(real gap, const vector& normal,
                                                const relative_motion& motion, real h) {
  // s(t) = gap + w t + a t^2 / 2 along the fixed normal.
  const real w = e3ga::scp(normal, start_velocity(motion));
  const real a = e3ga::scp(normal, acceleration(motion, h));
  const std::optional<real> time = approaching_root(a / 2, w / 2, gap);
  if (!time || !within_step(*time, h)) return std::nullopt;
  const real speed = -(w + a * *time);
  if (!(speed > 0)) return std::nullopt;
  return timed_impact{*time, normal, speed};
}

std::optional<timed_impact> impact_of_centres(real distance, const relative_motion& motion,
                                              real h) {
  // |p(t)| = distance. The acceleration term a t^2 / 2 is at most g h^2 / 2
  // (0.1 mm at 240 Hz), so a few fixed-point rounds, each solving the
  // quadratic with that term frozen, settle it.
  const vector w = start_velocity(motion);
  const vector a = acceleration(motion, h);
  real time = 0;
  for (int round = 0; round < 3; ++round) {
    const vector q = motion.offset + (time * time / 2) * a;
    const std::optional<real> root =
        approaching_root(e3ga::scp(w, w), e3ga::scp(q, w), e3ga::scp(q, q) - distance * distance);
    if (!root) return std::nullopt;
    time = *root;
  }
  if (!within_step(time, h)) return std::nullopt;
  const vector offset = motion.offset + time * w + (time * time / 2) * a;
  const vector normal = (1 / e3ga::norm(offset)) * offset;
  const real speed = -e3ga::scp(normal, w + time * a);
  if (!(speed > 0)) return std::nullopt;
  return timed_impact{time, normal, speed};
}

}  // namespace gaphys
