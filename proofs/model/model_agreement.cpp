// proofs.model_agreement: the Gappa models are the code.
//
// Each proofs/gappa/stable_<branch>.g mirrors one branch of the stable double
// path by hand. This test reads the model's computed expression `s`, evaluates
// it in double with exactly the model's roundings (gappa_model.hpp), and
// compares it bit for bit with the library's plain-path formula for that branch
// on at least `per_branch` inputs that the plain stage (stage::plain) routes to it; and
// with the solver's returned s, unless the model's value is on the wrong side
// of dy (or below -u in impact), where a clamp must have changed it. A slip in
// either the model or the code fails it.
//
// Before that, it shows it can fail: every single-operation mutant of every
// model (an operator swapped, an fma split into two roundings, a negation
// dropped), an altered model text, and an altered code formula must each be
// told apart on the branch's inputs, but for the mutants a model declares
// indistinguishable, with its reason ("#! indistinguishable:" lines).
#include <bit>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "contact/harness/families.hpp"
#include "contact/stable.hpp"
#include "gappa_model.hpp"

namespace {

using contact::harness::input;
using contact::proofs::evaluator;
using contact::proofs::model;
using contact::proofs::model_error;
using contact::proofs::node;
using contact::proofs::node_ptr;
using contact::proofs::parse_model;

constexpr std::size_t per_branch = 100000;
constexpr std::size_t mutant_inputs = 5000;  // a mutant must differ on one of the first of these

struct branch {
  std::string name;  // proofs/gappa/stable_<name>.g
  // the model's free variables for an input
  std::function<std::map<std::string, double>(const input<double>&)> model_inputs;
  // the library's plain-path formula for this branch
  std::function<double(const input<double>&)> code;
  // whether the model's value needs no clamp in the plain stage
  std::function<bool(const input<double>&, double)> on_its_side;
  std::vector<input<double>> inputs;
};

std::vector<branch> branches() {
  namespace form = contact::stable_form;
  auto u_dy_phi = [](const input<double>& x) {
    return std::map<std::string, double>{{"u_", x.u}, {"dy_", x.dy}, {"phi_", x.phi}};
  };
  auto release = [](const input<double>& x) { return form::release(x.u, x.dy, x.phi); };
  auto above_dy = [](const input<double>& x, double s) { return s > x.dy; };
  return {
      {"free", [](const input<double>& x) { return std::map<std::string, double>{{"u_", x.u}}; },
       [](const input<double>& x) { return contact::detail::stage::plain(x.u, x.dy, x.phi).s; },
       [](const input<double>&, double) { return true; }, {}},
      {"impact",
       [](const input<double>& x) {
         return std::map<std::string, double>{{"u_", x.u}, {"gap_", -x.dy}, {"phi_", x.phi}};
       },
       [](const input<double>& x) { return form::impact(x.u, double(-x.dy), x.phi); },
       [](const input<double>& x, double s) { return !(s < -x.u) && s < x.dy; }, {}},
      {"contact", u_dy_phi, [](const input<double>& x) { return form::contact(x.u, x.dy, x.phi); },
       [](const input<double>& x, double s) { return !(s > x.dy); }, {}},
      {"release_u_positive", u_dy_phi, release, above_dy, {}},
      {"release_u_nonpositive", u_dy_phi, release, above_dy, {}},
  };
}

std::size_t branch_index(const input<double>& x, contact::contact_case which) {
  switch (which) {
    case contact::contact_case::free: return 0;
    case contact::contact_case::impact: return 1;
    case contact::contact_case::contact: return 2;
    case contact::contact_case::release: return x.u > 0 ? 3 : 4;
    default: throw std::logic_error("an input of the window solved as invalid");
  }
}

// The families of the harness, kept where the plain path runs (safe_window),
// with a zero now and then where the window allows one.
input<double> draw(contact::harness::seeded_source& source) {
  namespace h = contact::harness;
  using s = h::distribution::shape;
  const h::distribution window_any{s::log2, -240, 240, 0}, window_positive{s::log2, -240, 240, 1};
  for (;;) {
    input<double> x;
    const long pick = source.integer(0, 9);
    if (pick < 5) x = h::box<double>(source, window_any, window_any, window_positive);
    else if (pick < 7) x = h::any_boundary<double>(source);
    else if (pick < 9) x = h::any_cancellation<double>(source);
    else x = h::physical<double>(source, h::audio_rate());
    if (source.integer(0, 49) == 0) x.u = 0;
    if (source.integer(0, 49) == 0) x.dy = 0;
    if (source.integer(0, 99) == 0) x.phi = 0;
    if (contact::detail::safe_window<double>::holds(x.u, x.dy, x.phi) && x.phi >= 0) return x;
  }
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

std::string show(const input<double>& x) {
  char text[160];
  std::snprintf(text, sizeof text, "u=%a dy=%a phi=%a", x.u, x.dy, x.phi);
  return text;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The model's s on an input, or nothing where it cannot be evaluated in double.
std::optional<double> model_value(const model& m, const branch& b, const input<double>& x) {
  try {
    return evaluator(m, b.model_inputs(x)).value_of("s");
  } catch (const model_error&) {
    return std::nullopt;
  }
}

// Whether the model and a formula differ on one of the first inputs of the branch.
bool told_apart(const model& m, const branch& b, const std::function<double(const input<double>&)>& code) {
  const std::size_t n = std::min(mutant_inputs, b.inputs.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto v = model_value(m, b, b.inputs[i]);
    if (!v || !same_bits(*v, code(b.inputs[i]))) return true;
  }
  return false;
}

// ---- single-operation mutants of a model ----------------------------------------

node_ptr deep_copy(const node_ptr& n) {
  auto c = std::make_shared<node>(*n);
  for (auto& o : c->operands) o = deep_copy(o);
  return c;
}

// The nodes of the computed expression: the definitions reachable from s through
// rounded names (the computed ones, not the exact S side), in a fixed order;
// owners[i], when asked for, names the definition that holds node i.
void computed_nodes(model& m, const node_ptr& n, std::vector<node_ptr>& out, std::set<std::string>& seen,
                    std::vector<std::string>* owners = nullptr, const std::string& owner = "s") {
  out.push_back(n);
  if (owners) owners->push_back(owner);
  if (n->what == node::kind::variable && m.definitions.count(n->name) && seen.insert(n->name).second)
    computed_nodes(m, m.definitions[n->name], out, seen, owners, n->name);
  for (auto& o : n->operands) computed_nodes(m, o, out, seen, owners, owner);
}

// The mutants a model declares indistinguishable by testing, one per line
// "#! indistinguishable: <mutation> in <definition>: <why>", each keyed
// "<mutation> in <definition>".
std::set<std::string> declared_indistinguishable(const std::string& text) {
  std::set<std::string> keys;
  const std::string tag = "#! indistinguishable: ";
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(tag, 0) != 0) continue;
    const std::string rest = line.substr(tag.size());
    const auto colon = rest.find(':');
    if (colon == std::string::npos) throw model_error("an indistinguishable mutant without its reason: " + line);
    keys.insert(rest.substr(0, colon));
  }
  return keys;
}

model copy_of(const model& m) {
  model c = m;
  for (auto& [name, def] : c.definitions) def = deep_copy(def);
  return c;
}

// The mutants of the node numbered `index`: each a description and a mutated model.
std::vector<std::pair<std::string, model>> mutants_at(const model& original, std::size_t index) {
  std::vector<std::pair<std::string, model>> out;
  auto mutate = [&](const std::string& what, auto change) {
    model m = copy_of(original);
    std::vector<node_ptr> nodes;
    std::set<std::string> seen{"s"};
    computed_nodes(m, m.definitions.at("s"), nodes, seen);
    change(*nodes[index]);
    out.emplace_back(what, std::move(m));
  };
  model probe = copy_of(original);
  std::vector<node_ptr> nodes;
  std::set<std::string> seen{"s"};
  computed_nodes(probe, probe.definitions.at("s"), nodes, seen);
  using k = node::kind;
  switch (nodes[index]->what) {
    case k::add: mutate("+ -> -", [](node& n) { n.what = k::subtract; }); break;
    case k::subtract: mutate("- -> +", [](node& n) { n.what = k::add; }); break;
    case k::multiply: mutate("* -> /", [](node& n) { n.what = k::divide; }); break;
    case k::divide: mutate("/ -> *", [](node& n) { n.what = k::multiply; }); break;
    case k::negate: mutate("negation dropped", [](node& n) {
        const node operand = *n.operands[0];
        n = operand;
      }); break;
    case k::fma:
      // a * b + c with two roundings: round(round(a * b) + c), as code without fma would do
      mutate("fma split", [rounding = *original.roundings.begin()](node& n) {
        auto product = std::make_shared<node>();
        product->what = k::multiply;
        product->operands = {n.operands[0], n.operands[1]};
        auto rounded_product = std::make_shared<node>();
        rounded_product->what = k::round;
        rounded_product->name = rounding;
        rounded_product->operands = {product};
        n.what = k::add;
        n.operands = {rounded_product, n.operands[2]};
      });
      break;
    default: break;
  }
  return out;
}

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  failures += !ok;
}

