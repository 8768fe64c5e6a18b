// `pivot-testbed defaults`: how WorldDef's defaults were chosen. Candidate splits of substeps x
// velocity / position iterations run FullNGS joints and NGS contacts on the two scenes the
// defaults must hold (bridge_crate: the crate stays on the deck; rope_load: every pin within
// 2 cm), kTrials perturbed runs each, and are timed against Box2D 2.4.1's 1 x 8/3 on those two
// and on an awake pyramid (what a contact-heavy game pays), in rounds that alternate the
// candidates. The rule, fixed before the timed run: a candidate qualifies when every run keeps
// the crate's centre above kCrateFloor and the rope within kRopeTarget, each with a 10% margin;
// the defaults are the qualifying candidate with the smallest median time ratio.
#pragma once

#include <ostream>

namespace pivot::report {

constexpr double kCrateFloor = 2.0;   ///< m above the ground (the deck is at 5 m)
constexpr double kRopeTarget = 0.02;  ///< m, the largest pin separation allowed

/// Runs the study and prints its table (Markdown) and verdict to `out`.
void runDefaultsStudy(std::ostream& out);

}  // namespace pivot::report
