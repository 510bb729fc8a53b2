// The plots: data files and one gnuplot script that draws each plot as SVG and
// PNG, with the colours and markers of plots.hpp. What each scene gets is what
// its [scene] plots asks for (scene.hpp).
#include "plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "contact/batch.hpp"
#include "contact/types.hpp"
#include "methods.hpp"
#include "output.hpp"
#include "targets.hpp"

namespace report {

namespace fs = std::filesystem;

// ---- the palette, the markers and the front ----

namespace {

const char* colour_of_method(method m) {
  switch (m) {
    case method::textbook: return "#d62728";             // red
    case method::stable: return "#1f77b4";               // blue
    case method::newton: return "#2ca02c";               // green
    case method::rounded: return "#9467bd";              // purple
    case method::batch: return "#17becf";                // cyan; its targets are darker cyans
    case method::rounded_batch: return "#c5b0d5";        // light purple
    case method::boost_quadratic: return "#ff7f0e";      // orange
    case method::eigen_companion: return "#8c564b";      // brown
    case method::boost_newton: return "#e377c2";         // pink
    case method::boost_halley: return "#bcbd22";         // olive
    case method::boost_toms748: return "#393b79";        // navy
    case method::practitioner_newton: return "#7f7f7f";  // grey
  }
  return "#000000";
}

// For names outside the registry (the candidates).
constexpr const char* further_colours[] = {"#637939", "#ad494a", "#a55194", "#6b6ecf", "#e7ba52", "#843c39"};

std::string hex(int r, int g, int b) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", r, g, b);
  return buffer;
}

// `rgb` ("#rrggbb") darkened towards black by `share` (0..1).
std::string darker(const std::string& rgb, double share) {
  const long v = std::strtol(rgb.c_str() + 1, nullptr, 16);
  auto part = [&](int shift) { return static_cast<int>(std::lround(double((v >> shift) & 0xff) * (1 - share))); };
  return hex(part(16), part(8), part(0));
}

struct type_marker {
  const char* type;
  int point_type;
  const char* shape;
};
constexpr type_marker type_markers[] = {
    {"double", 7, "filled circle"},          {"float", 5, "filled square"},
    {"long_double", 9, "filled triangle"},   {"float128", 11, "filled inverted triangle"},
    {"cpp_bin_float_50", 13, "filled diamond"}, {"cpp_bin_float_100", 15, "filled pentagon"},
    {"mpfr", 3, "star"}};

}  // namespace

std::string colour_of(std::string_view algorithm) {
  if (const auto m = method_named(algorithm)) return colour_of_method(*m);
  for (method kernel : {method::batch, method::rounded_batch}) {  // its targets: darker shades of its colour
    const std::string base = colour_of_method(kernel);
    if (!is_target_row_of(name_of(kernel), algorithm)) continue;
    const auto targets = contact::batch_targets();
    for (std::size_t i = 0; i < targets.size(); ++i)
      if (algorithm == target_row_name(name_of(kernel), targets[i]))
        return darker(base, 0.25 + 0.5 * double(i) / double(std::max<std::size_t>(1, targets.size() - 1)));
    return darker(base, 0.9);
  }
  return further_colours[std::hash<std::string_view>{}(algorithm) % std::size(further_colours)];
}

int marker_of(std::string_view type) {
  for (const auto& m : type_markers)
    if (type == m.type) return m.point_type;
  return 6;
}

std::string marker_name(std::string_view type) {
  for (const auto& m : type_markers)
    if (type == m.type) return m.shape;
  return "open circle";
}

std::vector<std::size_t> pareto_front(const std::vector<pareto_point>& points) {
  auto counts = [&](std::size_t i) { return std::isfinite(points[i].error) && std::isfinite(points[i].time); };
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!counts(i)) continue;
    const auto& p = points[i];
    bool dominated = false;
    for (std::size_t k = 0; k < points.size() && !dominated; ++k) {
      if (k == i || !counts(k)) continue;
      const auto& q = points[k];
      dominated = q.time <= p.time && q.error <= p.error && (q.time < p.time || q.error < p.error);
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].time != points[b].time) return points[a].time < points[b].time;
    if (points[a].error != points[b].error) return points[a].error < points[b].error;
    return a < b;
  });
  return front;
}

