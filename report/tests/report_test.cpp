// The report tool end to end: it runs a small scene with --raw, and every
// figure of report.md's tables and of results.csv must be what the raw
// measurements give; the raw measurements themselves are checked against an
// independent solve and the certified reference. Wherever batch is timed, each
// batch target the CPU supports is timed alone (batch[NAME]), and the header
// names the CPU, the targets and the one dispatch chose. A bad scene file
// stops the tool with "FILE:LINE: reason"; a scene that asks for double alone
// gets no other type.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "contact/batch.hpp"
#include "contact/reference.hpp"
#include "contact/solve.hpp"
#include "iterative_peers.hpp"
#include "methods.hpp"
#include "output.hpp"
#include "peers.hpp"
#include "plots.hpp"
#include "results.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const fs::path work = CONTACT_REPORT_TEST_DIR;

const char* small_scene = R"([scene]
name = "small"
title = "Small scene for the tests"
seed = 11
plots = ["headline", "pareto", "histograms", "energy"]

[[family]]
name = "tanpura"
generator = "physical"
samples = 300
mass = [1e-4, 1e-2]
spring = [1.0, 1e4]
barrier_stiffness = [1e5, 1e13]
displacement = { log10 = [-7, -3], sign = "both" }
compression = { log10 = [-7, -3], sign = "both" }
velocity = { log10 = [-2.5, 1.5], sign = "both" }

[[family]]
name = "wild"
generator = "box"
samples = 200
u = { log2 = [-1074, 1023], sign = "both" }
dy = { log2 = [-1074, 1023], sign = "both" }
phi = { log2 = [-1074, 1023] }

[[family]]
name = "merged"
generator = "box"
samples = 40
u = { log2 = [0, 0.5], sign = "positive" }
dy = { log2 = [-0.5, -0.1], sign = "negative" }
phi = { log2 = [112, 130] }

[[family]]
name = "release_cancel"
generator = "release_cancellation"
samples = 200
dy = { log10 = [-7, -3] }
phi = { log10 = [8, 16] }
ratio = { log10 = [0, 6] }

[[run]]
types = ["double"]
algorithms = ["textbook", "stable", "newton", "rounded", "batch", "boost_quadratic", "eigen_companion",
              "boost_newton", "boost_halley", "boost_toms748", "practitioner_newton"]
checks = ["accuracy", "timing"]
timing_inputs = 256
repetitions = 3
min_time = 0.005

[[run]]
types = ["float"]
algorithms = ["stable", "newton", "rounded", "boost_newton", "boost_halley", "boost_toms748", "practitioner_newton"]
checks = ["accuracy", "timing"]
timing_inputs = 256
repetitions = 2
min_time = 0.005

[[run]]
types = ["long_double", "cpp_bin_float_50"]
algorithms = ["textbook", "stable", "boost_newton", "boost_halley", "boost_toms748", "practitioner_newton"]
checks = ["accuracy", "timing"]
samples = 40
timing_inputs = 32
repetitions = 2
min_time = 0.005

[[run]]
types = ["long_double"]
algorithms = ["rounded"]
checks = ["accuracy", "timing"]
samples = 40
timing_inputs = 32
repetitions = 2
min_time = 0.005

[[run]]
types = ["double"]
algorithms = ["textbook", "stable", "boost_halley", "practitioner_newton"]
checks = ["energy"]

[oscillator]
duration = 0.02
plot_points = 50

[throughput]
lanes = 8192
cache_lanes = 1024
repetitions = 3
min_time = 0.005
)";

struct command_result {
  int status;
  std::string err;
};

command_result run_tool(const std::string& arguments, const std::string& tag) {
  const fs::path err = work / (tag + ".stderr");
  const std::string command = std::string(CONTACT_REPORT_EXE) + " " + arguments + " > /dev/null 2> '" + err.string() + "'";
  const int raw = std::system(command.c_str());
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

double value_of(const json& j) {  // numbers, or "inf"/"nan" strings
  if (j.is_number()) return j.get<double>();
  if (!j.is_string()) {
    ADD_FAILURE() << "not a figure: " << j.dump();
    return NAN;
  }
  const std::string s = j.get<std::string>();
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  return NAN;
}

std::vector<std::string> split(const std::string& line, char by) {
  std::vector<std::string> out;
  std::string cell;
  std::stringstream in(line);
  while (std::getline(in, cell, by)) out.push_back(cell);
  return out;
}

std::string trim(std::string s) {
  while (!s.empty() && s.front() == ' ') s.erase(s.begin());
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// The rows of the markdown table whose header row starts with `header`.
std::vector<std::vector<std::string>> table(const std::string& markdown, const std::string& header) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream in(markdown);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside) {
      if (line.rfind(header, 0) == 0) {
        inside = true;
        std::getline(in, line);  // |---|
      }
      continue;
    }
    if (line.empty() || line[0] != '|') break;
    auto cells = split(line.substr(1), '|');
    for (auto& c : cells) c = trim(c);
    rows.push_back(cells);
  }
  return rows;
}

struct raw_sample {
  std::string family;
  double u, dy, phi;
  std::string s;
  int which;
  double ulps;
  int iterations;  // -1: the method does not iterate (the column is empty)
};

std::vector<raw_sample> read_raw(const fs::path& p) {
  std::vector<raw_sample> rows;
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "index,family,u,dy,phi,s,case,ulp_error,iterations");
  while (std::getline(in, line)) {
    auto c = split(line, ',');
    if (c.size() == 8 && line.back() == ',') c.emplace_back();  // getline drops an empty last cell
    EXPECT_EQ(c.size(), 9u) << line;
    if (c.size() != 9) continue;
    rows.push_back({c[1], std::strtod(c[2].c_str(), nullptr), std::strtod(c[3].c_str(), nullptr),
                    std::strtod(c[4].c_str(), nullptr), c[5], std::stoi(c[6]), std::strtod(c[7].c_str(), nullptr),
                    c[8].empty() ? -1 : std::stoi(c[8])});
  }
  return rows;
}

// The (type, algorithm) pairs that the small scene measures accuracy and timing of, as "type/algorithm".
const std::vector<std::string> iterative_peers = {"boost_newton", "boost_halley", "boost_toms748",
                                                  "practitioner_newton"};

std::set<std::string> measured_in_small_scene() {
  std::set<std::string> out;
  for (const char* algorithm : {"textbook", "stable", "newton", "rounded", "batch", "boost_quadratic", "eigen_companion"})
    out.insert(std::string("double/") + algorithm);
  for (const char* type : {"float", "long_double"}) out.insert(std::string(type) + "/rounded");
  for (const auto& peer : iterative_peers)
    for (const char* type : {"double", "float", "long_double", "cpp_bin_float_50"}) out.insert(type + ("/" + peer));
  for (const char* type : {"float", "long_double", "cpp_bin_float_50"}) out.insert(std::string(type) + "/stable");
  for (const char* type : {"long_double", "cpp_bin_float_50"}) out.insert(std::string(type) + "/textbook");
  out.insert("float/newton");
  return out;
}

// The rows that time each batch target this CPU supports alone, "batch[NAME]",
// in the library's order.
std::vector<std::string> target_rows() {
  std::vector<std::string> rows;
  for (const contact::batch_target& t : contact::batch_targets())
    if (t.supported) rows.push_back(std::string("batch[") + t.name + "]");
  return rows;
}

// The (type, algorithm) pairs the small scene times: those it measures and,
// beside batch in double, each supported target.
std::set<std::string> timed_in_small_scene() {
  std::set<std::string> out = measured_in_small_scene();
  for (const auto& row : target_rows()) out.insert("double/" + row);
  return out;
}

