// The routes float and double take that no other type takes (the common-window
// test on bits, the moved stage and its bands, the subnormal-phi factors, the
// selects of the release, the clamps on bits, the dominant-binade test) give
// what the generic path gives on the same arithmetic: the same s bit for bit
// and the same case. The generic path is the one proofs.exhaustive checks on
// every input of its miniature formats; here it runs on `generic<T>`, a T that
// the solver does not recognise as hardware binary, so that solve_stable takes
// by_safe_window with frexp, ldexp and comparisons instead of bit patterns.
// The inputs cover every route; each route's count is checked, so that a test
// set which stopped reaching one fails.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <compare>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <ostream>
#include <type_traits>
#include <vector>

#include "contact/harness/families.hpp"
#include "contact/solve.hpp"

namespace generic_route {

// T's values and T's correctly rounded operations, under another name.
template <class T>
class generic {
 public:
  constexpr generic() = default;
  template <class I>
    requires std::is_arithmetic_v<I>
  constexpr generic(I x) : value_(static_cast<T>(x)) {}  // NOLINT: implicit, as for the literals of generic code
  constexpr explicit operator T() const { return value_; }
  T value() const { return value_; }

  friend constexpr generic operator-(generic a) { return generic(-a.value_); }
  friend constexpr generic operator+(generic a, generic b) { return generic(T(a.value_ + b.value_)); }
  friend constexpr generic operator-(generic a, generic b) { return generic(T(a.value_ - b.value_)); }
  friend constexpr generic operator*(generic a, generic b) { return generic(T(a.value_ * b.value_)); }
  friend constexpr generic operator/(generic a, generic b) { return generic(T(a.value_ / b.value_)); }
  friend bool operator==(generic a, generic b) { return a.value_ == b.value_; }
  friend std::partial_ordering operator<=>(generic a, generic b) { return a.value_ <=> b.value_; }

  friend generic sqrt(generic a) { return generic(std::sqrt(a.value_)); }
  friend generic fabs(generic a) { return generic(std::fabs(a.value_)); }
  friend generic fma(generic a, generic b, generic c) { return generic(std::fma(a.value_, b.value_, c.value_)); }
  friend generic frexp(generic a, int* exponent) { return generic(std::frexp(a.value_, exponent)); }
  friend generic ldexp(generic a, int exponent) { return generic(std::ldexp(a.value_, exponent)); }
  friend bool isfinite(generic a) { return std::isfinite(a.value_); }
  friend bool isinf(generic a) { return std::isinf(a.value_); }
  friend bool isnan(generic a) { return std::isnan(a.value_); }
  friend bool signbit(generic a) { return std::signbit(a.value_); }
  // Boost.Math's error messages (next.hpp) print the value
  friend std::ostream& operator<<(std::ostream& out, generic a) { return out << a.value_; }

 private:
  T value_ = 0;
};

}  // namespace generic_route

template <class T>
struct std::numeric_limits<generic_route::generic<T>> {
  using G = generic_route::generic<T>;
  using L = std::numeric_limits<T>;
  static constexpr bool is_specialized = true, is_signed = true, is_integer = false, is_exact = false;
  static constexpr bool has_infinity = true, has_quiet_NaN = true, has_signaling_NaN = L::has_signaling_NaN;
  static constexpr std::float_denorm_style has_denorm = L::has_denorm;
  static constexpr bool has_denorm_loss = L::has_denorm_loss, is_iec559 = L::is_iec559, is_bounded = true;
  static constexpr bool is_modulo = false, traps = false, tinyness_before = L::tinyness_before;
  static constexpr std::float_round_style round_style = L::round_style;
  static constexpr int radix = 2, digits = L::digits, digits10 = L::digits10, max_digits10 = L::max_digits10;
  static constexpr int min_exponent = L::min_exponent, max_exponent = L::max_exponent;
  static constexpr int min_exponent10 = L::min_exponent10, max_exponent10 = L::max_exponent10;
  static constexpr G min() { return G(L::min()); }
  static constexpr G max() { return G(L::max()); }
  static constexpr G lowest() { return G(L::lowest()); }
  static constexpr G epsilon() { return G(L::epsilon()); }
  static constexpr G round_error() { return G(L::round_error()); }
  static constexpr G infinity() { return G(L::infinity()); }
  static constexpr G quiet_NaN() { return G(L::quiet_NaN()); }
  static constexpr G signaling_NaN() { return G(L::signaling_NaN()); }
  static constexpr G denorm_min() { return G(L::denorm_min()); }
};

