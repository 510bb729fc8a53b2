#include "inputs.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>

namespace report {

const std::vector<generator_info>& generators() {
  static const std::vector<generator_info> list = {
      {"box", {"u", "dy", "phi"}, {}, false, "u, dy and phi drawn independently (phi as |phi|)"},
      {"physical",
       {"mass", "spring", "barrier_stiffness", "displacement", "compression", "velocity"},
       {"sample_rate"},
       false,
       "m, K, k_b, y, dy = h_b - y and v = p/m drawn; a = 2m/dt^2 + K/2, u = (K y - 2p/dt)/a, phi = k_b/(2a)"},
      {"free_impact_boundary", {"dy", "phi"}, {}, true, "dy = -|dy|, u = -dy moved by a uniform number of ulps in [-ulps, ulps]"},
      {"contact_release_boundary",
       {"dy", "phi"},
       {},
       true,
       "dy = |dy|, u = fl(dy (phi - 1)) moved by a uniform number of ulps in [-ulps, ulps]"},
      {"impact_grazing", {"dy", "phi", "relative"}, {}, false, "dy = -|dy|, u = -dy (1 + |r|): contact only just begins"},
      {"contact_cancellation",
       {"dy", "phi", "relative"},
       {},
       false,
       "dy = |dy|, u = 2 phi dy (1 + r): s = -2 phi dy r / (1 + phi) cancels in 2 phi dy - u"},
      {"release_cancellation",
       {"dy", "phi", "ratio"},
       {},
       false,
       "dy = |dy|, u = |ratio| sqrt(phi) dy (halved dy (phi - 1) if that is not below): -u + sqrt(u^2 + 4 phi dy^2) cancels"},
  };
  return list;
}

const generator_info* find_generator(const std::string& name) {
  for (const auto& g : generators())
    if (g.name == name) return &g;
  return nullptr;
}

namespace {

class random_source {
 public:
  explicit random_source(std::uint64_t seed) : engine_(seed) {}
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }  // [0, 1)
  bool coin() { return (engine_() >> 63) != 0; }
  long integer(long low, long high) {  // [low, high]
    const std::uint64_t span = static_cast<std::uint64_t>(high - low) + 1;
    return low + static_cast<long>(engine_() % span);
  }
  std::mt19937_64& engine() { return engine_; }

  double draw(const distribution& d) {
    double magnitude = d.low;
    switch (d.kind) {
      case distribution::shape::constant: return d.low;
      case distribution::shape::uniform: return d.low + (d.high - d.low) * unit();
      case distribution::shape::log10: magnitude = std::pow(10.0, d.low + (d.high - d.low) * unit()); break;
      case distribution::shape::log2: magnitude = std::exp2(d.low + (d.high - d.low) * unit()); break;
    }
    const int sign = d.sign != 0 ? d.sign : (coin() ? 1 : -1);
    return sign * magnitude;
  }

 private:
  std::mt19937_64 engine_;
};

// x moved by k representable doubles (through zero if need be), saturating at +-max.
double step_ulps(double x, long k) {
  auto order = [](double v) -> std::int64_t {
    const auto bits = std::bit_cast<std::int64_t>(v);
    return bits >= 0 ? bits : -(bits & 0x7fffffffffffffff);
  };
  const std::int64_t largest = order(1.7976931348623157e308);
  std::int64_t o = order(x) + k;
  if (o > largest) o = largest;
  if (o < -largest) o = -largest;
  const std::int64_t bits = o >= 0 ? o : ((-o) | std::int64_t(0x8000000000000000ull));
  return std::bit_cast<double>(bits);
}

input draw(random_source& r, const family& f, int index) {
  const auto& p = f.parameters;
  auto get = [&](const char* name) { return r.draw(p.at(name)); };
  input in{0, 0, 0, index};
  const std::string& g = f.generator;
  if (g == "box") {
    in.u = get("u");
    in.dy = get("dy");
    in.phi = std::fabs(get("phi"));
  } else if (g == "physical") {
    const double m = std::fabs(get("mass")), K = std::fabs(get("spring")), kb = std::fabs(get("barrier_stiffness"));
    const double y = get("displacement"), dy = get("compression"), v = get("velocity");
    const double rate = p.count("sample_rate") ? std::fabs(get("sample_rate")) : 44100.0;
    const double dt = 1.0 / rate;
    const double a = 2 * m / (dt * dt) + K / 2;
    const double momentum = m * v;
    in.u = (K * y - 2 * momentum / dt) / a;
    in.dy = dy;
    in.phi = kb / (2 * a);
  } else if (g == "free_impact_boundary") {
    in.dy = -std::fabs(get("dy"));
    in.phi = std::fabs(get("phi"));
    in.u = step_ulps(-in.dy, r.integer(-f.ulps, f.ulps));
  } else if (g == "contact_release_boundary") {
    in.dy = std::fabs(get("dy"));
    in.phi = std::fabs(get("phi"));
    in.u = step_ulps(in.dy * (in.phi - 1), r.integer(-f.ulps, f.ulps));
  } else if (g == "impact_grazing") {
    in.dy = -std::fabs(get("dy"));
    in.phi = std::fabs(get("phi"));
    in.u = std::fma(-in.dy, std::fabs(get("relative")), -in.dy);
  } else if (g == "contact_cancellation") {
    in.dy = std::fabs(get("dy"));
    in.phi = std::fabs(get("phi"));
    const double t = 2 * in.phi * in.dy;
    in.u = std::fma(t, get("relative"), t);
  } else {  // release_cancellation
    in.dy = std::fabs(get("dy"));
    in.phi = std::fabs(get("phi"));
    in.u = std::fabs(get("ratio")) * std::sqrt(in.phi) * in.dy;
    const double bound = in.dy * (in.phi - 1);
    if (!(in.u < bound) && bound > 0) in.u = bound / 2;
  }
  return in;
}

}  // namespace

std::vector<input> generate(const scene& s) {
  std::vector<input> out;
  for (std::size_t i = 0; i < s.families.size(); ++i) {
    const family& f = s.families[i];
    random_source r(s.seed * 0x9E3779B97F4A7C15ull + std::hash<std::string>{}(f.name));
    for (long k = 0; k < f.samples; ++k) {
      input in = draw(r, f, static_cast<int>(i));
      // a draw that overflowed (e.g. u from huge parameters) is drawn again
      for (int tries = 0; tries < 100 && !(std::isfinite(in.u) && std::isfinite(in.dy) && std::isfinite(in.phi)); ++tries)
        in = draw(r, f, static_cast<int>(i));
      out.push_back(in);
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