// results.csv as "check/type/algorithm/metric" -> value.
std::map<std::string, std::string> csv_figures(const fs::path& p) {
  std::ifstream csv(p);
  std::map<std::string, std::string> figures;
  for (std::string line; std::getline(csv, line);) {
    const auto c = split(line, ',');
    if (c.size() == 6) figures[c[1] + "/" + c[2] + "/" + c[3] + "/" + c[4]] = c[5];
  }
  return figures;
}

// The model name of /proc/cpuinfo, or "unknown".
std::string cpu_model_name() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
      return trim(line.substr(line.find(':') + 1));
  return "unknown";
}

bool is_iterative(const std::string& algorithm) {
  const auto m = report::method_named(algorithm);
  return m && report::iterative(*m);
}

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

class tool : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(work);
    fs::create_directories(work);
    std::ofstream(work / "small.toml") << small_scene;
    const auto r = run_tool("--scene '" + (work / "small.toml").string() + "' --out '" + (work / "out").string() + "' --raw",
                            "small");
    status_ = r.status;
    stderr_ = r.err;
    if (status_ == 0) {
      results_ = json::parse(read(work / "out" / "results.json"));
      markdown_ = read(work / "out" / "report.md");
    }
  }
  static int status_;
  static std::string stderr_, markdown_;
  static json results_;

  const json& scene() const { return results_["scenes"][0]; }
};
int tool::status_ = -1;
std::string tool::stderr_, tool::markdown_;
json tool::results_;

TEST_F(tool, runs_and_writes_every_output) {
  ASSERT_EQ(status_, 0) << stderr_;
  for (const char* name : {"report.md", "results.csv", "results.json", "plots/plots.gp", "plots/pareto_small.svg",
                           "plots/pareto_small.png", "plots/hist_double.svg", "plots/hist_double_textbook.dat",
                           "plots/energy_small_double.png", "plots/headline.svg", "plots/headline.png"})
    EXPECT_TRUE(fs::exists(work / "out" / name)) << name;
  EXPECT_NE(stderr_.find("contact-report: scene small"), std::string::npos);  // progress on stderr
  // a PNG is a PNG
  const std::string png = read(work / "out" / "plots" / "pareto_small.png");
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST_F(tool, only_what_the_scene_names_is_measured) {
  ASSERT_EQ(status_, 0) << stderr_;
  std::set<std::string> seen, timed;
  for (const auto& a : scene()["accuracy"]) seen.insert(a["type"].get<std::string>() + "/" + a["algorithm"].get<std::string>());
  for (const auto& t : scene()["timing"]) timed.insert(t["type"].get<std::string>() + "/" + t["algorithm"].get<std::string>());
  const std::set<std::string> expected = measured_in_small_scene();
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(timed, timed_in_small_scene());  // the batch[NAME] rows are timed only
  EXPECT_EQ(scene()["timing"].size(), timed_in_small_scene().size());
  EXPECT_EQ(scene()["energy"].size(), 4u);
}

// Every accuracy figure is what the raw samples give, and the raw samples are
// what an independent solve and the certified reference give.
TEST_F(tool, accuracy_figures_come_from_the_raw_samples) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto rows = table(markdown_, "| type | algorithm | samples |");
  ASSERT_EQ(rows.size(), timed_in_small_scene().size());
  for (const auto& a : scene()["accuracy"]) {
    const std::string type = a["type"], algorithm = a["algorithm"];
    SCOPED_TRACE(type + " " + algorithm);
    const auto raw = read_raw(work / "out" / "raw" / "small" / ("accuracy_" + type + "_" + algorithm + ".csv"));
    ASSERT_EQ(static_cast<long>(raw.size()), a["samples"].get<long>());
    std::vector<double> errors;
    std::vector<int> iterations;
    long nan = 0, inf = 0, violations = 0;
    std::map<std::string, double> family_max;
    for (const auto& r : raw) {
      errors.push_back(r.ulps);
      if (r.iterations >= 0) iterations.push_back(r.iterations);
      const double s = std::strtod(r.s.c_str(), nullptr);
      // wider types print decimals that may lie beyond double's range: read inf and nan as text
      nan += r.s.find("nan") != std::string::npos;
      inf += r.s.find("inf") != std::string::npos;
      const bool weakly = algorithm == "rounded" && s == r.dy;  // rounded promises complementarity weakly
      if (type == "double" && !contact::lies_on_its_side(static_cast<contact::contact_case>(r.which), s, r.dy) && !weakly)
        ++violations;
      double& worst = family_max[r.family];
      worst = std::max(worst, std::isnan(r.ulps) ? INFINITY : r.ulps);
    }
    const report::summary summary = report::summarize(errors);
    EXPECT_TRUE(same(summary.max, value_of(a["max_ulp"])));
    EXPECT_TRUE(same(summary.p99, value_of(a["p99_ulp"])));
    EXPECT_TRUE(same(summary.median, value_of(a["median_ulp"])));
    EXPECT_EQ(nan, a["nan"].get<long>());
    EXPECT_EQ(inf, a["inf"].get<long>());
    if (type == "double") {
      EXPECT_EQ(violations, a["complementarity_violations"].get<long>());
    }
    for (const auto& [family, worst] : family_max) EXPECT_TRUE(same(worst, value_of(a["family_max_ulp"][family])));
    // the iteration counts: one per sample for an iterative method, none otherwise
    report::accuracy_result counted;
    if (is_iterative(algorithm)) {
      ASSERT_EQ(iterations.size(), raw.size());
      report::count_iterations(iterations, counted);
      ASSERT_TRUE(a["iterations"].is_object()) << a.dump();
      EXPECT_DOUBLE_EQ(value_of(a["iterations"]["mean"]), counted.iterations_mean);
      EXPECT_EQ(a["iterations"]["max"].get<long>(), counted.iterations_max);
    } else {
      EXPECT_TRUE(iterations.empty());
      EXPECT_TRUE(a["iterations"].is_null());
    }

    // The raw s is what the named algorithm gives, and its error is what the reference says.
    if (type == "double") {
      const auto method = report::method_named(algorithm);
      ASSERT_TRUE(method.has_value());
      for (std::size_t i = 0; i < raw.size(); i += 7) {
        const auto& r = raw[i];
        contact::solution<double> mine{};
        int my_iterations = -1;
        const auto iterated = [&](const auto& result) {
          my_iterations = result.iterations;
          return result.answer;
        };
        switch (*method) {
          case report::method::textbook: mine = contact::solve_textbook(r.u, r.dy, r.phi); break;
          case report::method::rounded: mine = contact::solve_rounded(r.u, r.dy, r.phi); break;
          case report::method::newton: mine = iterated(contact::newton_iterate(r.u, r.dy, r.phi)); break;
          case report::method::boost_quadratic: mine = report::peers::solve_boost(r.u, r.dy, r.phi); break;
          case report::method::eigen_companion: mine = report::peers::solve_eigen(r.u, r.dy, r.phi); break;
          case report::method::boost_newton: mine = iterated(report::peers::solve_boost_newton(r.u, r.dy, r.phi)); break;
          case report::method::boost_halley: mine = iterated(report::peers::solve_boost_halley(r.u, r.dy, r.phi)); break;
          case report::method::boost_toms748:
            mine = iterated(report::peers::solve_boost_toms748(r.u, r.dy, r.phi));
            break;
          case report::method::practitioner_newton:
            mine = iterated(report::peers::solve_practitioner_newton(r.u, r.dy, r.phi));
            break;
          default: mine = contact::solve_stable(r.u, r.dy, r.phi); break;  // batch equals stable bit for bit
        }
        const double s = std::strtod(r.s.c_str(), nullptr);
        EXPECT_TRUE(same(mine.s, s)) << std::hexfloat << r.u << " " << r.dy << " " << r.phi;
        EXPECT_EQ(static_cast<int>(mine.which), r.which);
        EXPECT_EQ(my_iterations, r.iterations);
        if (*method == report::method::newton)  // the count is of the answer that contact::solve gives
          EXPECT_TRUE(same(contact::solve_newton(r.u, r.dy, r.phi).s, s));
        const auto exact = contact::reference::solve<double>(r.u, r.dy, r.phi);
        EXPECT_TRUE(same(contact::reference::ulp_error<double>(s, exact), r.ulps)) << std::hexfloat << r.u;
      }
    }

    // The table row of report.md shows these figures.
    bool found = false;
    for (const auto& row : rows) {
      if (row[0] != type || row[1] != algorithm) continue;
      found = true;
      EXPECT_EQ(row[2], std::to_string(a["samples"].get<long>()));
      EXPECT_EQ(row[3], report::format_ulp(summary.max));
      EXPECT_EQ(row[4], report::format_ulp(summary.p99));
      EXPECT_EQ(row[5], report::format_ulp(summary.median));
      const bool wide = row.size() == 16;  // with the "max ulp as double" column
      const std::size_t k = wide ? 7 : 6;
      EXPECT_EQ(row[k], std::to_string(nan));
      EXPECT_EQ(row[k + 1].substr(0, row[k + 1].find(' ')), std::to_string(inf));
      EXPECT_EQ(row[k + 2], std::to_string(a["complementarity_violations"].get<long>()));
      EXPECT_EQ(row[k + 3], std::to_string(a["wrong_case"].get<long>()));
      EXPECT_EQ(row[k + 4], is_iterative(algorithm) ? report::format_iterations(counted) : "—");
      report::accuracy_result slow;
      if (algorithm == "rounded") slow.slow_path_share = value_of(a["slow_path_share"]);
      EXPECT_EQ(row[k + 5], report::format_slow_path(slow));
    }
    EXPECT_TRUE(found);
  }
}

