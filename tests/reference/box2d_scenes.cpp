#include "box2d_scenes.h"

namespace pivot::reference {

namespace {
Box2dScene emptyScene() {
    Box2dScene scene;
    scene.world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    return scene;
}

b2Body* ground(b2World& world) {
    b2BodyDef def;
    b2Body* body = world.CreateBody(&def);
    b2PolygonShape slab;
    slab.SetAsBox(40.0f, 0.5f, b2Vec2(0.0f, -0.5f), 0.0f);
    body->CreateFixture(&slab, 0.0f);
    return body;
}
}  // namespace

Box2dScene box2dPendulum(float spin) {
    Box2dScene scene = emptyScene();
    const b2Vec2 pivot(0.0f, 10.0f);
    b2BodyDef groundDef;
    b2Body* anchorBody = scene.world->CreateBody(&groundDef);

    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = pivot + b2Vec2(0.0f, -5.0f);
    def.angularVelocity = spin;
    def.linearVelocity = b2Cross(spin, def.position - pivot);
    b2Body* ball = scene.world->CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = 0.5f;
    ball->CreateFixture(&circle, 1.0f);

    b2RevoluteJointDef jd;
    jd.Initialize(anchorBody, ball, pivot);
    scene.joints.push_back(scene.world->CreateJoint(&jd));
    scene.bodies.push_back(ball);
    return scene;
}

Box2dScene box2dChain() {
    Box2dScene scene = emptyScene();
    b2Body* previous = ground(*scene.world);
    b2PolygonShape box;
    box.SetAsBox(0.6f, 0.125f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = 20.0f;
    fixture.friction = 0.2f;
    const float y = 25.0f;
    for (int i = 0; i < 30; ++i) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(0.5f + static_cast<float>(i), y);
        b2Body* link = scene.world->CreateBody(&def);
        link->CreateFixture(&fixture);
        b2RevoluteJointDef jd;
        jd.Initialize(previous, link, b2Vec2(static_cast<float>(i), y));
        scene.joints.push_back(scene.world->CreateJoint(&jd));
        scene.bodies.push_back(link);
        previous = link;
    }
    return scene;
}

}  // namespace pivot::reference
