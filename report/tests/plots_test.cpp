// What the plots share (plots.hpp): a colour of its own for every algorithm of
// the registry and every batch target's row, a marker of its own for every
// registered type, and the Pareto front of a small made-up table.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "contact/batch.hpp"
#include "contact/types.hpp"
#include "methods.hpp"
#include "plots.hpp"
#include "targets.hpp"

namespace {

using report::pareto_front;
using report::pareto_point;

bool is_rgb(const std::string& c) {
  if (c.size() != 7 || c[0] != '#') return false;
  for (std::size_t i = 1; i < c.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(c[i]))) return false;
  return true;
}

TEST(plots, each_algorithm_of_the_registry_and_each_batch_target_has_a_colour_of_its_own) {
  std::map<std::string, std::string> owner;  // colour -> algorithm
  std::vector<std::string> names;
  for (report::method m : report::all_methods) names.push_back(report::name_of(m));
  for (const contact::batch_target& t : contact::batch_targets()) {
    names.push_back(report::batch_row_name(t));
    names.push_back(report::target_row_name("rounded_batch", t));
  }
  EXPECT_GE(names.size(), std::size(report::all_methods) + 1);  // at least the scalar target
  for (const auto& name : names) {
    const std::string colour = report::colour_of(name);
    EXPECT_TRUE(is_rgb(colour)) << name << ": " << colour;
    EXPECT_NE(colour, "#ffffff") << name;  // not the background
    const auto [at, fresh] = owner.emplace(colour, name);
    EXPECT_TRUE(fresh) << name << " and " << at->second << " share " << colour;
    EXPECT_EQ(report::colour_of(name), colour) << name;  // the same in every plot
  }
}

TEST(plots, a_name_outside_the_registry_gets_a_colour_too) {
  EXPECT_TRUE(is_rgb(report::colour_of("my_candidate")));
  EXPECT_EQ(report::colour_of("my_candidate"), report::colour_of("my_candidate"));
}

TEST(plots, each_registered_type_has_a_marker_of_its_own) {
  std::set<int> markers;
  for (std::string_view type : contact::type_names) {
    const int marker = report::marker_of(type);
    EXPECT_NE(marker, report::marker_of("no_such_type")) << type;
    EXPECT_TRUE(markers.insert(marker).second) << type << " shares marker " << marker;
    EXPECT_NE(report::marker_name(type), report::marker_name("no_such_type")) << type;
  }
}

TEST(plots, the_front_holds_the_points_no_other_beats_on_both_axes_by_increasing_time) {
  //                                  time  error
  const std::vector<pareto_point> table = {{10, 1},    // 0: front
                                           {5, 4},     // 1: front
                                           {20, 0.5},  // 2: front
                                           {12, 2},    // 3: beaten by 0 on both
                                           {30, 0.5},  // 4: as accurate as 2, slower
                                           {5, 8},     // 5: as fast as 1, less accurate
                                           {40, 0.1}};  // 6: front, the most accurate
  EXPECT_EQ(pareto_front(table), (std::vector<std::size_t>{1, 0, 2, 6}));
}

TEST(plots, equal_points_are_both_on_the_front) {
  const std::vector<pareto_point> table = {{3, 2}, {1, 5}, {3, 2}, {4, 2}};
  EXPECT_EQ(pareto_front(table), (std::vector<std::size_t>{1, 0, 2}));
}

TEST(plots, infinite_and_nan_errors_are_never_on_the_front_and_beat_nothing) {
  const std::vector<pareto_point> table = {{1, INFINITY},  // the fastest, and it failed
                                           {2, NAN},
                                           {5, 3},
                                           {8, 0.5},
                                           {9, INFINITY},
                                           {NAN, 0.1}};  // no time: not a point of the chart
  EXPECT_EQ(pareto_front(table), (std::vector<std::size_t>{2, 3}));
  EXPECT_TRUE(pareto_front({{1, INFINITY}, {2, NAN}}).empty());
  EXPECT_TRUE(pareto_front({}).empty());
  EXPECT_EQ(pareto_front({{7, 0}}), (std::vector<std::size_t>{0}));  // an exact algorithm, 0 ulps
}

}  // namespace