TEST_F(tool, timing_figures_come_from_the_repetitions) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto rows = table(markdown_, "| type | algorithm | samples |");
  for (const auto& t : scene()["timing"]) {
    const std::string type = t["type"], algorithm = t["algorithm"];
    SCOPED_TRACE(type + " " + algorithm);
    std::vector<double> reps;
    for (const auto& x : t["ns_repetitions"]) reps.push_back(value_of(x));
    // the raw file holds the same repetitions
    std::ifstream raw(work / "out" / "raw" / "small" / ("timing_" + type + "_" + algorithm + ".csv"));
    std::string line;
    std::getline(raw, line);
    std::vector<double> from_file;
    while (std::getline(raw, line)) from_file.push_back(std::strtod(split(line, ',')[1].c_str(), nullptr));
    EXPECT_EQ(from_file, reps);
    ASSERT_GE(reps.size(), 2u);
    for (double x : reps) EXPECT_GT(x, 0);
    std::vector<double> sorted = reps;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    EXPECT_DOUBLE_EQ(median, value_of(t["ns_median"]));
    EXPECT_DOUBLE_EQ(sorted.front(), value_of(t["ns_min"]));
    EXPECT_DOUBLE_EQ(sorted.back(), value_of(t["ns_max"]));
    for (const auto& row : rows)
      if (row[0] == type && row[1] == algorithm) {
        const std::size_t k = row.size() - 3;
        EXPECT_EQ(row[k], report::format_ns(median));
        EXPECT_EQ(row[k + 1], report::format_ns(sorted.front()) + "–" + report::format_ns(sorted.back()));
        EXPECT_EQ(row[k + 2], std::to_string(t["inputs"].get<long>()) + " × " + std::to_string(n));
      }
  }
}

