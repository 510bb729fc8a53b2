// contact::batch: solve_batch and solve_rounded_batch over Eigen arrays
// (Eigen3::Eigen), bit for bit the scalar solve_stable and solve_rounded on
// every lane: the four cases, lanes near (A.21)'s boundary, and lanes outside
// the vector window (which the scalar path solves).
#include <contact/batch.hpp>
#include <contact/rounded.hpp>
#include <contact/stable.hpp>

#include <Eigen/Core>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <type_traits>
#include <vector>

namespace {

template <class T>
using bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;

template <class T>
int check(const char* type, const std::vector<T>& us, const std::vector<T>& dys, const std::vector<T>& phis,
          bool rounded) {
  const Eigen::Index n = static_cast<Eigen::Index>(us.size());
  contact::batch_array<T> u(n), dy(n), phi(n), s;
  contact::batch_array<int> which;
  for (Eigen::Index i = 0; i < n; ++i) {
    u[i] = us[std::size_t(i)];
    dy[i] = dys[std::size_t(i)];
    phi[i] = phis[std::size_t(i)];
  }
  if (rounded)
    contact::solve_rounded_batch(u, dy, phi, s, which);
  else
    contact::solve_batch(u, dy, phi, s, which);
  int wrong = 0;
  if (s.size() != n || which.size() != n) {
    std::printf("batch<%s>: %td results for %td lanes\n", type, std::ptrdiff_t(s.size()), std::ptrdiff_t(n));
    return 1;
  }
  int cases[5] = {};
  for (Eigen::Index i = 0; i < n; ++i) {
    const contact::solution<T> r = rounded ? contact::solve_rounded(u[i], dy[i], phi[i]) : contact::solve_stable(u[i], dy[i], phi[i]);
    ++cases[static_cast<int>(r.which)];
    if (std::bit_cast<bits<T>>(s[i]) != std::bit_cast<bits<T>>(r.s) || which[i] != static_cast<int>(r.which)) {
      std::printf("batch<%s>: lane %td (u %a, dy %a, phi %a): batch %a case %d, scalar %a case %d\n", type,
                  std::ptrdiff_t(i), double(u[i]), double(dy[i]), double(phi[i]), double(s[i]), which[i],
                  double(r.s), static_cast<int>(r.which));
      ++wrong;
    }
  }
  // The first lane is (A.31)'s u=3 dy=1 phi=3: s = 3/4 exactly, case contact.
  if (s[0] != T(0.75) || which[0] != static_cast<int>(contact::contact_case::contact)) {
    std::printf("batch<%s>: lane 0: s %a case %d, expected 0.75 case 3\n", type, double(s[0]), which[0]);
    ++wrong;
  }
  for (int c = 1; c <= 4; ++c)
    if (cases[c] == 0) {
      std::printf("batch<%s>: no lane of case %d: the inputs do not cover every case\n", type, c);
      ++wrong;
    }
  std::printf("%sbatch<%s>: %td lanes (free %d, impact %d, contact %d, release %d, invalid %d): %s\n", rounded ? "rounded_" : "", type,
              std::ptrdiff_t(n), cases[1], cases[2], cases[3], cases[4], cases[0], wrong ? "WRONG" : "ok");
  return wrong;
}

template <class T>
int run(const char* type) {
  std::vector<T> u{3, 0.5, 2, -1, 1, 1}, dy{1, -2, -1, 1, 1, 0.25}, phi{3, 4, 0.5, 1, 1, 5};
  // a deterministic spread over every case (more lanes than a vector block, and a remainder)
  std::uint32_t state = 12345;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return T(int(state >> 8) % 2001 - 1000) / T(250);  // in [-4, 4], multiples of 1/250
  };
  for (int i = 0; i < 1000; ++i) {
    u.push_back(next());
    dy.push_back(next());
    phi.push_back(next() + T(4.01));  // positive
  }
  // on (A.21)'s boundary u = dy (phi - 1) and next to it, where the vector filter defers to the scalar path
  for (T d : {T(0.3), T(1.7), T(3)}) {
    const T p = T(2.5), boundary = d * (p - T(1));
    u.insert(u.end(), {boundary, std::nextafter(boundary, T(0)), std::nextafter(boundary, T(10))});
    dy.insert(dy.end(), {d, d, d});
    phi.insert(phi.end(), {p, p, p});
  }
  // outside the vector window: huge, tiny, subnormal, zero, NaN, infinity, phi < 0
  const T big = std::numeric_limits<T>::max() / T(8), tiny = std::numeric_limits<T>::denorm_min();
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  u.insert(u.end(), {big, tiny, 0, nan, 1, 1, -big});
  dy.insert(dy.end(), {T(1), tiny, 0, T(1), inf, T(1), big});
  phi.insert(phi.end(), {T(2), T(1), T(1), T(1), T(1), T(-1), T(3)});
  return check<T>(type, u, dy, phi, false) + check<T>(type, u, dy, phi, true);
}

}  // namespace

int main() {
  const int wrong = run<double>("double") + run<float>("float");
  return wrong == 0 ? 0 : 1;
}
