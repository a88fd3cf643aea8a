// Shared helpers for the generated-algebra tests: seeded random inputs,
// conversions to the general multivector, and approximate comparisons whose
// tolerance follows the scalar type and the size of the numbers compared.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

namespace gaphys_test {

using scalar_types = ::testing::Types<float, double>;

// Relative tolerance of a comparison after a handful of products.
template <class T>
constexpr T tolerance() {
  return std::is_same_v<T, float> ? T(1e-4) : T(1e-10);
}

constexpr double pi = 3.14159265358979323846;

// Near a full turn (half angle pi - delta) a motor fixes its axis only through
// O(delta) terms, so log(exp(B)) = B is ill-conditioned as eps / delta^2: it is
// only asserted for delta at or above this.
template <class T>
double resolvable_full_turn_distance() {
  return 4 * std::sqrt(double(std::numeric_limits<T>::epsilon()) / double(tolerance<T>()));
}

// Within this of a full turn the motor itself carries its screw only to
// eps / delta (its 4-vector part is O(delta)), so round trips through log are
// only required to stay finite there.
template <class T>
double full_turn_margin() {
  return 32 * std::sqrt(double(std::numeric_limits<T>::epsilon()));
}

// The coordinate array of a library value (named type or mv), its scalar and size.
template <class X>
using coords_of = std::decay_t<decltype(std::declval<X>().c)>;
template <class X>
using scalar_of = typename coords_of<X>::value_type;
template <class X>
constexpr std::size_t size_of = std::tuple_size_v<coords_of<X>>;

// Fixed seeds keep every run identical; each test owns its generator.
inline std::mt19937 make_rng(std::uint32_t seed) { return std::mt19937(seed); }

template <class T>
T uniform(std::mt19937& rng, T lo, T hi) {
  return std::uniform_real_distribution<T>(lo, hi)(rng);
}

template <class T, std::size_t N>
std::array<T, N> random_array(std::mt19937& rng, T lo = T(-1), T hi = T(1)) {
  std::array<T, N> a{};
  for (T& v : a) v = uniform(rng, lo, hi);
  return a;
}

// A named type with every stored coordinate uniform in [lo, hi].
template <class X>
X random_named(std::mt19937& rng, scalar_of<X> lo = -1, scalar_of<X> hi = 1) {
  X x;
  x.c = random_array<scalar_of<X>, size_of<X>>(rng, lo, hi);
  return x;
}

// A general multivector with every coefficient uniform in [lo, hi].
template <class MV>
MV random_mv(std::mt19937& rng, scalar_of<MV> lo = -1, scalar_of<MV> hi = 1) {
  return MV::from_array(random_array<scalar_of<MV>, size_of<MV>>(rng, lo, hi));
}

// A general multivector whose coefficients are random on a random subset of
// blades (so optimized variants see sparse bitmaps) and exactly zero elsewhere.
template <class MV>
MV random_sparse_mv(std::mt19937& rng) {
  auto a = random_array<scalar_of<MV>, size_of<MV>>(rng);
  std::bernoulli_distribution keep(0.4);
  for (auto& v : a)
    if (!keep(rng)) v = 0;
  return MV::from_array(a);
}

// Widens a library result (plain scalar, named type or mv) to the mv type MV.
template <class MV, class X>
MV as_mv(const X& x) {
  if constexpr (std::is_arithmetic_v<X>) {
    coords_of<MV> a{};
    a[0] = x;
    return MV::from_array(a);
  } else if constexpr (std::is_same_v<X, MV>) {
    return x;
  } else {
    return MV(x);
  }
}

// The same coefficients in another mv type (other scalar or namespace).
template <class To, class From>
To convert_mv(const From& x) {
  static_assert(size_of<To> == size_of<From>);
  coords_of<To> a{};
  const auto b = x.to_array();
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<scalar_of<To>>(b[i]);
  return To::from_array(a);
}

// True for the general multivector (it has a bitmap), false for named types.
template <class X, class = void>
struct has_bits : std::false_type {};
template <class X>
struct has_bits<X, std::void_t<decltype(std::declval<X>().bits)>> : std::true_type {};

// A random value of any library type: named types get every coordinate, mv
// types a dense or sparse random set.
template <class X>
X random_value(std::mt19937& rng, bool sparse = false) {
  if constexpr (has_bits<X>::value)
    return sparse ? random_sparse_mv<X>(rng) : random_mv<X>(rng);
  else
    return random_named<X>(rng);
}

// The same coordinates in another type of the same layout (e.g. the named
// type of the other variant's namespace).
template <class To, class From>
To same_coordinates(const From& x) {
  static_assert(size_of<To> == size_of<From>);
  To y;
  for (std::size_t i = 0; i < size_of<To>; ++i) y.c[i] = static_cast<scalar_of<To>>(x.c[i]);
  if constexpr (has_bits<To>::value) y.bits = x.bits;
  return y;
}

// Canonical index of a blade by its name, e.g. "e1^ni"; fails the test if absent.
template <class Names>
std::size_t blade_index(const Names& names, const std::string& name) {
  for (std::size_t i = 0; i < std::size(names); ++i)
    if (name == names[i]) return i;
  ADD_FAILURE() << "no blade named " << name;
  return 0;
}

template <class T, std::size_t N>
T max_abs(const std::array<T, N>& a) {
  T m = 0;
  for (T v : a) m = std::max(m, std::abs(v));
  return m;
}

// Every coefficient of x and y within abs_tol.
template <class MV, class X, class Y>
::testing::AssertionResult mv_within(const X& x, const Y& y, double abs_tol) {
  const MV a = as_mv<MV>(x), b = as_mv<MV>(y);
  const auto ca = a.to_array(), cb = b.to_array();
  for (std::size_t i = 0; i < ca.size(); ++i) {
    const double d = std::abs(double(ca[i]) - double(cb[i]));
    if (!(d <= abs_tol)) {
      std::ostringstream out;
      out << "coefficient " << i << " differs by " << d << " > " << abs_tol << "\n  lhs: " << a
          << "\n  rhs: " << b;
      return ::testing::AssertionFailure() << out.str();
    }
  }
  return ::testing::AssertionSuccess();
}

// Every coefficient within rel_tol times the larger of 1 and the largest
// coefficient of either side.
template <class MV, class X, class Y>
::testing::AssertionResult mv_near(const X& x, const Y& y, double rel_tol) {
  const double scale = std::max(
      {1.0, double(max_abs(as_mv<MV>(x).to_array())), double(max_abs(as_mv<MV>(y).to_array()))});
  return mv_within<MV>(x, y, rel_tol * scale);
}

// Scalars within rel_tol times the larger of 1, |a| and |b|.
inline ::testing::AssertionResult scalar_near(double a, double b, double rel_tol) {
  const double tol = rel_tol * std::max({1.0, std::abs(a), std::abs(b)});
  if (std::abs(a - b) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (tolerance " << tol << ")";
}

// Calls f; an exception becomes a test failure carrying its message, so one
// bad case does not hide the others in a loop.
template <class F>
auto checked_call(F f) -> std::optional<decltype(f())> {
  try {
    return f();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw: " << e.what();
    return std::nullopt;
  }
}

// The invariant of basic_mv: a clear bit means an exactly zero coefficient.
template <class MV>
::testing::AssertionResult bits_consistent(const MV& x) {
  for (std::size_t i = 0; i < x.c.size(); ++i)
    if (!(x.bits >> i & 1u) && x.c[i] != 0)
      return ::testing::AssertionFailure() << "bit " << i << " clear but coefficient is " << x.c[i];
  return ::testing::AssertionSuccess();
}

// exp by its Taylor series, summed in the given mv type: an implementation
// independent of the library's closed forms. Fine for |x| up to a few units.
template <class MV>
MV exp_taylor(const MV& x) {
  using T = scalar_of<MV>;
  coords_of<MV> one{};
  one[0] = 1;
  MV sum = MV::from_array(one), term = sum;
  for (int k = 1; k <= 60; ++k) {
    term = (term * x) * (T(1) / T(k));
    sum = sum + term;
  }
  return sum;
}

// Plain 3-D vector maths for closed-form truths.
using vec3 = std::array<double, 3>;

inline double dot(const vec3& a, const vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline vec3 cross(const vec3& a, const vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline vec3 operator+(const vec3& a, const vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline vec3 operator-(const vec3& a, const vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline vec3 operator*(double s, const vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double length(const vec3& a) { return std::sqrt(dot(a, a)); }

inline vec3 random_vec3(std::mt19937& rng, double lo = -1, double hi = 1) {
  return random_array<double, 3>(rng, lo, hi);
}

inline vec3 random_unit_vec3(std::mt19937& rng) {
  for (;;) {
    const vec3 v = random_vec3(rng);
    const double n = length(v);
    if (n > 0.1 && n <= 1) return (1 / n) * v;
  }
}

// Rodrigues' formula: v rotated by angle about the unit axis n (right-handed).
inline vec3 rodrigues(const vec3& n, double angle, const vec3& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * cross(n, v) + ((1 - c) * dot(n, v)) * n;
}

// The bivector n I3 (I3 = e1^e2^e3) dual to a vector n, in the canonical
// bivector order e1^e2, e1^e3, e2^e3: n I3 = n3 e12 - n2 e13 + n1 e23.
// The rotor exp(-angle/2 n I3) rotates by angle about n, right-handed.
inline vec3 bivector_of_axis(const vec3& n) { return {n[2], -n[1], n[0]}; }

// Conformal objects in the null basis, written from their closed forms. P, S
// and D are the algebra's normalized point, dual sphere and dual plane types.
// The normalized point no + x + |x|^2/2 ni (no = 1 is not stored).
template <class P>
P make_point(const vec3& x) {
  using T = scalar_of<P>;
  return P{T(x[0]), T(x[1]), T(x[2]), T(dot(x, x) / 2)};
}

// The dual sphere c - r^2/2 ni, c the normalized centre.
template <class S>
S make_dual_sphere(const vec3& c, double r) {
  using T = scalar_of<S>;
  return S{T(1), T(c[0]), T(c[1]), T(c[2]), T((dot(c, c) - r * r) / 2)};
}

// The dual plane n + d ni of the plane {x : x . n = d}, n a unit normal.
template <class D>
D make_dual_plane(const vec3& n, double d) {
  using T = scalar_of<D>;
  return D{T(n[0]), T(n[1]), T(n[2]), T(d)};
}

}  // namespace gaphys_test
