#include "inputs.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>

#include "contact/harness/families.hpp"

namespace report {

namespace {

namespace harness = contact::harness;
using drawn = harness::input<double>;

drawn box(harness::seeded_source& source, const family& f) {
  const auto& p = f.parameters;
  return harness::box<double>(source, p.at("u"), p.at("dy"), p.at("phi"));
}

drawn physical(harness::seeded_source& source, const family& f) {
  const auto& p = f.parameters;
  harness::physical_ranges ranges{p.at("mass"),         p.at("spring"),      p.at("barrier_stiffness"),
                                  p.at("displacement"), p.at("compression"), p.at("velocity")};
  if (const auto rate = p.find("sample_rate"); rate != p.end()) ranges.sample_rate = rate->second;
  return harness::physical<double>(source, ranges);
}

drawn free_impact_boundary(harness::seeded_source& source, const family& f) {
  return harness::free_impact_boundary<double>(source, f.parameters.at("dy"), f.parameters.at("phi"), f.ulps);
}

drawn contact_release_boundary(harness::seeded_source& source, const family& f) {
  return harness::contact_release_boundary<double>(source, f.parameters.at("dy"), f.parameters.at("phi"), f.ulps);
}

drawn impact_grazing(harness::seeded_source& source, const family& f) {
  const auto& p = f.parameters;
  return harness::impact_grazing<double>(source, p.at("dy"), p.at("phi"), p.at("relative"));
}

drawn contact_cancellation(harness::seeded_source& source, const family& f) {
  const auto& p = f.parameters;
  // the scene's relative offset alone sets how close u lies to 2 phi dy: no further ulp steps
  return harness::contact_cancellation<double>(source, p.at("dy"), p.at("phi"), p.at("relative"), 0);
}

drawn release_cancellation(harness::seeded_source& source, const family& f) {
  const auto& p = f.parameters;
  return harness::release_cancellation<double>(source, p.at("dy"), p.at("phi"), p.at("ratio"));
}

}  // namespace

const std::vector<generator_info>& generators() {
  static const std::vector<generator_info> list = {
      {"box", {"u", "dy", "phi"}, {}, false, "u, dy and phi drawn independently (phi as |phi|)", &box},
      {"physical",
       {"mass", "spring", "barrier_stiffness", "displacement", "compression", "velocity"},
       {"sample_rate"},
       false,
       "m, K, k_b, y, dy = h_b - y and v = p/m drawn; a = 2m/dt^2 + K/2, u = (K y - 2p/dt)/a, phi = k_b/(2a)",
       &physical},
      {"free_impact_boundary",
       {"dy", "phi"},
       {},
       true,
       "dy = -|dy|, u = -dy moved by a uniform number of ulps in [-ulps, ulps]",
       &free_impact_boundary},
      {"contact_release_boundary",
       {"dy", "phi"},
       {},
       true,
       "dy = |dy|, u = fl(dy (phi - 1)) moved by a uniform number of ulps in [-ulps, ulps]",
       &contact_release_boundary},
      {"impact_grazing",
       {"dy", "phi", "relative"},
       {},
       false,
       "dy = -|dy|, u = -dy (1 + |r|): contact only just begins",
       &impact_grazing},
      {"contact_cancellation",
       {"dy", "phi", "relative"},
       {},
       false,
       "dy = |dy|, u = 2 phi dy (1 + r): s = -2 phi dy r / (1 + phi) cancels in 2 phi dy - u",
       &contact_cancellation},
      {"release_cancellation",
       {"dy", "phi", "ratio"},
       {},
       false,
       "dy = |dy|, u = |ratio| sqrt(phi) dy (halved dy (phi - 1) if that is not below): -u + sqrt(u^2 + 4 phi dy^2) "
       "cancels",
       &release_cancellation},
  };
  return list;
}

const generator_info* find_generator(const std::string& name) {
  for (const auto& g : generators())
    if (g.name == name) return &g;
  return nullptr;
}

std::vector<input> generate(const scene& s) {
  std::vector<input> out;
  for (std::size_t i = 0; i < s.families.size(); ++i) {
    const family& f = s.families[i];
    const generator_info& generator = *find_generator(f.generator);  // the parser checked the name
    // one stream per family, so that adding a family changes no other family's inputs
    harness::seeded_source source(s.seed * 0x9E3779B97F4A7C15ull + std::hash<std::string>{}(f.name));
    auto finite = [](const drawn& x) { return std::isfinite(x.u) && std::isfinite(x.dy) && std::isfinite(x.phi); };
    for (long k = 0; k < f.samples; ++k) {
      drawn x = generator.draw(source, f);
      // a draw that overflowed (e.g. u from huge parameters) is drawn again
      for (int tries = 0; tries < 100 && !finite(x); ++tries) x = generator.draw(source, f);
      out.push_back({x.u, x.dy, x.phi, static_cast<int>(i)});
    }
  }
  return out;
}

std::vector<input> mixed(const std::vector<input>& inputs, long length, std::uint64_t seed) {
  std::vector<input> shuffled = inputs;
  std::mt19937_64 engine(seed ^ 0x5DEECE66Dull);
  std::shuffle(shuffled.begin(), shuffled.end(), engine);
  std::vector<input> out;
  out.reserve(static_cast<std::size_t>(length));
  while (static_cast<long>(out.size()) < length && !shuffled.empty())
    for (const auto& in : shuffled) {
      if (static_cast<long>(out.size()) == length) break;
      out.push_back(in);
    }
  return out;
}

std::string describe(const distribution& d) {
  std::ostringstream out;
  const char* sign = d.sign == 0 ? "±" : (d.sign < 0 ? "-" : "");
  switch (d.kind) {
    case distribution::shape::constant: out << d.low; break;
    case distribution::shape::uniform: out << "U[" << d.low << ", " << d.high << "]"; break;
    case distribution::shape::log10: out << sign << "10^[" << d.low << ", " << d.high << "]"; break;
    case distribution::shape::log2: out << sign << "2^[" << d.low << ", " << d.high << "]"; break;
  }
  return out.str();
}

}  // namespace report
