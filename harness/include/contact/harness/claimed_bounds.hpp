// The claimed error bounds of the stable path, per branch, as
// proofs/claimed_bounds.txt states them and proofs.gappa holds them to what
// Gappa proves. Every test and fuzzer that asserts a bound reads it here.
//
// Format: one "branch ulps" pair per line; '#' starts a comment; blank lines
// are ignored. Anything else (a third field, a number that is not finite and
// non-negative, an unknown or repeated branch) is an error naming the file and
// line, and so is a file without every branch.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/cases.hpp"

namespace contact::harness {

// The branch of solve_stable that an input of case `which` takes, named as the
// Gappa files proofs/gappa/stable_<branch>.g: the case's name, and for (A.32)
// the sign of u, which picks the rationalised root or the plain one.
inline std::string branch_of(contact_case which, bool u_positive) {
  if (which != contact_case::release) return std::string(name_of(which));
  return std::string(name_of(which)) + (u_positive ? "_u_positive" : "_u_nonpositive");
}

inline const std::vector<std::string>& stable_branches() {
  static const std::vector<std::string> names = {
      branch_of(contact_case::free, false), branch_of(contact_case::impact, false),
      branch_of(contact_case::contact, false), branch_of(contact_case::release, true),
      branch_of(contact_case::release, false)};
  return names;
}

class claimed_bounds {
 public:
  // Throws std::runtime_error("FILE:LINE: reason").
  static claimed_bounds read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ":0: cannot read the claimed bounds");
    return parse(in, path);
  }

  static claimed_bounds parse(std::istream& in, const std::string& path) {
    claimed_bounds result;
    std::string line;
    for (long number = 1; std::getline(in, line); ++number) {
      auto fail = [&](const std::string& reason) { throw std::runtime_error(path + ":" + std::to_string(number) + ": " + reason); };
      std::istringstream fields(line.substr(0, line.find('#')));
      std::string branch, ulps, extra;
      if (!(fields >> branch)) continue;
      if (!(fields >> ulps)) fail("'" + branch + "' has no bound");
      if (fields >> extra) fail("expected 'branch ulps', found a third field '" + extra + "'");
      const auto& known = stable_branches();
      if (std::find(known.begin(), known.end(), branch) == known.end()) fail("unknown branch '" + branch + "'");
      if (result.per_branch_.count(branch)) fail("branch '" + branch + "' is given twice");
      char* end = nullptr;
      const double value = std::strtod(ulps.c_str(), &end);
      if (end == ulps.c_str() || *end != '\0' || !std::isfinite(value) || value < 0)
        fail("'" + ulps + "' is not a finite, non-negative number of ulps");
      result.per_branch_[branch] = value;
    }
    for (const auto& branch : stable_branches())
      if (!result.per_branch_.count(branch)) throw std::runtime_error(path + ": no bound for branch '" + branch + "'");
    return result;
  }

  double of_branch(const std::string& branch) const { return per_branch_.at(branch); }
  double for_case(contact_case which, bool u_positive) const { return of_branch(branch_of(which, u_positive)); }
  // The largest bound over all branches: what cross-case checks use.
  double largest() const {
    double most = 0;
    for (const auto& [branch, bound] : per_branch_) most = std::max(most, bound);
    return most;
  }
  const std::map<std::string, double>& per_branch() const { return per_branch_; }

 private:
  std::map<std::string, double> per_branch_;
};

#ifdef CONTACT_CLAIMED_BOUNDS
// The bounds of the source tree's proofs/claimed_bounds.txt, read once.
inline const claimed_bounds& project_bounds() {
  static const claimed_bounds bounds = claimed_bounds::read(CONTACT_CLAIMED_BOUNDS);
  return bounds;
}
#endif

}  // namespace contact::harness
