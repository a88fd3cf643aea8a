// Makes a known set of e3ga calls in the instrumented variant;
// check_known_profile.py runs it and compares the profile it writes.
#include <array>
#include <e3ga/e3ga.hpp>

int main() {
  using namespace e3ga;
  const vector a{1, 2, 3}, b{-2, 0.5, 4};
  for (int i = 0; i < 3; ++i) (void)gp(mv(a), mv(b));  // gp {e1,e2,e3} x {e1,e2,e3} -> {1, e12, e13, e23}
  // (e1 + e2)(e1 + e2) = 2: the e1^e2 terms cancel, so the result counts as scalar only.
  const vector d{1, 1, 0};
  (void)gp(mv(d), mv(d));
  // A named-type call is recorded once, with its arguments' bitmaps.
  const rotor r{0.5, 0.5, 0.5, 0.5};
  (void)gp(r, r);  // gp {1, e12, e13, e23} x {1, e12, e13, e23} -> {1, e12, e13, e23}
  (void)op(mv(a), mv(a));  // a ^ a = 0: result bitmap 0
  // Every nonzero set of blades once, reversed (the same blades): 255 more
  // entries, more than the recorder's table starts with.
  for (int blades = 1; blades < 256; ++blades) {
    std::array<double, 8> c{};
    for (int i = 0; i < 8; ++i) c[i] = blades >> i & 1 ? i + 1 : 0;
    (void)reverse(mv::from_array(c));
  }
  return flush_profile() ? 0 : 1;
}
