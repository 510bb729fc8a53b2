// Candidates (contact-report --candidate NAME=SPEC): implementations of (A.2)
// from outside the library, run through the harness's candidate runner
// (contact/harness/candidate.hpp) and measured in double beside the built-in
// algorithms: accuracy in every run with double, timing (which includes the
// runner's pipe, so it bounds the candidate's own speed from above).
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

}  // namespace report
