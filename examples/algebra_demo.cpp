// A tour of the generated algebras: rotate a vector with a rotor (e3ga), then
// move a point with a motor and intersect two spheres (c3ga).
#include <c3ga/c3ga.hpp>
#include <e3ga/e3ga.hpp>

#include <cmath>
#include <iostream>

namespace {

c3ga::normalized_point point(double x, double y, double z) {
  return {x, y, z, 0.5 * (x * x + y * y + z * z)};
}

// Dual sphere c - 1/2 r^2 ni around a normalized point c.
c3ga::dual_sphere sphere(const c3ga::normalized_point& centre, double radius) {
  return {1.0, centre.e1(), centre.e2(), centre.e3(), centre.ni() - 0.5 * radius * radius};
}

}  // namespace

int main() {
  const double pi = std::acos(-1.0);

  // A quarter turn in the e1^e2 plane: R = exp(-pi/4 e12) takes e1 to e2.
  const e3ga::rotor turn = e3ga::exp(e3ga::bivector{-pi / 4, 0, 0});
  std::cout << "rotor R        = " << turn << "\n"
            << "R e1 ~R        = " << e3ga::apply(turn, e3ga::vector{1, 0, 0}) << "\n"
            << "log R          = " << e3ga::log(turn) << "\n";

  // A screw motion: translate by (0, 0, 2) after the same quarter turn.
  const c3ga::translator lift{1, 0, 0, -1};  // 1 - 1/2 t ni, t = 2 e3
  const c3ga::rotor quarter{turn.scalar(), turn.e12(), turn.e13(), turn.e23()};
  const c3ga::motor screw = c3ga::gp(lift, quarter);
  std::cout << "motor M        = " << screw << "\n"
            << "M (1,0,0) ~M   = " << c3ga::apply(screw, point(1, 0, 0)) << "\n";

  // Two unit spheres 1.5 apart meet in a circle; C^2 > 0 means they overlap.
  const auto s1 = c3ga::undual(sphere(point(0, 0, 0), 1.0));
  const auto s2 = c3ga::undual(sphere(point(1.5, 0, 0), 1.0));
  const c3ga::circle c = c3ga::meet(s1, s2);
  std::cout << "circle C       = " << c << "\n"
            << "C^2 (scalar)   = " << c3ga::scp(c, c) << "\n";
  return 0;
}
