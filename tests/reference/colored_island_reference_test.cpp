// A coloured island (src/islands/island_schedule.h) is solved in another order than Box2D 2.4.1
// solves it, so the bits differ; the joints must hold as well as Box2D's do.
#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "islands/island_schedule.h"
#include "pivot/pivot.h"

using namespace pivot;

namespace {

constexpr int kSize = 30;  // 1,740 joints: one coloured island
constexpr int kSteps = 300;
constexpr float kDt = 1.0f / 60.0f;

bool isPinned(int row, int col) {
    return row == 0 && std::abs(col - kSize / 2) <= 1;
}

// The worst pin separation over the run of a kSize x kSize grid of circles, each jointed to its
// neighbours above and to the left, hanging from three bodies of its top row.
float pivotWorstSeparation(int workers) {
    WorldDef def;
    def.workerCount = workers;
    World world(def);
    std::vector<BodyId> bodies;
    std::vector<JointId> joints;
    ShapeDef shape;
    shape.filter.categoryBits = 0x0002;
    shape.filter.maskBits = 0x0001;
    for (int row = 0; row < kSize; ++row) {
        for (int col = 0; col < kSize; ++col) {
            BodyDef body;
            body.type = isPinned(row, col) ? BodyType::Static : BodyType::Dynamic;
            body.position = {float(col), -float(row)};
            BodyId id = world.createBody(body);
            world.createShape(id, shape, Circle{{0.0f, 0.0f}, 0.4f});
            bodies.push_back(id);
            if (row > 0) {
                joints.push_back(world.createJoint(RevoluteJointDef::atWorldAnchor(
                    bodies[(row - 1) * kSize + col], id, {float(col), 0.5f - float(row)})));
            }
            if (col > 0) {
                joints.push_back(world.createJoint(RevoluteJointDef::atWorldAnchor(
                    bodies[row * kSize + col - 1], id, {float(col) - 0.5f, -float(row)})));
            }
        }
    }
    EXPECT_GE(int(joints.size()), kColoringThreshold);
    float worst = 0.0f;
    for (int i = 0; i < kSteps; ++i) {
        world.step(kDt, 8, 3);
        for (JointId j : joints) worst = std::max(worst, world.jointSeparation(j));
    }
    return worst;
}

float box2dWorstSeparation() {
    b2World world(b2Vec2(0.0f, -10.0f));
    std::vector<b2Body*> bodies;
    std::vector<b2Joint*> joints;
    b2CircleShape circle;
    circle.m_radius = 0.4f;
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = 1.0f;
    fixture.filter.categoryBits = 0x0002;
    fixture.filter.maskBits = 0x0001;
    for (int row = 0; row < kSize; ++row) {
        for (int col = 0; col < kSize; ++col) {
            b2BodyDef body;
            body.type = isPinned(row, col) ? b2_staticBody : b2_dynamicBody;
            body.position.Set(float(col), -float(row));
            b2Body* b = world.CreateBody(&body);
            b->CreateFixture(&fixture);
            bodies.push_back(b);
            b2RevoluteJointDef joint;
            if (row > 0) {
                joint.Initialize(bodies[(row - 1) * kSize + col], b,
                                 b2Vec2(float(col), 0.5f - float(row)));
                joints.push_back(world.CreateJoint(&joint));
            }
            if (col > 0) {
                joint.Initialize(bodies[row * kSize + col - 1], b,
                                 b2Vec2(float(col) - 0.5f, -float(row)));
                joints.push_back(world.CreateJoint(&joint));
            }
        }
    }
    float worst = 0.0f;
    for (int i = 0; i < kSteps; ++i) {
        world.Step(kDt, 8, 3);
        for (b2Joint* j : joints)
            worst = std::max(worst, (j->GetAnchorB() - j->GetAnchorA()).Length());
    }
    return worst;
}

constexpr int kRows = 40;  // 820 boxes, about 1,600 touching contacts: one coloured island

float rowX(int row, int i) {
    const int count = kRows - row;
    return -0.55f * float(count - 1) + 1.1f * float(i);
}

// How far the top box of a kRows-row pyramid drifts in 10 s, after 1 s to settle.
float pivotPyramidDrift(int workers) {
    WorldDef def;
    def.workerCount = workers;
    World world(def);
    ShapeDef ground;
    ground.density = 0.0f;
    world.createShape(world.createBody(BodyDef{}), ground,
                      Polygon::box(kRows + 10.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    ShapeDef box;
    box.friction = 0.6f;
    BodyId top;
    for (int row = 0; row < kRows; ++row) {
        for (int i = 0; i < kRows - row; ++i) {
            BodyDef body;
            body.type = BodyType::Dynamic;
            body.position = {rowX(row, i), 0.5f + float(row)};
            top = world.createBody(body);
            world.createShape(top, box, Polygon::box(0.5f, 0.5f));
        }
    }
    for (int i = 0; i < 60; ++i) world.step(kDt, 8, 3);
    EXPECT_GE(world.lastStepStats().touchingCount, kColoringThreshold);
    const Vec2 start = world.bodyPosition(top);
    for (int i = 0; i < 600; ++i) world.step(kDt, 8, 3);
    return distance(world.bodyPosition(top), start);
}

float box2dPyramidDrift() {
    b2World world(b2Vec2(0.0f, -10.0f));
    b2PolygonShape groundShape;
    groundShape.SetAsBox(kRows + 10.0f, 0.5f, b2Vec2(0.0f, -0.5f), 0.0f);
    b2BodyDef groundDef;
    world.CreateBody(&groundDef)->CreateFixture(&groundShape, 0.0f);
    b2PolygonShape square;
    square.SetAsBox(0.5f, 0.5f);
    b2FixtureDef fixture;
    fixture.shape = &square;
    fixture.density = 1.0f;
    fixture.friction = 0.6f;
    b2Body* top = nullptr;
    for (int row = 0; row < kRows; ++row) {
        for (int i = 0; i < kRows - row; ++i) {
            b2BodyDef body;
            body.type = b2_dynamicBody;
            body.position.Set(rowX(row, i), 0.5f + float(row));
            top = world.CreateBody(&body);
            top->CreateFixture(&fixture);
        }
    }
    for (int i = 0; i < 60; ++i) world.Step(kDt, 8, 3);
    const b2Vec2 start = top->GetPosition();
    for (int i = 0; i < 600; ++i) world.Step(kDt, 8, 3);
    return (top->GetPosition() - start).Length();
}

}  // namespace

TEST(ColoredIsland, APyramidStandsAtLeastAsWellAsInBox2d) {
    const float theirs = box2dPyramidDrift();
    for (int workers : {1, 2}) {
        const float ours = pivotPyramidDrift(workers);
        EXPECT_LE(ours, 1.1f * theirs) << workers << " workers; Box2D " << theirs;
    }
}

TEST(ColoredIsland, AJointGridHoldsAtLeastAsWellAsInBox2d) {
    const float theirs = box2dWorstSeparation();
    for (int workers : {1, 2}) {
        const float ours = pivotWorstSeparation(workers);
        EXPECT_LE(ours, 1.1f * theirs) << workers << " workers; Box2D " << theirs;
    }
}