TEST_F(tool, headline_csv_throughput_and_energy_agree_with_the_measurements) {
  ASSERT_EQ(status_, 0) << stderr_;
  // headline: max ulp in double per algorithm
  const auto head = table(markdown_, "| algorithm | small | worst |");
  ASSERT_EQ(head.size(), 11u);  // every double algorithm of the small scene, rounded included
  for (const auto& row : head)
    for (const auto& a : scene()["accuracy"])
      if (a["type"] == "double" && a["algorithm"] == row[0]) {
        EXPECT_EQ(row[1], report::format_ulp(value_of(a["max_ulp"])));
        EXPECT_EQ(row[2], "**" + report::format_ulp(value_of(a["max_ulp"])) + "**");
      }
  // results.csv holds the same numbers as results.json
  std::ifstream csv(work / "out" / "results.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "scene,check,type,algorithm,metric,value");
  std::map<std::string, double> figures;
  while (std::getline(csv, line)) {
    const auto c = split(line, ',');
    ASSERT_EQ(c.size(), 6u) << line;
    figures[c[1] + "/" + c[2] + "/" + c[3] + "/" + c[4]] = std::strtod(c[5].c_str(), nullptr);
  }
  for (const auto& a : scene()["accuracy"])
    EXPECT_TRUE(same(figures.at("accuracy/" + a["type"].get<std::string>() + "/" + a["algorithm"].get<std::string>() + "/max_ulp"),
                     value_of(a["max_ulp"])));
  for (const auto& t : scene()["timing"])
    EXPECT_EQ(figures.at("timing/" + t["type"].get<std::string>() + "/" + t["algorithm"].get<std::string>() + "/ns_median"),
              value_of(t["ns_median"]));
  // throughput: medians of the repetitions, and the headline ratios from them
  std::map<std::string, double> streamed;
  for (const auto& t : scene()["throughput"]) {
    std::vector<double> reps;
    for (const auto& x : t["ns_repetitions"]) reps.push_back(value_of(x));
    std::sort(reps.begin(), reps.end());
    ASSERT_EQ(reps.size(), 3u);
    EXPECT_DOUBLE_EQ(reps[1], value_of(t["ns_median"]));
    if (t["lanes"] == 8192) streamed[t["path"]] = reps[1];
  }
  ASSERT_EQ(streamed.size(), 5u + target_rows().size());  // the floors, batch, stable, textbook, each target
  const auto& batch = results_["headline"]["batch"]["streamed"];
  EXPECT_DOUBLE_EQ(value_of(batch["speedup_over_textbook"]), streamed["textbook"] / streamed["batch"]);
  EXPECT_DOUBLE_EQ(value_of(batch["batch_to_floor"]), streamed["batch"] / streamed["floor"]);
  EXPECT_DOUBLE_EQ(value_of(batch["division_floor_speedup_over_textbook"]), streamed["textbook"] / streamed["division floor"]);
  // energy: the maximum is the maximum of the plotted series; the table shows it
  const auto energy_rows = table(markdown_, "| type | algorithm | steps in contact |");
  ASSERT_EQ(energy_rows.size(), 4u);
  for (const auto& e : scene()["energy"]) {
    double worst = 0;
    for (const auto& x : e["plot_max_relative_error"]) worst = std::max(worst, value_of(x));
    EXPECT_EQ(worst, value_of(e["max_relative_error"]));
    EXPECT_EQ(e["steps"].get<long>(), 882);
    for (const auto& row : energy_rows)
      if (row[0] == e["type"] && row[1] == e["algorithm"]) {
        EXPECT_EQ(row[3], report::format_energy(worst));
      }
  }
}

// results.csv has the iteration counts of exactly the iterative methods, as results.json has them.
TEST_F(tool, iteration_counts_appear_in_csv_and_json) {
  ASSERT_EQ(status_, 0) << stderr_;
  std::ifstream csv(work / "out" / "results.csv");
  std::string line;
  std::map<std::string, std::string> figures;
  while (std::getline(csv, line)) {
    const auto c = split(line, ',');
    if (c.size() == 6) figures[c[1] + "/" + c[2] + "/" + c[3] + "/" + c[4]] = c[5];
  }
  long iterating = 0;
  for (const auto& a : scene()["accuracy"]) {
    const std::string key = "accuracy/" + a["type"].get<std::string>() + "/" + a["algorithm"].get<std::string>();
    SCOPED_TRACE(key);
    if (!is_iterative(a["algorithm"])) {
      EXPECT_EQ(figures.count(key + "/iterations_mean"), 0u);
      EXPECT_EQ(figures.count(key + "/iterations_max"), 0u);
      continue;
    }
    ++iterating;
    ASSERT_EQ(figures.count(key + "/iterations_mean"), 1u);
    EXPECT_EQ(std::strtod(figures[key + "/iterations_mean"].c_str(), nullptr), value_of(a["iterations"]["mean"]));
    EXPECT_EQ(figures[key + "/iterations_max"], std::to_string(a["iterations"]["max"].get<long>()));
  }
  EXPECT_EQ(iterating, 1 + 4 * 4 + 1);  // newton in double and float, each peer in four types
  // the headline has the double counts of every iterative method
  const auto& headline = results_["headline"]["double_iterations"];
  for (const char* algorithm : {"newton", "boost_newton", "boost_halley", "boost_toms748", "practitioner_newton"})
    EXPECT_TRUE(headline[algorithm]["small"].is_object()) << algorithm;
  EXPECT_NE(markdown_.find("### Iterations in double: mean / max"), std::string::npos);
}

// The rounded rows: every result correctly rounded (at most half an ulp, the
// exact case), complementarity weakly, and the share of samples that took the
// exact decision in csv and json, recounted here from the raw inputs; the
// other methods have no such share.
TEST_F(tool, the_rounded_rows_are_correctly_rounded_and_give_their_slow_path_share) {
  ASSERT_EQ(status_, 0) << stderr_;
  std::ifstream csv(work / "out" / "results.csv");
  std::map<std::string, std::string> figures;
  for (std::string line; std::getline(csv, line);) {
    const auto c = split(line, ',');
    if (c.size() == 6) figures[c[1] + "/" + c[2] + "/" + c[3] + "/" + c[4]] = c[5];
  }
  long rounded_rows = 0;
  for (const auto& a : scene()["accuracy"]) {
    const std::string type = a["type"], algorithm = a["algorithm"];
    const std::string key = "accuracy/" + type + "/" + algorithm + "/slow_path_share";
    SCOPED_TRACE(key);
    if (algorithm != "rounded") {
      EXPECT_TRUE(a["slow_path_share"].is_null());
      EXPECT_EQ(figures.count(key), 0u);
      continue;
    }
    ++rounded_rows;
    EXPECT_LE(value_of(a["max_ulp"]), 0.5);
    EXPECT_EQ(a["wrong_case"].get<long>(), 0);
    EXPECT_EQ(a["complementarity_violations"].get<long>(), 0);
    const double share = value_of(a["slow_path_share"]);
    ASSERT_EQ(figures.count(key), 1u);
    EXPECT_EQ(std::strtod(figures[key].c_str(), nullptr), share);
    const auto raw = read_raw(work / "out" / "raw" / "small" / ("accuracy_" + type + "_" + algorithm + ".csv"));
    auto recounted_share = [&raw]<class T>(T) {
      long slow = 0;
      for (const auto& r : raw) slow += contact::detail::solve_rounded_traced<T>(r.u, r.dy, r.phi).exact_decision;
      return double(slow) / double(raw.size());
    };
    if (type == "double") {
      EXPECT_EQ(share, recounted_share(0.0));
      long beyond_window = 0;
      for (const auto& r : raw) beyond_window += !contact::detail::inside_plain_window(r.u, r.dy, r.phi);
      EXPECT_GT(beyond_window, 0);  // the wild family reaches beyond double's own step, to long double's
    }
    if (type == "long_double") {
      EXPECT_EQ(share, recounted_share(0.0L));
      // (A.30) with its roots nearly merged, in the merged family: the impact margin is too
      // wide for long double's step, the root too far from dy for the value beside it, and
      // no wider step exists
      EXPECT_GT(share, 0);
    }
  }
  EXPECT_EQ(rounded_rows, 3);
}

// On the physical family every iterative peer gives a finite error in every
// type it ran in, and the Pareto chart plots it.
TEST_F(tool, the_iterative_peers_give_finite_errors_on_physical_inputs) {
  ASSERT_EQ(status_, 0) << stderr_;
  const std::string pareto = read(work / "out" / "plots" / "pareto_small.dat");
  for (const auto& a : scene()["accuracy"]) {
    const std::string type = a["type"], algorithm = a["algorithm"];
    if (std::find(iterative_peers.begin(), iterative_peers.end(), algorithm) == iterative_peers.end()) continue;
    SCOPED_TRACE(type + " " + algorithm);
    const double tanpura = value_of(a["family_max_ulp"]["tanpura"]);
    EXPECT_TRUE(std::isfinite(tanpura)) << tanpura;
    EXPECT_GE(value_of(a["iterations"]["mean"]), 1);
    // halley_iterate's search beyond its bracket can run past max_iter (peers_test.cpp)
    if (algorithm != "boost_halley")
      EXPECT_LE(a["iterations"]["max"].get<long>(), algorithm == "practitioner_newton" ? 20 : 50);
    EXPECT_NE(pareto.find("# " + type + " " + algorithm + "\n"), std::string::npos);
  }
}

// ---- the pictures: the headline figure, the Pareto panels, the histograms ----

// The blocks of a Pareto data file: "type algorithm" -> its data line's
// columns, and "front TYPE" -> the front's algorithms by increasing time.
struct pareto_data {
  std::map<std::string, std::vector<std::string>> points;
  std::map<std::string, std::vector<std::string>> fronts;
};

pareto_data read_pareto(const fs::path& p) {
  pareto_data out;
  std::ifstream in(p);
  std::string line, block;
  std::getline(in, line);  // what the columns are
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.rfind("# ", 0) == 0) {
      block = line.substr(2);
      continue;
    }
    const auto cells = split(line, ' ');
    if (block.rfind("front ", 0) == 0) {
      EXPECT_EQ(cells.size(), 3u) << line;
      if (cells.size() == 3) out.fronts[block.substr(6)].push_back(cells[2]);
    } else {
      out.points[block] = cells;
    }
  }
  return out;
}

// The algorithms that no other beats on both time and error, by increasing
// time: failures (an infinite or NaN error) are never on it and beat nothing.
std::vector<std::string> front_of(const std::vector<std::tuple<std::string, double, double>>& points) {
  std::vector<std::tuple<double, double, std::string>> front;
  for (const auto& [name, time, error] : points) {
    if (!std::isfinite(error)) continue;
    bool beaten = false;
    for (const auto& [other, t, e] : points)
      beaten = beaten || (std::isfinite(e) && t <= time && e <= error && (t < time || e < error));
    if (!beaten) front.emplace_back(time, error, name);
  }
  std::sort(front.begin(), front.end());
  std::vector<std::string> names;
  for (const auto& f : front) names.push_back(std::get<2>(f));
  return names;
}

