// The report's exact baseline: each strategy's position correction measured against the
// converged answer, not only as separation. On small scenes of revolute pins without limits
// (pendulum_20, double_pendulum, chain; not the bridge, whose deck is as long as its span: taut,
// its pins' Jacobian is singular and Newton's method does not converge), every step of a strategy's run is also
// taken from the same state without its position phase (a snapshot restored, the step run with 0
// position iterations: the velocity phase and integration only), and those poses are projected
// onto the joints exactly: Newton steps x <- x - M^-1 J^T (J M^-1 J^T)^-1 C(x) in double
// precision, each a dense factorisation of the whole joint system, until every pin is closed to
// 1e-9 m. The mass-weighted closest point is where infinitely many exact position iterations
// would take the bodies; the strategy's error is how far its own step left each body's centre
// from it (and its angle, times the body's radius of gyration), the largest over bodies and
// steps. The run then goes on from the strategy's own step. Every configuration kTrials
// perturbed times, at one substep of 8 velocity and 3 position iterations.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report/observations.h"

namespace pivot::report {

struct ExactBaseline {
    std::string markdown;
    int runs = 0;
    /// Every trial: scene, strategy, seed and its figures (docs/results/runs-exact.csv).
    std::string csv;
};

/// The scenes of the baseline (revolute pins without limits, at most a few dozen bodies).
const std::vector<std::string>& exactBaselineScenes();

ExactBaseline runExactBaseline(int steps, int threads,
                               const std::function<void(const std::string&)>& progress);

}  // namespace pivot::report
