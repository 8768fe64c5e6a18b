// The testbed's result table, as aligned text and as CSV.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scenes/metrics.h"

namespace pivot::testbed {

struct TableRow {
    std::string scene;
    std::string solver;
    std::string contact;
    float bias = 0.0f;
    scenes::RunMetrics metrics;
};

void printTable(std::ostream& out, const std::vector<TableRow>& rows);
void writeCsv(std::ostream& out, const std::vector<TableRow>& rows);

}  // namespace pivot::testbed
