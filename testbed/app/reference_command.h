// `pivot-testbed reference`: pivot2d's four position solvers beside Box2D 2.4.1's revolute
// joint on the reference scenes.
#pragma once

#include <ostream>

namespace pivot::testbed {

/// Prints the agreement and side-by-side tables; writes the side-by-side table as CSV when
/// csv is not null. Returns the process exit code.
int runReferenceCommand(std::ostream& out, std::ostream* csv);

}  // namespace pivot::testbed
