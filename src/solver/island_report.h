// What solving an island did that the world reports or acts on after the step.
#pragma once

namespace pivot {

struct IslandReport {
    int translationClamps = 0;
    int rotationClamps = 0;
    int positionIterations = 0;
    int extraPositionSolves = 0;  // joint solves of the extra sweeps joints asked for
    int letGoJoints = 0;      // joints let go this step
    int edgeBodies = 0;       // bodies held at the world's edge (holdAtWorldEdge)
    int discardedBodies = 0;  // bodies whose solved state was non-finite, kept where they were
    bool fellAsleep = false;
};

}  // namespace pivot
