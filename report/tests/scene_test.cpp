// The scene parser: well-formed scenes give what they say; every bad one gives
// "FILE:LINE: reason" with the line of the offending key or value.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "contact/types.hpp"
#include "inputs.hpp"
#include "scene.hpp"
#include "type_ops.hpp"

namespace {

using report::scene_error;

const char* good_scene = R"(# a comment
[scene]
name = "example"
title = "An example"
seed = 9
mpfr_digits10 = 30

[[family]]
name = "phys"
generator = "physical"
samples = 10
mass = [1e-4, 1e-2]
spring = [1.0, 1e4]
barrier_stiffness = [1e5, 1e13]
displacement = { log10 = [-7, -3], sign = "both" }
compression = { log10 = [-7, -3], sign = "negative" }
velocity = { uniform = [-1.0, 1.0] }

[[family]]
name = "edge"
generator = "contact_release_boundary"
samples = 20
ulps = 3
dy = { log2 = [-10, 10] }
phi = 2.5

[[run]]
types = ["double", "float128"]
algorithms = ["stable", "textbook"]
checks = ["accuracy", "timing"]
samples = 5
timing_inputs = 64
repetitions = 2
min_time = 0.01

[[run]]
types = ["double"]
algorithms = ["newton"]
checks = ["energy"]

[oscillator]
mass = 2e-3
barrier_stiffness = 1e9
duration = 0.01

[throughput]
lanes = 1000
cache_lanes = 100
)";

// The scene text with `from` replaced by `to` (which must occur).
// `text` (by default the good scene) with its first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to, std::string text = good_scene) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Line (1-based) of the first occurrence of `needle` in `text`.
long line_of(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<long>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// Parsing `text` fails at the line of `where` with a reason containing `reason`.
void expect_error(const std::string& text, const std::string& where, const std::string& reason) {
  try {
    report::parse_scene_text(text, "scenes/bad.toml");
    ADD_FAILURE() << "no error; expected line of '" << where << "': " << reason;
  } catch (const scene_error& e) {
    EXPECT_EQ(e.file(), "scenes/bad.toml");
    EXPECT_EQ(e.line(), line_of(text, where)) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()), "scenes/bad.toml:" + std::to_string(e.line()) + ": " + e.reason());
  }
}

TEST(scene, a_good_scene_says_what_it_asks_for) {
  const auto s = report::parse_scene_text(good_scene, "good.toml");
  EXPECT_EQ(s.name, "example");
  EXPECT_EQ(s.title, "An example");
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(s.mpfr_digits10, 30);
  ASSERT_EQ(s.families.size(), 2u);
  EXPECT_EQ(s.families[0].generator, "physical");
  EXPECT_EQ(s.families[0].samples, 10);
  const auto& mass = s.families[0].parameters.at("mass");
  EXPECT_EQ(mass.kind, report::distribution::shape::log10);
  EXPECT_DOUBLE_EQ(mass.low, -4);
  EXPECT_DOUBLE_EQ(mass.high, -2);
  EXPECT_EQ(s.families[0].parameters.at("displacement").sign, 0);
  EXPECT_EQ(s.families[0].parameters.at("compression").sign, -1);
  EXPECT_EQ(s.families[0].parameters.at("velocity").kind, report::distribution::shape::uniform);
  EXPECT_EQ(s.families[1].ulps, 3);
  EXPECT_EQ(s.families[1].parameters.at("dy").kind, report::distribution::shape::log2);
  EXPECT_EQ(s.families[1].parameters.at("phi").kind, report::distribution::shape::constant);
  ASSERT_EQ(s.runs.size(), 2u);
  EXPECT_EQ(s.runs[0].types, (std::vector<std::string>{"double", "float128"}));
  EXPECT_EQ(s.runs[0].methods, (std::vector<report::method>{report::method::stable, report::method::textbook}));
  EXPECT_EQ(s.runs[0].samples, 5);
  EXPECT_EQ(s.runs[0].timing_inputs, 64);
  EXPECT_EQ(s.runs[0].repetitions, 2);
  EXPECT_DOUBLE_EQ(s.runs[0].min_time, 0.01);
  EXPECT_EQ(s.runs[1].checks, (std::vector<report::check>{report::check::energy}));
  ASSERT_TRUE(s.energy.has_value());
  EXPECT_DOUBLE_EQ(s.energy->mass, 2e-3);
  EXPECT_DOUBLE_EQ(s.energy->spring, 1e3);  // default
  ASSERT_TRUE(s.batch_throughput.has_value());
  EXPECT_EQ(s.batch_throughput->lanes, 1000);
}