namespace {

// ---- gnuplot ----

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

std::string text_of(double x) {  // a figure of a data file's comment column
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return "inf";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string fraction(double x) {  // a screen coordinate
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", x);
  return buffer;
}

constexpr const char* font = "Helvetica,11";
// What one character of the terminal's font and of a point label takes, in
// pixels (pngcairo at the font above; the SVG has the same size), for placing the labels.
constexpr double char_width = 7.0, char_height = 15.0, label_char_width = 7.0;

// Draws `body` as NAME.svg and NAME.png, each `width` by `height` pixels.
void emit(std::ostream& gp, const std::string& name, int width, int height, const std::string& body) {
  gp << "\n# " << name << "\nreset\nset terminal svg size " << width << "," << height << " dynamic noenhanced font '"
     << font << "' background rgb 'white'\nset output " << quoted(name + ".svg") << "\n"
     << body << "unset output\nreset\nset terminal pngcairo size " << width << "," << height << " noenhanced font '"
     << font << "' background rgb 'white'\nset output " << quoted(name + ".png") << "\n"
     << body << "unset output\n";
}

// ---- placing the point labels ----

struct rect {  // pixels, y downwards
  double x0, y0, x1, y1;
};

double overlap(const rect& a, const rect& b) {
  return std::max(0.0, std::min(a.x1, b.x1) - std::max(a.x0, b.x0)) *
         std::max(0.0, std::min(a.y1, b.y1) - std::max(a.y0, b.y0));
}

struct placement {
  double dx, dy;        // offset in characters of the terminal's font, y upwards
  const char* justify;  // left, right or center
};

// The candidate places of a label around its point, the preferred first.
constexpr placement candidates[] = {
    {1.0, 0, "left"},      {-1.0, 0, "right"},   {0.8, 0.9, "left"},    {0.8, -0.9, "left"},
    {-0.8, 0.9, "right"},  {-0.8, -0.9, "right"}, {0, 1.2, "center"},    {0, -1.2, "center"},
    {1.0, 1.8, "left"},    {1.0, -1.8, "left"},  {-1.0, 1.8, "right"},  {-1.0, -1.8, "right"},
    {2.5, 0, "left"},      {-2.5, 0, "right"},   {0, 2.4, "center"},    {0, -2.4, "center"}};

rect label_box(double px, double py, const placement& p, std::size_t length) {
  const double width = double(length) * label_char_width, x = px + p.dx * char_width, y = py - p.dy * char_height;
  const double left = p.justify[0] == 'l' ? x : (p.justify[0] == 'r' ? x - width : x - width / 2);
  return {left, y - char_height / 2, left + width, y + char_height / 2};
}

// Greedily, from left to right, the candidate place of each label that
// overlaps the points, the lines (`taken`), the labels placed so far and the
// outside of `area` least.
std::vector<placement> place_labels(const std::vector<std::pair<double, double>>& at,
                                    const std::vector<std::string>& texts, const rect& area,
                                    std::vector<rect> taken) {
  for (const auto& [x, y] : at) taken.push_back({x - 6, y - 6, x + 6, y + 6});
  std::vector<std::size_t> order(at.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return at[a].first < at[b].first; });
  std::vector<placement> out(at.size(), candidates[0]);
  for (std::size_t i : order) {
    double best = INFINITY;
    rect chosen{};
    for (std::size_t c = 0; c < std::size(candidates); ++c) {
      const rect box = label_box(at[i].first, at[i].second, candidates[c], texts[i].size());
      const double size = (box.x1 - box.x0) * (box.y1 - box.y0);
      double cost = 4 * (size - overlap(box, area)) + 0.02 * size * double(c);
      for (const rect& t : taken) cost += overlap(box, t);
      if (cost < best) best = cost, chosen = box, out[i] = candidates[c];
    }
    taken.push_back(chosen);
  }
  return out;
}

// ---- error against run time: the Pareto panels and the headline figure ----

struct point {
  std::string type, algorithm, label;
  double time, time_min, time_max, error, p99;
  int block = 0;  // its block (index) in the data file
  bool failed() const { return !std::isfinite(error); }
  double plotted() const { return std::max(error, 1e-3); }  // a log axis shows no 0
};

// A panel of a chart of error against time: its points, the inf/NaN strip on
// top of it, one front per type.
struct panel {
  std::string title;
  std::vector<point> points;
  std::vector<std::string> types;  // in the order of the key
  std::vector<int> front_blocks;   // per type, its front's block in the data file (-1: under two points)
  double zoom_low = 0, zoom_high = 0;  // a closer look: only these errors, and no strip (0: the whole range)
};

struct canvas {
  int width, height;
  double x(double px) const { return px / width; }
  double y(double py) const { return 1 - py / height; }
};

// The layout of a panel, in pixels: the margins left of the plot and right of
// it (the key), above the title, the title, the strip's least height, the gap
// under the strip and the time axis under the plot.
constexpr int left_px = 95, key_px = 235, top_px = 16, title_px = 30, strip_px = 56, gap_px = 8, axis_px = 52;

std::string label_commands(const std::vector<point>& pts, const std::vector<std::pair<double, double>>& at,
                           const rect& area, const std::vector<rect>& lines) {
  std::vector<std::string> texts;
  for (const auto& p : pts) texts.push_back(p.label);
  const auto places = place_labels(at, texts, area, lines);
  std::ostringstream out;
  for (std::size_t i = 0; i < pts.size(); ++i)
    out << "set label " << quoted(pts[i].label) << " at first " << pts[i].time << ", first "
        << pts[i].plotted() << " offset char " << places[i].dx << "," << places[i].dy << " "
        << places[i].justify << " textcolor rgb '" << colour_of(pts[i].algorithm) << "' font ',10' front\n";
  return out.str();
}

// The decades of the time axis of a panel: every point with its bars.
std::pair<double, double> time_decades(const panel& pn) {
  double x_lo = INFINITY, x_hi = 0;
  for (const auto& p : pn.points) x_lo = std::min({x_lo, p.time_min, p.time}), x_hi = std::max({x_hi, p.time_max, p.time});
  return {std::floor(std::log10(x_lo) - 0.05), std::ceil(std::log10(x_hi) + 0.25)};
}

// The failures of a panel, by increasing time, each in the first row of the
// strip where its point, its bars and its label (right of the point, or left
// of it near the right edge) meet nothing drawn before.
struct strip_layout {
  std::vector<const point*> failed;
  std::vector<int> row;
  std::vector<bool> label_left;
  int rows = 1;
  double height() const { return std::max<double>(strip_px, 18.0 * rows + 16); }
};

strip_layout lay_out_strip(const panel& pn, double width) {
  strip_layout out;
  if (pn.zoom_high > 0) return out;
  const auto [lx0, lx1] = time_decades(pn);
  const double left = left_px, right = width - key_px;
  auto px = [&](double t) { return left + (std::log10(t) - lx0) / (lx1 - lx0) * (right - left); };
  for (const auto& p : pn.points)
    if (p.failed()) out.failed.push_back(&p);
  std::stable_sort(out.failed.begin(), out.failed.end(), [](const point* a, const point* b) { return a->time < b->time; });
  std::vector<double> row_end;  // pixels
  for (const point* p : out.failed) {
    const double x = px(p->time), label = (double(p->label.size()) + 1) * label_char_width;
    const bool on_left = x + 7 + label > right;
    const double from = std::min(on_left ? x - 7 - label : x - 7, px(p->time_min));
    const double to = std::max(on_left ? x + 7 : x + 7 + label, px(p->time_max));
    std::size_t r = 0;
    while (r < row_end.size() && row_end[r] > from) ++r;
    if (r == row_end.size()) row_end.push_back(to);
    row_end[r] = to;
    out.row.push_back(static_cast<int>(r));
    out.label_left.push_back(on_left);
  }
  out.rows = std::max<int>(1, static_cast<int>(row_end.size()));
  return out;
}

// Draws one panel between pixel rows top and bottom of `c`.
void draw_panel(std::ostream& body, const canvas& c, double top, double bottom, const panel& pn,
                const std::string& dat, const std::string& x_label) {
  const double left = left_px, right = c.width - key_px;
  double y_lo = INFINITY, y_hi = 0;
  for (const auto& p : pn.points)
    if (!p.failed()) y_lo = std::min(y_lo, p.plotted()), y_hi = std::max(y_hi, p.plotted());
  if (!(y_lo <= y_hi)) y_lo = 0.1, y_hi = 10;
  const auto [lx0, lx1] = time_decades(pn);
  const bool zoomed = pn.zoom_high > 0;
  const double pad = std::max(0.15, 0.03 * (std::log10(y_hi) - std::log10(y_lo)));  // decades
  const double ly0 = zoomed ? std::log10(pn.zoom_low) : std::floor(std::log10(y_lo) - pad);
  const double ly1 = zoomed ? std::log10(pn.zoom_high) : std::ceil(std::log10(y_hi) + pad);
  const strip_layout strip = lay_out_strip(pn, c.width);
  const double strip_top = top + top_px + title_px, strip_bottom = strip_top + strip.height();
  const double main_top = zoomed ? strip_top : strip_bottom + gap_px, main_bottom = bottom - axis_px;
  auto px = [&](double t) { return left + (std::log10(t) - lx0) / (lx1 - lx0) * (right - left); };
  auto py = [&](double e) { return main_bottom - (std::log10(e) - ly0) / (ly1 - ly0) * (main_bottom - main_top); };
  const std::string margins_x =
      "set lmargin at screen " + fraction(c.x(left)) + "; set rmargin at screen " + fraction(c.x(right)) + "\n";
  const std::string x_range = "set logscale x\nset xrange [" + text_of(std::pow(10, lx0)) + ":" +
                              text_of(std::pow(10, lx1)) + "]\nset format x '%g'\nset mxtics 10\n";

  std::vector<point> finite;
  for (const auto& p : pn.points)
    if (!p.failed() && (!zoomed || (p.plotted() >= pn.zoom_low && p.plotted() <= pn.zoom_high))) finite.push_back(p);
  body << "unset label\nunset key\nunset logscale\n" << margins_x;
  if (zoomed) {
    body << "set title " << quoted(pn.title) << "\n";
  } else {  // the strip: the points whose error is infinite or NaN somewhere, a row each where they would meet
    body << "set tmargin at screen " << fraction(c.y(strip_top)) << "; set bmargin at screen "
         << fraction(c.y(strip_bottom)) << "\n"
         << x_range << "set format x ''\nset xlabel ''\nset yrange [" << strip.rows << ":0]\nunset ytics\n"
         << "set ylabel ''\nset grid xtics\nset title " << quoted(pn.title) << "\n"
         << "set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb '#f4e4e4' fillstyle solid noborder\n"
         << "set label 'inf/NaN' at graph 0, graph 0.5 offset char -0.6,0 right\n";
    if (strip.failed.empty()) body << "set label 'none' at graph 0.5, graph 0.5 center textcolor rgb '#808080'\n";
    for (std::size_t i = 0; i < strip.failed.size(); ++i) {
      const point& p = *strip.failed[i];
      body << "set label " << quoted(p.label) << " at first " << p.time << ", first " << strip.row[i] + 0.5
           << " offset char " << (strip.label_left[i] ? "-1,0 right" : "1,0 left") << " textcolor rgb '"
           << colour_of(p.algorithm) << "' font ',10' front\n";
    }
    body << "plot -1 notitle";
    for (std::size_t i = 0; i < strip.failed.size(); ++i) {
      const point& p = *strip.failed[i];
      body << ", \\\n  " << quoted(dat) << " index " << p.block << " using 1:(" << strip.row[i] + 0.5
           << "):3:4 with xerrorbars lc rgb '" << colour_of(p.algorithm) << "' pt " << marker_of(p.type)
           << " ps 1.4 notitle";
    }
    body << "\nunset object 1\nunset label\nunset title\n";
  }

  // the main plot
  body << "set tmargin at screen " << fraction(c.y(main_top)) << "; set bmargin at screen " << fraction(c.y(main_bottom))
       << "\nset yrange [" << text_of(std::pow(10, ly0)) << ":" << text_of(std::pow(10, ly1))
       << "]\nset logscale xy\n" << x_range << "set ytics auto\nset format y '%g'\nset grid xtics ytics\n"
       << "set xlabel " << quoted(x_label) << "\nset ylabel "
       << quoted("max ulp error (0 drawn at 1e-3)") << " offset 0,0\n"
       << "set key at screen " << fraction(c.x(right + 14)) << ", screen " << fraction(c.y(main_top))
       << " left top Left reverse samplen 2.5 spacing 1.2 box\n";
  {
    std::vector<std::pair<double, double>> at;
    std::vector<rect> lines;  // the error bars and the fronts
    for (const auto& p : finite) {
      at.emplace_back(px(p.time), py(p.plotted()));
      lines.push_back({px(p.time_min), py(p.plotted()) - 2, px(p.time_max), py(p.plotted()) + 2});
    }
    for (const auto& type : pn.types) {
      std::vector<pareto_point> pts;
      std::vector<const point*> of_type;
      for (const auto& p : finite)
        if (p.type == type) pts.push_back({p.time, p.error}), of_type.push_back(&p);
      const auto front = pareto_front(pts);
      for (std::size_t k = 1; k < front.size(); ++k) {
        const point &a = *of_type[front[k - 1]], &b = *of_type[front[k]];
        const double ax = px(a.time), ay = py(a.plotted()), bx = px(b.time), by = py(b.plotted());
        const int steps = 1 + static_cast<int>(std::hypot(bx - ax, by - ay) / 4);
        for (int j = 0; j <= steps; ++j) {
          const double x = ax + (bx - ax) * j / steps, y = ay + (by - ay) * j / steps;
          lines.push_back({x - 2, y - 2, x + 2, y + 2});
        }
      }
    }
    body << label_commands(finite, at, {left, main_top, right, main_bottom}, lines);
  }
  body << "plot ";
  const char* separator = "";
  for (std::size_t k = 0; k < pn.types.size(); ++k) {
    body << separator << "keyentry with points pt " << marker_of(pn.types[k]) << " ps 1.4 lc rgb 'black' title "
         << quoted(pn.types[k]);
    separator = ", \\\n  ";
  }
  for (std::size_t k = 0; k < pn.types.size(); ++k)
    if (pn.front_blocks[k] >= 0)
      body << separator << quoted(dat) << " index " << pn.front_blocks[k] << " using 1:2 with lines lw 2 dt " << k + 1
           << " lc rgb '#303030' title " << quoted("front, " + pn.types[k]);
  for (const auto& p : finite)
    body << separator << quoted(dat) << " index " << p.block << " using 1:2:3:4 with xerrorbars lc rgb '"
         << colour_of(p.algorithm) << "' pt " << marker_of(p.type) << " ps 1.4 notitle";
  if (finite.empty())  // a curve below the axis: gnuplot draws no plot of key entries alone
    body << separator << text_of(std::pow(10, ly0 - 10)) << " notitle";
  body << "\nunset label\nunset key\nunset title\n";
}

// Writes the points' blocks and, per type with two or more points on its
// front, the front's block into `dat`, numbering the blocks from `block`.
void write_blocks(std::ostream& dat, panel& pn, int& block) {
  for (auto& p : pn.points) {
    dat << "# " << p.type << " " << p.algorithm << "\n"
        << p.time << " " << (p.failed() ? std::string("?") : value(p.plotted())) << " " << p.time_min << " "
        << p.time_max << " " << value(std::isfinite(p.p99) ? std::max(p.p99, 1e-3) : NAN) << " " << text_of(p.error)
        << "\n\n\n";
    p.block = block++;
  }
  for (const auto& type : pn.types) {
    std::vector<pareto_point> pts;
    std::vector<const point*> of_type;
    for (const auto& p : pn.points)
      if (p.type == type) pts.push_back({p.time, p.error}), of_type.push_back(&p);
    const auto front = pareto_front(pts);
    if (front.size() < 2) {
      pn.front_blocks.push_back(-1);
      continue;
    }
    dat << "# front " << type << "\n";
    for (std::size_t i : front) dat << of_type[i]->time << " " << value(of_type[i]->plotted()) << " " << of_type[i]->algorithm << "\n";
    dat << "\n\n";
    pn.front_blocks.push_back(block++);
  }
}

// Draws the panels one above the other as NAME.svg and NAME.png.
// The first panel once more, closer: the errors around its fronts, when its
// errors span far more decades than they do (nothing, if not).
std::optional<panel> closer(const panel& pn) {
  double lowest = INFINITY, highest = 0, front_low = INFINITY, front_high = 0;
  for (const auto& type : pn.types) {
    std::vector<pareto_point> pts;
    std::vector<const point*> of_type;
    for (const auto& p : pn.points)
      if (p.type == type && !p.failed()) {
        pts.push_back({p.time, p.error}), of_type.push_back(&p);
        lowest = std::min(lowest, p.plotted()), highest = std::max(highest, p.plotted());
      }
    for (std::size_t i : pareto_front(pts))
      front_low = std::min(front_low, of_type[i]->plotted()), front_high = std::max(front_high, of_type[i]->plotted());
  }
  if (!(front_low <= front_high)) return std::nullopt;
  const double low = std::floor(std::log10(front_low) - 0.2), high = std::ceil(std::log10(front_high) + 1.2);
  if (std::log10(highest) - std::log10(lowest) < high - low + 4) return std::nullopt;
  panel out = pn;
  out.zoom_low = std::pow(10, low), out.zoom_high = std::pow(10, high);
  out.title = "The same, closer: the errors from " + text_of(out.zoom_low) + " to " + text_of(out.zoom_high) + " ulps";
  return out;
}

void draw_panels(std::ostream& gp, const fs::path& dir, const std::string& name, std::vector<panel> panels,
                 const std::string& x_label, std::vector<std::string>& made, bool zoom = false) {
  std::erase_if(panels, [](const panel& p) { return p.points.empty(); });
  if (panels.empty()) return;
  std::ofstream dat(dir / (name + ".dat"));
  dat << "# ns per solve (median), max ulp error (0 as 1e-3; ? when infinite or NaN), ns min, ns max, p99 ulp "
         "error, max ulp error as measured\n";
  int block = 0;
  for (auto& pn : panels) write_blocks(dat, pn, block);
  if (zoom)
    if (auto more = closer(panels.front())) panels.push_back(std::move(*more));  // the same blocks
  const int width = 1100;
  std::vector<double> heights;  // pixels: the plot's, and the strip's as many rows as it needs
  for (const auto& pn : panels) heights.push_back(504 + (pn.zoom_high > 0 ? 0 : lay_out_strip(pn, width).height()));
  double total = 0;
  for (double h : heights) total += h;
  const canvas c{width, static_cast<int>(total)};
  std::ostringstream body;
  body << "set datafile missing '?'\nset multiplot\n";
  double top = 0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    draw_panel(body, c, top, top + heights[i], panels[i], name + ".dat", x_label);
    top += heights[i];
  }
  body << "unset multiplot\n";
  emit(gp, name, c.width, c.height, body.str());
  made.push_back(name);
}

