// The position strategies, in one home. Each is a policy over the operations every joint
// constraint offers (joints/revolute_constraint.h lists them): where its bias goes, and when the
// error, the radius vectors and the effective mass are measured again. The phases that run them
// (velocity_phase.cpp, position_phase.cpp) are written once for all strategies and joint types;
// a new strategy that fits these hooks is one more struct here and its PositionSolver value.
//
// Every strategy has (StrategyDefaults gives what a strategy does not say otherwise):
//   kSolver, kName, kDefaultBias           its PositionSolver value, testbed name and bias
//   prepareSoftness(c, joint, step)        as the joint is built (its own settings)
//   prepareBias(c, poses, invDt)           at the start of the step, after the joint is built
//   solveVelocity(c, velocities)           one velocity iteration
//   kWarmStart                             starts from the impulses the last (sub)step stored
//   kXpbdSweeps                            runs XPBD sweeps after integration, with
//     solveCompliant(c, poses)               one XPBD solve on the poses (velocities derived)
//                                            and takeXpbdReactions(invH) after them
//   kRelax                                 runs relax sweeps after integration, with
//     relax(c, velocities)                   one rigid velocity solve without bias
//   kStoreAfterPositionPhase               its impulses are stored after the position phase
//                                            (relax or XPBD adds to them), not before
//   kKeptAcrossSubsteps                    its constraints hold at a substep's end what the
//                                            next would rebuild them with (the impulses it
//                                            stored), so later substeps re-measure them at the
//                                            new poses (remeasure) instead of rebuilding them
//   kPseudoVelocityPass                    runs the pseudo-velocity pass after integration, with
//     beginPass(c, poses, invH), solvePass(c, pseudo)
//   kNgsSweeps                             joins the NGS sweeps of the position phase, with
//     beginSweeps(c, poses)                  before the first sweep
//     solvePosition(c, poses) -> bool        one solve; true when within slop
// The maths of each is in docs/position-correction.md.
#pragma once

#include <algorithm>
#include <type_traits>
#include <utility>

#include "constraints/rows.h"
#include "constraints/soft_factors.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "constraints/xpbd_rows.h"
#include "joints/joint.h"
#include "pivot/constants.h"
#include "pivot/solvers.h"

namespace pivot {

/// Friction and motor joints (ClampedVelocityRows::kVelocityOnly): no position rows, so every
/// strategy solves them alike.
template <typename C, typename = void>
struct HasVelocityOnly : std::false_type {};
template <typename C>
struct HasVelocityOnly<C, std::void_t<decltype(C::kVelocityOnly)>> : std::true_type {};
template <typename C>
constexpr bool isVelocityOnly() {
    if constexpr (HasVelocityOnly<C>::value) {
        return C::kVelocityOnly;
    } else {
        return false;
    }
}

/// Joint constraints that can be re-measured at later substeps without their joint and bodies
/// (remeasure(poses, step): the part of prepare that depends on the poses); the others are
/// rebuilt.
template <typename C, typename = void>
struct CanRemeasure : std::false_type {};
template <typename C>
struct CanRemeasure<C, std::void_t<decltype(std::declval<C&>().remeasure(
                           std::declval<const SolverPose*>(), std::declval<const StepContext&>()))>>
    : std::true_type {};
/// Those whose remeasure also takes each solver slot's rotation (remeasure(poses, rotations,
/// step)), so that a body's sine and cosine are computed once, not once per joint.
template <typename C, typename = void>
struct RemeasuresWithRotations : std::false_type {};
template <typename C>
struct RemeasuresWithRotations<C, std::void_t<decltype(std::declval<C&>().remeasure(
                                      std::declval<const SolverPose*>(), std::declval<const Rot*>(),
                                      std::declval<const StepContext&>()))>> : std::true_type {};
/// Those whose prepare also takes each solver slot's rotation (the same reason).
template <typename C, typename = void>
struct PreparesWithRotations : std::false_type {};
template <typename C>
struct PreparesWithRotations<
    C, std::void_t<decltype(std::declval<C&>().prepare(
           std::declval<const Joint&>(), std::int32_t{}, std::declval<const SolverBodyInputs*>(),
           std::declval<const JointSlots&>(), std::declval<const SolverPose*>(),
           std::declval<const Rot*>(), std::declval<const StepContext&>()))>> : std::true_type {};

/// What a strategy does unless it says otherwise: rigid velocities, no bias, no position phase.
struct StrategyDefaults {
    static constexpr bool kPseudoVelocityPass = false;
    static constexpr bool kNgsSweeps = false;
    static constexpr bool kRelax = false;
    static constexpr bool kStoreAfterPositionPhase = false;
    static constexpr bool kWarmStart = true;
    static constexpr bool kXpbdSweeps = false;
    static constexpr bool kKeptAcrossSubsteps = false;

