// The Box2D 2.4.1 twins of scenes/parts.h: the same layouts, built through Box2D's API with the
// same shapes, densities, frictions and filters, in the same order.
#pragma once

#include <box2d/box2d.h>

#include <vector>

#include "scenes/parts.h"

namespace pivot::box2d {

/// As scenes::addShelf.
b2Body* addShelf(b2World& world, float left, float right, float top, float friction = 0.6f);

/// As scenes::addPyramid.
std::vector<b2Body*> addPyramid(b2World& world, const scenes::PyramidSpec& spec);

struct JointGrid {
    std::vector<b2Body*> bodies;   ///< by index (scenes::layJointGrid)
    std::vector<b2Joint*> joints;  ///< in creation order
};

/// As scenes::addJointGrid.
JointGrid addJointGrid(b2World& world, const scenes::JointGridSpec& spec);

struct Chain {
    std::vector<b2Body*> links;
    std::vector<b2Joint*> joints;
};

/// As scenes::addChain.
Chain addChain(b2World& world, b2Body* root, float x0, float y);

/// As scenes::addChains.
void addChains(b2World& world, int count);

}  // namespace pivot::box2d
