#include <contact/solve.hpp>

int main() {
  const auto r = contact::solve(3.0, 1.0, 3.0);  // (A.31): s = 3/4
  return r.s == 0.75 && r.which == contact::contact_case::contact ? 0 : 1;
}