// The test of the test: what it must catch, it catches.
void check_it_can_fail(std::vector<branch>& all, const std::filesystem::path& dir) {
  for (auto& b : all) {
    const std::string text = read(dir / ("stable_" + b.name + ".g"));
    const model m = parse_model(text);
    // A mutant the model declares indistinguishable must exist and must not be
    // told apart (else the declaration is stale); it then counts as neither.
    std::set<std::string> declared = declared_indistinguishable(text);
    std::vector<node_ptr> nodes;
    std::vector<std::string> owners;
    model probe = copy_of(m);
    std::set<std::string> seen{"s"};
    computed_nodes(probe, probe.definitions.at("s"), nodes, seen, &owners);
    int count = 0, caught = 0, exempt = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (auto& [what, mutant] : mutants_at(m, i)) {
        const std::string key = what + " in " + owners[i];
        const bool found = told_apart(mutant, b, b.code);
        if (declared.erase(key)) {
          check(!found, b.name + ": the mutant declared indistinguishable, " + key + ", is not told apart");
          ++exempt;
          continue;
        }
        ++count;
        caught += found;
        if (!found) std::printf("     mutant of %s not told apart: %s (node %zu)\n", b.name.c_str(), key.c_str(), i);
      }
    for (const auto& key : declared) check(false, b.name + ": no mutant " + key + " to declare indistinguishable");
    check(count > 0 && caught == count,
          b.name + ": " + std::to_string(caught) + " of " + std::to_string(count) +
              " single-operation mutants of the model told apart" +
              (exempt ? " (and " + std::to_string(exempt) + " declared indistinguishable)" : ""));
  }
  // an altered model text: the contact numerator as a rounded product and a sum
  {
    auto& b = all[2];
    std::string text = read(dir / "stable_contact.g");
    const std::string fused = "rnd(fma(phi, rnd(2 * dy), -u))";
    const auto at = text.find(fused);
    check(at != std::string::npos, "stable_contact.g computes the numerator as " + fused);
    if (at != std::string::npos) {
      text.replace(at, fused.size(), "rnd(rnd(phi * rnd(2 * dy)) - u)");
      check(told_apart(parse_model(text), b, b.code), "contact: the model with an unfused numerator is told apart");
    }
  }
  // altered code: the (A.31) numerator rounded twice, and impact with u + gap
  check(told_apart(parse_model(read(dir / "stable_contact.g")), all[2],
                   [](const input<double>& x) { return (x.phi * (2 * x.dy) - x.u) / (1 + x.phi); }),
        "contact: code with an unfused numerator is told apart from the model");
  check(told_apart(parse_model(read(dir / "stable_impact.g")), all[1],
                   [](const input<double>& x) {  // stable_form::impact but for the slip
                     using contact::detail::two_sum;
                     const double gap = -x.dy, push = x.phi * gap, push_error = std::fma(x.phi, gap, -push);
                     const double root = std::sqrt(std::fma(x.u, x.u, 4 * (push * (x.u + gap))));
                     const auto head = two_sum(x.u, 2 * push);
                     const auto numerator = two_sum(head.high, root);
                     const double numerator_low = numerator.low + (head.low + 2 * push_error);
                     const auto one_plus_phi = two_sum(1.0, x.phi);
                     const double denominator = 2 * one_plus_phi.high, inverse = 1 / denominator;
                     const double quotient = numerator.high * inverse;
                     const double residual = std::fma(-quotient, denominator, numerator.high);
                     const double correction = std::fma(-quotient, 2 * one_plus_phi.low, residual + numerator_low);
                     return -std::fma(correction, inverse, quotient);
                   }),
        "impact: code with u + gap in the discriminant is told apart from the model");
  // the reader refuses what it does not understand rather than guessing
  auto refused = [](const std::string& text) {
    try {
      parse_model(text);
      return false;
    } catch (const model_error&) {
      return true;
    }
  };
  check(refused("@rnd = float<24, ne>;\ns = rnd(u_);"), "the reader refuses a rounding other than binary64 to nearest even");
  check(refused("@rnd = float<53, ne>;\ns = rnd(exp(u_));"), "the reader refuses an unknown function");
  check(refused("@rnd = float<53, ne>;\ns = rnd(u_ * 0.1);"), "the reader refuses a decimal number");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s proofs/gappa\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  auto all = branches();
  try {
    // every model has a branch here, every branch a model
    std::set<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("stable_", 0) == 0 && entry.path().extension() == ".g") files.insert(name);
    }
    std::set<std::string> known;
    for (const auto& b : all) known.insert("stable_" + b.name + ".g");
    check(files == known, "the branches checked here are exactly the models in " + dir.string());

    contact::harness::seeded_source source(20261123);
    std::size_t draws = 0;
    auto short_of_inputs = [&] {
      for (const auto& b : all)
        if (b.inputs.size() < per_branch) return true;
      return false;
    };
    while (short_of_inputs() && draws < 200 * per_branch) {
      const input<double> x = draw(source);
      ++draws;
      auto& b = all[branch_index(x, contact::detail::stage::plain(x.u, x.dy, x.phi).which)];
      if (b.inputs.size() < per_branch) b.inputs.push_back(x);
    }

    check_it_can_fail(all, dir);

    for (auto& b : all) {
      const model m = parse_model(read(dir / ("stable_" + b.name + ".g")));
      std::size_t agree = 0, clamped = 0;
      std::string first_difference;
      for (const auto& x : b.inputs) {
        const auto v = model_value(m, b, x);
        const double code = b.code(x);
        const double solved = contact::detail::stage::plain(x.u, x.dy, x.phi).s;
        bool ok = v && same_bits(*v, code);
        if (ok && !same_bits(*v, solved)) {
          ok = !b.on_its_side(x, *v);  // only a clamp may change the formula's value
          clamped += ok;
        }
        agree += ok;
        if (!ok && first_difference.empty()) {
          char text[200];
          std::snprintf(text, sizeof text, "; first difference at %s: model %a, code %a, solve %a", show(x).c_str(),
                        v ? *v : std::nan(""), code, solved);
          first_difference = text;
        }
      }
      check(b.inputs.size() >= per_branch && agree == b.inputs.size(),
            b.name + ": model and code agree bit for bit on " + std::to_string(agree) + " of " +
                std::to_string(b.inputs.size()) + " inputs (" + std::to_string(clamped) + " clamped)" + first_difference);
    }
    std::printf("%zu draws\n", draws);
  } catch (const std::exception& error) {
    check(false, error.what());
  }
  std::printf("%d failed check%s\n", failures, failures == 1 ? "" : "s");
  return failures ? 1 : 0;
}
