// The properties contact-check holds a candidate to. Each draws a trial from
// the harness's input families, turns it into the inputs ("probes") the
// candidate solves, and judges the answers against the certified reference.
//
// A trial is a triple and an integer, the property's own parameter (ulp steps
// from a case boundary, a step in u, a power of two): shrinking simplifies both.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "contact/cases.hpp"
#include "contact/detail/float_tools.hpp"
#include "contact/harness/candidate.hpp"
#include "contact/harness/families.hpp"
#include "domain.hpp"
#include "exact.hpp"

namespace check {

using contact::harness::input;
using contact::harness::outcome;
using contact::harness::seeded_source;

template <class T>
struct trial {
  input<T> x;
  long k = 0;
  int family = -1;  // the domain's family that x was drawn from, if any
};

// The candidate's answer and the certified root (absent for invalid input) of one probe.
template <class T>
struct probe_result {
  input<T> x;
  T s;
  int which;
  std::optional<certified> exact;
};

template <class T>
bool valid(const input<T>& x) {
  using std::isfinite;
  return isfinite(x.u) && isfinite(x.dy) && isfinite(x.phi) && !(x.phi < 0);
}

template <class T>
struct property {
  std::string name;
  std::string claim;  // what it says, in one line
  std::function<trial<T>(seeded_source&)> draw;
  std::function<std::vector<input<T>>(const trial<T>&)> probes;
  // why the answers break it, or nothing when they keep it (or when it does not apply)
  std::function<std::optional<std::string>(const trial<T>&, const std::vector<probe_result<T>>&)> verdict;
};

inline std::string number_text(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

// ---- what one answer must satisfy -------------------------------------------------

template <class T>
std::optional<std::string> forward_error(const probe_result<T>& p, double max_ulp) {
  if (!p.exact) return std::nullopt;
  const double error = contact::reference::accepted_ulp_error<T>(p.s, *p.exact, p.x.dy);
  if (error <= max_ulp) return std::nullopt;
  return "|s - s*| = " + number_text(error) + " ulps > " + number_text(max_ulp);
}

template <class T>
std::optional<std::string> residual(const probe_result<T>& p, double max_ulp) {
  using std::isfinite;
  if (!p.exact) return std::nullopt;
  if (std::isnan(p.s)) return "s is NaN for a valid input";
  if (!isfinite(p.s)) {
    if (contact::reference::accepted_ulp_error<T>(p.s, *p.exact, p.x.dy) == 0) return std::nullopt;
    return "s is infinite, but the root does not round to infinity";
  }
  if (root_within(p.s, p.x.u, p.x.dy, p.x.phi, max_ulp)) return std::nullopt;
  return "the exact residual R keeps its sign across s -+ " + number_text(max_ulp) + " ulps: the root is not there";
}

template <class T>
std::optional<std::string> same_case(const probe_result<T>& p) {
  if (!p.exact || p.which == static_cast<int>(p.exact->which)) return std::nullopt;
  return "case " + std::to_string(p.which) + ", the exact case is " + std::to_string(static_cast<int>(p.exact->which));
}

// The side of dy the candidate's own case claims (a wrong or invalid case is the case property's).
template <class T>
std::optional<std::string> complementarity(const probe_result<T>& p) {
  if (!p.exact || p.which < 1 || p.which > 4) return std::nullopt;
  const auto c = static_cast<contact::contact_case>(p.which);
  if (contact::lies_on_its_side(c, p.s, p.x.dy)) return std::nullopt;
  static const char* sides[] = {"", "s >= dy", "s < dy", "s <= dy", "s > dy"};
  return "case " + std::to_string(p.which) + " claims " + sides[p.which] + ", but s is on the other side of dy";
}

template <class T>
std::optional<std::string> rejects_invalid(const probe_result<T>& p) {
  if (p.exact) return std::nullopt;
  if (std::isnan(p.s) && p.which == 0) return std::nullopt;
  return "invalid input must give NaN with case 0";
}

// ---- the properties ---------------------------------------------------------------

template <class T>
std::vector<input<T>> the_trial(const trial<T>& t) {
  return {t.x};
}

template <class T>
std::function<trial<T>(seeded_source&)> any_valid(const domain<T>& d) {
  return [&d](seeded_source& source) {
    const tagged<T> t = d.draw(source);
    return trial<T>{t.x, 0, t.family};
  };
}

// A single-input property from a check of one answer.
template <class T>
property<T> single(std::string name, std::string claim, std::function<trial<T>(seeded_source&)> draw,
                   std::function<std::optional<std::string>(const probe_result<T>&)> check_one) {
  return {std::move(name), std::move(claim), std::move(draw), the_trial<T>,
          [check_one](const trial<T>&, const std::vector<probe_result<T>>& r) { return check_one(r[0]); }};
}

// Two probes either side of a case boundary, `k` ulps from it, must move no
// more than the exact root does between them, give or take max_ulp at each.
template <class T>
property<T> continuity(std::string name, std::string claim, bool contact_release, double max_ulp, const domain<T>& d) {
  auto on_boundary = [contact_release](const T& dy, const T& phi, long steps) {
    return contact_release ? contact::harness::on_contact_release_boundary(dy, phi, steps)
                           : contact::harness::on_free_impact_boundary(dy, phi, steps);
  };
  return {std::move(name), std::move(claim),
          [contact_release, &d](seeded_source& source) {
            return trial<T>{d.draw_for_boundary(source, contact_release), source.integer(-3, 2)};
          },
          [on_boundary](const trial<T>& t) {
            return std::vector<input<T>>{on_boundary(t.x.dy, t.x.phi, t.k), on_boundary(t.x.dy, t.x.phi, t.k + 1)};
          },
          [contact_release, max_ulp](const trial<T>& t, const std::vector<probe_result<T>>& r) -> std::optional<std::string> {
            using std::isfinite;
            if ((t.x.dy > 0) != contact_release || !r[0].exact || !r[1].exact) return std::nullopt;
            if (!isfinite(r[0].s) || !isfinite(r[1].s)) {
              if (forward_error(r[0], max_ulp) || forward_error(r[1], max_ulp)) return "s is not finite at the boundary";
              return std::nullopt;
            }
            const double excess = excess_move(r[1].s, r[0].s, *r[1].exact, *r[0].exact);
            if (std::fabs(excess) <= max_ulp) return std::nullopt;
            return "across neighbouring u the candidate moves " + number_text(excess) +
                   " ulps more than the exact root (allowed " + number_text(max_ulp) + ")";
          }};
}

// The properties, drawing from the domain d (which must outlive them). Inside
// a scene's domain, phi = 0 and invalid input are not drawn: the properties
// about them are the whole range's.
template <class T>
std::vector<property<T>> properties(double max_ulp, const domain<T>& d) {
  using contact::harness::any_finite;
  using contact::harness::any_phi;
  std::vector<property<T>> list;
  list.push_back(single<T>("forward_error", "s lies within max-ulp ulps of the certified root", any_valid<T>(d),
                           [max_ulp](const probe_result<T>& p) { return forward_error(p, max_ulp); }));
  list.push_back(single<T>("residual", "the exact residual of (A.2) changes sign within max-ulp ulps of s",
                           any_valid<T>(d), [max_ulp](const probe_result<T>& p) { return residual(p, max_ulp); }));
  list.push_back(single<T>("case", "the case is the exact case", any_valid<T>(d), same_case<T>));
  list.push_back(single<T>("complementarity", "s lies on the side of dy that its case claims", any_valid<T>(d),
                           complementarity<T>));
  list.push_back(
      continuity<T>("continuity_free_impact", "s is continuous across u = -dy, (A.29)/(A.30)", false, max_ulp, d));
  list.push_back(continuity<T>("continuity_contact_release", "s is continuous across u = dy (phi - 1), (A.31)/(A.32)",
                               true, max_ulp, d));
  list.push_back({"monotonicity", "s is non-increasing in u (within max-ulp ulps at each end)",
                  [&d](seeded_source& source) {
                    const tagged<T> t = d.draw(source);
                    return trial<T>{t.x, 1L << source.integer(0, 24), t.family};
                  },
                  [](const trial<T>& t) {
                    return std::vector<input<T>>{t.x, {contact::detail::ulp_steps(t.x.u, t.k), t.x.dy, t.x.phi}};
                  },
                  [max_ulp](const trial<T>& t, const std::vector<probe_result<T>>& r) -> std::optional<std::string> {
                    using std::isfinite;
                    if (t.k <= 0 || !r[0].exact || !r[1].exact) return std::nullopt;
                    if (!isfinite(r[0].s) || !isfinite(r[1].s)) {
                      if (std::isnan(r[0].s) || std::isnan(r[1].s)) return "s is NaN for a valid input";
                      return r[1].s <= r[0].s ? std::nullopt : std::optional<std::string>("s grows with u");
                    }
                    const double excess = excess_move(r[1].s, r[0].s, *r[1].exact, *r[0].exact);
                    if (r[1].s <= r[0].s || excess <= max_ulp) return std::nullopt;
                    return "s grows by " + number_text(excess) + " ulps more than the exact root as u grows";
                  }});
  list.push_back({"homogeneity", "(u, dy) -> (2^k u, 2^k dy) scales s by 2^k (within max-ulp ulps at each end)",
                  [&d](seeded_source& source) {
                    const long k = d.homogeneity_exponent(source);
                    const tagged<T> t = d.draw(source);
                    return trial<T>{t.x, k, t.family};
                  },
                  [](const trial<T>& t) {
                    using std::ldexp;
                    const int k = static_cast<int>(t.k);
                    return std::vector<input<T>>{t.x, {T(ldexp(t.x.u, k)), T(ldexp(t.x.dy, k)), t.x.phi}};
                  },
                  [max_ulp](const trial<T>& t, const std::vector<probe_result<T>>& r) -> std::optional<std::string> {
                    using std::isfinite;
                    using std::ldexp;
                    using std::fabs;
                    const int k = static_cast<int>(t.k);
                    // only where the scaling is exact, the roots are normal and the answers finite
                    auto normal_or_zero = [](const T& x) { return x == 0 || (isfinite(x) && fabs(x) >= std::numeric_limits<T>::min()); };
                    if (!r[0].exact || !r[1].exact || t.k == 0) return std::nullopt;
                    if (ldexp(r[1].x.u, -k) != t.x.u || ldexp(r[1].x.dy, -k) != t.x.dy) return std::nullopt;
                    const T root0 = T(contact::reference::rounded_to_double(r[0].exact->s));
                    const T root1 = T(contact::reference::rounded_to_double(r[1].exact->s));
                    if (!normal_or_zero(root0) || !normal_or_zero(root1)) return std::nullopt;
                    if (!isfinite(r[0].s) || !isfinite(r[1].s)) return std::nullopt;  // forward_error's concern
                    const double excess = excess_move(r[1].s, r[0].s, *r[1].exact, *r[0].exact, std::ldexp(1.0, k));
                    if (std::fabs(excess) <= max_ulp) return std::nullopt;
                    return "s(2^k u, 2^k dy) - 2^k s(u, dy) is off by " + number_text(excess) + " ulps (k = " +
                           std::to_string(k) + ")";
                  }});
  if (!d.is_whole_range()) return list;
  list.push_back(single<T>("phi_zero", "phi = 0 gives s = -u exactly, with the exact case",
                           [](seeded_source& source) {
                             return trial<T>{{any_finite<T>(source), any_finite<T>(source), T(0)}, 0};
                           },
                           [](const probe_result<T>& p) -> std::optional<std::string> {
                             if (!p.exact) return std::nullopt;
                             if (p.s != -p.x.u) return std::string("s is not -u");
                             return same_case(p);
                           }));
  list.push_back(single<T>("invalid_input", "NaN or infinite input, or phi < 0, gives NaN with case 0",
                           [](seeded_source& source) {
                             input<T> x = contact::harness::any_input<T>(source);
                             const T bad[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                                              -std::numeric_limits<T>::infinity()};
                             T* fields[] = {&x.u, &x.dy, &x.phi};
                             const long which = source.integer(0, 3);
                             if (which == 3) x.phi = -contact::harness::log_uniform<T>(source, -30, 30);
                             else *fields[which] = bad[source.integer(0, 2)];
                             return trial<T>{x, 0};
                           },
                           rejects_invalid<T>));
  return list;
}

// The name of the property that a crash, a hang or an unreadable answer breaks.
inline const std::string returns_name = "returns";
inline const std::string returns_claim = "the candidate returns an answer for every input: no crash, no hang";

}  // namespace check