namespace {

namespace harness = contact::harness;
using generic_route::generic;

static_assert(!contact::detail::hardware_binary<generic<double>> && !contact::detail::binary_bits<generic<double>>);

template <class T>
using bits = std::conditional_t<std::is_same_v<T, double>, std::uint64_t, std::uint32_t>;

// The route solve_stable<T> takes for an input, as its stages choose it: the
// common window (plain T), the moved stage with a normal or a subnormal phi
// (its factors), u or dy zero or subnormal (read as integers), and the rest
// (phi = 0, phi beyond the last band, non-finite or invalid input).
enum class route { common_window, moved, moved_subnormal_phi, zero_or_subnormal_u_or_dy, elsewhere, count };
constexpr const char* route_names[] = {"common window", "moved", "moved, phi subnormal", "u or dy zero or subnormal",
                                       "elsewhere"};

template <class T>
route route_of(T u, T dy, T phi) {
  if (contact::detail::inside_common_window(u, dy, phi)) return route::common_window;
  const bool phi_in_bands = phi > 0 && phi < contact::detail::phi_bands<T>::end;
  if (!phi_in_bands || !std::isfinite(u) || !std::isfinite(dy)) return route::elsewhere;
  if (!std::isnormal(u) || !std::isnormal(dy)) return route::zero_or_subnormal_u_or_dy;
  return std::isnormal(phi) ? route::moved : route::moved_subnormal_phi;
}

template <class T>
::testing::AssertionResult same_as_generic(T u, T dy, T phi) {
  const auto hardware = contact::solve_stable(u, dy, phi);
  const auto generic_path = contact::solve_stable(generic<T>(u), generic<T>(dy), generic<T>(phi));
  const T generic_s = generic_path.s.value();
  const bool same_s = std::bit_cast<bits<T>>(hardware.s) == std::bit_cast<bits<T>>(generic_s) ||
                      (std::isnan(hardware.s) && std::isnan(generic_s));
  if (hardware.which == generic_path.which && same_s) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << std::hexfloat << "u=" << u << " dy=" << dy << " phi=" << phi << ": "
                                       << "solve_stable s=" << hardware.s << " case " << int(hardware.which)
                                       << ", generic path s=" << generic_s << " case " << int(generic_path.which);
}

// Inputs of every family (harness::any_input: the whole range with zeros,
// subnormals and huge values, both boundaries, both cancellations, physical)
// and the top of the range, so that every route is taken.
template <class T>
std::vector<std::array<T, 3>> every_family(int count, std::uint64_t seed) {
  std::vector<std::array<T, 3>> inputs;
  harness::seeded_source source(seed);
  for (int i = 0; i < count; ++i) {
    const auto x = harness::any_input<T>(source);
    inputs.push_back({x.u, x.dy, x.phi});
  }
  for (const auto& x : harness::top_of_range<T>()) inputs.push_back({x.u, x.dy, x.phi});
  return inputs;
}

template <class T>
void expect_every_route_as_generic(int count, std::uint64_t seed) {
  std::array<long, std::size_t(route::count)> taken{};
  long mismatches = 0;
  for (const auto& [u, dy, phi] : every_family<T>(count, seed)) {
    ++taken[std::size_t(route_of(u, dy, phi))];
    const auto same = same_as_generic(u, dy, phi);
    if (!same && ++mismatches <= 10) ADD_FAILURE() << same.message();
  }
  EXPECT_EQ(mismatches, 0);
  for (std::size_t r = 0; r < taken.size(); ++r) {
    std::printf("  %-26s %ld inputs\n", route_names[r], taken[r]);
    EXPECT_GE(taken[r], 1000) << route_names[r] << ": too seldom taken";
  }
}

TEST(GenericRoute, DoubleRoutesGiveTheGenericPathsAnswerBitForBit) {
  expect_every_route_as_generic<double>(500000, 20261127);
}

TEST(GenericRoute, FloatRoutesGiveTheGenericPathsAnswerBitForBit) {
  expect_every_route_as_generic<float>(500000, 20261128);
}

}  // namespace
