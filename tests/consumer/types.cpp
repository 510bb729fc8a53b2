// contact::types: the scalar type registry, solving in float128 (libquadmath)
// and in mpfr_float (MPFR, GMP) through contact::with_type.
#include <contact/solve.hpp>
#include <contact/types.hpp>

#include <boost/math/tools/precision.hpp>

#include <cstdio>
#include <string>
#include <string_view>

namespace {

// Solves two inputs of known answer in the type named `name`:
//   (A.31) u=3 dy=1 phi=3: s = 3/4 exactly;
//   (A.32) u=-1 dy=1 phi=1: s = (1 + sqrt 5) / 2, to within 4 ulps of the type.
bool check(std::string_view name) {
  bool ok = false;
  const bool known = contact::with_type(name, [&](auto zero) {
    using T = decltype(zero);
    using std::abs;
    using std::sqrt;
    const auto contact = contact::solve(T(3), T(1), T(3));
    const auto release = contact::solve(T(-1), T(1), T(1));
    const T golden = (T(1) + sqrt(T(5))) / T(2);
    const T eps = boost::math::tools::epsilon<T>();  // at mpfr_float's run-time precision too
    ok = contact.s == T(0.75) && contact.which == contact::contact_case::contact &&
         release.which == contact::contact_case::release && abs(release.s - golden) <= T(4) * eps * golden &&
         contact::type_name<T> == name;
    std::printf("types: %s (%d bits): s = %s, %s; s = %s, %s: %s\n", std::string(contact::type_name<T>).c_str(),
                contact::detail::precision_of<T>(), contact::round_trip_text(contact.s).c_str(),
                contact::name_of(contact.which).data(), contact::round_trip_text(release.s).c_str(),
                contact::name_of(release.which).data(), ok ? "ok" : "WRONG");
  });
  if (!known) std::printf("types: no type '%s' in the registry\n", std::string(name).c_str());
  return known && ok;
}

}  // namespace

int main() {
  contact::mpfr_float::default_precision(60);  // digits10 of the run-time precision
  bool ok = check("float128");
  ok = check("mpfr") && ok;  // both, whatever the first says
  ok = ok && contact::detail::precision_of<contact::float128>() == 113;
  ok = ok && !contact::with_type("no_such_type", [](auto) {});
  return ok ? 0 : 1;
}