TEST(scene, generation_is_deterministic_and_follows_the_families) {
  const auto s = report::parse_scene_text(good_scene, "good.toml");
  const auto a = report::generate(s), b = report::generate(s);
  ASSERT_EQ(a.size(), 30u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].u, b[i].u);
    EXPECT_EQ(a[i].family, i < 10 ? 0 : 1);
    EXPECT_GE(a[i].phi, 0);
  }
  for (std::size_t i = 10; i < 30; ++i) {
    EXPECT_GT(a[i].dy, 0);
    EXPECT_EQ(a[i].phi, 2.5);
  }
  for (std::size_t i = 0; i < 10; ++i) EXPECT_LE(a[i].dy, 0);  // compression sign = "negative"
}

TEST(scene, toml_syntax_errors_give_their_line) {
  expect_error(edited("seed = 9", "seed = = 9"), "seed = = 9", "");
  expect_error(edited("samples = 10\n", "samples = 10\nsamples = 11\n"), "samples = 11", "");
}

TEST(scene, unknown_keys_are_errors_not_ignored) {
  expect_error(edited("seed = 9", "seed = 9\nsede = 3"), "sede", "unknown key 'sede' in [scene]");
  expect_error(edited("ulps = 3", "ulps = 3\nulp = 3"), "ulp = 3", "unknown key 'ulp'");
  expect_error(edited("timing_inputs = 64", "timing_inputs = 64\nthreads = 2"), "threads", "unknown key 'threads'");
  expect_error(edited("[throughput]", "[throughput]\nwidth = 2"), "width", "unknown key 'width' in [throughput]");
  expect_error(edited("[oscillator]", "[oscillator]\ndamping = 0.1"), "damping", "unknown key 'damping' in [oscillator]");
  expect_error(edited("[[family]]\nname = \"edge\"", "[[familly]]\nname = \"edge\""), "[[familly]]",
               "unknown key 'familly' in the top level");
  expect_error(edited("dy = { log2 = [-10, 10] }", "dy = { log2 = [-10, 10], base = 3 }"), "dy = { log2",
               "unknown key 'base'");
  // a parameter of another generator
  expect_error(edited("ulps = 3", "ulps = 3\nratio = [1.0, 2.0]"), "ratio", "unknown key 'ratio'");
}

TEST(scene, names_of_types_algorithms_checks_and_generators_are_checked) {
  expect_error(edited("\"double\", \"float128\"", "\"double\", \"float129\""), "\"float129\"", "unknown type 'float129'");
  expect_error(edited("[\"stable\", \"textbook\"]", "[\"stable\", \"textbok\"]"), "\"textbok\"",
               "unknown algorithm 'textbok'");
  expect_error(edited("[\"accuracy\", \"timing\"]", "[\"accuracy\", \"speed\"]"), "\"speed\"", "unknown check 'speed'");
  expect_error(edited("generator = \"physical\"", "generator = \"physics\""), "generator = \"physics\"",
               "unknown generator 'physics'");
  expect_error(edited("[\"stable\", \"textbook\"]", "[\"stable\", \"eigen_companion\"]"), "\"eigen_companion\"",
               "eigen_companion runs in float, double and long_double only");
  expect_error(edited("[\"stable\", \"textbook\"]", "[\"stable\", \"stable\"]"), "[\"stable\", \"stable\"]",
               "named twice");
}

