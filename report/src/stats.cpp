#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "results.hpp"

namespace report {

int histogram_bin(double ulps) {
  if (std::isnan(ulps)) return 64;
  if (ulps == 0) return 0;
  if (ulps <= 0.5) return 1;
  if (ulps <= 1) return 2;
  for (int k = 3; k <= 62; ++k)
    if (ulps <= std::ldexp(1.0, k - 2)) return k;
  return 63;
}

std::string histogram_label(int bin) {
  if (bin == 0) return "0";
  if (bin == 1) return "(0,0.5]";
  if (bin == 2) return "(0.5,1]";
  if (bin == 63) return ">2^60";
  if (bin == 64) return "NaN";
  return "(2^" + std::to_string(bin - 3) + ",2^" + std::to_string(bin - 2) + "]";
}

summary summarize(std::vector<double> errors) {
  summary s;
  s.count = static_cast<long>(errors.size());
  if (errors.empty()) return s;
  for (double& e : errors)
    if (std::isnan(e)) e = std::numeric_limits<double>::infinity();
  std::sort(errors.begin(), errors.end());
  auto rank = [&](double q) {
    const auto r = static_cast<std::size_t>(std::ceil(q * static_cast<double>(errors.size())));
    return errors[std::max<std::size_t>(r, 1) - 1];
  };
  s.max = errors.back();
  s.p99 = rank(0.99);
  s.median = rank(0.5);
  return s;
}

void count_iterations(const std::vector<int>& counts, accuracy_result& a) {
  if (counts.empty()) return;
  double total = 0;
  long most = 0;
  for (int k : counts) {
    total += k;
    most = std::max<long>(most, k);
  }
  a.iterations_mean = total / static_cast<double>(counts.size());
  a.iterations_max = most;
}

progress::progress(std::string label, long total)
    : label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()), last_(start_) {}

void progress::update(long done) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::seconds(2)) return;
  last_ = now;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "contact-report: %s: %ld/%ld (%.0f%%), %.1f s\n", label_.c_str(), done, total_,
               total_ > 0 ? 100.0 * double(done) / double(total_) : 100.0, seconds);
}

void progress::finish() { last_ = std::chrono::steady_clock::now(); }

}  // namespace report
