// A body as the constraints see it while an island is solved: its velocity and its pose, each
// in an array indexed by solver slot. Constraints never touch Body objects while solving: they
// read and write these, so each stage is a tight loop over contiguous memory that a team of
// workers can share out by graph colour.
#pragma once

#include <array>
#include <cstdint>

#include "pivot/math.h"

namespace pivot {

// 16 bytes, so that the wide contact sweeps load and store a body's velocity whole, one vector
// per body, transposed into lanes (lanes.h, loadColumns), rather than float by float.
struct SolverVelocity {
    Vec2 v;
    float w = 0.0f;
    float spare = 0.0f;  // never read; a wide store may write anything here
};
static_assert(sizeof(SolverVelocity) == 4 * sizeof(float), "four floats, no more");

// 16 bytes, as SolverVelocity (the wide NGS sweeps load and store poses whole).
struct SolverPose {
    Vec2 c;  // centre of mass (a pose, not to be confused with PositionSolver, the strategy)
    float a = 0.0f;
    float spare = 0.0f;  // never read; a wide store may write anything here
};
static_assert(sizeof(SolverPose) == 4 * sizeof(float), "four floats, no more");

/// What a contact's set-up (ContactSolver::prepare) reads of a body, copied into an array by
/// solver slot as the step loads the bodies: prepare then reads two of these, close together,
/// instead of two Body objects from anywhere in the pool (each body is read once a step, not
/// once for each of its contacts).
struct SolverBodyInputs {
    Vec2 localCenter;
    float invMass = 0.0f;
    float invInertia = 0.0f;
    SolverVelocity start;  // the body's velocity before this step's forces
};
static_assert(sizeof(SolverBodyInputs) == 8 * sizeof(float), "two to a cache line");

/// How far a solver slot has moved since the start of the step: its centre's displacement and
/// the rotation by its angle's change. Soft contacts, built once a step, measure their
/// separation at later substeps from these (contact_solver.h).
struct SolverMotion {
    Vec2 dp;
    Rot dq;
};
static_assert(sizeof(SolverMotion) == 4 * sizeof(float), "loaded whole by the wide sweeps");

/// The solver slots of a constraint's two bodies within its island.
using BodyPair = std::array<std::int32_t, 2>;

/// The solver slots of the bodies a joint acts on within its island: A and B, then C and D for
/// a joint that acts on four (a gear, which also moves the bodies its two joints hang from);
/// kNoSlot for a body a joint does not have.
constexpr int kMaxJointBodies = 4;
constexpr std::int32_t kNoSlot = -1;
using JointSlots = std::array<std::int32_t, kMaxJointBodies>;

}  // namespace pivot