// The report's types are the registry's: each name resolves to its own
// measurements, and a name the registry does not hold is an error, never a default.
TEST(scene, type_names_are_the_registry_s_and_an_unknown_one_is_an_error) {
  for (std::string_view name : contact::type_names) {
    EXPECT_EQ(report::ops_for(name).name, name);
    EXPECT_EQ(report::unsupported(report::method::stable, name), "") << name;
  }
  EXPECT_THROW(report::ops_for("quad"), std::invalid_argument);
  EXPECT_THROW(report::unsupported(report::method::stable, "quad"), std::invalid_argument);
  EXPECT_EQ(report::unsupported(report::method::eigen_companion, "double"), "");
  EXPECT_NE(report::unsupported(report::method::eigen_companion, "mpfr"), "");
}

// The correctly rounded mode runs in the IEEE types only; a scene that names it
// for another type is refused with the reason.
TEST(scene, rounded_runs_in_the_ieee_types_only) {
  for (const char* type : {"float", "double", "long_double", "float128"})
    EXPECT_EQ(report::unsupported(report::method::rounded, type), "") << type;
  for (const char* type : {"cpp_bin_float_50", "cpp_bin_float_100", "mpfr"})
    EXPECT_EQ(report::unsupported(report::method::rounded, type), "rounded runs in float, double, long_double and float128 only")
        << type;
  EXPECT_FALSE(report::iterative(report::method::rounded));
}

// The iterative peers are templates on T that run in every registered type:
// a run may name each of them in any type, and they are the iterative methods.
TEST(scene, the_iterative_peers_are_accepted_in_every_registered_type) {
  for (const std::string name : {"boost_newton", "boost_halley", "boost_toms748", "practitioner_newton"}) {
    const auto m = report::method_named(name);
    ASSERT_TRUE(m.has_value()) << name;
    EXPECT_EQ(report::name_of(*m), name);
    EXPECT_TRUE(report::iterative(*m)) << name;
    for (std::string_view type : contact::type_names) {
      SCOPED_TRACE(name + " in " + std::string(type));
      EXPECT_EQ(report::unsupported(*m, type), "");
      std::string text = edited("[\"stable\", \"textbook\"]", "[\"stable\", \"" + name + "\"]");
      const std::string types = "types = [\"double\", \"float128\"]";
      text.replace(text.find(types), types.size(), "types = [\"" + std::string(type) + "\"]");
      const auto s = report::parse_scene_text(text, "good.toml");
      EXPECT_EQ(s.runs[0].types, std::vector<std::string>{std::string(type)});
      EXPECT_EQ(s.runs[0].methods, (std::vector<report::method>{report::method::stable, *m}));
    }
  }
  EXPECT_TRUE(report::iterative(report::method::newton));
  for (auto m : {report::method::textbook, report::method::stable, report::method::batch,
                 report::method::boost_quadratic, report::method::eigen_companion})
    EXPECT_FALSE(report::iterative(m)) << report::name_of(m);
  // every method's name leads back to it
  for (auto m : report::all_methods) EXPECT_EQ(report::method_named(report::name_of(m)), m);
}

