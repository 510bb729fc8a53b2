// The four cases of the one-sided contact step (A.2) and the result type.
#pragma once

#include <limits>
#include <string_view>

namespace contact {

// Which closed form of the appendix's summary applies. The numbering is the
// appendix's own, so `static_cast<int>(c)` is what the CLI prints.
enum class contact_case : int {
  invalid = 0,   // NaN or infinite input, or phi < 0: s is NaN
  free = 1,      // (A.29) dy <= 0, u <= -dy: no contact before or after, s = -u, s >= dy
  impact = 2,    // (A.30) dy <= 0, u >  -dy: contact begins, s < dy
  contact = 3,   // (A.31) dy >  0, u >= dy (phi - 1): contact persists, s <= dy
  release = 4,   // (A.32) dy >  0, u <  dy (phi - 1): contact ends, s > dy
};

constexpr std::string_view equation_of(contact_case c) {
  switch (c) {
    case contact_case::free: return "(A.29)";
    case contact_case::impact: return "(A.30)";
    case contact_case::contact: return "(A.31)";
    case contact_case::release: return "(A.32)";
    case contact_case::invalid: break;
  }
  return "invalid";  // contact_case::invalid, or a number that names no case
}

// The case's name, as the CLI, the report and the fuzzers print it.
constexpr std::string_view name_of(contact_case c) {
  switch (c) {
    case contact_case::free: return "free";
    case contact_case::impact: return "impact";
    case contact_case::contact: return "contact";
    case contact_case::release: return "release";
    case contact_case::invalid: break;
  }
  return "invalid";  // contact_case::invalid, or a number that names no case
}

inline constexpr contact_case valid_cases[] = {contact_case::free, contact_case::impact, contact_case::contact,
                                               contact_case::release};

// Complementarity: the side of dy on which s lies, as each case claims it
// (for release with dy the largest finite T, below).
template <class T>
constexpr bool lies_on_its_side(contact_case c, const T& s, const T& dy) {
  switch (c) {
    case contact_case::free: return s >= dy;
    case contact_case::impact: return s < dy;
    case contact_case::contact: return s <= dy;
    case contact_case::release: return s > dy || (s == dy && dy == (std::numeric_limits<T>::max)());
    case contact_case::invalid: break;
  }
  return false;
}

// Release claims s > dy; with dy the largest finite T no finite value lies
// there, and a root that rounds to the largest T is answered as dy itself,
// which lies_on_its_side admits in that one place (impact, s < dy, cannot
// have dy = -largest: u would exceed it). An implementation that keeps s > dy
// strictly answers +infinity there instead: the checker of other
// implementations accepts that (reference::accepted_ulp_error); the library's
// own algorithms do not give it.
template <class T>
constexpr bool only_infinity_on_its_side(contact_case c, const T& dy) {
  return c == contact_case::release && dy == (std::numeric_limits<T>::max)();
}

template <class T>
struct solution {
  T s;                 // the step s_b = y[n+1] - y[n]
  contact_case which;  // the case that produced it
};

// rounded: the exact root rounded to nearest in T (rounded.hpp); for the types
// of contact::rounded_available only.
enum class algorithm { textbook, stable, newton, rounded };

// The switches on contact_case and algorithm name every enumerator and have no
// default: the build compiles them with -Werror=switch (solver/CMakeLists.txt),
// so a new enumerator without its name does not compile.
constexpr std::string_view name_of(algorithm a) {
  std::string_view name;  // stays empty only for a number that names no algorithm
  switch (a) {
    case algorithm::textbook: name = "textbook"; break;
    case algorithm::stable: name = "stable"; break;
    case algorithm::newton: name = "newton"; break;
    case algorithm::rounded: name = "rounded"; break;
  }
  return name;
}

}  // namespace contact
