// What every plot of the report shares: one colour per algorithm, one marker
// per type, and the Pareto front of (run time, error) points. plots.cpp draws
// with these and nothing else.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace report {

// The colour of an algorithm in every plot, "#rrggbb": a colour of its own for
// each method of all_methods (methods.hpp); shades of batch's for the rows
// "batch[NAME]" of the batch targets (targets.hpp), in the library's order;
// for any other name (a candidate) one of a few further colours, chosen by the name.
std::string colour_of(std::string_view algorithm);

// The gnuplot point type of a registered type in every plot: filled shapes,
// distinct per type (an unknown name gets the open circle).
int marker_of(std::string_view type);
// The shape's name, for captions ("filled circle").
std::string marker_name(std::string_view type);

// One point of a Pareto chart: lower is better on both axes.
struct pareto_point {
  double time = 0;   // ns per solve
  double error = 0;  // ulps; infinity or NaN: the algorithm failed somewhere
};

// The points no other point dominates, as indices into `points`, by
// increasing time (ties by increasing error, then by index). q dominates p
// when q is no slower and no less accurate and better in one of the two. A
// point with an infinite or NaN error, or a time that is not finite, is a
// failure: it is never on the front and dominates nothing. Equal points do
// not dominate each other: both are on the front.
std::vector<std::size_t> pareto_front(const std::vector<pareto_point>& points);

}  // namespace report