// (algorithm, ns median, max ulp) of the scene's rows in `type` that have both a timing and an accuracy.
std::vector<std::tuple<std::string, double, double>> timed_and_measured(const json& scene, const std::string& type) {
  std::vector<std::tuple<std::string, double, double>> out;
  for (const auto& a : scene["accuracy"])
    for (const auto& t : scene["timing"])
      if (a["type"] == type && t["type"] == type && a["algorithm"] == t["algorithm"]) {
        const double error = value_of(a["max_ulp"]);
        out.emplace_back(a["algorithm"].get<std::string>(), value_of(t["ns_median"]), std::isnan(error) ? INFINITY : error);
      }
  return out;
}

TEST_F(tool, the_headline_figure_comes_first_in_report_md) {
  ASSERT_EQ(status_, 0) << stderr_;
  const std::string png = read(work / "out" / "plots" / "headline.png");
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto figure = markdown_.find("](plots/headline.png)");
  ASSERT_NE(figure, std::string::npos);
  EXPECT_LT(figure, markdown_.find("## Headline figures"));
  EXPECT_EQ(markdown_.find("!["), markdown_.rfind("![", figure));  // the first picture
  // every algorithm timed in double, and none of the batch[NAME] rows, which have no error of their own
  const auto data = read_pareto(work / "out" / "plots" / "headline.dat");
  for (const auto& [algorithm, time, error] : timed_and_measured(scene(), "double"))
    EXPECT_EQ(data.points.count("double " + algorithm), 1u) << algorithm;
  for (const auto& row : target_rows()) EXPECT_EQ(data.points.count("double " + row), 0u) << row;
  EXPECT_EQ(data.points.size(), timed_and_measured(scene(), "double").size());
}

TEST_F(tool, the_fronts_drawn_join_the_points_no_other_of_their_type_beats) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto pareto = read_pareto(work / "out" / "plots" / "pareto_small.dat");
  for (const char* type : {"double", "float", "long_double"}) {
    const auto expected = front_of(timed_and_measured(scene(), type));
    SCOPED_TRACE(type);
    if (expected.size() < 2) {
      EXPECT_EQ(pareto.fronts.count(type), 0u);  // a front of one point is no line
      continue;
    }
    ASSERT_EQ(pareto.fronts.count(type), 1u);
    EXPECT_EQ(pareto.fronts.at(type), expected);
  }
  EXPECT_GE(pareto.fronts.count("double"), 1u);
  // the headline figure: the worst error over the scenes (here one) against the time
  const auto headline = read_pareto(work / "out" / "plots" / "headline.dat");
  ASSERT_EQ(headline.fronts.count("double"), 1u);
  EXPECT_EQ(headline.fronts.at("double"), front_of(timed_and_measured(scene(), "double")));
}

TEST_F(tool, infinite_and_nan_errors_go_to_the_strip_not_onto_the_error_axis) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto pareto = read_pareto(work / "out" / "plots" / "pareto_small.dat");
  const std::string script = read(work / "out" / "plots" / "plots.gp");
  int failures = 0;
  for (const auto& a : scene()["accuracy"]) {
    const std::string key = a["type"].get<std::string>() + " " + a["algorithm"].get<std::string>();
    if (!pareto.points.count(key)) continue;
    const auto& cells = pareto.points.at(key);
    ASSERT_EQ(cells.size(), 6u) << key;
    const double error = value_of(a["max_ulp"]);
    if (std::isfinite(error)) {
      EXPECT_NE(cells[1], "?") << key;
      EXPECT_LE(std::strtod(cells[1].c_str(), nullptr), std::max(error, 1e-3) * (1 + 1e-5)) << key;
    } else {
      ++failures;
      EXPECT_EQ(cells[1], "?") << key;  // no number on the error axis
      EXPECT_EQ(cells[5], std::isnan(error) ? "nan" : "inf") << key;
    }
  }
  EXPECT_GT(failures, 0);  // the wild family breaks some algorithm
  EXPECT_NE(script.find("set label 'inf/NaN'"), std::string::npos);
  EXPECT_NE(script.find("using 1:(0.5):3:4"), std::string::npos);  // the failures, drawn in the strip
  EXPECT_EQ(script.find("1e19"), std::string::npos);
}

TEST_F(tool, the_pareto_plot_has_a_panel_for_double_and_float_and_one_for_the_wider_types) {
  ASSERT_EQ(status_, 0) << stderr_;
  const std::string script = read(work / "out" / "plots" / "plots.gp");
  const auto begin = script.find("\n# pareto_small\n");
  ASSERT_NE(begin, std::string::npos);
  const std::string pareto = script.substr(begin, script.find("\n# ", begin + 1) - begin);
  EXPECT_NE(pareto.find("set multiplot"), std::string::npos);
  EXPECT_NE(pareto.find("set title 'Scene small, double and float'"), std::string::npos);
  EXPECT_NE(pareto.find("set title 'Scene small, the wider types (long_double, cpp_bin_float_50)'"), std::string::npos);
  // labelled points, one colour per algorithm and one marker per type
  for (const auto& [algorithm, time, error] : timed_and_measured(scene(), "double")) {
    SCOPED_TRACE(algorithm);
    EXPECT_NE(pareto.find("set label '" + algorithm + "' at first "), std::string::npos);
    EXPECT_NE(pareto.find("lc rgb '" + report::colour_of(algorithm) + "' pt " + std::to_string(report::marker_of("double"))),
              std::string::npos);
  }
  EXPECT_NE(pareto.find("set label 'stable (cpp_bin_float_50)' at first "), std::string::npos);
}

TEST_F(tool, the_histograms_are_a_figure_per_type_with_a_data_file_per_algorithm) {
  ASSERT_EQ(status_, 0) << stderr_;
  for (const auto& a : scene()["accuracy"]) {
    const std::string type = a["type"], algorithm = a["algorithm"];
    SCOPED_TRACE(type + " " + algorithm);
    EXPECT_TRUE(fs::exists(work / "out" / "plots" / ("hist_" + type + "_" + algorithm + ".dat")));
    EXPECT_FALSE(fs::exists(work / "out" / "plots" / ("hist_" + type + "_" + algorithm + ".png")));
    EXPECT_TRUE(fs::exists(work / "out" / "plots" / ("hist_" + type + ".png")));
    EXPECT_NE(markdown_.find("](plots/hist_" + type + ".png)"), std::string::npos);
  }
}

TEST_F(tool, a_scene_that_asks_for_no_plots_gets_none) {
  std::ofstream(work / "no-plots.toml") << R"([scene]
name = "no_plots"
plots = []
[[family]]
name = "box"
generator = "box"
samples = 50
u = [1e-6, 1e-3]
dy = { log10 = [-6, -3], sign = "both" }
phi = [1e-2, 1e4]
[[run]]
types = ["double"]
algorithms = ["stable", "textbook"]
checks = ["accuracy", "timing"]
timing_inputs = 64
repetitions = 2
min_time = 0.002
)";
  const auto r = run_tool("--scene '" + (work / "no-plots.toml").string() + "' --out '" + (work / "no-plots-out").string() + "'",
                          "no-plots");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(work / "no-plots-out" / "plots"));
  const std::string md = read(work / "no-plots-out" / "report.md");
  EXPECT_EQ(md.find("!["), std::string::npos);
  EXPECT_TRUE(json::parse(read(work / "no-plots-out" / "results.json"))["plots"].empty());
}

