// The error map (contact-check --map, contact-report --candidate): a solver's
// largest error in ulps over a grid of log10|u| by log10|dy| that covers the
// domain, a panel per sign of u and dy (they decide the case) and per phi,
// with the case boundaries (A.29)/(A.30) and (A.31)/(A.32) drawn as lines.
// Written as DIR/STEM.dat and STEM.gp, drawn by gnuplot as STEM.png and STEM.svg.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "contact/harness/candidate.hpp"
#include "contact/reference.hpp"
#include "domain.hpp"

namespace check {

struct map_written {
  bool ok = false;
  std::string message;  // the files written, or why not
};

// Answers s for each input (NaN where there is none).
using batch_solver = std::function<std::vector<double>(const std::vector<input<double>>&)>;

inline batch_solver solver_of(contact::harness::candidate& c) {
  return [&c](const std::vector<input<double>>& inputs) {
    std::vector<double> out;
    std::vector<input<double>> rest = inputs;
    // a fault leaves the rest unanswered: they are asked again, the faulting one counts as NaN
    while (!rest.empty()) {
      const auto outcomes = c.solve(rest);
      std::size_t i = 0;
      for (; i < rest.size() && outcomes[i].answered(); ++i) out.push_back(outcomes[i].s);
      if (i == rest.size()) break;
      out.push_back(std::nan(""));
      rest.erase(rest.begin(), rest.begin() + long(i) + 1);
    }
    return out;
  };
}

struct map_grid {
  double u_low, u_high, dy_low, dy_high;  // log10 of the magnitudes
  int cells = 36;                         // per axis
  int samples = 2;                        // per cell
  std::vector<double> phis;               // a row of panels each
};

// A grid that covers the domain: whole decades around its |u| and |dy|, and
// three values of phi spread over its range (one where it has one).
template <class T>
map_grid grid_of(const domain<T>& d) {
  map_grid g;
  g.u_low = std::floor(std::log10(d.u().least));
  g.u_high = std::ceil(std::log10(d.u().most));
  g.dy_low = std::floor(std::log10(d.dy().least));
  g.dy_high = std::ceil(std::log10(d.dy().most));
  if (g.u_high <= g.u_low) g.u_high = g.u_low + 1;
  if (g.dy_high <= g.dy_low) g.dy_high = g.dy_low + 1;
  const double low = std::log10(d.phi().least), high = std::log10(d.phi().most);
  if (!(d.phi().most > 0)) g.phis = {0};
  else if (!(high - low > 1)) g.phis = {d.phi().most};
  else
    for (double f : {1.0 / 6, 0.5, 5.0 / 6}) g.phis.push_back(std::pow(10.0, std::round(2 * (low + f * (high - low))) / 2));
  return g;
}

// The quadrants of signs, as panels: (sign of u, sign of dy).
inline constexpr int quadrants[4][2] = {{1, -1}, {-1, -1}, {1, 1}, {-1, 1}};

// The largest ulp error of `solve` in each cell; NaN for a NaN answer, infinity for an infinite one.
template <class T>
std::vector<double> map_errors(const batch_solver& solve, const map_grid& g, std::uint64_t seed = 7) {
  seeded_source source(seed);
  std::vector<input<double>> inputs;
  const double du = (g.u_high - g.u_low) / g.cells, ddy = (g.dy_high - g.dy_low) / g.cells;
  for (double phi : g.phis)
    for (const auto& q : quadrants)
      for (int j = 0; j < g.cells; ++j)
        for (int i = 0; i < g.cells; ++i)
          for (int k = 0; k < g.samples; ++k) {
            const double u = q[0] * std::pow(10.0, g.u_low + (i + contact::harness::unit(source)) * du);
            const double dy = q[1] * std::pow(10.0, g.dy_low + (j + contact::harness::unit(source)) * ddy);
            inputs.push_back({double(T(u)), double(T(dy)), double(T(phi))});
          }
  const auto answers = solve(inputs);
  std::vector<double> worst(inputs.size() / std::size_t(g.samples), 0.0);
  for (std::size_t n = 0; n < inputs.size(); ++n) {
    const auto& x = inputs[n];
    const auto exact = contact::reference::solve<T>(T(x.u), T(x.dy), T(x.phi));
    double error = contact::reference::accepted_ulp_error<T>(T(answers[n]), exact, T(x.dy));
    if (std::isnan(error) || std::isinf(answers[n])) error = std::numeric_limits<double>::infinity();
    double& w = worst[n / std::size_t(g.samples)];
    w = std::max(w, error);
  }
  return worst;
}

namespace detail_map {

// log10 of the error as the colour: 0.1 ulp and below at the bottom, NaN and infinity at `top`.
inline constexpr double top = 18;
inline double shade(double error) {
  if (!std::isfinite(error)) return top;
  return std::min(top - 1, std::log10(std::max(error, 0.1)));
}

inline std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

// The gnuplot commands of one panel's boundary line, log10|dy| = log10|u| - offset,
// and the names of the cases on its sides that the panel shows.
inline std::string cases_of(const int q[2], double phi, double u_low, double u_high, double dy_low, double dy_high) {
  std::ostringstream gp;
  gp << "unset label\n";
  auto label = [&](const char* text, bool upper_left) {
    gp << "set label " << quoted(text) << " at graph " << (upper_left ? "0.05,0.92" : "0.7,0.08")
       << " front font ',10' tc rgb '#202020'\n";
  };
  // the case above-left of the line, the case below-right, and the line's offset (NaN: no line)
  const char *above = "free", *below = "free";
  double offset = std::nan("");
  if (q[1] < 0 && q[0] > 0) above = "free", below = "impact", offset = 0;
  else if (q[1] > 0 && q[0] > 0) {
    above = "release", below = "contact";
    if (phi > 1) offset = std::log10(phi - 1);
    else above = "contact";
  } else if (q[1] > 0) {
    above = "contact", below = "release";
    if (phi < 1) offset = std::log10(1 - phi);
    else above = "release";
  }
  if (std::isnan(offset)) {
    label(above, true);
    gp << "f(x) = NaN\n";
    return gp.str();
  }
  const bool shows_above = dy_high > u_low - offset, shows_below = dy_low < u_high - offset;
  if (shows_above) label(above, true);
  if (shows_below) label(below, !shows_above);
  gp << "f(x) = x - (" << offset << ")\n";
  return gp.str();
}

}  // namespace detail_map

// Writes DIR/STEM.dat, STEM.gp and, through gnuplot, STEM.png and STEM.svg.
inline map_written write_map_files(const std::vector<double>& worst, const map_grid& g, double max_ulp,
                                   const std::string& dir, const std::string& stem, const std::string& title) {
  namespace fs = std::filesystem;
  using detail_map::quoted;
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path base = fs::path(dir) / stem;
  std::ofstream dat(base.string() + ".dat");
  if (!dat) return {false, "cannot write " + base.string() + ".dat"};
  const double du = (g.u_high - g.u_low) / g.cells, ddy = (g.dy_high - g.dy_low) / g.cells;
  std::size_t n = 0;
  const int panels = int(g.phis.size()) * 4;
  for (int p = 0; p < panels; ++p) {
    dat << "# panel " << p << ": phi = " << g.phis[std::size_t(p / 4)] << ", sign of u " << quadrants[p % 4][0]
        << ", sign of dy " << quadrants[p % 4][1] << "; log10|u| log10|dy| shade max_ulps\n";
    for (int j = 0; j < g.cells; ++j) {
      for (int i = 0; i < g.cells; ++i, ++n)
        dat << g.u_low + (i + 0.5) * du << ' ' << g.dy_low + (j + 0.5) * ddy << ' ' << detail_map::shade(worst[n]) << ' '
            << worst[n] << '\n';
      dat << '\n';
    }
    dat << "\n";
  }
  if (!dat) return {false, "cannot write " + base.string() + ".dat"};
  dat.close();

  std::ostringstream body;
  const int rows = int(g.phis.size());
  body << "set multiplot layout " << rows << ",4 title " << quoted(title) << "\n"
       << "set xrange [" << g.u_low << ":" << g.u_high << "]\nset yrange [" << g.dy_low << ":" << g.dy_high << "]\n"
       << "set cbrange [-1:" << detail_map::top << "]\n"
       << "set palette defined (-1 '#1a9850', " << std::log10(max_ulp) << " '#a6d96a', " << std::log10(max_ulp) + 0.01
       << " '#fee08b', 4 '#fdae61', 10 '#f46d43', 16 '#a50026', 17.5 '#40004b', 18 'black')\n"
       << "set cblabel 'log10 of the largest error in ulps (18: NaN or inf)'\n"
       << "set xlabel 'log10 |u|'\nset ylabel 'log10 |dy|'\nset key off\nset tics out\n";
  for (int p = 0; p < panels; ++p) {
    const auto& q = quadrants[p % 4];
    const double phi = g.phis[std::size_t(p / 4)];
    char heading[160];
    std::snprintf(heading, sizeof heading, "u %s 0, dy %s 0, phi = %.3g", q[0] > 0 ? ">" : "<", q[1] > 0 ? ">" : "<", phi);
    body << detail_map::cases_of(q, phi, g.u_low, g.u_high, g.dy_low, g.dy_high) << "set title " << quoted(heading) << "\n"
         << (p % 4 == 3 ? "set colorbox\n" : "unset colorbox\n")
         << "plot " << quoted(stem + ".dat") << " index " << p
         << " using 1:2:3 with image, f(x) with lines lw 2 lc rgb 'black'\n";
  }
  body << "unset multiplot\n";
  const int width = 1700, height = 420 * rows + 60;
  std::ofstream gp(base.string() + ".gp");
  gp << "# draws " << stem << ".png and " << stem << ".svg from " << stem << ".dat: cd here, then gnuplot " << stem
     << ".gp\n"
     << "set terminal pngcairo size " << width << "," << height << " noenhanced font 'Sans,10'\nset output "
     << quoted(stem + ".png") << "\n"
     << body.str() << "unset output\nreset\n"
     << "set terminal svg size " << width << "," << height << " noenhanced font 'Sans,10'\nset output "
     << quoted(stem + ".svg") << "\n"
     << body.str() << "unset output\n";
  gp.close();
  if (!gp) return {false, "cannot write " + base.string() + ".gp"};
  const std::string command = "cd '" + dir + "' && " + std::string(CONTACT_GNUPLOT) + " '" + stem + ".gp' > '" + stem +
                              ".log' 2>&1";
  if (std::system(command.c_str()) != 0)
    return {false, "gnuplot failed on " + base.string() + ".gp (see " + base.string() + ".log)"};
  return {true, base.string() + ".png and .svg"};
}

template <class T>
map_written write_error_map(contact::harness::candidate& c, const domain<T>& d, double max_ulp, const std::string& dir,
                            const std::string& stem, const std::string& title) {
  const map_grid g = grid_of(d);
  return write_map_files(map_errors<T>(solver_of(c), g), g, max_ulp, dir, stem, title + " on " + d.name());
}

}  // namespace check
