// What a joint's stored impulses stand for as a force and a torque on body B: the reaction
// queries report it, and breakable joints (breakForce, breakTorque) compare it with their
// thresholds.
#include "joints/joint.h"

namespace pivot {

Vec2 Joint::reactionForce() const {
    const Joint& j = *this;
    if (const auto* distance = std::get_if<DistanceJoint>(&j.data)) {
        return (j.impulseInvDt * distance->axialImpulse()) * distance->axis;
    }
    if (const auto* pulley = std::get_if<PulleyJoint>(&j.data)) {
        return (j.impulseInvDt * -pulley->ratio * pulley->impulse) * pulley->axisB;
    }
    if (const auto* friction = std::get_if<FrictionJoint>(&j.data)) {
        return j.impulseInvDt * friction->linearImpulse;
    }
    if (const auto* motor = std::get_if<MotorJoint>(&j.data)) {
        return j.impulseInvDt * motor->linearImpulse;
    }
    if (const auto* weld = std::get_if<WeldJoint>(&j.data)) {
        return j.impulseInvDt * Vec2{weld->impulse.x, weld->impulse.y};
    }
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        const Vec2 perp{-wheel->axis.y, wheel->axis.x};
        return j.impulseInvDt * (wheel->impulse * perp + wheel->axialImpulse() * wheel->axis);
    }
    if (const auto* prismatic = std::get_if<PrismaticJoint>(&j.data)) {
        const Vec2 perp{-prismatic->axis.y, prismatic->axis.x};
        return j.impulseInvDt *
               (prismatic->impulse.x * perp + prismatic->axialImpulse() * prismatic->axis);
    }
    if (const auto* gear = std::get_if<GearJoint>(&j.data)) {
        return (j.impulseInvDt * gear->impulse) * gear->linearB;
    }
    return j.impulseInvDt * std::get<RevoluteJoint>(j.data).impulse;
}

float Joint::reactionTorque() const {
    const Joint& j = *this;
    if (const auto* r = std::get_if<RevoluteJoint>(&j.data)) {
        return j.impulseInvDt * (r->motorImpulse + r->lowerImpulse - r->upperImpulse);
    }
    if (const auto* friction = std::get_if<FrictionJoint>(&j.data)) {
        return j.impulseInvDt * friction->angularImpulse;
    }
    if (const auto* motor = std::get_if<MotorJoint>(&j.data)) {
        return j.impulseInvDt * motor->angularImpulse;
    }
    if (const auto* prismatic = std::get_if<PrismaticJoint>(&j.data)) {
        return j.impulseInvDt * prismatic->impulse.y;
    }
    if (const auto* weld = std::get_if<WeldJoint>(&j.data)) {
        return j.impulseInvDt * weld->impulse.z;
    }
    if (const auto* wheel = std::get_if<WheelJoint>(&j.data)) {
        return j.impulseInvDt * wheel->motorImpulse;
    }
    if (const auto* gear = std::get_if<GearJoint>(&j.data)) {
        return (j.impulseInvDt * gear->impulse) * gear->angularB;
    }
    return 0.0f;
}

}  // namespace pivot
