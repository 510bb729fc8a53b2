// Runs what a scene asks for.
#pragma once

#include "results.hpp"

namespace report {

struct measure_options {
  bool raw = false;  // keep every sample's measurement (for --raw)
};

scene_result measure(const scene& s, const measure_options& options);

// Times the batch kernels (batch, and each target the CPU runs alone) on the
// timing inputs of every measured scene that times batch in double, all in
// the same rounds, and compares each round with the same kernel's on the
// reference scene (batch_reference); nothing without a reference.
void measure_batch_across_scenes(std::vector<scene_result>& results);

}  // namespace report
