// Prints the boxes proofs/gappa_window proves, from the solver's own constants
// (window.hpp), so that the proofs follow the table rather than a copy of it.
// One line per box:
//   TYPE NAME P Q TOP LOWEST IMPACT_LOWEST PHI_MAY_BE_ZERO
// phi in [2^P, 2^(Q+1)] (or 0 where the last field is 1); |u|, |dy| are 0 or in
// [2^LOWEST, 2^TOP]; in an impact on a band, u in [2^(TOP-1), 2^TOP] and gap = -dy
// in [2^IMPACT_LOWEST, 2^TOP] (in the plain window, which moves nothing, as u
// and dy). A band with LOWEST > TOP admits no input and is printed all the
// same, so that the runner can say it skipped it.
#include <cstdio>

#include "contact/detail/window.hpp"

namespace {

template <class T>
void print(const char* type) {
  using bands = contact::detail::phi_bands<T>;
  // the plain window: phi, u and dy each 0 or in [2^-E, 2^E] (safe_window; phi = 0 included)
  const long E = contact::detail::plain_window<T>;
  std::printf("%s plain %ld %ld %ld %ld %ld 1\n", type, -E, E - 1, E, -E, -E);
  for (int j = 0; j < bands::count; ++j) {
    const auto band = bands::table[j];
    std::printf("%s band%d %d %d %d %d %d 0\n", type, j, bands::first_of(j), bands::last_of(j), band.top, band.lowest,
                band.impact_lowest);
  }
}

}  // namespace

int main() {
  print<double>("double");
  print<float>("float");
}
