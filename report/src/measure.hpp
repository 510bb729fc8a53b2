// Runs what a scene asks for.
#pragma once

#include "results.hpp"

namespace report {

struct measure_options {
  bool raw = false;  // keep every sample's measurement (for --raw)
};

scene_result measure(const scene& s, const measure_options& options);

}  // namespace report
