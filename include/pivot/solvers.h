// The solver choices: how each joint corrects its position error (PositionSolver, per joint),
// and how a world's contacts remove penetration (ContactCorrection). The methods are described
// in docs/position-correction.md and docs/contacts.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace pivot {

/// The position-correction algorithms of the seed note, chosen per joint.
enum class PositionSolver : std::uint8_t {
    /// A fraction (bias factor / h) of the position error is added to the velocity constraint.
    /// No position phase. Cheapest; the correction adds momentum (bounce, jitter).
    Baumgarte,
    /// After the velocity iterations and position integration: recompute error, Jacobian and
    /// effective mass once, solve for pseudo velocities that start at zero (no warm start) with
    /// the bias, then add them to the positions. Real momentum is untouched.
    PseudoVelocity,
    /// Per constraint solve: re-measure the error and radius vectors from the current positions
    /// and move the positions at once, with the effective mass frozen at the start of the
    /// position phase. Stops early once every error is below kLinearSlop.
    ModifiedNGS,
    /// As ModifiedNGS, with the effective mass rebuilt at every solve. The default.
    FullNGS,
    /// Box2D v3's soft step: the error is a stiff, heavily damped spring (the joint's
    /// JointSoftness: hertz and damping ratio), solved implicitly in the velocity iterations
    /// from the error at the start of each substep; after integration, relax iterations
    /// (positionIterations of them) solve the joint again without the spring's bias, so the
    /// correction leaves no momentum behind. Meant for substeps (WorldDef::substepCount; Box2D
    /// v3 uses 4). No bias factor.
    SoftStep,
    /// XPBD (Mueller et al. 2020), as Avian solves joints: no position rows in the velocity
    /// iterations; after integration, positionIterations XPBD sweeps move the poses with the
    /// joint's compliance (JointSoftness::compliance, 0 = rigid) and the velocities take the
    /// moves. Its multipliers start at zero every substep (no warm start). Meant for substeps
    /// and velocity-level contacts (Soft or Baumgarte). With no position iterations an XPBD
    /// joint holds nothing but its motor and spring. No bias factor.
    XPBD,
};

constexpr int kPositionSolverCount = 6;

/// The solver's name as the testbed spells it: baumgarte, pseudo_velocity, modified_ngs,
/// full_ngs, soft_step, xpbd. An out-of-range value gives "invalid".
const char* positionSolverName(PositionSolver solver);
/// Parses a name made by positionSolverName; nullopt for anything else.
std::optional<PositionSolver> parsePositionSolver(std::string_view name);
/// The bias factor a joint uses when its def does not set one: 0.2 for Baumgarte and
/// PseudoVelocity, 1.0 for the NGS pair, 0 for SoftStep and XPBD (which have none).
float defaultBiasFactor(PositionSolver solver);

/// How contacts remove penetration (all contacts of a world use the same).
enum class ContactCorrection : std::uint8_t {
    /// A velocity bias proportional to the penetration, in the velocity iterations.
    Baumgarte,
    /// After integration, re-measure each point's penetration from the bodies' current
    /// transforms (the manifold is kept in the bodies' local frames, so collision is not run
    /// again) and move the bodies apart, in the same iterations as NGS joints.
    NGS,
    /// Box2D v3's soft contacts: the penetration is a spring (WorldDef::contactHertz,
    /// contactDampingRatio) pushing apart no faster than WorldDef::contactPushSpeed, solved in
    /// the velocity iterations; after integration, relax iterations without it (and with
    /// restitution). Goes with SoftStep joints and substeps.
    Soft,
};

}  // namespace pivot
