#include "scenes/box2d/parts.h"

namespace pivot::box2d {

b2Body* addShelf(b2World& world, float left, float right, float top, float friction) {
    b2BodyDef def;
    b2Body* shelf = world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(0.5f * (right - left), 0.5f, b2Vec2(0.5f * (left + right), top - 0.5f), 0.0f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.friction = friction;
    shelf->CreateFixture(&fixture);
    return shelf;
}

std::vector<b2Body*> addPyramid(b2World& world, const scenes::PyramidSpec& spec) {
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.5f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = 1.0f;
    fixture.friction = 0.6f;
    std::vector<b2Body*> boxes;
    scenes::layPyramid(spec, [&](Vec2 centre) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(centre.x, centre.y);
        b2Body* body = world.CreateBody(&def);
        body->CreateFixture(&fixture);
        boxes.push_back(body);
    });
    return boxes;
}

JointGrid addJointGrid(b2World& world, const scenes::JointGridSpec& spec) {
    JointGrid grid;
    grid.bodies.resize(static_cast<std::size_t>(spec.size) * static_cast<std::size_t>(spec.size));
    b2CircleShape circle;
    circle.m_radius = 0.4f;
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.filter.categoryBits = scenes::kGridCategory;
    fixture.filter.maskBits = static_cast<std::uint16_t>(0xFFFF & ~scenes::kGridCategory);
    scenes::layJointGrid(
        spec,
        [&](int index, Vec2 position, bool pinned) {
            b2BodyDef def;
            def.type = pinned ? b2_staticBody : b2_dynamicBody;
            def.position.Set(position.x, position.y);
            b2Body* body = world.CreateBody(&def);
            fixture.density = pinned ? 0.0f : 1.0f;
            body->CreateFixture(&fixture);
            grid.bodies[index] = body;
        },
        [&](int a, int b, Vec2 anchor) {
            b2RevoluteJointDef def;
            def.Initialize(grid.bodies[a], grid.bodies[b], b2Vec2(anchor.x, anchor.y));
            grid.joints.push_back(world.CreateJoint(&def));
        });
    return grid;
}

Chain addChain(b2World& world, b2Body* root, float x0, float y) {
    b2PolygonShape box;
    box.SetAsBox(0.6f, 0.125f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = 20.0f;
    fixture.friction = 0.2f;
    Chain chain;
    b2Body* previous = root;
    scenes::layChain(x0, y, [&](Vec2 centre, Vec2 anchor) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(centre.x, centre.y);
        b2Body* link = world.CreateBody(&def);
        link->CreateFixture(&fixture);
        b2RevoluteJointDef joint;
        joint.Initialize(previous, link, b2Vec2(anchor.x, anchor.y));
        chain.joints.push_back(world.CreateJoint(&joint));
        chain.links.push_back(link);
        previous = link;
    });
    return chain;
}

void addChains(b2World& world, int count) {
    addShelf(world, -10.0f, static_cast<float>(count) * scenes::kChainPitch + 10.0f, 0.0f);
    const float y = 25.0f;
    for (int c = 0; c < count; ++c) {
        const float x0 = static_cast<float>(c) * scenes::kChainPitch;
        b2BodyDef rootDef;
        rootDef.position.Set(x0, y);
        addChain(world, world.CreateBody(&rootDef), x0, y);
    }
}

}  // namespace pivot::box2d