    template <typename C>
    static void prepareSoftness(C&, const Joint&, const StepContext&) {}
    template <typename C>
    static void prepareBias(C&, const SolverPose*, float) {}
    template <typename C>
    static void solveVelocity(C& c, SolverVelocity* velocities) {
        c.template solveVelocity<Rows::Rigid>(velocities);
    }
    template <typename C>
    static void beginSweeps(C&, const SolverPose*) {}
    template <typename C>
    static bool solvePosition(const C&, SolverPose*) {
        return true;
    }
};

/// No position phase: a share (bias factor / h) of the error measured at the start of the step
/// is fed back as a velocity in every velocity iteration.
struct BaumgarteStrategy : StrategyDefaults {
    static constexpr PositionSolver kSolver = PositionSolver::Baumgarte;
    static constexpr const char* kName = "baumgarte";
    static constexpr float kDefaultBias = kDefaultBaumgarteBias;
    static constexpr bool kKeptAcrossSubsteps = true;

    template <typename C>
    static void prepareBias(C& c, const SolverPose* poses, float invDt) {
        c.setBias(poses, c.biasFactor * invDt);
    }
    template <typename C>
    static void solveVelocity(C& c, SolverVelocity* velocities) {
        c.template solveVelocity<Rows::Biased>(velocities);
    }
};

/// Rigid velocities; after integration, the error is measured again and solved for pseudo
/// velocities (starting at zero, with the bias), which move the poses only.
struct PseudoVelocityStrategy : StrategyDefaults {
    static constexpr PositionSolver kSolver = PositionSolver::PseudoVelocity;
    static constexpr const char* kName = "pseudo_velocity";
    static constexpr float kDefaultBias = kDefaultPseudoVelocityBias;
    static constexpr bool kPseudoVelocityPass = true;
    // Not kKeptAcrossSubsteps: the pass leaves its own accumulators in the constraint.

    /// The pass's set-up at the integrated poses (the velocity phase's impulses are stored by
    /// then, so the constraint's accumulators and bias are free to hold the pass's own).
    template <typename C>
    static void beginPass(C& c, const SolverPose* poses, float invH) {
        c.restartAt(poses, invH);
        c.setBias(poses, c.biasFactor * invH);
    }
    template <typename C>
    static void solvePass(C& c, SolverVelocity* pseudo) {
        c.solvePseudoVelocity(pseudo);
    }
};

/// Rigid velocities; after integration, each solve re-measures the error and radius vectors
/// and moves the poses at once, with the effective mass of the poses the sweeps start from.
struct ModifiedNgsStrategy : StrategyDefaults {
    static constexpr PositionSolver kSolver = PositionSolver::ModifiedNGS;
    static constexpr const char* kName = "modified_ngs";
    static constexpr float kDefaultBias = kDefaultNgsBias;
    static constexpr bool kNgsSweeps = true;
    static constexpr bool kKeptAcrossSubsteps = true;

    template <typename C>
    static void beginSweeps(C& c, const SolverPose* poses) {
        c.freezeMass(poses);
    }
    template <typename C>
    static bool solvePosition(const C& c, SolverPose* poses) {
        return c.template solvePosition<false>(poses);
    }
};

/// As ModifiedNGS, with the effective mass rebuilt at every solve.
struct FullNgsStrategy : StrategyDefaults {
    static constexpr PositionSolver kSolver = PositionSolver::FullNGS;
    static constexpr const char* kName = "full_ngs";
    static constexpr float kDefaultBias = kDefaultNgsBias;
    static constexpr bool kNgsSweeps = true;
    static constexpr bool kKeptAcrossSubsteps = true;

