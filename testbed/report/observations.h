// The seed note's observations, each turned into a measurement with an explicit rule for
// "confirmed". Evaluated on the report's runs, so every number the docs quote is regenerated
// with the report.
#pragma once

#include <string>
#include <vector>

#include "report/run_matrix.h"

namespace pivot::report {

struct Observation {
    std::string algorithm;  ///< whose observation: "Baumgarte", ..., or "Recommendation"
    std::string claim;      ///< the note's words (quoted)
    std::string test;       ///< what is measured, and the rule for "confirmed"
    std::string result;     ///< the measured numbers
    std::string verdict;    ///< "confirmed", "not confirmed", or "partly: ..."
};

std::vector<Observation> evaluateObservations(const RunMatrix& matrix);

}  // namespace pivot::report