TEST_F(tool, two_scenes_that_ask_for_the_headline_figure_are_an_error_with_file_and_line) {
  const std::string scene = "[scene]\nname = \"NAME\"\nplots = [\"headline\"]\n[[family]]\nname = \"box\"\n"
                            "generator = \"box\"\nsamples = 8\nu = [1e-6, 1e-3]\ndy = [1e-6, 1e-3]\nphi = 2.0\n"
                            "[[run]]\ntypes = [\"double\"]\nalgorithms = [\"stable\"]\nchecks = [\"timing\"]\n";
  std::ofstream(work / "head-a.toml") << std::string(scene).replace(scene.find("NAME"), 4, "head_a");
  std::ofstream(work / "head-b.toml") << std::string(scene).replace(scene.find("NAME"), 4, "head_b");
  const auto r = run_tool("--check --scene '" + (work / "head-a.toml").string() + "' --scene '" +
                              (work / "head-b.toml").string() + "'",
                          "two-headlines");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("head-b.toml:3: plots: the headline figure is already asked for by scene 'head_a'"),
            std::string::npos)
      << r.err;
}

// ---- the batch targets: each kernel the CPU runs, timed alone as batch[NAME] ----

TEST_F(tool, the_library_holds_a_scalar_target_that_every_cpu_supports) {
  ASSERT_FALSE(target_rows().empty());
  EXPECT_EQ(target_rows().back(), "batch[scalar]");
}

TEST_F(tool, results_json_times_batch_on_each_supported_target_in_double) {
  ASSERT_EQ(status_, 0) << stderr_;
  for (const auto& row : target_rows()) {
    SCOPED_TRACE(row);
    long found = 0;
    for (const auto& t : scene()["timing"])
      if (t["type"] == "double" && t["algorithm"] == row) {
        ++found;
        EXPECT_GT(value_of(t["ns_median"]), 0);
        EXPECT_EQ(t["inputs"].get<long>(), 256);
      }
    EXPECT_EQ(found, 1);
  }
}

TEST_F(tool, results_csv_times_batch_on_each_supported_target_in_double) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto figures = csv_figures(work / "out" / "results.csv");
  for (const auto& row : target_rows()) {
    SCOPED_TRACE(row);
    ASSERT_EQ(figures.count("timing/double/" + row + "/ns_median"), 1u);
    EXPECT_GT(std::strtod(figures.at("timing/double/" + row + "/ns_median").c_str(), nullptr), 0);
    EXPECT_EQ(figures.at("timing/double/" + row + "/inputs"), "256");
  }
}

TEST_F(tool, no_target_the_cpu_does_not_support_is_timed) {
  ASSERT_EQ(status_, 0) << stderr_;
  for (const contact::batch_target& t : contact::batch_targets()) {
    if (t.supported) continue;
    const std::string row = std::string("batch[") + t.name + "]";
    EXPECT_EQ(markdown_.find(row), std::string::npos) << row;
    EXPECT_EQ(read(work / "out" / "results.csv").find(row), std::string::npos) << row;
  }
}

TEST_F(tool, the_scene_table_gives_each_target_s_row_after_batch_in_the_library_s_order) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto rows = table(markdown_, "| type | algorithm | samples |");
  const auto batch = std::find_if(rows.begin(), rows.end(),
                                  [](const auto& row) { return row[0] == "double" && row[1] == "batch"; });
  ASSERT_NE(batch, rows.end());
  const auto targets = target_rows();
  ASSERT_GE(static_cast<std::size_t>(rows.end() - batch), 1 + targets.size());
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const auto& row = *(batch + 1 + static_cast<std::ptrdiff_t>(k));
    EXPECT_EQ(row[0], "double");
    EXPECT_EQ(row[1], targets[k]);
    EXPECT_EQ(row[2], "—");  // no accuracy figures: every target gives batch's results bit for bit
  }
}

TEST_F(tool, the_headline_speed_table_gives_each_target_in_double) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto rows = table(markdown_.substr(markdown_.find("### Speed in double")), "| algorithm | small |");
  for (const auto& target : target_rows()) {
    SCOPED_TRACE(target);
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r[0] == target; });
    ASSERT_NE(row, rows.end());
    for (const auto& t : scene()["timing"])
      if (t["type"] == "double" && t["algorithm"] == target) {
        EXPECT_EQ((*row)[1], report::format_ns(value_of(t["ns_median"])));
        EXPECT_EQ(value_of(results_["headline"]["double_ns_per_solve"][target]["small"]), value_of(t["ns_median"]));
      }
  }
}

TEST_F(tool, the_throughput_gives_each_target_streamed_and_in_cache_with_its_ratios) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto figures = csv_figures(work / "out" / "results.csv");
  for (const long lanes : {8192L, 1024L}) {
    std::map<std::string, double> ns;
    for (const auto& t : scene()["throughput"])
      if (t["lanes"] == lanes) ns[t["path"]] = value_of(t["ns_median"]);
    const char* pass = lanes == 8192 ? "streamed" : "in_cache";
    for (const auto& row : target_rows()) {
      SCOPED_TRACE(row + " " + pass);
      ASSERT_EQ(ns.count(row), 1u);
      EXPECT_EQ(figures.count("throughput@" + std::to_string(lanes) + "/double/" + row + "/ns_median"), 1u);
      const json& headline = results_["headline"]["batch_per_target"][row][pass];
      EXPECT_DOUBLE_EQ(value_of(headline["batch_ns"]), ns[row]);
      EXPECT_DOUBLE_EQ(value_of(headline["batch_to_floor"]), ns[row] / ns["floor"]);
      EXPECT_DOUBLE_EQ(value_of(headline["speedup_over_textbook"]), ns["textbook"] / ns[row]);
    }
  }
}

TEST_F(tool, the_headline_throughput_table_has_a_row_per_target_streamed_and_in_cache) {
  ASSERT_EQ(status_, 0) << stderr_;
  const auto rows = table(markdown_, "| lanes | kernel |");
  for (const auto& target : target_rows())
    for (const char* lanes : {"8192 (streamed)", "1024 (in cache)"}) {
      SCOPED_TRACE(target + " " + lanes);
      const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r[0] == lanes && r[1] == target; });
      ASSERT_NE(row, rows.end());
      const json& headline = results_["headline"]["batch_per_target"][target][lanes[0] == '8' ? "streamed" : "in_cache"];
      EXPECT_EQ((*row)[6], "**" + report::format_ratio(value_of(headline["speedup_over_textbook"])) + "**");
      EXPECT_EQ((*row)[8], "**" + report::format_ratio(value_of(headline["batch_to_floor"])) + "**");
    }
}

TEST_F(tool, report_md_names_the_target_dispatch_chose) {
  ASSERT_EQ(status_, 0) << stderr_;
  const std::string header = markdown_.substr(0, markdown_.find("## Headline figures"));
  EXPECT_NE(header.find(std::string("dispatch chose: **") + contact::chosen_batch_target().name + "**"),
            std::string::npos)
      << header;
}

TEST_F(tool, the_header_names_the_cpu_model) {
  ASSERT_EQ(status_, 0) << stderr_;
  const std::string header = markdown_.substr(0, markdown_.find("## Headline figures"));
  EXPECT_NE(header.find("- **CPU:** " + cpu_model_name() + "\n"), std::string::npos) << header;
}

TEST_F(tool, the_header_says_which_ratios_are_measured_side_by_side) {
  ASSERT_EQ(status_, 0) << stderr_;
  const std::string header = markdown_.substr(0, markdown_.find("## Headline figures"));
  EXPECT_NE(header.find("- **Ratios measured side by side:** within a scene, each type's algorithms are timed in turn"),
            std::string::npos)
      << header;
}

