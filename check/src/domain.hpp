// The domain a candidate is judged on: the whole range of the type (the
// default), or the families of a scene file (--scene FILE|NAME), which say
// which inputs a model hands to its contact step. Every draw of the suite, the
// campaign, the sweep and the map comes from here, tagged with its family so
// that the verdicts can be given per family.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/harness/families.hpp"
#include "inputs.hpp"
#include "scene.hpp"

namespace check {

using contact::harness::input;
using contact::harness::seeded_source;

template <class T>
struct tagged {
  input<T> x;
  int family = -1;  // index into domain::families; -1 for inputs of no family (invalid input)
};

// The closed interval of magnitudes one coordinate takes in the domain, and its signs.
struct span {
  double least = 0, most = 0;  // of the nonzero magnitudes
  bool zero = false, negative = false, positive = false;

  bool holds(double x) const {
    if (x == 0) return zero;
    if (x < 0 ? !negative : !positive) return false;
    return std::fabs(x) >= least && std::fabs(x) <= most;
  }
  void widen(double x) {
    if (x == 0) { zero = true; return; }
    (x < 0 ? negative : positive) = true;
    const double m = std::fabs(x);
    if (least == 0 || m < least) least = m;
    most = std::max(most, m);
  }
};

template <class T>
class domain {
 public:
  // The whole range of T: the harness's mix of every family (any_input), named by family.
  static domain whole_range() {
    domain d;
    d.name_ = "the whole range";
    d.whole_ = true;
    d.families_ = {"whole_range", "boundaries", "cancellation", "physical"};
    const double least = std::ldexp(1.0, int(contact::harness::lowest_exponent<T>()));
    const double most = double(std::numeric_limits<T>::max());
    const span everything{least, most, true, true, true};
    d.u_ = d.dy_ = d.phi_ = everything;
    d.phi_.negative = false;
    return d;
  }

  // The families of a scene file, drawn in proportion to their samples; throws report::scene_error.
  static domain of_scene(const std::string& file_or_name) {
    domain d;
    d.scene_ = report::parse_scene(scene_path(file_or_name));
    if (d.scene_.families.empty())
      throw report::scene_error(d.scene_.file, 1, "the scene has no [[family]]: it names no inputs to judge on");
    d.name_ = "scene " + d.scene_.name + " (" + d.scene_.file + ")";
    long total = 0;
    for (const auto& f : d.scene_.families) {
      d.families_.push_back(f.name);
      total += std::max(1L, f.samples);
      d.cumulative_.push_back(total);
    }
    // the domain's box: what many draws of its families span
    seeded_source source(0x5eed);
    for (int i = 0; i < 20000; ++i) {
      const auto t = d.draw(source);
      d.u_.widen(double(t.x.u));
      d.dy_.widen(double(t.x.dy));
      d.phi_.widen(double(t.x.phi));
    }
    return d;
  }

  // A scene's name (a file of the scenes directory) or a path.
  static std::string scene_path(const std::string& file_or_name) {
    namespace fs = std::filesystem;
    if (fs::exists(file_or_name) || file_or_name.find('/') != std::string::npos ||
        file_or_name.find('.') != std::string::npos)
      return file_or_name;
    return std::string(CONTACT_SCENES_DIR) + "/" + file_or_name + ".toml";
  }

  const std::string& name() const { return name_; }
  bool is_whole_range() const { return whole_; }
  const std::vector<std::string>& families() const { return families_; }
  const span& u() const { return u_; }
  const span& dy() const { return dy_; }
  const span& phi() const { return phi_; }

  bool contains(const input<T>& x) const {
    using std::isfinite;
    if (!isfinite(x.u) || !isfinite(x.dy) || !isfinite(x.phi) || x.phi < 0) return false;
    return u_.holds(double(x.u)) && dy_.holds(double(x.dy)) && phi_.holds(double(x.phi));
  }

  // A u that the domain holds: stands for a boundary property's u, which the boundary sets.
  T draw_free_u() const { return T(u_.positive ? u_.most : -u_.most); }

  // One valid input of the domain, with its family.
  tagged<T> draw(seeded_source& source) const {
    using namespace contact::harness;
    if (whole_) {
      // any_input's mix, family by family
      const long pick = source.integer(0, 12);
      if (pick < 6) return {contact::harness::whole_range<T>(source), 0};
      if (pick < 9) return {any_boundary<T>(source), 1};
      if (pick < 11) return {any_cancellation<T>(source), 2};
      return {physical<T>(source, audio_rate()), 3};
    }
    const long pick = source.integer(0, cumulative_.back() - 1);
    const auto which = std::upper_bound(cumulative_.begin(), cumulative_.end(), pick) - cumulative_.begin();
    const report::family& f = scene_.families[static_cast<std::size_t>(which)];
    const auto& generator = *report::find_generator(f.generator);  // the parser checked the name
    input<T> x{};
    for (int tries = 0; tries < 100; ++tries) {
      const auto drawn = generator.draw(source, f);
      x = {T(drawn.u), T(drawn.dy), T(drawn.phi)};
      if (valid_input(x)) break;  // a draw that overflows (in T) is drawn again
    }
    return {x, static_cast<int>(which)};
  }

  // A draw whose |dy| and phi the boundary properties use: dy > 0 for the
  // (A.31)/(A.32) boundary, dy <= 0 for (A.29)/(A.30).
  input<T> draw_for_boundary(seeded_source& source, bool contact_release) const {
    using std::fabs;
    if (whole_) {
      const T dy = fabs(contact::harness::any_finite<T>(source));
      return {0, contact_release ? dy : T(-dy), contact::harness::any_phi<T>(source)};
    }
    input<T> x = draw(source).x;
    for (int tries = 0; tries < 100; ++tries) {
      const T dy = contact_release ? fabs(x.dy) : T(-fabs(x.dy));
      if (dy_.holds(double(dy))) {
        // a boundary whose u the domain never reaches is not the domain's
        const input<T> on = contact_release ? contact::harness::on_contact_release_boundary(dy, x.phi, 0)
                                            : contact::harness::on_free_impact_boundary(dy, x.phi, 0);
        if (u_.holds(double(on.u)) || tries == 99) return {0, dy, x.phi};
      }
      x = draw(source).x;
    }
    return {0, contact_release ? fabs(x.dy) : T(-fabs(x.dy)), x.phi};
  }

  // The power of two of the homogeneity property: any size in the whole
  // range, a few octaves inside a scene's domain.
  long homogeneity_exponent(seeded_source& source) const {
    const long k = source.integer(1, whole_ ? 64 : 3);
    return source.integer(0, 1) ? k : -k;
  }

 private:
  static bool valid_input(const input<T>& x) {
    using std::isfinite;
    return isfinite(x.u) && isfinite(x.dy) && isfinite(x.phi) && !(x.phi < 0);
  }

  std::string name_;
  bool whole_ = false;
  std::vector<std::string> families_;
  report::scene scene_;
  std::vector<long> cumulative_;  // of the families' samples: the odds of each
  span u_, dy_, phi_;
};

}  // namespace check
