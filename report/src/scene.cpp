#include "scene.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "contact/types.hpp"
#include "inputs.hpp"

namespace report {

bool asks_for(const run& r, check c) { return std::find(r.checks.begin(), r.checks.end(), c) != r.checks.end(); }

bool asks_for(const scene& s, plot p) { return std::find(s.plots.begin(), s.plots.end(), p) != s.plots.end(); }

std::string name_of(plot p) {
  switch (p) {
    case plot::headline: return "headline";
    case plot::pareto: return "pareto";
    case plot::histograms: return "histograms";
    case plot::energy: return "energy";
  }
  return "?";
}

const run* batch_timing_run(const scene& s) {
  for (const run& r : s.runs)
    if (asks_for(r, check::timing) && std::find(r.types.begin(), r.types.end(), "double") != r.types.end() &&
        std::find(r.methods.begin(), r.methods.end(), method::batch) != r.methods.end())
      return &r;
  return nullptr;
}

namespace {

template <class Names>
std::string join(const Names& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

class reader {
 public:
  explicit reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(long line, const std::string& reason) const { throw scene_error(file_, line, reason); }
  [[noreturn]] void fail(const toml::node& node, const std::string& reason) const { fail(line_of(node), reason); }
  static long line_of(const toml::node& node) { return static_cast<long>(node.source().begin.line); }

  // Every key of `table` must be one of `allowed`.
  void only(const toml::table& table, const std::vector<std::string>& allowed, const std::string& where) const {
    for (auto&& [key, value] : table) {
      if (std::find(allowed.begin(), allowed.end(), std::string(key.str())) == allowed.end())
        fail(static_cast<long>(key.source().begin.line ? key.source().begin.line : value.source().begin.line),
             "unknown key '" + std::string(key.str()) + "' in " + where + " (allowed: " + join(allowed) + ")");
    }
  }

  const toml::node& require(const toml::table& table, const std::string& key, const std::string& where) const {
    const toml::node* node = table.get(key);
    if (!node) fail(line_of(table), where + " needs the key '" + key + "'");
    return *node;
  }

  std::string string(const toml::node& node, const std::string& key) const {
    if (!node.is_string()) fail(node, "'" + key + "' must be a string");
    return std::string(*node.value<std::string>());
  }

  double number(const toml::node& node, const std::string& key) const {
    if (!node.is_number()) fail(node, "'" + key + "' must be a number");
    const double value = *node.value<double>();
    if (!std::isfinite(value)) fail(node, "'" + key + "' must be finite");
    return value;
  }

  long integer(const toml::node& node, const std::string& key, long low, long high) const {
    if (!node.is_integer()) fail(node, "'" + key + "' must be an integer");
    const long value = static_cast<long>(*node.value<std::int64_t>());
    if (value < low || value > high)
      fail(node, "'" + key + "' must lie in [" + std::to_string(low) + ", " + std::to_string(high) + "], not " +
                     std::to_string(value));
    return value;
  }

  bool boolean(const toml::node& node, const std::string& key) const {
    if (!node.is_boolean()) fail(node, "'" + key + "' must be true or false");
    return *node.value<bool>();
  }

  double positive(const toml::node& node, const std::string& key) const {
    const double value = number(node, key);
    if (!(value > 0)) fail(node, "'" + key + "' must be positive");
    return value;
  }

  // min_time of a [[run]] or of [throughput]: Google Benchmark's time per repetition
  double seconds_per_repetition(const toml::node& node) const {
    const double value = positive(node, "min_time");
    if (value > 10) fail(node, "'min_time' is in seconds per repetition and must be at most 10");
    return value;
  }

  std::vector<std::string> strings(const toml::node& node, const std::string& key) const {
    const toml::array* array = node.as_array();
    if (!array) fail(node, "'" + key + "' must be an array of strings");
    if (array->empty()) fail(node, "'" + key + "' must not be empty");
    std::vector<std::string> out;
    for (const toml::node& item : *array) {
      if (!item.is_string()) fail(item, "'" + key + "' must be an array of strings");
      std::string value(*item.value<std::string>());
      if (std::find(out.begin(), out.end(), value) != out.end()) fail(item, "'" + value + "' is named twice in '" + key + "'");
      out.push_back(value);
    }
    return out;
  }

  std::vector<std::string> types(const toml::node& node) const {
    const auto names = strings(node, "types");
    const auto array = node.as_array();
    for (std::size_t i = 0; i < names.size(); ++i)
      if (std::find(contact::type_names.begin(), contact::type_names.end(), names[i]) == contact::type_names.end())
        fail((*array)[i], "unknown type '" + names[i] + "' (known: " + join(contact::type_names) + ")");
    return names;
  }

  std::vector<method> methods(const toml::node& node, const std::vector<std::string>& types) const {
    const auto names = strings(node, "algorithms");
    const auto array = node.as_array();
    std::vector<method> out;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const auto m = method_named(names[i]);
      if (!m) {
        std::vector<std::string> known;
        for (method k : all_methods) known.push_back(name_of(k));
        fail((*array)[i], "unknown algorithm '" + names[i] + "' (known: " + join(known) + ")");
      }
      for (const auto& type : types)
        if (auto why = unsupported(*m, type); !why.empty()) fail((*array)[i], why + ", and this table names " + type);
      out.push_back(*m);
    }
    return out;
  }

  distribution parse_distribution(const toml::node& node, const std::string& key) const {
    distribution d;
    if (node.is_number()) {
      d.kind = distribution::shape::constant;
      d.low = d.high = number(node, key);
      d.sign = d.low < 0 ? -1 : 1;
      return d;
    }
    auto pair = [&](const toml::node& n, const std::string& name) {
      const toml::array* a = n.as_array();
      if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number())
        fail(n, "'" + name + "' must be an array of two numbers [low, high]");
      const double low = number((*a)[0], name), high = number((*a)[1], name);
      if (low > high) fail(n, "'" + name + "': low " + std::to_string(low) + " exceeds high " + std::to_string(high));
      return std::pair{low, high};
    };
    if (node.is_array()) {  // [low, high]: positive, log-uniform between the two values
      auto [low, high] = pair(node, key);
      if (!(low > 0)) fail(node, "'" + key + "' = [low, high] draws log-uniformly and needs 0 < low");
      d.kind = distribution::shape::log10;
      d.low = std::log10(low);
      d.high = std::log10(high);
      return d;
    }
    const toml::table* table = node.as_table();
    if (!table) fail(node, "'" + key + "' must be a number, [low, high] or a table {log10|log2|uniform = [a, b], sign}");
    only(*table, {"log10", "log2", "uniform", "sign"}, "'" + key + "'");
    int shapes = 0;
    for (const char* name : {"log10", "log2", "uniform"}) {
      if (const toml::node* n = table->get(name)) {
        ++shapes;
        auto [low, high] = pair(*n, std::string(name));
        d.low = low;
        d.high = high;
        d.kind = std::string(name) == "log10" ? distribution::shape::log10
                 : std::string(name) == "log2" ? distribution::shape::log2
                                               : distribution::shape::uniform;
        if (d.kind == distribution::shape::log10 && (low < -324 || high > 308.25))
          fail(*n, "'" + key + ".log10' must lie within [-324, 308.25] (the range of double)");
        if (d.kind == distribution::shape::log2 && (low < -1074 || high > 1023.99))
          fail(*n, "'" + key + ".log2' must lie within [-1074, 1023.99] (the range of double)");
      }
    }
    if (shapes != 1) fail(node, "'" + key + "' needs exactly one of log10, log2 or uniform");
    if (const toml::node* s = table->get("sign")) {
      if (d.kind == distribution::shape::uniform) fail(*s, "'" + key + "': 'sign' applies to log10 and log2 only");
      const std::string sign = string(*s, "sign");
      if (sign == "positive") d.sign = 1;
      else if (sign == "negative") d.sign = -1;
      else if (sign == "both") d.sign = 0;
      else fail(*s, "'sign' must be \"positive\", \"negative\" or \"both\", not \"" + sign + "\"");
    }
    return d;
  }