    template <typename C>
    static bool solvePosition(const C& c, SolverPose* poses) {
        return c.template solvePosition<true>(poses);
    }
};

/// Box2D v3's soft step, per joint: the position rows are springs of the joint's hertz and
/// damping ratio (rows.h), biased in the velocity iterations by the error at the (sub)step's
/// start; after integration, relax sweeps solve the rows rigidly without bias, removing the
/// velocity the bias added so it does not carry into the next (sub)step as momentum.
struct SoftStepStrategy : StrategyDefaults {
    static constexpr PositionSolver kSolver = PositionSolver::SoftStep;
    static constexpr const char* kName = "soft_step";
    static constexpr float kDefaultBias = 0.0f;  // none: hertz and damping ratio take its place
    static constexpr bool kRelax = true;
    static constexpr bool kStoreAfterPositionPhase = true;
    static constexpr bool kKeptAcrossSubsteps = true;

    template <typename C>
    static void prepareSoftness(C& c, const Joint& joint, const StepContext& step) {
        const float hertz = std::min(joint.softness.hertz, kMaxSoftHertzShare * step.invDt);
        c.soft = SoftFactors::of(hertz, joint.softness.dampingRatio, step.dt);
    }
    template <typename C>
    static void prepareBias(C& c, const SolverPose* poses, float) {
        c.setBias(poses, c.soft.biasRate);
    }
    template <typename C>
    static void solveVelocity(C& c, SolverVelocity* velocities) {
        c.template solveVelocity<Rows::Soft>(velocities);
    }
    template <typename C>
    static void relax(C& c, SolverVelocity* velocities) {
        if constexpr (!isVelocityOnly<C>()) c.template solveVelocity<Rows::Rigid>(velocities);
    }
};

/// XPBD (Mueller et al. 2020), per joint: after integration, each substep's XPBD sweeps move the
/// poses with the joint's compliance, and the velocities take the moves (v += dx / h), so the
/// correction is real motion, as in position-based dynamics. No warm start: each substep's
/// multipliers start at zero. A compliant joint's position rows stay out of the velocity
/// iterations (motors and springs stay), as published. A rigid one (compliance 0) keeps them
/// there unbiased (Rows::Rigid): C = 0 implies Cdot = 0, so the model is the same, and the
/// joints and contacts around it then see it hold during the velocity solve instead of
/// letting go until the sweeps pull its bodies back alone (docs/position-correction.md, XPBD).
struct XpbdStrategy : StrategyDefaults {
    static constexpr PositionSolver kSolver = PositionSolver::XPBD;
    static constexpr const char* kName = "xpbd";
    static constexpr float kDefaultBias = 0.0f;  // none: the compliance takes its place
    static constexpr bool kWarmStart = false;
    static constexpr bool kXpbdSweeps = true;
    // Not kKeptAcrossSubsteps: each substep's multipliers start at zero.
    static constexpr bool kStoreAfterPositionPhase = true;

    template <typename C>
    static void prepareSoftness(C& c, const Joint& joint, const StepContext& step) {
        c.xpbd = XpbdRows{};
        c.xpbd.alphaTilde = joint.softness.compliance * step.invDt * step.invDt;
    }
    template <typename C>
    static void solveVelocity(C& c, SolverVelocity* velocities) {
        if (c.xpbd.alphaTilde == 0.0f) {
            c.template solveVelocity<Rows::Rigid>(velocities);
        } else {
            c.template solveVelocity<Rows::None>(velocities);
        }
    }
    template <typename C>
    static void solveCompliant(C& c, SolverPose* poses) {
        c.solveCompliant(poses);
    }
};

template <typename... Strategies>
struct StrategyList {
    static constexpr int kCount = sizeof...(Strategies);
    /// Calls f(Strategy{}) for each strategy, in PositionSolver order.
    template <typename F>
    static void forEach(F&& f) {
        (f(Strategies{}), ...);
    }
    static constexpr bool inSolverOrder() {
        int expected = 0;
        return ((static_cast<int>(Strategies::kSolver) == expected++) && ...);
    }
};

using PositionStrategies =
    StrategyList<BaumgarteStrategy, PseudoVelocityStrategy, ModifiedNgsStrategy, FullNgsStrategy,
                 SoftStepStrategy, XpbdStrategy>;

static_assert(PositionStrategies::inSolverOrder() &&
                  PositionStrategies::kCount == kPositionSolverCount,
              "one strategy per PositionSolver value, in the enum's order");

}  // namespace pivot