bool narrow(const std::string& type) { return type == "double" || type == "float"; }

// The registered types in the registry's order, `pick`ed among `present`.
std::vector<std::string> in_registry_order(const std::vector<std::string>& present) {
  std::vector<std::string> out;
  for (std::string_view name : contact::type_names)
    if (std::find(present.begin(), present.end(), name) != present.end()) out.emplace_back(name);
  return out;
}

// Per scene: double and float in one panel, the wider types in another.
void write_pareto(std::ostream& gp, const fs::path& dir, const scene_result& r, std::vector<std::string>& made) {
  panel narrow_panel{"double and float", {}, {}, {}}, wide_panel{"the wider types", {}, {}, {}};
  std::vector<std::string> wide_types, narrow_types;
  for (const auto& a : r.accuracy)
    for (const auto& t : r.timing)
      if (a.type == t.type && a.algorithm == t.algorithm && !t.ns.empty()) {
        const double error = std::isnan(a.ulps.max) ? INFINITY : a.ulps.max;
        auto& pn = narrow(a.type) ? narrow_panel : wide_panel;
        pn.points.push_back({a.type, a.algorithm, a.algorithm, t.median, t.min, t.max, error, a.ulps.p99});
        auto& types = narrow(a.type) ? narrow_types : wide_types;
        if (std::find(types.begin(), types.end(), a.type) == types.end()) types.push_back(a.type);
      }
  narrow_panel.types = in_registry_order(narrow_types);
  wide_panel.types = in_registry_order(wide_types);
  if (wide_panel.types.size() > 1)  // the type tells the points apart where the markers are many
    for (auto& p : wide_panel.points) p.label = p.algorithm + " (" + p.type + ")";
  std::string joined;
  for (const auto& t : wide_panel.types) joined += (joined.empty() ? "" : ", ") + t;
  wide_panel.title = "Scene " + r.s.name + ", the wider types (" + joined + ")";
  narrow_panel.title = "Scene " + r.s.name + ", " +
                       (narrow_panel.types.size() == 2 ? std::string("double and float") :
                        narrow_panel.types.empty() ? std::string() : narrow_panel.types.front());
  draw_panels(gp, dir, "pareto_" + r.s.name, {narrow_panel, wide_panel},
              "ns per solve (median; bars: min to max over repetitions); ulps in each type's own ulps", made);
}

