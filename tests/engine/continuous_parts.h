// The parts continuous collision's tests shoot with: thin static walls and fast balls.
#pragma once

#include <algorithm>

#include "pivot/pivot.h"

namespace pivot::test {

/// A static box of the given half extents at `at` (density 0).
inline BodyId staticBox(World& world, Vec2 at, float halfWidth, float halfHeight) {
    BodyDef def;
    def.position = at;
    BodyId body = world.createBody(def);
    ShapeDef shape;
    shape.density = 0.0f;
    world.createShape(body, shape, Polygon::box(halfWidth, halfHeight));
    return body;
}

/// A dynamic ball (density 1) at `at` moving at `velocity`.
inline BodyId ball(World& world, Vec2 at, Vec2 velocity, float radius) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = at;
    def.linearVelocity = velocity;
    BodyId body = world.createBody(def);
    world.createShape(body, ShapeDef{}, Circle{{0.0f, 0.0f}, radius});
    return body;
}

/// What a shot did over some steps: the largest x the projectile's origin reached, and the
/// impacts continuous collision counted.
struct Shot {
    float furthest = -1e9f;
    int impacts = 0;
};

/// Steps the world `steps` times of 1/60 s, following `projectile`.
inline Shot follow(World& world, BodyId projectile, int steps) {
    Shot result;
    for (int i = 0; i < steps; ++i) {
        world.step(1.0f / 60.0f);
        result.furthest = std::max(result.furthest, world.bodyPosition(projectile).x);
        result.impacts += world.lastStepStats().impactCount;
    }
    return result;
}

}  // namespace pivot::test