// Where a scene times textbook and stable in a type wider than double, the
// headline table of what each precision costs divides each type's stable
// median by its own textbook median, in every type that times both.
TEST_F(tool, the_cost_table_divides_each_type_s_stable_by_its_own_textbook) {
  ASSERT_EQ(status_, 0) << stderr_;
  std::map<std::string, double> median;
  for (const auto& t : scene()["timing"])
    median[t["type"].get<std::string>() + "/" + t["algorithm"].get<std::string>()] = value_of(t["ns_median"]);
  std::set<std::string> types;
  for (const auto& row : table(markdown_, "| type | textbook | stable | stable / textbook |")) {
    types.insert(row[0]);
    const double ratio = median.at(row[0] + "/stable") / median.at(row[0] + "/textbook");
    EXPECT_EQ(row[3], "**" + report::format_ratio(ratio) + "**") << row[0];
    EXPECT_DOUBLE_EQ(value_of(results_["headline"]["cost_by_type"]["small"][row[0]]["stable_over_textbook"]), ratio);
  }
  EXPECT_EQ(types, (std::set<std::string>{"double", "long_double", "cpp_bin_float_50"}));
}

TEST_F(tool, the_header_names_the_targets_the_library_holds_and_those_the_cpu_supports) {
  ASSERT_EQ(status_, 0) << stderr_;
  std::string held, supported;
  for (const contact::batch_target& t : contact::batch_targets()) {
    held += (held.empty() ? "" : ", ") + std::string(t.name);
    if (t.supported) supported += (supported.empty() ? "" : ", ") + std::string(t.name);
  }
  const std::string header = markdown_.substr(0, markdown_.find("## Headline figures"));
  EXPECT_NE(header.find("the library holds: " + held + "; this CPU supports: " + supported + ";"), std::string::npos)
      << header;
}

TEST_F(tool, results_json_names_the_cpu_the_targets_and_the_chosen_one) {
  ASSERT_EQ(status_, 0) << stderr_;
  const json& machine = results_["machine"];
  EXPECT_EQ(machine["cpu"], cpu_model_name());
  EXPECT_EQ(machine["batch_chosen"], contact::chosen_batch_target().name);
  std::vector<std::string> held, supported;
  for (const contact::batch_target& t : contact::batch_targets()) {
    held.emplace_back(t.name);
    if (t.supported) supported.emplace_back(t.name);
  }
  EXPECT_EQ(machine["batch_targets"].get<std::vector<std::string>>(), held);
  EXPECT_EQ(machine["batch_supported"].get<std::vector<std::string>>(), supported);
}

TEST_F(tool, batch_in_float_is_timed_per_target_too_and_wider_types_are_not) {
  std::ofstream(work / "float.toml") << R"([scene]
name = "float_batch"
[[family]]
name = "box"
generator = "box"
samples = 50
u = [1e-6, 1e-3]
dy = { log10 = [-6, -3], sign = "both" }
phi = [1e-2, 1e4]
[[run]]
types = ["float", "long_double"]
algorithms = ["batch"]
checks = ["timing"]
timing_inputs = 64
repetitions = 2
min_time = 0.002
)";
  const auto r = run_tool("--scene '" + (work / "float.toml").string() + "' --out '" + (work / "float-out").string() + "'",
                          "float");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read(work / "float-out" / "results.json"));
  std::set<std::string> timed;
  for (const auto& t : j["scenes"][0]["timing"]) timed.insert(t["type"].get<std::string>() + "/" + t["algorithm"].get<std::string>());
  std::set<std::string> expected{"float/batch", "long_double/batch"};
  for (const auto& row : target_rows()) expected.insert("float/" + row);
  EXPECT_EQ(timed, expected);
}

TEST_F(tool, a_bad_scene_file_stops_the_tool_with_file_line_and_reason) {
  const fs::path bad = work / "bad.toml";
  std::string text = small_scene;
  text.replace(text.find("seed = 11"), 9, "seed = 11\nsamples = 3");
  std::ofstream(bad) << text;
  const auto r = run_tool("--scene '" + bad.string() + "' --out '" + (work / "bad-out").string() + "'", "bad");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(bad.string() + ":5: unknown key 'samples' in [scene]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(work / "bad-out" / "report.md"));

  std::ofstream(work / "syntax.toml") << "[scene]\nname = \"x\"\nseed = \n";
  const auto s = run_tool("--scene '" + (work / "syntax.toml").string() + "' --out '" + (work / "bad-out").string() + "'",
                          "syntax");
  EXPECT_EQ(s.status, 1);
  EXPECT_NE(s.err.find((work / "syntax.toml").string() + ":3: "), std::string::npos) << s.err;

  const auto missing = run_tool("--scene '" + (work / "missing.toml").string() + "' --out '" + (work / "bad-out").string() + "'",
                                "missing");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("missing.toml:0: cannot read the scene file"), std::string::npos) << missing.err;
}

TEST_F(tool, a_double_only_scene_builds_no_other_type) {
  std::ofstream(work / "double.toml") << R"([scene]
name = "double_only"
[[family]]
name = "box"
generator = "box"
samples = 50
u = [1e-6, 1e-3]
dy = { log10 = [-6, -3], sign = "both" }
phi = [1e-2, 1e4]
[[run]]
types = ["double"]
algorithms = ["stable"]
checks = ["accuracy"]
)";
  const auto r = run_tool("--scene '" + (work / "double.toml").string() + "' --out '" + (work / "double-out").string() + "'",
                          "double");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read(work / "double-out" / "results.json"));
  ASSERT_EQ(j["scenes"][0]["accuracy"].size(), 1u);
  EXPECT_EQ(j["scenes"][0]["accuracy"][0]["type"], "double");
  EXPECT_TRUE(j["scenes"][0]["timing"].empty());
  EXPECT_TRUE(j["scenes"][0]["energy"].empty());
  EXPECT_TRUE(j["scenes"][0]["throughput"].empty());
  EXPECT_EQ(r.err.find("timed"), std::string::npos);  // no benchmark ran
}

// Two scenes that time batch in double, one of them the reference: each gets
// its ns per lane from the shared rounds and, per round, its ratio to the
// reference's ns of the same round; the reference's own ratios are 1.
std::string batch_scene(const std::string& name, bool reference, const std::string& dy) {
  return "[scene]\nname = \"" + name + "\"\n" + (reference ? "batch_reference = true\n" : "") +
         "[[family]]\nname = \"box\"\ngenerator = \"box\"\nsamples = 64\nu = { log10 = [-6, -3], sign = \"both\" }\n"
         "dy = " + dy + "\nphi = [1e-2, 1e4]\n"
         "[[run]]\ntypes = [\"double\"]\nalgorithms = [\"batch\"]\nchecks = [\"timing\"]\ntiming_inputs = 512\n"
         "repetitions = 3\nmin_time = 0.002\n";
}

// Runs the tool on two scene files of `work`, writing into work/TAG-out.
command_result run_on_two_scenes(const std::string& first, const std::string& second, const std::string& tag) {
  return run_tool("--scene '" + (work / first).string() + "' --scene '" + (work / second).string() + "' --out '" +
                      (work / (tag + "-out")).string() + "'",
                  tag);
}