// In double: each algorithm's worst maximum error over every scene against its
// median time on the scene that asks for the headline figure.
void write_headline_figure(std::ostream& gp, const fs::path& dir, const std::vector<scene_result>& scenes,
                           std::vector<std::string>& made) {
  const scene_result* timed = nullptr;
  for (const auto& r : scenes)
    if (asks_for(r.s, plot::headline)) timed = &r;
  if (!timed) return;
  const std::string type(contact::type_name<double>);
  panel pn{"Double: the worst error over all scenes against the run time on scene " + timed->s.name, {}, {type}, {}};
  for (const auto& t : timed->timing) {
    if (t.type != type || t.ns.empty()) continue;
    double worst = -1, p99 = -1;
    for (const auto& r : scenes)
      for (const auto& a : r.accuracy)
        if (a.type == type && a.algorithm == t.algorithm) {
          worst = std::isnan(a.ulps.max) || std::isnan(worst) ? NAN : std::max(worst, a.ulps.max);
          p99 = std::max(p99, a.ulps.p99);
        }
    if (worst < 0) continue;  // no accuracy of its own (batch[NAME])
    pn.points.push_back({type, t.algorithm, t.algorithm, t.median, t.min, t.max, std::isnan(worst) ? INFINITY : worst, p99});
  }
  draw_panels(gp, dir, "headline", {pn},
              "ns per solve on scene " + timed->s.name + " (median; bars: min to max over repetitions)", made, true);
}

