// Uses the installed e3ga and a library generated from this app's own spec,
// and runs the app's own workload: what the two-pass build profiles.
#include <cmath>
#include <e2ga/e2ga.hpp>
#include <e3ga/e3ga.hpp>
#include <iostream>

namespace {

// A wheel turning at 2 rad/s for 10 s in steps of 10 ms, its attitude
// composed from one small rotor per step, and the area the tip of a spoke of
// length 1 sweeps (half the outer product of successive spokes). The app
// keeps its attitude and these products in e2ga::mv, as code written against
// the general multivector does: the optimized variant has straight-line code
// for them only when a profile of this workload asks for it. (Products of
// named types have kernels whether or not the spec declares them.)
bool spin_wheel() {
  using e2ga::to_mv;
  const int steps = 1000;
  const float turn = 2.0f * 0.01f;  // per step
  const e2ga::mv step = to_mv(e2ga::rotor{std::cos(0.5f * turn), -std::sin(0.5f * turn)});
  e2ga::mv attitude = to_mv(e2ga::rotor{1, 0});
  e2ga::vector spoke{1, 0};
  float swept = 0;
  for (int i = 0; i < steps; ++i) {
    attitude = e2ga::gp(step, attitude);  // on mv
    const e2ga::vector next = e2ga::apply(e2ga::rotor(attitude), e2ga::vector{1, 0});
    swept += 0.5f * e2ga::op(to_mv(spoke), to_mv(next))[3];  // on mv; coefficient 3 is e1^e2
    spoke = next;
  }
  // Mirrored in the e2 axis: -e1 spoke e1.
  const e2ga::mv e1 = to_mv(e2ga::vector{1, 0});
  const e2ga::vector mirrored(-e2ga::gp(e2ga::gp(e1, to_mv(spoke)), e1));  // on mv

  const float angle = turn * steps;
  const float area = 0.5f * steps * std::sin(turn);
  std::cout << "workload: spoke " << spoke << ", mirrored " << mirrored << ", swept area " << swept
            << "\n";
  return std::abs(spoke.e1() - std::cos(angle)) < 1e-3f &&
         std::abs(spoke.e2() - std::sin(angle)) < 1e-3f &&
         std::abs(mirrored.e1() + spoke.e1()) < 1e-5f &&
         std::abs(mirrored.e2() - spoke.e2()) < 1e-5f && std::abs(swept - area) < 1e-3f * area;
}

}  // namespace

int main() {
  // Rotating e1 by 90 degrees in the plane gives e2.
  const e2ga::rotor quarter{std::cos(0.25f * 3.14159265f), -std::sin(0.25f * 3.14159265f)};
  const e2ga::vector turned = e2ga::apply(quarter, e2ga::vector{1, 0});
  const e3ga::vector v = e3ga::vector{1, 2, 3} * 2.0;
  std::cout << "e2ga: " << turned << "\ne3ga: " << v << "\n";
  const bool ok =
      std::abs(turned.e1()) < 1e-6f && std::abs(turned.e2() - 1) < 1e-6f && v.e3() == 6.0;
  return ok && spin_wheel() ? 0 : 1;
}