TEST(scene, values_are_checked) {
  expect_error(edited("samples = 10", "samples = \"ten\""), "samples = \"ten\"", "'samples' must be an integer");
  expect_error(edited("samples = 10", "samples = 0"), "samples = 0", "must lie in [1, 10000000]");
  expect_error(edited("mass = [1e-4, 1e-2]", "mass = [1e-2, 1e-4]"), "mass = [1e-2", "exceeds high");
  expect_error(edited("mass = [1e-4, 1e-2]", "mass = [0.0, 1e-2]"), "mass = [0.0", "needs 0 < low");
  expect_error(edited("mass = [1e-4, 1e-2]", "mass = [1e-4]"), "mass = [1e-4]", "array of two numbers");
  expect_error(edited("dy = { log2 = [-10, 10] }", "dy = { log2 = [-10, 1100] }"), "dy = {", "range of double");
  expect_error(edited("sign = \"both\"", "sign = \"any\""), "sign = \"any\"", "\"positive\", \"negative\" or \"both\"");
  expect_error(edited("dy = { log2 = [-10, 10] }", "dy = { log2 = [-10, 10], log10 = [1, 2] }"), "dy = {",
               "exactly one of log10, log2 or uniform");
  expect_error(edited("min_time = 0.01", "min_time = -1.0"), "min_time = -1.0", "must be positive");
  expect_error(edited("name = \"example\"", "name = \"an example\""), "name = \"an example\"", "identifier");
  expect_error(edited("types = [\"double\", \"float128\"]", "types = []"), "types = []", "must not be empty");
  expect_error(edited("types = [\"double\", \"float128\"]", "types = \"double\""), "types = \"double\"",
               "array of strings");
  expect_error(edited("barrier_stiffness = 1e9", "barrier_stiffness = -1e9"), "barrier_stiffness = -1e9",
               "must be positive");
}

TEST(scene, missing_and_unused_parts_are_errors) {
  expect_error(edited("samples = 10\n", "\n"), "[[family]]\nname = \"phys\"", "needs the key 'samples'");
  expect_error(edited("name = \"example\"\n", ""), "[scene]", "needs the key 'name'");
  expect_error(edited("spring = [1.0, 1e4]\n", ""), "[[family]]\nname = \"phys\"", "needs the key 'spring'");
  expect_error(edited("name = \"edge\"", "name = \"phys\""), "[[family]]\nname = \"phys\"\ngenerator = \"contact",
               "defined twice");
  // the energy check needs an [oscillator]; an [oscillator] needs the energy check
  expect_error(edited("[oscillator]\nmass = 2e-3\nbarrier_stiffness = 1e9\nduration = 0.01\n", ""),
               "[[run]]\ntypes = [\"double\"]", "has no [oscillator]");
  expect_error(edited("checks = [\"energy\"]", "checks = [\"timing\"]"), "[oscillator]", "[oscillator] is not used");
  const std::string no_families =
      "[scene]\nname = \"x\"\n\n[[run]]\ntypes = [\"double\"]\nalgorithms = [\"stable\"]\nchecks = [\"accuracy\"]\n";
  expect_error(no_families, "[[run]]", "has no [[family]]");
  expect_error("[scene]\nname = \"x\"\n", "[scene]", "asks for nothing");
  expect_error("name = \"x\"\n", "name", "unknown key 'name' in the top level");
}

TEST(scene, batch_reference_is_a_boolean_of_a_scene_that_times_batch_in_double) {
  const std::string timing_batch = R"([scene]
name = "x"
batch_reference = true

[[family]]
name = "phys"
generator = "box"
samples = 10
u = [1e-6, 1e-3]
dy = [1e-6, 1e-3]
phi = [1e-2, 1e4]

[[run]]
types = ["double"]
algorithms = ["batch"]
checks = ["timing"]
)";
  const auto s = report::parse_scene_text(timing_batch, "x.toml");
  EXPECT_TRUE(s.batch_reference);
  ASSERT_NE(report::batch_timing_run(s), nullptr);
  EXPECT_FALSE(report::parse_scene_text(good_scene, "good.toml").batch_reference);
  auto with = [&](const std::string& from, const std::string& to) { return edited(from, to, timing_batch); };
  expect_error(with("batch_reference = true", "batch_reference = 1"), "batch_reference = 1",
               "'batch_reference' must be true or false");
  expect_error(with("checks = [\"timing\"]", "checks = [\"accuracy\"]"), "batch_reference = true",
               "no [[run]] of the scene times batch in double");
  expect_error(with("types = [\"double\"]", "types = [\"float\"]"), "batch_reference = true",
               "no [[run]] of the scene times batch in double");
}