// ---- error histograms: per type, a panel per algorithm ----

// The tick label of a histogram bin: its upper edge, on every fourth power of two when the range is wide.
std::string histogram_tick(int bin, int first, int last) {
  if (bin <= 2) return bin == 0 ? "0" : (bin == 1 ? "0.5" : "1");
  if (bin == 63) return ">2^60";
  if (bin == 64) return "NaN";
  if (last - first <= 16 || (bin - 2) % 4 == 0) return "2^" + std::to_string(bin - 2);
  return "";
}

struct histogram_lines {
  std::string algorithm;
  std::vector<std::pair<std::string, const accuracy_result*>> lines;  // per scene
  int first = histogram_bins, last = -1;
};

// Keeps the data file of each (type, algorithm), hist_TYPE_ALGORITHM.dat (a
// column per scene), and draws them as one figure, hist_TYPE, on shared axes.
void write_histogram_figure(std::ostream& gp, const fs::path& dir, const std::vector<const scene_result*>& scenes,
                            const std::string& type, std::vector<std::string>& made) {
  std::vector<std::string> algorithms;
  for (method m : all_methods) algorithms.push_back(name_of(m));
  for (const auto* r : scenes)
    for (const auto& a : r->accuracy)
      if (std::find(algorithms.begin(), algorithms.end(), a.algorithm) == algorithms.end()) algorithms.push_back(a.algorithm);
  std::vector<std::string> scene_names;
  std::vector<histogram_lines> panels;
  int first = histogram_bins, last = -1;
  double smallest = 1;
  for (const auto& algorithm : algorithms) {
    histogram_lines h{algorithm, {}};
    for (const auto* r : scenes)
      for (const auto& a : r->accuracy)
        if (a.type == type && a.algorithm == algorithm) {
          h.lines.emplace_back(r->s.name, &a);
          if (std::find(scene_names.begin(), scene_names.end(), r->s.name) == scene_names.end())
            scene_names.push_back(r->s.name);
          for (int b = 0; b < histogram_bins; ++b)
            if (const long n = a.histogram[static_cast<std::size_t>(b)]) {
              h.first = std::min(h.first, b), h.last = std::max(h.last, b);
              smallest = std::min(smallest, double(n) / double(std::max(1L, a.samples)));
            }
        }
    if (h.first > h.last) continue;
    first = std::min(first, h.first), last = std::max(last, h.last);
    std::ofstream dat(dir / ("hist_" + type + "_" + algorithm + ".dat"));
    dat << "# bin, its upper edge, then the fraction of samples per scene (NaN: none):";
    for (const auto& [scene, a] : h.lines) dat << " " << scene;
    dat << "\n";
    for (int b = h.first; b <= h.last; ++b) {
      dat << b << " \"" << histogram_tick(b, h.first, h.last) << "\"";
      for (const auto& [scene, a] : h.lines) {  // NaN: an empty bin, where the line breaks
        const long n = a->histogram[static_cast<std::size_t>(b)];
        dat << " " << (n ? value(double(n) / double(std::max(1L, a->samples))) : std::string("NaN"));
      }
      dat << "\n";
    }
    panels.push_back(std::move(h));
  }
  if (panels.empty()) return;
  const int n = static_cast<int>(panels.size());
  const int columns = static_cast<int>(std::ceil(std::sqrt(double(n)))), rows = (n + columns - 1) / columns;
  const int cell_w = 300, cell_h = 230, margin_l = 80, margin_r = 20, margin_t = 80, margin_b = 80;
  const canvas c{margin_l + margin_r + columns * cell_w, margin_t + margin_b + rows * cell_h};
  // the tick labels of the bottom panels, far enough apart to be read: by
  // priority 1, NaN, 0, then the edges 2^k by the largest power of two dividing k
  const int gap = static_cast<int>(std::ceil(14.0 * (last - first + 1) / (cell_w - 8)));
  std::vector<int> ticked;
  auto tick = [&](int bin) {
    if (bin < first || bin > last) return;
    for (int t : ticked)
      if (std::abs(t - bin) < gap) return;
    ticked.push_back(bin);
  };
  tick(2), tick(64), tick(0), tick(63), tick(1);
  for (int step = 32; step >= 1; step /= 2)
    for (int b = 3; b <= 62; ++b)
      if ((b - 2) % step == 0) tick(b);
  std::string labelled = "(", bare = "(";
  for (int b = first; b <= last; ++b) {
    const std::string sep = b == first ? "" : ", ";
    const bool shown = std::find(ticked.begin(), ticked.end(), b) != ticked.end();
    labelled += sep + quoted(shown ? histogram_tick(b, 0, 0) : "") + " " + std::to_string(b);
    bare += sep + "'' " + std::to_string(b);
  }
  labelled += ")", bare += ")";
  const double y_low = std::pow(10, std::floor(std::log10(smallest)));
  std::ostringstream body;
  body << "set datafile missing '?'\nset multiplot title "
       << quoted(type + ": distribution of the ulp error, a panel per algorithm, a line per scene (shared axes)")
       << "\nset logscale y\nset yrange [" << text_of(y_low) << ":1.5]\nset format y '%g'\nset grid\n"
       << "set xrange [" << first - 0.5 << ":" << last + 0.5 << "]\nset style data linespoints\n";
  for (int i = 0; i < n; ++i) {
    const int row = i / columns, column = i % columns;
    const bool bottom = i + columns >= n, leftmost = column == 0;
    const double x0 = margin_l + column * cell_w, y0 = margin_t + row * cell_h;
    body << "set lmargin at screen " << fraction(c.x(x0 + 4)) << "; set rmargin at screen "
         << fraction(c.x(x0 + cell_w - 4)) << "; set tmargin at screen " << fraction(c.y(y0 + 22))
         << "; set bmargin at screen " << fraction(c.y(y0 + cell_h - 4)) << "\n"
         << "set xtics " << (bottom ? labelled : bare) << " rotate by 90 right font ',9'\n"
         << "set xlabel " << quoted(bottom ? "ulp error (upper edge of the bin)" : "") << "\n"
         << "set format y " << (leftmost ? "'%g'" : "''") << "\nset ylabel "
         << quoted(leftmost ? "fraction of samples" : "") << "\n"
         << "set title " << quoted(panels[static_cast<std::size_t>(i)].algorithm) << " textcolor rgb '"
         << colour_of(panels[static_cast<std::size_t>(i)].algorithm) << "' offset 0,-0.6\n";
    body << "unset key\nplot ";
    const auto& h = panels[static_cast<std::size_t>(i)];
    const char* separator = "";
    for (std::size_t k = 0; k < h.lines.size(); ++k) {
      const auto s = std::find(scene_names.begin(), scene_names.end(), h.lines[k].first) - scene_names.begin();
      body << separator << quoted("hist_" + type + "_" + h.algorithm + ".dat") << " using 1:" << k + 3 << " lw 2 dt "
           << s + 1 << " pt " << marker_of(type) << " ps 0.6 lc rgb '" << colour_of(h.algorithm) << "' notitle";
      separator = ", \\\n  ";
    }
    body << "\n";
  }
  // the key, a line style per scene, in a band of the figure's width under its title
  body << "set lmargin at screen 0.02; set rmargin at screen 0.98; set tmargin at screen " << fraction(c.y(38))
       << "; set bmargin at screen " << fraction(c.y(62)) << "\nunset border\nunset tics\nunset title\nunset xlabel\n"
       << "unset ylabel\nunset grid\nunset logscale\nset xrange [0:1]\nset yrange [0:1]\n"
       << "set key inside center center horizontal maxrows 1 samplen 3 width 2\nplot ";
  for (std::size_t s = 0; s < scene_names.size(); ++s)
    body << "keyentry with linespoints lw 2 dt " << s + 1 << " pt " << marker_of(type) << " lc rgb 'black' title "
         << quoted(scene_names[s]) << ", \\\n  ";
  body << "2 notitle\nunset multiplot\n";
  emit(gp, "hist_" + type, c.width, c.height, body.str());
  made.push_back("hist_" + type);
}

