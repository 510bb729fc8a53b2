// The input generators a scene names: the harness's input families
// (contact/harness/families.hpp) with the names, parameters and summaries of
// the scene grammar. Every draw is in double; every type of a run solves the
// same doubles (each converts exactly).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene.hpp"

namespace report {

struct generator_info {
  std::string name;
  std::vector<std::string> required, optional;  // parameters: distributions, by name
  bool needs_ulps = false;
  std::string summary;  // one line for report.md
  // One input, drawn by the harness family with the family's parameters.
  contact::harness::input<double> (*draw)(contact::harness::seeded_source& source, const family& f);
};

const std::vector<generator_info>& generators();
const generator_info* find_generator(const std::string& name);

struct input {
  double u, dy, phi;
  int family;  // index into scene::families
};

// All families of the scene, each `samples` long, in the order of the file.
// Deterministic: the same scene and seed give the same inputs.
std::vector<input> generate(const scene& s);

// The lanes of a timing or throughput array: the inputs shuffled (so that the
// cases mix), repeated to `length`.
std::vector<input> mixed(const std::vector<input>& inputs, long length, std::uint64_t seed);

// A readable description of a distribution, e.g. "±10^[-7, -3]".
std::string describe(const distribution& d);

}  // namespace report
