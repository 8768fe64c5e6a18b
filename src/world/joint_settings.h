// The setters the joint defs and the typed World calls share: a def's limit, motor and spring
// stored into a joint's storage. A new prismatic or wheel limit restarts the limit's impulses.
#pragma once

#include "joints/joint.h"
#include "pivot/joint.h"

namespace pivot {

inline void setLimit(DistanceJoint& joint, const LengthLimit& limit) {
    joint.enableLimit = limit.enabled;
    joint.minLength = limit.min;
    joint.maxLength = limit.max;
}
template <typename Storage>
void setSpring(Storage& joint, const JointSpring& spring) {
    joint.enableSpring = spring.enabled;
    joint.hertz = spring.hertz;
    joint.dampingRatio = spring.dampingRatio;
}
inline void setLimit(PrismaticJoint& joint, const TranslationLimit& limit) {
    joint.enableLimit = limit.enabled;
    joint.lowerTranslation = limit.lower;
    joint.upperTranslation = limit.upper;
    joint.lowerImpulse = joint.upperImpulse = 0.0f;
}
inline void setLimit(WheelJoint& joint, const TranslationLimit& limit) {
    joint.enableLimit = limit.enabled;
    joint.lowerTranslation = limit.lower;
    joint.upperTranslation = limit.upper;
    joint.lowerImpulse = joint.upperImpulse = 0.0f;
}
inline void setMotor(WheelJoint& joint, const JointMotor& motor) {
    joint.enableMotor = motor.enabled;
    joint.motorSpeed = motor.speed;
    joint.maxMotorTorque = motor.maxTorque;
}
inline void setMotor(PrismaticJoint& joint, const LinearMotor& motor) {
    joint.enableMotor = motor.enabled;
    joint.motorSpeed = motor.speed;
    joint.maxMotorForce = motor.maxForce;
}

}  // namespace pivot