TEST(scene, plots_names_the_pictures_and_without_it_a_scene_gets_every_picture_but_the_headline) {
  using report::plot;
  const auto plain = report::parse_scene_text(good_scene, "good.toml");
  EXPECT_EQ(plain.plots, (std::vector<plot>{plot::pareto, plot::histograms, plot::energy}));
  EXPECT_FALSE(report::asks_for(plain, plot::headline));
  const auto some = report::parse_scene_text(edited("seed = 9", "seed = 9\nplots = [\"headline\", \"pareto\"]"), "x.toml");
  EXPECT_EQ(some.plots, (std::vector<plot>{plot::headline, plot::pareto}));
  EXPECT_EQ(some.plots_line, 6);
  EXPECT_TRUE(report::asks_for(some, plot::headline));
  EXPECT_FALSE(report::asks_for(some, plot::histograms));
  const auto none = report::parse_scene_text(edited("seed = 9", "seed = 9\nplots = []"), "x.toml");
  EXPECT_TRUE(none.plots.empty());
  for (plot p : report::all_plots)
    EXPECT_EQ(report::parse_scene_text(edited("seed = 9", "seed = 9\nplots = [\"" + report::name_of(p) + "\"]"), "x.toml").plots,
              std::vector<plot>{p});
}

TEST(scene, plots_names_are_checked) {
  expect_error(edited("seed = 9", "seed = 9\nplots = [\"pareto\", \"paretto\"]"), "plots", "unknown plot 'paretto'");
  expect_error(edited("seed = 9", "seed = 9\nplots = [\"pareto\", \"pareto\"]"), "plots", "named twice");
  expect_error(edited("seed = 9", "seed = 9\nplots = \"pareto\""), "plots", "'plots' must be an array of strings");
}

TEST(scene, the_headline_figure_needs_a_run_that_times_double) {
  const std::string asks = edited("seed = 9", "seed = 9\nplots = [\"headline\"]");
  EXPECT_NO_THROW(report::parse_scene_text(asks, "x.toml"));
  // the good scene's only timing run, in double and float128, times float128 alone
  expect_error(edited("types = [\"double\", \"float128\"]", "types = [\"float128\"]", asks), "plots",
               "no [[run]] of it times double");
}

TEST(scene, the_default_scenes_ask_for_the_headline_once_and_for_the_pareto_panels_and_histograms) {
  int headline = 0, pareto = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CONTACT_SCENES_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    const auto s = report::parse_scene(entry.path().string());
    headline += report::asks_for(s, report::plot::headline);
    bool measures = false;
    for (const auto& r : s.runs) measures = measures || report::asks_for(r, report::check::accuracy);
    if (!measures) continue;
    EXPECT_TRUE(report::asks_for(s, report::plot::pareto)) << s.name;
    EXPECT_TRUE(report::asks_for(s, report::plot::histograms)) << s.name;
    pareto += report::asks_for(s, report::plot::pareto);
  }
  EXPECT_EQ(headline, 1);
  EXPECT_GE(pareto, 4);
  EXPECT_TRUE(report::asks_for(report::parse_scene(std::string(CONTACT_SCENES_DIR) + "/physical.toml"),
                               report::plot::headline));
}

TEST(scene, an_unreadable_file_is_an_error_at_line_0) {
  try {
    report::parse_scene("/nonexistent/scene.toml");
    ADD_FAILURE();
  } catch (const scene_error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.toml:0: cannot read the scene file");
  }
}

TEST(scene, the_default_scenes_are_well_formed) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CONTACT_SCENES_DIR))
    if (entry.path().extension() == ".toml") {
      ++count;
      EXPECT_NO_THROW(report::parse_scene(entry.path().string())) << entry.path();
    }
  EXPECT_GE(count, 5);
}

}  // namespace