  family parse_family(const toml::table& table) const {
    family f;
    f.line = line_of(table);
    f.name = string(require(table, "name", "a [[family]]"), "name");
    f.generator = string(require(table, "generator", "family '" + f.name + "'"), "generator");
    const generator_info* info = find_generator(f.generator);
    if (!info) {
      std::vector<std::string> known;
      for (const auto& g : generators()) known.push_back(g.name);
      fail(*table.get("generator"), "unknown generator '" + f.generator + "' (known: " + join(known) + ")");
    }
    std::vector<std::string> allowed = {"name", "generator", "samples"};
    if (info->needs_ulps) allowed.push_back("ulps");
    for (const auto& p : info->required) allowed.push_back(p);
    for (const auto& p : info->optional) allowed.push_back(p);
    only(table, allowed, "family '" + f.name + "' (generator " + f.generator + ")");
    f.samples = integer(require(table, "samples", "family '" + f.name + "'"), "samples", 1, 10'000'000);
    if (info->needs_ulps) f.ulps = integer(require(table, "ulps", "family '" + f.name + "'"), "ulps", 0, 1'000'000);
    for (const auto& p : info->required)
      f.parameters[p] = parse_distribution(require(table, p, "family '" + f.name + "' (generator " + f.generator + ")"), p);
    for (const auto& p : info->optional)
      if (const toml::node* n = table.get(p)) f.parameters[p] = parse_distribution(*n, p);
    return f;
  }