void write_histograms(std::ostream& gp, const fs::path& dir, const std::vector<scene_result>& scenes,
                      std::vector<std::string>& made) {
  std::vector<const scene_result*> asking;
  std::vector<std::string> types;
  for (const auto& r : scenes)
    if (asks_for(r.s, plot::histograms)) {
      asking.push_back(&r);
      for (const auto& a : r.accuracy) types.push_back(a.type);
    }
  for (const auto& type : in_registry_order(types)) write_histogram_figure(gp, dir, asking, type, made);
}

// ---- energy ----

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
  std::ostringstream body;
  body << "set datafile missing '?'\nset grid\nset key outside right top\nset title " << quoted(title)
       << "\nset logscale y\nset format y '%g'\nset xlabel 'time (s)'\n"
       << "set ylabel 'max |H[n] - H[0]| / H[0] within each interval'\nplot ";
  const std::size_t every = std::max<std::size_t>(1, rows / 12);
  for (std::size_t i = 0; i < group.size(); ++i)
    body << (i ? ", \\\n  " : "") << quoted(name + ".dat") << " using 1:" << i + 2 << " with linespoints lw 2 pt "
         << marker_of(group[i]->type) << " pi " << every << " lc rgb '" << colour_of(group[i]->algorithm)
         << "' dt " << (by_type ? i + 1 : 1) << " title " << quoted(by_type ? group[i]->type : group[i]->algorithm);
  body << "\n";
  emit(gp, name, 1000, 620, body.str());
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
  std::ostringstream gp;
  gp << "# Generated by contact-report; run in this directory: gnuplot plots.gp\n";
  const bool any = std::any_of(scenes.begin(), scenes.end(), [](const scene_result& r) { return !r.s.plots.empty(); });
  if (!any) return true;
  fs::create_directories(dir);
  write_headline_figure(gp, dir, scenes, made);
  for (const auto& r : scenes)
    if (asks_for(r.s, plot::pareto)) write_pareto(gp, dir, r, made);
  write_histograms(gp, dir, scenes, made);
  for (const auto& r : scenes)
    if (!r.energy.empty() && asks_for(r.s, plot::energy)) write_energy_plots(gp, dir, r, made);
  std::ofstream(dir / "plots.gp") << gp.str();
  return made.empty() || run_gnuplot(dir, made);
}

}  // namespace report
