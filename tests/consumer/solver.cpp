// contact::solver: header-only, Boost headers only.
#include <contact/solve.hpp>

#include <cstdio>

int main() {
  const auto r = contact::solve(3.0, 1.0, 3.0);  // (A.31): s = (2 phi dy - u) / (1 + phi) = 3/4 exactly
  if (r.s != 0.75 || r.which != contact::contact_case::contact) {
    std::printf("solver: solve(3, 1, 3) = %a, case %d; expected 0x1.8p-1, case 3 (contact)\n", r.s,
                static_cast<int>(r.which));
    return 1;
  }
  std::printf("solver: solve(3, 1, 3) = %g, %s\n", r.s, contact::name_of(r.which).data());
  return 0;
}
