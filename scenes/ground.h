// The static ground most scenes stand on: an 80 m wide slab whose top face is y = 0 (Box2D's
// testbed uses an edge there; the scenes were written before pivot2d had segments, and keep the
// slab, whose top is the same line, so that their recorded results stay comparable).
// Its friction is Box2D's default fixture friction, 0.2, as on the testbed ground the
// reference scenes copy; contacts mix it with the other shape's (sqrt of the product).
#pragma once

#include "pivot/pivot.h"

namespace pivot::scenes {

inline BodyId createGround(World& world, float friction = 0.2f) {
    BodyId ground = world.createBody(BodyDef{});
    ShapeDef def;
    def.density = 0.0f;
    def.friction = friction;
    world.createShape(ground, def, Polygon::box(40.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    return ground;
}

}  // namespace pivot::scenes
