// Reading a decimal or C99 hex number into float, double, long double or
// float128 with one rounding, to nearest (ties to even), gradual underflow
// and overflow included: MPFR reads the text at T's precision in T's exponent
// range. glibc's strtof rounds some decimals of float's subnormals twice, and
// neither it nor std::from_chars reads float128; MPFR reads every type alike.
#pragma once

#include <mpfr.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "contact/detail/float_tools.hpp"

namespace contact::cli {

enum class reading { number, not_a_number, overflows };

template <class T>
struct read_result {
  T value;
  reading status;
};

// text, all of it one number, rounded to T (one of the four types above).
template <class T>
read_result<T> read_rounded(const std::string& text) {
  using std::ldexp;
  const int p = detail::precision_of<T>();
  const mpfr_exp_t old_emin = mpfr_get_emin(), old_emax = mpfr_get_emax();
  // T's range in MPFR's convention (significand in [1/2, 1)): the least subnormal is 2^(emin - p)
  mpfr_set_emin(std::numeric_limits<T>::min_exponent - p + 1);
  mpfr_set_emax(std::numeric_limits<T>::max_exponent);
  mpfr_t x;
  mpfr_init2(x, p);
  mpfr_clear_flags();
  char* end = nullptr;
  int inexact = mpfr_strtofr(x, text.c_str(), &end, 0, MPFR_RNDN);  // base 0: decimal, or hex after 0x
  const bool whole = end != text.c_str() && *end == '\0';  // something read, and nothing left after it
  inexact = mpfr_check_range(x, inexact, MPFR_RNDN);
  mpfr_subnormalize(x, inexact, MPFR_RNDN);  // a subnormal at its own precision, from the ternary value: still one rounding
  const bool overflowed = mpfr_overflow_p() != 0;
  read_result<T> result{T(0), whole ? (overflowed ? reading::overflows : reading::number) : reading::not_a_number};
  if (mpfr_nan_p(x)) {
    result.value = std::numeric_limits<T>::quiet_NaN();
  } else if (mpfr_inf_p(x)) {
    result.value = mpfr_sgn(x) > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
  } else if (!mpfr_zero_p(x)) {
    // the significand, at most p bits, exactly in T, 32 bits at a time; then one exact scaling
    mpz_t significand;
    mpz_init(significand);
    const mpfr_exp_t exponent = mpfr_get_z_2exp(significand, x);
    mpz_abs(significand, significand);
    T value = 0;
    for (long chunk = long((mpz_sizeinbase(significand, 2) + 31) / 32) - 1; chunk >= 0; --chunk) {
      mpz_t part;
      mpz_init(part);
      mpz_tdiv_q_2exp(part, significand, mp_bitcnt_t(32 * chunk));
      value = ldexp(value, 32) + T(static_cast<double>(mpz_get_ui(part) & 0xffffffffUL));
      mpz_clear(part);
    }
    mpz_clear(significand);
    value = ldexp(value, static_cast<int>(exponent));
    result.value = mpfr_sgn(x) < 0 ? T(-value) : value;
  } else {
    result.value = mpfr_signbit(x) ? T(-0.0) : T(0);
  }
  mpfr_clear(x);
  mpfr_set_emin(old_emin);
  mpfr_set_emax(old_emax);
  return result;
}

}  // namespace contact::cli
