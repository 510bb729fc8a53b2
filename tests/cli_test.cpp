// contact-solve, run as a user runs it: through a shell, on files.
#include <sys/wait.h>

#include <cstdio>
#include <fstream>

#include "harness.hpp"
#include "read_number.hpp"

namespace contact::testing {
namespace {

struct run_result {
  std::string out, err;
  int status;
};

run_result run_cli(const std::string& arguments, const std::string& input) {
  // ctest runs these tests in parallel processes: each gets files of its own
  const std::string dir = ::testing::TempDir() + ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string in = dir + ".in", out = dir + ".out", err = dir + ".err";
  std::ofstream(in) << input;
  const std::string command = std::string(CONTACT_SOLVE) + " " + arguments + " " + in + " >" + out + " 2>" + err;
  const int status = std::system(command.c_str());
  auto slurp = [](const std::string& path) {
    std::ifstream f(path);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  return {slurp(out), slurp(err), WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(ContactSolve, WritesHexStepAndCasePerLine) {
  const auto r = run_cli("--algo stable --type double", "3 1 3\n0x1p0 -0x1p0 3\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "0x1.8p-1 3\n-0x1p+0 1\n");
  EXPECT_EQ(r.err, "");
}

TEST(ContactSolve, KeepsCommentsAndBlankLinesInPlace) {
  const auto r = run_cli("", "# header\n\n3 1 3 # trailing comment\n");
  EXPECT_EQ(r.out, "# header\n\n0x1.8p-1 3\n");
}

TEST(ContactSolve, ReportsEachBadLineInPlaceAndOnStderrWithItsNumber) {
  const auto r = run_cli("", "3 1 3\n1 2\n1 1 -1\nnan 1 1\n1 1e999 1\nx 1 1\n1 1 1 1\n0x1.8 1 1\n");
  EXPECT_EQ(r.status, 1);
  const auto out = lines_of(r.out), err = lines_of(r.err);
  ASSERT_EQ(out.size(), 8u);
  EXPECT_EQ(out[0], "0x1.8p-1 3");
  EXPECT_EQ(out[1], "error expected 3 numbers (u dy phi), found 2");
  EXPECT_EQ(out[2], "error phi is negative");
  EXPECT_EQ(out[3], "error u is not finite");
  EXPECT_EQ(out[4], "error '1e999' overflows double");
  EXPECT_EQ(out[5], "error 'x' is not a number");
  EXPECT_EQ(out[6], "error expected 3 numbers (u dy phi), found 4");
  EXPECT_EQ(out[7], "0x1p-2 3");  // "0x1.8" is a valid hex float: 1.5, and (A.31) gives 1/4
  ASSERT_EQ(err.size(), 6u);
  EXPECT_EQ(err[0], "contact-solve: line 2: expected 3 numbers (u dy phi), found 2");
  EXPECT_EQ(err[5], "contact-solve: line 7: expected 3 numbers (u dy phi), found 4");
}

TEST(ContactSolve, ExplainsEachMalformedNumber) {
  const auto r = run_cli(
      "", "0x1.8.8 1 1\n0x 1 1\n0x1q3 1 1\n0x1p 1 1\n0x1pz 1 1\n0x1p3x 1 1\n1.5x 1 1\n1 inf 1\n1 1 nan\n+0x1p-2 -0x1P-1 3\n");
  const auto out = lines_of(r.out);
  ASSERT_EQ(out.size(), 10u);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(out[i].substr(0, 7), "error '") << out[i];
  EXPECT_EQ(out[7], "error dy is not finite");
  EXPECT_EQ(out[8], "error phi is not finite");
  EXPECT_EQ(out[9], "-0x1p-2 1");  // u = 1/4, dy = -1/2: (A.29), s = -u
  EXPECT_EQ(lines_of(r.err).size(), 9u);
}

TEST(ContactSolve, AcceptsAnUpperCaseHexPrefix) {
  EXPECT_EQ(run_cli("", "0X1P0 -0X1p0 3\n").out, "-0x1p+0 1\n");
}

// strtod's answer: the nearest double, here 0 (C99 says ERANGE; it is no overflow).
TEST(ContactSolve, ReadsADecimalBelowTheSubnormalRangeAsZero) {
  const auto out = lines_of(run_cli("", "1e-400 1 3\n0 1 3\n").out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], out[1]);
}

// ---- reading numbers: one rounding to nearest, ties to even -----------------

// x exactly in decimal ("0.DIGITSeE"), from MPFR: a dyadic number has a finite
// decimal expansion, and mpfr_get_str with enough digits writes all of it.
std::string exact_decimal(const reference::real& x) {
  if (mpfr_zero_p(x.get())) return "0";
  // x = m 2^(e - prec), m an integer of prec bits: at most prec + |e| digits
  const long digits = long(mpfr_get_prec(x.get())) + std::labs(long(mpfr_get_exp(x.get()))) + 2;
  mpfr_exp_t exponent = 0;
  char* text = mpfr_get_str(nullptr, &exponent, 10, std::size_t(digits), x.get(), MPFR_RNDN);
  std::string digits_text(text);
  mpfr_free_str(text);
  const bool negative = digits_text[0] == '-';
  if (negative) digits_text.erase(0, 1);
  return (negative ? "-0." : "0.") + digits_text + "e" + std::to_string(exponent);
}

template <class T>
bool same_bits(const T& a, const T& b) {
  using std::signbit;
  return a == b && signbit(a) == signbit(b);
}

// For neighbours low < high of T (high infinite past the largest T): the exact
// midpoint, and the midpoint moved by 2^-40 of their spacing either way, as
// exact decimals of either sign, must read as the even one of the two, high,
// and low; an infinite answer must be reported as an overflow. Returns how
// many it read.
template <class T>
int expect_midpoints_read_to_nearest_even(const T& low, bool low_is_even) {
  using contact::cli::read_rounded;
  using contact::cli::reading;
  constexpr T infinity = std::numeric_limits<T>::infinity();
  const mpfr_prec_t bits = detail::precision_of<T>() + 64;  // low, its neighbours and the points between, exactly
  const T high = detail::next_up(low);
  // the spacing of T at low (beyond the largest T, the largest T's own)
  reference::real spacing = high < infinity ? reference::exactly(high, bits) : reference::exactly(low, bits);
  mpfr_sub(spacing.get(), spacing.get(), (high < infinity ? reference::exactly(low, bits) : reference::exactly(detail::next_down(low), bits)).get(), MPFR_RNDN);
  int read = 0;
  for (int direction : {0, 1, -1}) {
    reference::real x = reference::exactly(low, bits), step(bits);
    mpfr_div_2ui(step.get(), spacing.get(), 1, MPFR_RNDN);
    mpfr_add(x.get(), x.get(), step.get(), MPFR_RNDN);  // the midpoint
    mpfr_div_2ui(step.get(), spacing.get(), 40, MPFR_RNDN);
    if (direction > 0) mpfr_add(x.get(), x.get(), step.get(), MPFR_RNDN);
    if (direction < 0) mpfr_sub(x.get(), x.get(), step.get(), MPFR_RNDN);
    const T expected = direction == 0 ? (low_is_even ? low : high) : direction > 0 ? high : low;
    for (bool negative : {false, true}) {
      const std::string text = (negative ? "-" : "") + exact_decimal(x);
      const auto got = read_rounded<T>(text);
      ++read;
      if (!(expected < infinity)) {
        EXPECT_EQ(got.status, reading::overflows) << text.substr(0, 60);
      } else {
        EXPECT_EQ(got.status, reading::number) << text.substr(0, 60);
        EXPECT_TRUE(same_bits(got.value, negative ? T(-expected) : expected))
            << "direction " << direction << ": " << text.substr(0, 80) << "...";
      }
    }
  }
  return read;
}

// Whether low is an even value of T (its last significand bit 0): low over
// the spacing of T at low is an even integer.
template <class T>
bool is_even(const T& low) {
  const mpfr_prec_t bits = detail::precision_of<T>() + 8;
  const T high = detail::next_up(low), neighbour = high < std::numeric_limits<T>::infinity() ? high : detail::next_down(low);
  reference::real quotient = reference::exactly(low, bits), spacing = reference::exactly(neighbour, bits);
  mpfr_sub(spacing.get(), spacing.get(), quotient.get(), MPFR_RNDN);
  mpfr_abs(spacing.get(), spacing.get(), MPFR_RNDN);
  mpfr_div(quotient.get(), quotient.get(), spacing.get(), MPFR_RNDN);
  mpfr_div_2ui(quotient.get(), quotient.get(), 1, MPFR_RNDN);
  return mpfr_integer_p(quotient.get()) != 0;
}

template <class T>
class ReadsNumbers : public ::testing::Test {};
using types_read_by_mpfr = ::testing::Types<float, double, long double, float128>;
TYPED_TEST_SUITE(ReadsNumbers, types_read_by_mpfr, type_names_for_gtest);

// Halfway cases and their neighbours, as exact decimals: in the normal range,
// in the subnormals (the least of them, and one of many bits at the top of
// them), below the least subnormal, and at the largest T and the threshold of
// overflow beyond it.
TYPED_TEST(ReadsNumbers, HardDecimalsRoundOnceToNearestEven) {
  using T = TypeParam;
  using std::ldexp;
  const T one = 1, tiny = std::numeric_limits<T>::denorm_min(), largest = (std::numeric_limits<T>::max)();
  const T least_normal = (std::numeric_limits<T>::min)();
  const T many_bits = T(least_normal - T(10 * tiny));  // a subnormal of many bits, just below the normals
  const T lows[] = {one,  detail::next_up(one),   T(0),          tiny,    T(2 * tiny), many_bits, detail::next_up(many_bits),
                    T(least_normal / 2), detail::next_down(largest), largest, ldexp(one, 100)};
  int read = 0;
  for (const T& low : lows) read += expect_midpoints_read_to_nearest_even(low, is_even(low));
  EXPECT_EQ(read, 6 * int(std::size(lows)));
}

// Random neighbours over T's whole range (harness::any_finite), each midpoint
// and its two neighbours.
TYPED_TEST(ReadsNumbers, RandomMidpointsRoundOnceToNearestEven) {
  using T = TypeParam;
  using std::fabs;
  harness::seeded_source source(31);
  int read = 0;
  for (int k = 0; k < 150; ++k) {
    const T low = fabs(harness::any_finite<T>(source));
    if (detail::next_up(low) < std::numeric_limits<T>::infinity()) read += expect_midpoints_read_to_nearest_even(low, is_even(low));
  }
  EXPECT_GT(read, 800);
}

// glibc's strtof reads this decimal, the exact value of -0x1.6ce193p-127
// (midway between no two floats), as -0x1.6ce19p-127; the nearest float is
// -0x1.6ce194p-127.
TEST(ContactSolve, ReadsASubnormalFloatDecimalToTheNearestFloat) {
  EXPECT_EQ(contact::cli::read_rounded<float>(exact_decimal(reference::exactly(-0x1.6ce193p-127, 64))).value, -0x1.6ce194p-127f);
  const auto out = lines_of(run_cli("--type float", exact_decimal(reference::exactly(-0x1.6ce193p-127, 64)) + " 0 0\n").out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], "0x1.6ce194p-127 1");
}

TEST(ContactSolve, RejectsMalformedNumbersInWiderTypes) {
  const auto r = run_cli("--type cpp_bin_float_50", "abc 1 1\n1e5000000000000 1 1\n3 1 3\n");
  const auto out = lines_of(r.out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], "error 'abc' is not a number");
  EXPECT_EQ(out[2], "0.75 3");
  EXPECT_EQ(r.status, 1);
}

// The wider types read hex digit by digit (exactly), in either case, with or
// without a point, a sign or a power; a malformed one is an error, as decimals are.
TEST(ContactSolve, ReadsHexExactlyAndExplainsEachMalformedOneInWiderTypes) {
  const auto hex = run_cli("--type cpp_bin_float_50", "-0x1.8p+1 0x1p-2 0X1P0\n+0xA.bp0 0xa.Bp0 0x1p0\n0x2 0x1 0x1\n");
  const auto decimal = run_cli("--type cpp_bin_float_50", "-3 0.25 1\n10.6875 10.6875 1\n2 1 1\n");
  EXPECT_EQ(hex.out, decimal.out);
  EXPECT_EQ(hex.status, 0);
  const auto bad = run_cli("--type cpp_bin_float_50", "0x 1 1\n0x1..2 1 1\n0x1q3 1 1\n0x1p 1 1\n0x1pz 1 1\n0x1p3z 1 1\n");
  const auto out = lines_of(bad.out);
  ASSERT_EQ(out.size(), 6u);
  for (const auto& line : out) EXPECT_EQ(line.substr(0, 7), "error '") << line;
  EXPECT_EQ(bad.status, 1);
}

TEST(ContactSolve, ReadsStandardInputWithoutAFile) {
  const std::string in = ::testing::TempDir() + "stdin_test.in", out = ::testing::TempDir() + "stdin_test.out";
  std::ofstream(in) << "3 1 3\n";
  ASSERT_EQ(std::system((std::string(CONTACT_SOLVE) + " --type float <" + in + " >" + out).c_str()), 0);
  std::ifstream result(out);
  std::string line;
  std::getline(result, line);
  EXPECT_EQ(line, "0x1.8p-1 3");
}

TEST(ContactSolve, RejectsUnknownAlgorithmAndUnreadableFile) {
  EXPECT_EQ(run_cli("--algo bisection", "").status, 2);
  EXPECT_EQ(std::system((std::string(CONTACT_SOLVE) + " /nonexistent/file 2>/dev/null").c_str()) >> 8, 2);
}

TEST(ContactSolve, HelpListsAlgorithmsAndTypes) {
  const auto r = run_cli("--help", "");
  for (auto a : algorithms) EXPECT_NE(r.out.find(name_of(a)), std::string::npos) << name_of(a);
  for (auto type : type_names) EXPECT_NE(r.out.find(type), std::string::npos) << type;
}

TEST(ContactSolve, RejectsUnknownTypeNamingTheKnownOnes) {
  const auto r = run_cli("--type half", "3 1 3\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("unknown type 'half'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cpp_bin_float_100"), std::string::npos) << r.err;
}

TEST(ContactSolve, WiderTypesPrintRoundTripDecimals) {
  for (const char* type : {"long_double", "float128", "cpp_bin_float_50", "cpp_bin_float_100", "mpfr"}) {
    const auto r = run_cli(std::string("--type ") + type, "3 1 3\n1 1 3\n");
    const auto out = lines_of(r.out);
    ASSERT_EQ(out.size(), 2u) << type;
    EXPECT_EQ(out[0], "0.75 3") << type;
    EXPECT_EQ(out[1].substr(0, 12), "1.3027756377") << type;  // (A.32): (-1 + sqrt(13)) / 2
  }
}

// The command-line solver over inputs spanning the whole double range,
// the stable double CLI gives no NaN and no infinity where the root is finite,
// and stays within the proven bound. Inputs written as hex, read back exactly.
TEST(ContactSolve, StableDoubleStaysWithinBoundOverTheWholeRange) {
  harness::seeded_source source(20261123);
  std::vector<input<double>> inputs;
  std::string text;
  char line[128];
  for (int i = 0; i < 20000; ++i) {
    const input<double> x = harness::whole_range<double>(source);
    inputs.push_back(x);
    std::snprintf(line, sizeof line, "%a %a %a\n", x.u, x.dy, x.phi);
    text += line;
  }
  const auto r = run_cli("--algo stable --type double", text);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = lines_of(r.out);
  ASSERT_EQ(out.size(), inputs.size());
  double worst = 0;
  int beyond_range = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const double s = std::strtod(out[i].c_str(), nullptr);
    const auto exact = reference::solve(inputs[i].u, inputs[i].dy, inputs[i].phi);
    if (!root_is_finite_in<double>(exact)) {
      ++beyond_range;
      EXPECT_TRUE(std::isinf(s)) << out[i];
      continue;
    }
    ASSERT_TRUE(std::isfinite(s)) << "line " << i + 1 << ": " << out[i];
    worst = std::max(worst, reference::ulp_error(s, exact));
  }
  RecordProperty("max_ulp", std::to_string(worst));
  std::printf("contact-solve stable double, 20000 whole-range inputs: max %.3g ulp, %d roots beyond double\n", worst,
              beyond_range);
  EXPECT_LE(worst, stable_bound_any());
}

// The committed hard cases of the correctly rounded mode, through the CLI: each
// line's u dy phi gives exactly its expected_s and expected_case.
TEST(ContactSolve, RoundedGivesTheExpectedStepOnEveryHardCase) {
  for (const char* name : {"exact_ties_contact", "exact_ties_release", "exact_ties_impact", "near_ties", "range_edges",
                           "subnormal_phi"}) {
    std::ifstream file(std::string(CONTACT_ROUNDED_HARD_CASES) + "/" + name + ".txt");
    ASSERT_TRUE(file) << name;
    std::string input;
    std::vector<std::string> expected;
    for (std::string line; std::getline(file, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      std::string u, dy, phi, s, which;
      fields >> u >> dy >> phi >> s >> which;
      input += u + " " + dy + " " + phi + "\n";
      expected.push_back(s + " " + which);
    }
    const auto r = run_cli("--algo rounded --type double", input);
    EXPECT_EQ(r.status, 0) << name;
    EXPECT_EQ(r.err, "") << name;
    const auto out = lines_of(r.out);
    ASSERT_EQ(out.size(), expected.size()) << name;
    for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], expected[i]) << name << " line " << i + 1;
  }
}

TEST(ContactSolve, RoundedWorksForEachTypeThatHasIt) {
  for (const char* type : {"float", "double", "long_double", "float128"}) {
    const auto r = run_cli(std::string("--algo rounded --type ") + type, "3 1 3\n");
    EXPECT_EQ(r.status, 0) << type;
    EXPECT_TRUE(r.out == "0x1.8p-1 3\n" || r.out == "0.75 3\n") << type << ": " << r.out;
  }
}

// The multiprecision types have no correctly rounded mode: a clear error and
// status 2, never an answer from another algorithm.
TEST(ContactSolve, RoundedIsRefusedForTypesWithoutIt) {
  for (const char* type : {"cpp_bin_float_50", "cpp_bin_float_100", "mpfr"}) {
    const auto r = run_cli(std::string("--algo rounded --type ") + type, "3 1 3\n");
    EXPECT_EQ(r.status, 2) << type;
    EXPECT_EQ(r.out, "") << type;
    EXPECT_NE(r.err.find("--algo rounded is not available for --type " + std::string(type)), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace contact::testing