  std::vector<check> checks(const toml::node& node) const {
    const auto names = strings(node, "checks");
    const auto array = node.as_array();
    std::vector<check> out;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == "accuracy") out.push_back(check::accuracy);
      else if (names[i] == "timing") out.push_back(check::timing);
      else if (names[i] == "energy") out.push_back(check::energy);
      else fail((*array)[i], "unknown check '" + names[i] + "' (known: accuracy, timing, energy)");
    }
    return out;
  }

  // [scene] plots: names of all_plots, each at most once; [] asks for none.
  std::vector<plot> plots(const toml::node& node) const {
    if (const toml::array* empty = node.as_array(); empty && empty->empty()) return {};
    const std::vector<std::string> names = strings(node, "plots");  // names each at most once
    const toml::array& array = *node.as_array();
    std::vector<plot> out;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const plot* p = std::find_if(std::begin(all_plots), std::end(all_plots),
                                   [&](plot k) { return name_of(k) == names[i]; });
      if (p == std::end(all_plots)) {
        std::vector<std::string> known;
        for (plot k : all_plots) known.push_back(name_of(k));
        fail(array[i], "unknown plot '" + names[i] + "' (known: " + join(known) + ")");
      }
      out.push_back(*p);
    }
    return out;
  }

  run parse_run(const toml::table& table) const {
    run r;
    r.line = line_of(table);
    only(table, {"types", "algorithms", "checks", "samples", "timing_inputs", "repetitions", "min_time"}, "a [[run]]");
    r.types = types(require(table, "types", "a [[run]]"));
    r.methods = methods(require(table, "algorithms", "a [[run]]"), r.types);
    r.checks = checks(require(table, "checks", "a [[run]]"));
    if (const toml::node* n = table.get("samples")) r.samples = integer(*n, "samples", 1, 10'000'000);
    if (const toml::node* n = table.get("timing_inputs")) r.timing_inputs = integer(*n, "timing_inputs", 1, 1 << 24);
    if (const toml::node* n = table.get("repetitions")) r.repetitions = static_cast<int>(integer(*n, "repetitions", 1, 100));
    if (const toml::node* n = table.get("min_time")) r.min_time = seconds_per_repetition(*n);
    return r;
  }

  throughput parse_throughput(const toml::table& table) const {
    throughput t;
    t.line = line_of(table);
    only(table, {"lanes", "cache_lanes", "repetitions", "min_time"}, "[throughput]");
    if (const toml::node* n = table.get("lanes")) t.lanes = integer(*n, "lanes", 1, 1 << 26);
    if (const toml::node* n = table.get("cache_lanes")) t.cache_lanes = integer(*n, "cache_lanes", 1, 1 << 26);
    if (const toml::node* n = table.get("repetitions")) t.repetitions = static_cast<int>(integer(*n, "repetitions", 1, 100));
    if (const toml::node* n = table.get("min_time")) t.min_time = seconds_per_repetition(*n);
    return t;
  }

  oscillator parse_oscillator(const toml::table& table) const {
    oscillator o;
    o.line = line_of(table);
    only(table, {"mass", "spring", "barrier_height", "barrier_stiffness", "sample_rate", "duration",
                 "initial_displacement", "initial_velocity", "plot_points"},
         "[oscillator]");
    if (const toml::node* n = table.get("mass")) o.mass = positive(*n, "mass");
    if (const toml::node* n = table.get("spring")) o.spring = positive(*n, "spring");
    if (const toml::node* n = table.get("barrier_height")) o.barrier_height = number(*n, "barrier_height");
    if (const toml::node* n = table.get("barrier_stiffness")) o.barrier_stiffness = positive(*n, "barrier_stiffness");
    if (const toml::node* n = table.get("sample_rate")) o.sample_rate = positive(*n, "sample_rate");
    if (const toml::node* n = table.get("duration")) o.duration = positive(*n, "duration");
    if (const toml::node* n = table.get("initial_displacement")) o.initial_displacement = number(*n, "initial_displacement");
    if (const toml::node* n = table.get("initial_velocity")) o.initial_velocity = number(*n, "initial_velocity");
    if (const toml::node* n = table.get("plot_points")) o.plot_points = integer(*n, "plot_points", 2, 100000);
    if (o.duration * o.sample_rate > 1e7)
      fail(table, "[oscillator]: duration * sample_rate must be at most 1e7 steps");
    if (o.duration * o.sample_rate < 2) fail(table, "[oscillator]: duration * sample_rate must be at least 2 steps");
    return o;
  }

  scene parse(const toml::table& root) const {
    scene s;
    s.file = file_;
    only(root, {"scene", "family", "run", "throughput", "oscillator"}, "the top level");
    const toml::node& header_node = require(root, "scene", "a scene file");
    const toml::table* header = header_node.as_table();
    if (!header) fail(header_node, "'scene' must be a table: [scene]");
    only(*header, {"name", "title", "description", "seed", "mpfr_digits10", "batch_reference", "plots"}, "[scene]");
    const toml::node& name = require(*header, "name", "[scene]");
    s.name = string(name, "name");
    if (s.name.empty() || !std::all_of(s.name.begin(), s.name.end(), [](char c) {
          return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
        }))
      fail(name, "'name' must be a non-empty identifier of a-z, 0-9, '_' and '-' (it names output files)");
    s.title = s.name;
    if (const toml::node* n = header->get("title")) s.title = string(*n, "title");
    if (const toml::node* n = header->get("description")) s.description = string(*n, "description");
    if (const toml::node* n = header->get("seed")) s.seed = static_cast<std::uint64_t>(integer(*n, "seed", 0, LONG_MAX));
    if (const toml::node* n = header->get("mpfr_digits10")) s.mpfr_digits10 = static_cast<int>(integer(*n, "mpfr_digits10", 16, 1000));
    if (const toml::node* n = header->get("batch_reference")) {
      s.batch_reference = boolean(*n, "batch_reference");
      s.batch_reference_line = line_of(*n);
    }
    if (const toml::node* n = header->get("plots")) {
      s.plots = plots(*n);
      s.plots_line = line_of(*n);
    }

    auto tables = [&](const char* key, auto&& each) {
      const toml::node* node = root.get(key);
      if (!node) return;
      const toml::array* array = node->as_array();
      if (!array || !array->is_array_of_tables())
        fail(*node, std::string("'") + key + "' must be an array of tables: [[" + key + "]]");
      for (const toml::node& item : *array) each(*item.as_table());
    };
    std::set<std::string> family_names;
    tables("family", [&](const toml::table& t) {
      family f = parse_family(t);
      if (!family_names.insert(f.name).second) fail(t, "family '" + f.name + "' is defined twice");
      s.families.push_back(std::move(f));
    });
    tables("run", [&](const toml::table& t) { s.runs.push_back(parse_run(t)); });
    if (const toml::node* n = root.get("throughput")) {
      if (!n->is_table()) fail(*n, "'throughput' must be a table: [throughput]");
      s.batch_throughput = parse_throughput(*n->as_table());
    }
    if (const toml::node* n = root.get("oscillator")) {
      if (!n->is_table()) fail(*n, "'oscillator' must be a table: [oscillator]");
      s.energy = parse_oscillator(*n->as_table());
    }
    if (s.runs.empty() && !s.batch_throughput)
      fail(header_node, "the scene asks for nothing: it needs a [[run]] or a [throughput]");
    bool solves_families = s.batch_throughput.has_value(), simulates = false;
    for (const run& r : s.runs)
      for (check c : r.checks) {
        if (c == check::energy) {
          simulates = true;
          if (!s.energy) fail(r.line, "this [[run]] asks for the energy check, and the scene has no [oscillator]");
        } else {
          solves_families = true;
          if (s.families.empty())
            fail(r.line, "this [[run]] asks for accuracy or timing, which solve the scene's families, and it has no [[family]]");
        }
      }
    if (s.batch_throughput && s.families.empty())
      fail(s.batch_throughput->line, "[throughput] solves the inputs of the scene's families, and it has no [[family]]");
    if (s.energy && !simulates) fail(s.energy->line, "[oscillator] is not used: no [[run]] asks for the energy check");
    if (s.batch_reference && !batch_timing_run(s))
      fail(s.batch_reference_line, "batch_reference: no [[run]] of the scene times batch in double");
    if (asks_for(s, plot::headline) &&
        std::none_of(s.runs.begin(), s.runs.end(), [](const run& r) {
          return asks_for(r, check::timing) && std::find(r.types.begin(), r.types.end(), "double") != r.types.end();
        }))
      fail(s.plots_line, "plots: the headline figure takes its times from this scene, and no [[run]] of it times double");
    if (!s.families.empty() && !solves_families)
      fail(s.families.front().line, "the families are not used: no [[run]] asks for accuracy or timing, and there is no [throughput]");
    return s;
  }

 private:
  std::string file_;
};

}  // namespace

scene parse_scene_text(const std::string& text, const std::string& path) {
  reader r(path);
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& error) {
    std::ostringstream reason;
    reason << error.description() << " (column " << error.source().begin.column << ")";
    throw scene_error(path, static_cast<long>(error.source().begin.line), reason.str());
  }
  return r.parse(root);
}

scene parse_scene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw scene_error(path, 0, "cannot read the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene_text(text.str(), path);
}

}  // namespace report
