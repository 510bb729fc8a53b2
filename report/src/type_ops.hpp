// The measurements that depend on the scalar type, behind one table of
// function pointers per registered type (contact/types.hpp), so that only the
// translation units that instantiate them (typed_instance.cpp) compile the
// templates of typed.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "contact/reference.hpp"
#include "results.hpp"

namespace report {

using reference_list = std::vector<contact::reference::certified>;

struct type_ops {
  std::string name;  // contact::type_name<T>
  int (*digits)();   // significand bits (MPFR: at the current default precision)
  // The inputs as T holds them, back in double: rounded (and saturated at its
  // largest finite value) for a type narrower than double, unchanged for the others.
  std::vector<input> (*as_held)(const std::vector<input>& inputs);
  // Solves `inputs` with each of the run's methods and scores the results
  // against `references`, the certified roots of the same inputs.
  void (*accuracy)(const run& r, const std::vector<input>& inputs, const reference_list& references,
                   std::size_t families, bool keep_raw, progress& bar, std::vector<accuracy_result>& out);
  // Registers one Google Benchmark per row and round, named "<prefix><type>|<row>#<round>", and
  // returns the rows: the run's methods and, after batch, "batch[NAME]" per target the CPU runs.
  std::vector<std::string> (*register_timings)(const run& r, const std::vector<input>& lanes, const std::string& prefix);
  energy_result (*simulate)(const oscillator& o, method m);
};

// The measurements of the registered type named `type`; a name the registry
// does not hold throws std::invalid_argument (the scene parser reports it first).
const type_ops& ops_for(std::string_view type);

// The measurements of the type at `index` in contact::scalar_types, one
// specialisation per typed_instance.cpp.
template <std::size_t index>
type_ops ops_at();

}  // namespace report
