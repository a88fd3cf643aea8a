// Batches (<algebra>/batch.hpp): a function called on W values of named
// types at once gives, in each lane, what the scalar call on that lane's
// values gives. In the optimized variant the straight-line kernels run on the
// packs; elsewhere (exp, log, the reference variant) they run lane by lane.
// Lanes are compared to a few units in the last place: with FMA contraction
// the compiler may fuse a pack's products where it does not fuse a scalar's.
#include <gtest/gtest.h>

#include <c3ga/batch.hpp>
#include <cmath>
#include <e3ga/batch.hpp>
#include <tuple>
#include <type_traits>

#include "algebra_test_support.hpp"

namespace {

using namespace gaphys_test;

template <class X>
constexpr bool is_scalar_result = std::is_arithmetic_v<X>;

template <class T>
void expect_lane_equal(T batch_lane, T scalar, const char* what, int lane) {
  const T tolerance = 8 * std::numeric_limits<T>::epsilon() * (1 + std::fabs(scalar));
  EXPECT_NEAR(batch_lane, scalar, tolerance) << what << ", lane " << lane;
}

// Every lane of `batched` against `scalar_call` on that lane's arguments.
template <int W, class Batched, class ScalarCall>
void expect_lanes(const Batched& batched, ScalarCall scalar_call, const char* what) {
  for (int i = 0; i < W; ++i) {
    const auto expected = scalar_call(i);
    const auto got = gaphys::ga::lane(batched, i);
    if constexpr (is_scalar_result<decltype(expected)>) {
      expect_lane_equal(got, expected, what, i);
    } else {
      for (std::size_t k = 0; k < expected.c.size(); ++k) expect_lane_equal(got.c[k], expected.c[k], what, i);
    }
  }
}

// A batch of W random values of named type X, and the values.
template <int W, class X>
struct random_batch {
  std::array<X, W> values;
  gaphys::ga::batch_of_t<X, W> batch;

