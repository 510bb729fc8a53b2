// libFuzzer entry point of the cancellation hunter; the measurement is in
// ../checks.hpp (check_cancellation).
//
// The textbook algorithm's ulp error is fed back to the fuzzer as coverage:
// each (exact case, error bucket) pair calls its own function, so reaching a
// larger error bucket is new coverage and the input is kept in the corpus. The
// buckets are a quarter of a binade wide up to 2^64 ulps, so the fuzzer is
// rewarded for every extra bit of cancellation and climbs.
//
// The inputs are folded into the range where the textbook formulas cannot
// overflow or underflow (see check_cancellation), so every error is
// cancellation. The first time in a process that the error reaches 1e3, 1e6,
// 1e9 or 1e12 ulps, a line is printed, and appended to the file
// named by $CONTACT_FUZZ_EVENTS when set (the campaign runner reads it: in
// -fork mode the children's output is not kept). Times are seconds since
// $CONTACT_FUZZ_T0 (a Unix time, the campaign's start) or else since start-up.
#include <fcntl.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "checks.hpp"
#include "feedback.hpp"

namespace {

double now() {
  timeval tv{};
  gettimeofday(&tv, nullptr);
  return tv.tv_sec + tv.tv_usec * 1e-6;
}

double start_time = 0;
long executions = 0;

void announce(const char* what, const contact::fuzz::hunt_result& r) {
  using contact::fuzz::hex;
  char line[1024];
  std::snprintf(line, sizeof line,
                "==contact-fuzz== hunter: %s after %.3f s (execution %ld of this process, pid %d): "
                "u=%s dy=%s phi=%s case %s, textbook error %.6g ulps\n",
                what, now() - start_time, executions, int(getpid()), hex(r.x.u).c_str(), hex(r.x.dy).c_str(),
                hex(r.x.phi).c_str(), contact::fuzz::case_label(r.which).c_str(), r.ulps);
  std::fputs(line, stderr);
  if (const char* events = std::getenv("CONTACT_FUZZ_EVENTS")) {
    const int fd = open(events, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
      ssize_t ignored = write(fd, line, std::strlen(line));
      (void)ignored;
      close(fd);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* t0 = std::getenv("CONTACT_FUZZ_T0");
  start_time = t0 ? std::atof(t0) : now();
  contact::fuzz::print_stats_at_exit_if_asked();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ++executions;
  const contact::fuzz::hunt_result r = contact::fuzz::check_cancellation(data, size);
  if (r.bucket < 0) return 0;
  contact::fuzz::feedback<3, contact::fuzz::hunter::total>(r.bucket);

  static const double thresholds[] = {1e3, 1e6, 1e9, 1e12};
  static const char* const names[] = {"first error >= 1e3 ulps", "first error >= 1e6 ulps",
                                      "first error >= 1e9 ulps", "first error >= 1e12 ulps"};
  static bool seen[4] = {};
  for (int i = 0; i < 4; ++i)
    if (!seen[i] && r.ulps >= thresholds[i]) {
      seen[i] = true;
      announce(names[i], r);
    }
  // per case: the contact case cancels only where u matches 2 phi dy bit by bit,
  // the release case wherever u >> sqrt(phi) dy; the climb shows in the former
  static const char* const per_case[] = {"free case: first error >= 1e6 ulps", "impact case: first error >= 1e6 ulps",
                                         "contact case: first error >= 1e6 ulps", "release case: first error >= 1e6 ulps"};
  static bool seen_case[4] = {};
  const int c = static_cast<int>(r.which) - 1;
  if (0 <= c && c < 4 && !seen_case[c] && r.ulps >= 1e6) {
    seen_case[c] = true;
    announce(per_case[c], r);
  }
  return 0;
}
