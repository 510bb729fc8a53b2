// Candidates (contact-report --candidate NAME=SPEC): implementations of (A.2)
// from outside the library, run through the harness's candidate runner
// (contact/harness/candidate.hpp) and measured in double beside the built-in
// algorithms: accuracy in every run with double, through the isolating runner;
// timing of a library in this process (once that runner has shown it neither
// crashes nor hangs on the timed inputs), of a command not at all.
#pragma once

#include <string>
#include <vector>

#include "results.hpp"
#include "type_ops.hpp"

namespace report {

// Parses "NAME=SPEC" and opens the candidate; throws contact::harness::candidate_error.
void add_candidate(const std::string& name_equals_spec);
bool has_candidates();

void measure_candidates(const std::vector<input>& inputs, const reference_list& references, std::size_t families,
                        std::vector<accuracy_result>& out);
void time_candidates(const run& r, const std::vector<input>& lanes, std::vector<timing_result>& out);
// Appends to DIR/report.md each candidate's error map beside the stable
// path's; false when gnuplot failed.
bool write_candidate_maps(const std::string& out_dir, const std::vector<scene>& scenes);

}  // namespace report