  explicit random_batch(std::mt19937& rng) {
    for (X& x : values) x = random_named<X>(rng);
    batch = gaphys::ga::gather<W>([&](int i) { return values[i]; });
  }
};

// A function of the library as an object, callable where the library has
// an overload for its arguments (and not otherwise: SFINAE on the result).
#define GAPHYS_TEST_CALLABLE(NAME, F)                                  \
  struct NAME {                                                        \
    static constexpr const char* name = #F;                            \
    template <class... X>                                              \
    auto operator()(const X&... x) const -> decltype(F(x...)) {        \
      return F(x...);                                                  \
    }                                                                  \
  };

GAPHYS_TEST_CALLABLE(c3ga_op, c3ga::op)
GAPHYS_TEST_CALLABLE(c3ga_lc, c3ga::lc)
GAPHYS_TEST_CALLABLE(c3ga_scp, c3ga::scp)
GAPHYS_TEST_CALLABLE(c3ga_gp, c3ga::gp)
GAPHYS_TEST_CALLABLE(c3ga_meet, c3ga::meet)
GAPHYS_TEST_CALLABLE(c3ga_apply, c3ga::apply)
GAPHYS_TEST_CALLABLE(c3ga_add, c3ga::add)
GAPHYS_TEST_CALLABLE(c3ga_sub, c3ga::sub)
GAPHYS_TEST_CALLABLE(c3ga_reverse, c3ga::reverse)
GAPHYS_TEST_CALLABLE(c3ga_dual, c3ga::dual)
GAPHYS_TEST_CALLABLE(c3ga_undual, c3ga::undual)
GAPHYS_TEST_CALLABLE(c3ga_involute, c3ga::involute)
GAPHYS_TEST_CALLABLE(c3ga_exp, c3ga::exp)
GAPHYS_TEST_CALLABLE(c3ga_inverse, c3ga::inverse)
GAPHYS_TEST_CALLABLE(e3ga_op, e3ga::op)
GAPHYS_TEST_CALLABLE(e3ga_lc, e3ga::lc)
GAPHYS_TEST_CALLABLE(e3ga_scp, e3ga::scp)
GAPHYS_TEST_CALLABLE(e3ga_gp, e3ga::gp)
GAPHYS_TEST_CALLABLE(e3ga_apply, e3ga::apply)
GAPHYS_TEST_CALLABLE(e3ga_exp, e3ga::exp)
GAPHYS_TEST_CALLABLE(e3ga_log, e3ga::log)
GAPHYS_TEST_CALLABLE(e3ga_reverse, e3ga::reverse)

// How many functions expect_batch_agrees compared, so that a test can tell
// that the list it gave was not skipped.
int compared = 0;

template <int W, class X>
using batch_of = gaphys::ga::batch_of_t<X, W>;

// F on batches of the Args against F on each lane, where the algebra has a
// named-type kernel F for these types (batches are never widened to an mv)
// with a result other than an mv (which has no batch form).
template <class F, int W, class... Args>
void expect_batch_agrees(std::mt19937& rng) {
  if constexpr (std::is_invocable_v<F, const Args&...> &&
                std::is_invocable_v<F, const batch_of<W, Args>&...>) {
    using result = std::invoke_result_t<F, const Args&...>;
    using first = std::tuple_element_t<0, std::tuple<Args...>>;
    using mv = typename first::algebra::template mv<typename first::scalar_type>;
    if constexpr (!std::is_same_v<result, mv>) {
      ++compared;
      const std::tuple<random_batch<W, Args>...> x{random_batch<W, Args>(rng)...};
      const auto batched = std::apply([](const auto&... a) { return F{}(a.batch...); }, x);
      expect_lanes<W>(
          batched,
          [&](int i) { return std::apply([&](const auto&... a) { return F{}(a.values[i]...); }, x); },
          F::name);
    }
  }
}

template <int W, class A, class B>
void expect_products_agree(std::mt19937& rng) {
  expect_batch_agrees<c3ga_op, W, A, B>(rng);
  expect_batch_agrees<c3ga_lc, W, A, B>(rng);
  expect_batch_agrees<c3ga_scp, W, A, B>(rng);
  expect_batch_agrees<c3ga_gp, W, A, B>(rng);
}

template <int W, class A>
void expect_unary_agree(std::mt19937& rng) {
  expect_batch_agrees<c3ga_reverse, W, A>(rng);
  expect_batch_agrees<c3ga_dual, W, A>(rng);
  expect_batch_agrees<c3ga_undual, W, A>(rng);
  expect_batch_agrees<c3ga_involute, W, A>(rng);
}

template <class T>
class BatchTest : public ::testing::Test {};
TYPED_TEST_SUITE(BatchTest, scalar_types);

template <class T, int W>
void check_c3ga(std::mt19937& rng) {
  using namespace c3ga;
  using point = basic_normalized_point<T>;
  using sphere_dual = basic_dual_sphere<T>;
  using plane_dual = basic_dual_plane<T>;
  using pair = basic_point_pair<T>;
  using round = basic_circle<T>;
  using versor = basic_motor<T>;
  // The contact meet's products, and a sample of every other kind.
  expect_products_agree<W, sphere_dual, sphere_dual>(rng);
  expect_products_agree<W, sphere_dual, plane_dual>(rng);
  expect_products_agree<W, plane_dual, round>(rng);
  expect_products_agree<W, pair, round>(rng);
  expect_products_agree<W, round, basic_sphere<T>>(rng);
  expect_products_agree<W, pair, plane_dual>(rng);
  expect_products_agree<W, point, point>(rng);
  expect_products_agree<W, versor, versor>(rng);
  expect_unary_agree<W, pair>(rng);
  expect_unary_agree<W, round>(rng);
  expect_unary_agree<W, versor>(rng);
  expect_batch_agrees<c3ga_meet, W, basic_sphere<T>, basic_sphere<T>>(rng);
  expect_batch_agrees<c3ga_meet, W, basic_sphere<T>, basic_plane<T>>(rng);
  expect_batch_agrees<c3ga_apply, W, versor, point>(rng);
  expect_batch_agrees<c3ga_apply, W, versor, sphere_dual>(rng);
  expect_batch_agrees<c3ga_exp, W, basic_euclidean_bivector<T>>(rng);
  expect_batch_agrees<c3ga_inverse, W, versor>(rng);
  expect_batch_agrees<c3ga_inverse, W, sphere_dual>(rng);
  expect_batch_agrees<c3ga_add, W, pair, pair>(rng);
  expect_batch_agrees<c3ga_sub, W, round, round>(rng);
}

template <class T, int W>
void check_e3ga(std::mt19937& rng) {
  using namespace e3ga;
  using v = basic_vector<T>;
  using b = basic_bivector<T>;
  using r = basic_rotor<T>;
  expect_batch_agrees<e3ga_op, W, v, v>(rng);
  expect_batch_agrees<e3ga_lc, W, v, b>(rng);
  expect_batch_agrees<e3ga_lc, W, b, b>(rng);
  expect_batch_agrees<e3ga_scp, W, v, v>(rng);
  expect_batch_agrees<e3ga_gp, W, r, r>(rng);
  expect_batch_agrees<e3ga_apply, W, r, v>(rng);
  expect_batch_agrees<e3ga_exp, W, b>(rng);
  expect_batch_agrees<e3ga_log, W, r>(rng);
  expect_batch_agrees<e3ga_reverse, W, r>(rng);
}

// At the native width (2 doubles, 4 floats on baseline x86-64): one width
// a scalar type, since each is a few thousand instantiations (72 s of the
// sanitized build's compile time with three).
TYPED_TEST(BatchTest, EveryLaneIsTheScalarCall) {
  using T = TypeParam;
  constexpr int W = gaphys::ga::native_lanes<T>;
  auto rng = make_rng(2026);
  compared = 0;
  check_c3ga<T, W>(rng);
  const int c3ga_functions = compared;
  check_e3ga<T, W>(rng);
  const int e3ga_functions = compared - c3ga_functions;
  // Every function of the lists that has a named-type kernel with a
  // named-type or scalar result (the others are skipped by design).
  EXPECT_EQ(c3ga_functions, 38);
  EXPECT_EQ(e3ga_functions, 9);
  for (int round = 0; round < 20; ++round) {
    check_c3ga<T, W>(rng);
    check_e3ga<T, W>(rng);
  }
}

// A kernel that checks its argument (the versor inverse of a null
// multivector) throws when any lane fails the check.
TEST(BatchTest, ANullLaneMakesTheInverseThrow) {
  using sphere_dual = c3ga::dual_sphere_batch<4>;
  auto rng = make_rng(7);
  random_batch<4, c3ga::dual_sphere> spheres(rng);
  c3ga::dual_sphere null_point{1, 0.5, 0.25, -1, 0.5 * (0.25 + 0.0625 + 1)};  // a point: x^2 = 0
  sphere_dual x = spheres.batch;
  gaphys::ga::set_lane(x, 2, null_point);
  EXPECT_NO_THROW(c3ga::inverse(spheres.batch));
  EXPECT_THROW(c3ga::inverse(x), std::domain_error);
}

}  // namespace
