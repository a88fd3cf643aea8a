// Uses the installed e3ga and a library generated from this app's own spec.
#include <e2ga/e2ga.hpp>
#include <e3ga/e3ga.hpp>

#include <cmath>
#include <iostream>

int main() {
  // Rotating e1 by 90 degrees in the plane gives e2.
  const e2ga::rotor quarter{std::cos(0.25f * 3.14159265f), -std::sin(0.25f * 3.14159265f)};
  const e2ga::vector turned = e2ga::apply(quarter, e2ga::vector{1, 0});
  const e3ga::vector v = e3ga::vector{1, 2, 3} * 2.0;
  std::cout << "e2ga: " << turned << "\ne3ga: " << v << "\n";
  const bool ok = std::abs(turned.e1()) < 1e-6f && std::abs(turned.e2() - 1) < 1e-6f && v.e3() == 6.0;
  return ok ? 0 : 1;
}
