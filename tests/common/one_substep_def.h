// The world most tests build: one substep of 8 velocity and 3 position iterations (Box2D
// 2.4.1's budget), the other settings as WorldDef's defaults. The tests were written for it and
// pin it, so that a change of the defaults does not change what they measure; the defaults
// themselves are tested in tests/engine/defaults_test.cpp.
#pragma once

#include "pivot/pivot.h"

namespace pivot {

inline WorldDef oneSubstepDef() {
    WorldDef def;
    def.substepCount = 1;
    def.velocityIterations = kBox2D241VelocityIterations;
    def.positionIterations = kBox2D241PositionIterations;
    return def;
}

inline WorldDef oneSubstepDef(Vec2 gravity) {
    WorldDef def = oneSubstepDef();
    def.gravity = gravity;
    return def;
}

}  // namespace pivot
