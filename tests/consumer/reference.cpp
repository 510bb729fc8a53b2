// contact::reference: the certified MPFR/GMP reference.
#include <contact/reference.hpp>

#include <mpfr.h>

#include <cstdio>

namespace {

// The certified root of (A.2) for (u, dy, phi) lies within 2^-240 of `expected`
// (an MPFR number at 512 bits), is certified, brackets `expected`, and has case `which`.
bool check(const char* what, double u, double dy, double phi, mpfr_srcptr expected, contact::contact_case which) {
  const contact::reference::certified r = contact::reference::solve(u, dy, phi);
  mpfr_t difference;
  mpfr_init2(difference, 512);
  mpfr_sub(difference, r.s.get(), expected, MPFR_RNDN);
  mpfr_abs(difference, difference, MPFR_RNDN);
  const bool close = mpfr_cmp_ui_2exp(difference, 1, -240) <= 0;
  mpfr_clear(difference);
  const bool bracketed = mpfr_cmp(r.lower.get(), expected) <= 0 && mpfr_cmp(expected, r.upper.get()) <= 0;
  const bool ok = r.is_certified && close && bracketed && r.which == which;
  std::printf("reference: %s: s = %s, case %s, certified %d: %s\n", what, r.s.to_string(25).c_str(),
              contact::name_of(r.which).data(), int(r.is_certified), ok ? "ok" : "WRONG");
  return ok;
}

}  // namespace

int main() {
  mpfr_t expected;
  mpfr_init2(expected, 512);
  bool ok = true;

  // (A.31): (2 phi dy - u) / (1 + phi) = 3/4, exactly
  mpfr_set_d(expected, 0.75, MPFR_RNDN);
  ok &= check("(A.31) u=3 dy=1 phi=3", 3.0, 1.0, 3.0, expected, contact::contact_case::contact);

  // (A.32): (sqrt(u^2 + 4 phi dy^2) - u) / 2 = (1 + sqrt 5) / 2, the golden ratio
  mpfr_sqrt_ui(expected, 5, MPFR_RNDN);
  mpfr_add_ui(expected, expected, 1, MPFR_RNDN);
  mpfr_div_2ui(expected, expected, 1, MPFR_RNDN);
  ok &= check("(A.32) u=-1 dy=1 phi=1", -1.0, 1.0, 1.0, expected, contact::contact_case::release);

  // (A.29): -u
  mpfr_set_d(expected, -0.5, MPFR_RNDN);
  ok &= check("(A.29) u=0.5 dy=-2 phi=4", 0.5, -2.0, 4.0, expected, contact::contact_case::free);

  mpfr_clear(expected);
  mpfr_free_cache();
  return ok ? 0 : 1;
}
