// The plots: data files and one gnuplot script that draws each plot as SVG and PNG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "output.hpp"

namespace report {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& text) {  // a gnuplot single-quoted string
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string value(double x) {
  if (!std::isfinite(x) || x <= 0) return "?";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string label(std::string text) {  // no enhanced-text markup in titles
  for (char& c : text)
    if (c == '_') c = ' ';
  return text;
}

void begin(std::ostream& gp, const std::string& name, const std::string& title) {
  gp << "\n# " << name << "\nreset\nset datafile missing '?'\nset grid\nset key outside right top\n"
     << "set terminal svg size 1000,620 dynamic noenhanced font 'Helvetica,12' background rgb 'white'\n"
     << "set output " << quoted(name + ".svg") << "\nset title " << quoted(title) << "\n";
}

void finish(std::ostream& gp, const std::string& name) {
  gp << "set terminal pngcairo size 1000,620 noenhanced font 'Helvetica,11' background rgb 'white'\n"
     << "set output " << quoted(name + ".png") << "\nreplot\nunset output\n";
}

// Pareto chart: max (filled) and p99 (open) ulp error against ns per solve, one per scene.
void write_pareto(std::ostream& gp, const fs::path& dir, const scene_result& r, std::vector<std::string>& made) {
  std::vector<std::pair<const accuracy_result*, const timing_result*>> points;
  for (const auto& a : r.accuracy)
    for (const auto& t : r.timing)
      if (a.type == t.type && a.algorithm == t.algorithm && !t.ns.empty()) points.emplace_back(&a, &t);
  if (points.empty()) return;
  const std::string name = "pareto_" + r.s.name;
  std::ofstream dat(dir / (name + ".dat"));
  bool clamped_inf = false;
  auto y = [&](double e) {  // a log axis shows neither 0 nor infinity
    if (!(e <= 1e19)) {
      clamped_inf = true;
      return 1e19;
    }
    return std::max(e, 1e-3);
  };
  for (const auto& [a, t] : points)
    dat << "# " << a->type << " " << a->algorithm << "\n"
        << t->median << " " << y(a->ulps.max) << " " << t->min << " " << t->max << " " << y(a->ulps.p99) << "\n\n\n";
  begin(gp, name, "Scene " + r.s.name + ": error against run time (filled: max, open: 99th percentile)");
  gp << "set logscale xy\nset xlabel 'ns per solve (median; bars: min to max over repetitions)'\n"
     << "set ylabel " << quoted(std::string("ulp error (0 drawn at 1e-3") + (clamped_inf ? "; 1e19 and above, inf and NaN at 1e19)" : ")"))
     << "\nset yrange [5e-4:*]\nset format y '%g'\nplot ";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int colour = static_cast<int>(i % 8) + 1, shape = static_cast<int>(i / 8) * 4 + 5;
    gp << (i ? ", \\\n  " : "") << quoted(name + ".dat") << " index " << i << " using 1:2:3:4 with xerrorbars lc "
       << colour << " pt " << shape << " ps 1.6 title " << quoted(points[i].first->type + " " + points[i].first->algorithm)
       << ", '' index " << i << " using 1:5 with points lc " << colour << " pt " << shape - 1 << " ps 1.6 notitle";
  }
  gp << "\n";
  finish(gp, name);
  made.push_back(name);
}

// The tick label of a histogram bin: its upper edge, on every fourth power of two when the range is wide.
std::string histogram_tick(int bin, int first, int last) {
  if (bin <= 2) return bin == 0 ? "0" : (bin == 1 ? "0.5" : "1");
  if (bin == 63) return ">2^60";
  if (bin == 64) return "NaN";
  if (last - first <= 16 || (bin - 2) % 4 == 0) return "2^" + std::to_string(bin - 2);
  return "";
}

// Error histogram of one (type, algorithm), one line per scene that ran it.
void write_histogram(std::ostream& gp, const fs::path& dir, const std::vector<scene_result>& scenes,
                     const std::string& type, const std::string& algorithm, std::vector<std::string>& made) {
  std::vector<std::pair<std::string, const accuracy_result*>> lines;
  for (const auto& r : scenes)
    for (const auto& a : r.accuracy)
      if (a.type == type && a.algorithm == algorithm) lines.emplace_back(r.s.name, &a);
  int first = histogram_bins, last = 0;
  for (const auto& [scene, a] : lines)
    for (int b = 0; b < histogram_bins; ++b)
      if (a->histogram[static_cast<std::size_t>(b)]) first = std::min(first, b), last = std::max(last, b);
  if (first > last) return;
  const std::string name = "hist_" + type + "_" + algorithm;
  std::ofstream dat(dir / (name + ".dat"));
  for (int b = first; b <= last; ++b) {
    dat << b << " \"" << histogram_tick(b, first, last) << "\"";
    for (const auto& [scene, a] : lines)
      dat << " " << value(double(a->histogram[static_cast<std::size_t>(b)]) / double(std::max(1L, a->samples)));
    dat << "\n";
  }
  begin(gp, name, label(type) + ", " + label(algorithm) + ": distribution of the ulp error");
  gp << "set logscale y\nset xlabel 'ulp error (upper edge of each bin; bins double from 1 ulp on)'\n"
     << "set ylabel 'fraction of samples'\nset xtics rotate by -45\n"
     << "set xrange [" << first - 0.5 << ":" << last + 0.5 << "]\nset style data linespoints\nplot ";
  for (std::size_t i = 0; i < lines.size(); ++i)
    gp << (i ? ", \\\n  " : "") << quoted(name + ".dat") << " using 1:" << i + 3 << (i == 0 ? ":xtic(2)" : "")
       << " lw 2 pt 7 title " << quoted(lines[i].first);
  gp << "\n";
  finish(gp, name);
  made.push_back(name);
}

void write_histograms(std::ostream& gp, const fs::path& dir, const std::vector<scene_result>& scenes,
                      std::vector<std::string>& made) {
  std::vector<std::pair<std::string, std::string>> series;
  for (const auto& r : scenes)
    for (const auto& a : r.accuracy)
      if (std::find(series.begin(), series.end(), std::pair{a.type, a.algorithm}) == series.end())
        series.emplace_back(a.type, a.algorithm);
  for (const auto& [type, algorithm] : series) write_histogram(gp, dir, scenes, type, algorithm, made);
}

// Energy error against time, one line per result of `group`, titled by type or by algorithm.
void write_energy_plot(std::ostream& gp, const fs::path& dir, const std::string& name, const std::string& title,
                       const std::vector<const energy_result*>& group, bool by_type, std::vector<std::string>& made) {
  if (group.empty()) return;
  std::ofstream dat(dir / (name + ".dat"));
  const std::size_t rows = group.front()->time.size();
  for (std::size_t k = 0; k < rows; ++k) {
    dat << group.front()->time[k];
    for (const auto* e : group) dat << " " << (k < e->envelope.size() ? value(e->envelope[k]) : "?");
    dat << "\n";
  }
  begin(gp, name, title);
  gp << "set logscale y\nset format y '%g'\nset xlabel 'time (s)'\n"
     << "set ylabel 'max |H[n] - H[0]| / H[0] within each interval'\nset style data lines\nplot ";
  for (std::size_t i = 0; i < group.size(); ++i)
    gp << (i ? ", \\\n  " : "") << quoted(name + ".dat") << " using 1:" << i + 2 << " lw 2 title "
       << quoted(by_type ? group[i]->type : group[i]->algorithm);
  gp << "\n";
  finish(gp, name);
  made.push_back(name);
}

// Per type, one line per algorithm; and the stable form across the types.
void write_energy_plots(std::ostream& gp, const fs::path& dir, const scene_result& r, std::vector<std::string>& made) {
  std::vector<std::string> types;
  for (const auto& e : r.energy)
    if (std::find(types.begin(), types.end(), e.type) == types.end()) types.push_back(e.type);
  for (const auto& type : types) {
    std::vector<const energy_result*> group;
    for (const auto& e : r.energy)
      if (e.type == type) group.push_back(&e);
    write_energy_plot(gp, dir, "energy_" + r.s.name + "_" + type,
                      "Scene " + r.s.name + ": relative energy error in " + type, group, false, made);
  }
  std::vector<const energy_result*> stable;
  for (const auto& e : r.energy)
    if (e.algorithm == name_of(method::stable)) stable.push_back(&e);
  if (stable.size() > 1)
    write_energy_plot(gp, dir, "energy_" + r.s.name + "_types",
                      "Scene " + r.s.name + ": relative energy error of the stable form", stable, true, made);
}

// Runs gnuplot on plots.gp in `dir`; on failure no plot counts as made.
bool run_gnuplot(const fs::path& dir, std::vector<std::string>& made) {
  const std::string command =
      "cd '" + dir.string() + "' && " + std::string(CONTACT_GNUPLOT) + " plots.gp > gnuplot.log 2>&1";
  const int status = std::system(command.c_str());
  if (status == 0) return true;
  std::fprintf(stderr, "contact-report: gnuplot failed (status %d); see %s\n", status,
               (dir / "gnuplot.log").string().c_str());
  made.clear();
  return false;
}

}  // namespace

bool write_plots(const std::string& directory, const std::vector<scene_result>& scenes, std::vector<std::string>& made) {
  const fs::path dir = fs::path(directory) / "plots";
  fs::create_directories(dir);
  std::ostringstream gp;
  gp << "# Generated by contact-report; run in this directory: gnuplot plots.gp\n";
  for (const auto& r : scenes) write_pareto(gp, dir, r, made);
  write_histograms(gp, dir, scenes, made);
  for (const auto& r : scenes)
    if (!r.energy.empty()) write_energy_plots(gp, dir, r, made);
  std::ofstream(dir / "plots.gp") << gp.str();
  return made.empty() || run_gnuplot(dir, made);
}

}  // namespace report