TEST_F(tool, batch_across_scenes_gives_each_round_s_ratio_to_the_reference_scene) {
  std::ofstream(work / "near.toml") << batch_scene("near", true, "{ log10 = [-6, -3], sign = \"both\" }");
  std::ofstream(work / "far.toml") << batch_scene("far", false, "{ log2 = [-1000, 1000], sign = \"both\" }");
  const auto r = run_on_two_scenes("near.toml", "far.toml", "across");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read(work / "across-out" / "results.json"));
  ASSERT_EQ(j["scenes"].size(), 2u);
  const json& near = j["scenes"][0]["batch_across_scenes"];
  const json& far = j["scenes"][1]["batch_across_scenes"];
  ASSERT_EQ(near["ns_repetitions"].size(), 3u);
  ASSERT_EQ(far["ns_repetitions"].size(), 3u);
  EXPECT_EQ(near["reference"], "near");
  EXPECT_EQ(far["reference"], "near");
  std::vector<double> ratios;
  for (std::size_t round = 0; round < 3; ++round) {
    const double reference_ns = value_of(near["ns_repetitions"][round]);
    EXPECT_GT(reference_ns, 0);
    EXPECT_EQ(value_of(near["over_reference_repetitions"][round]), 1.0);
    const double ratio = value_of(far["over_reference_repetitions"][round]);
    EXPECT_DOUBLE_EQ(ratio, value_of(far["ns_repetitions"][round]) / reference_ns);
    ratios.push_back(ratio);
  }
  std::sort(ratios.begin(), ratios.end());
  EXPECT_DOUBLE_EQ(value_of(far["over_reference_median"]), ratios[1]);
  // results.csv and report.md give the same medians
  const std::string csv = read(work / "across-out" / "results.csv");
  EXPECT_NE(csv.find("far,batch_across_scenes,double,batch,over_near_median,"), std::string::npos) << csv;
  const auto rows = table(read(work / "across-out" / "report.md"), "| scene | ns per lane (median) | over near");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][0], "far");
  EXPECT_EQ(rows[1][2], "**" + report::format_ratio(value_of(far["over_reference_median"])) + "**");
}

// Per target, the same: each target's kernel on each scene, over the same
// target's time on the reference scene in the same round.
TEST_F(tool, batch_across_scenes_gives_each_target_its_own_ratios_to_the_reference_scene) {
  std::ofstream(work / "near.toml") << batch_scene("near", true, "{ log10 = [-6, -3], sign = \"both\" }");
  std::ofstream(work / "far.toml") << batch_scene("far", false, "{ log2 = [-1000, 1000], sign = \"both\" }");
  const auto r = run_on_two_scenes("near.toml", "far.toml", "across-targets");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read(work / "across-targets-out" / "results.json"));
  const std::string csv = read(work / "across-targets-out" / "results.csv");
  const auto rows = table(read(work / "across-targets-out" / "report.md"), "| scene | kernel | ns per lane (median) | over near");
  for (const auto& target : target_rows()) {
    SCOPED_TRACE(target);
    const json& near = j["scenes"][0]["batch_across_scenes_per_target"][target];
    const json& far = j["scenes"][1]["batch_across_scenes_per_target"][target];
    ASSERT_EQ(near["ns_repetitions"].size(), 3u);
    ASSERT_EQ(far["ns_repetitions"].size(), 3u);
    for (std::size_t round = 0; round < 3; ++round) {
      EXPECT_EQ(value_of(near["over_reference_repetitions"][round]), 1.0);
      EXPECT_DOUBLE_EQ(value_of(far["over_reference_repetitions"][round]),
                       value_of(far["ns_repetitions"][round]) / value_of(near["ns_repetitions"][round]));
    }
    EXPECT_NE(csv.find("far,batch_across_scenes,double," + target + ",over_near_median,"), std::string::npos);
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& x) { return x[0] == "far" && x[1] == target; });
    ASSERT_NE(row, rows.end());
    EXPECT_EQ((*row)[3], "**" + report::format_ratio(value_of(far["over_reference_median"])) + "**");
  }
}

TEST_F(tool, two_scenes_that_set_batch_reference_are_an_error_with_file_and_line) {
  std::ofstream(work / "first.toml") << batch_scene("first", true, "[1e-6, 1e-3]");
  std::ofstream(work / "second.toml") << batch_scene("second", true, "[1e-6, 1e-3]");
  const auto r = run_on_two_scenes("first.toml", "second.toml", "twice");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find((work / "second.toml").string() + ":3: batch_reference is already set by scene 'first'"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(work / "twice-out" / "report.md"));
}

// A small scene of stable in double, timed, beside which a candidate is measured.
std::string candidate_scene(const std::string& name) {
  return "[scene]\nname = \"" + name + "\"\n" + R"([[family]]
name = "box"
generator = "box"
samples = 50
u = [1e-6, 1e-3]
dy = { log10 = [-6, -3], sign = "both" }
phi = [1e-2, 1e4]
[[run]]
types = ["double"]
algorithms = ["stable"]
checks = ["accuracy", "timing"]
repetitions = 1
min_time = 0.01
)";
}

TEST_F(tool, a_candidate_is_measured_beside_the_algorithms_in_double) {
  std::ofstream(work / "candidate.toml") << candidate_scene("with_candidate");
  // free flight for every input, s = -u: right in the free case only
  const std::string minus_u =
      "minus_u=cmd:python3 -c \"import sys; [print(repr(-float.fromhex(l.split()[0])), 1) for l in sys.stdin]\"";
  const auto r = run_tool("--scene '" + (work / "candidate.toml").string() + "' --out '" +
                              (work / "candidate-out").string() + "' --candidate '" + minus_u + "'",
                          "candidate");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read(work / "candidate-out" / "results.json"));
  std::set<std::string> measured, timed;
  for (const auto& a : j["scenes"][0]["accuracy"]) measured.insert(a["algorithm"].get<std::string>());
  for (const auto& t : j["scenes"][0]["timing"]) timed.insert(t["algorithm"].get<std::string>());
  EXPECT_EQ(measured, (std::set<std::string>{"stable", "minus_u"}));
  EXPECT_EQ(timed, (std::set<std::string>{"stable"}));  // a command's time would be its protocol's
  for (const auto& a : j["scenes"][0]["accuracy"])
    if (a["algorithm"] == "minus_u") EXPECT_GT(a["wrong_case"].get<long>(), 0);  // box draws contact too
  EXPECT_NE(read(work / "candidate-out" / "report.md").find("| double | minus_u |"), std::string::npos);
}

TEST_F(tool, a_library_candidate_is_timed_in_process_and_mapped_beside_stable) {
  std::ofstream(work / "library.toml") << candidate_scene("with_library");
  const auto r = run_tool("--scene '" + (work / "library.toml").string() + "' --out '" + (work / "library-out").string() +
                              "' --candidate 'mine=lib:" CONTACT_STABLE_CANDIDATE "'",
                          "library");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(read(work / "library-out" / "results.json"));
  std::set<std::string> timed;
  for (const auto& t : j["scenes"][0]["timing"]) timed.insert(t["algorithm"].get<std::string>());
  EXPECT_EQ(timed, (std::set<std::string>{"stable", "mine"}));
  EXPECT_NE(read(work / "library-out" / "report.md").find("![mine](plots/map_mine.png) | ![stable](plots/map_stable.png)"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(work / "library-out" / "plots" / "map_mine.png"));
  EXPECT_TRUE(fs::exists(work / "library-out" / "plots" / "map_stable.svg"));
}

TEST_F(tool, a_bad_candidate_is_a_usage_error) {
  const auto r = run_tool("--check --candidate 'nameless'", "bad-candidate");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("NAME=SPEC"), std::string::npos) << r.err;
}

}  // namespace
