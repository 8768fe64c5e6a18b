#include "scenes/box2d/box2d_scenes.h"

#include <cmath>

#include "scenes/box2d/parts.h"

namespace pivot::box2d {

namespace {

Box2dScene emptyScene(bool continuous) {
    Box2dScene scene;
    scene.world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    scene.world->SetContinuousPhysics(continuous);
    return scene;
}

b2Body* staticBody(b2World& world) {
    b2BodyDef def;
    return world.CreateBody(&def);
}

// As scenes/ground.h: a slab whose top face is y = 0.
b2Body* ground(b2World& world) {
    b2Body* body = staticBody(world);
    b2PolygonShape slab;
    slab.SetAsBox(40.0f, 0.5f, b2Vec2(0.0f, -0.5f), 0.0f);
    body->CreateFixture(&slab, 0.0f);
    return body;
}

b2Body* ball(b2World& world, b2Vec2 position, float radius, float density) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = position;
    b2Body* body = world.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = radius;
    body->CreateFixture(&circle, density);
    return body;
}

b2RevoluteJoint* pin(Box2dScene& scene, b2Body* a, b2Body* b, b2Vec2 anchor) {
    b2RevoluteJointDef jd;
    jd.Initialize(a, b, anchor);
    auto* joint = static_cast<b2RevoluteJoint*>(scene.world->CreateJoint(&jd));
    scene.joints.push_back(joint);
    return joint;
}

// The seed note's pendulum ball: 1 m across, 5 m below `pivot`, turning about it at `spin`.
b2Body* spinningBall(b2World& world, b2Vec2 pivot, float spin) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = pivot + b2Vec2(0.0f, -5.0f);
    def.angularVelocity = spin;
    def.linearVelocity = b2Cross(spin, def.position - pivot);
    b2Body* body = world.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = 0.5f;
    body->CreateFixture(&circle, 1.0f);
    return body;
}

}  // namespace

Box2dScene buildSpinningPendulum(float spin, bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    const b2Vec2 pivot(0.0f, 10.0f);
    b2Body* anchor = staticBody(*scene.world);
    b2Body* body = spinningBall(*scene.world, pivot, spin);
    pin(scene, anchor, body, pivot);
    scene.bodies.push_back(body);
    return scene;
}

Box2dScene buildDistancePendulum(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    const b2Vec2 pivot(0.0f, 10.0f);
    b2Body* anchor = staticBody(*scene.world);
    b2Body* body = spinningBall(*scene.world, pivot, 100.0f);
    b2DistanceJointDef jd;
    jd.bodyA = anchor;
    jd.bodyB = body;
    jd.localAnchorA = pivot;
    jd.localAnchorB.SetZero();
    jd.length = 5.0f;  // a rod: rigid (stiffness 0) at min = max = length
    jd.minLength = 5.0f;
    jd.maxLength = 5.0f;
    scene.joints.push_back(scene.world->CreateJoint(&jd));
    scene.bodies.push_back(body);
    return scene;
}

Box2dScene buildPulley(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.5f);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(-2.0f, 5.0f);
    b2Body* heavy = scene.world->CreateBody(&def);
    heavy->CreateFixture(&box, 2.0f);
    def.position.Set(2.5f, 5.0f);
    b2Body* light = scene.world->CreateBody(&def);
    light->CreateFixture(&box, 1.0f);
    b2PulleyJointDef jd;
    jd.Initialize(heavy, light, b2Vec2(-2.0f, 10.0f), b2Vec2(2.0f, 10.0f),
                  heavy->GetWorldPoint(b2Vec2(0.0f, 0.5f)),
                  light->GetWorldPoint(b2Vec2(0.0f, 0.5f)), 1.5f);
    scene.joints.push_back(scene.world->CreateJoint(&jd));
    scene.bodies.push_back(heavy);
    scene.bodies.push_back(light);
    return scene;
}

Box2dScene buildTopDown(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    scene.world->SetGravity(b2Vec2(0.0f, 0.0f));
    b2Body* table = staticBody(*scene.world);
    for (int i = 0; i < 12; ++i) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(0.0f, 2.0f * static_cast<float>(i));
        def.linearVelocity.Set(2.0f + 0.5f * static_cast<float>(i), 0.3f);
        def.angularVelocity = 3.0f - 0.5f * static_cast<float>(i);
        b2Body* box = scene.world->CreateBody(&def);
        b2PolygonShape shape;
        shape.SetAsBox(0.5f, 0.5f);
        box->CreateFixture(&shape, 1.0f);
        const float weight = box->GetMass() * 10.0f;
        b2FrictionJointDef jd;
        jd.bodyA = table;
        jd.bodyB = box;
        jd.localAnchorA.SetZero();
        jd.localAnchorB.SetZero();
        jd.maxForce = 0.5f * weight;
        jd.maxTorque = 0.5f * weight * 0.5f;
        scene.joints.push_back(scene.world->CreateJoint(&jd));
        scene.bodies.push_back(box);
    }
    return scene;
}

Box2dScene buildMotorDrive(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2Body* ground = staticBody(*scene.world);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(0.0f, 8.0f);
    b2Body* plank = scene.world->CreateBody(&def);
    b2PolygonShape shape;
    shape.SetAsBox(2.0f, 0.5f);
    plank->CreateFixture(&shape, 1.0f);
    b2MotorJointDef jd;
    jd.Initialize(ground, plank);
    jd.maxForce = 500.0f;
    jd.maxTorque = 1000.0f;
    auto* joint = static_cast<b2MotorJoint*>(scene.world->CreateJoint(&jd));
    scene.joints.push_back(joint);
    scene.bodies.push_back(plank);
    scene.beforeStep = [joint](Box2dScene&, int step) {
        const float t = (1.0f / 60.0f) * static_cast<float>(step);  // as the pivot2d scene
        joint->SetLinearOffset(b2Vec2(6.0f * std::sin(2.0f * t), 8.0f + 4.0f * std::sin(t)));
        joint->SetAngularOffset(t);
    };
    return scene;
}

Box2dScene buildElevator(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2Body* ground = staticBody(*scene.world);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(0.0f, 1.0f);
    b2Body* platform = scene.world->CreateBody(&def);
    b2PolygonShape shape;
    shape.SetAsBox(1.5f, 0.1f);
    b2FixtureDef fixture;  // pivot2d's default friction, 0.6 (Box2D's is 0.2)
    fixture.shape = &shape;
    fixture.friction = 0.6f;
    fixture.density = 1.0f;
    platform->CreateFixture(&fixture);
    def.position.Set(1.0f, 1.6f);
    b2Body* load = scene.world->CreateBody(&def);
    shape.SetAsBox(0.5f, 0.5f);
    fixture.density = 5.0f;
    load->CreateFixture(&fixture);
    b2PrismaticJointDef jd;
    jd.Initialize(ground, platform, b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, 1.0f));
    jd.enableLimit = true;
    jd.lowerTranslation = 0.0f;
    jd.upperTranslation = 4.0f;
    jd.enableMotor = true;
    jd.motorSpeed = 1.0f;
    jd.maxMotorForce = 500.0f;
    auto* joint = static_cast<b2PrismaticJoint*>(scene.world->CreateJoint(&jd));
    scene.joints.push_back(joint);
    scene.bodies.push_back(platform);
    scene.bodies.push_back(load);
    scene.beforeStep = [joint](Box2dScene&, int step) {
        if (step == 0 || step % 300 != 0) return;  // as the pivot2d scene
        joint->SetMotorSpeed(-joint->GetMotorSpeed());
    };
    return scene;
}

Box2dScene buildGearTrain(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    const auto dynamicBody = [&](float x, float y, const b2Shape& shape) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(x, y);
        b2Body* body = scene.world->CreateBody(&def);
        body->CreateFixture(&shape, 1.0f);
        return body;
    };
    b2CircleShape smallDisc;
    smallDisc.m_radius = 1.0f;
    b2Body* small = dynamicBody(-3.0f, 8.0f, smallDisc);
    b2CircleShape bigDisc;
    bigDisc.m_radius = 2.0f;
    b2Body* big = dynamicBody(0.0f, 8.0f, bigDisc);
    b2PolygonShape rackShape;
    rackShape.SetAsBox(0.2f, 2.0f);
    b2Body* rack = dynamicBody(2.3f, 8.0f, rackShape);
    b2BodyDef carrierDef;
    carrierDef.type = b2_kinematicBody;
    carrierDef.position.Set(0.0f, 8.0f);
    carrierDef.linearVelocity.Set(0.5f, 0.0f);
    b2Body* carrier = scene.world->CreateBody(&carrierDef);

    b2PrismaticJointDef slide;
    slide.Initialize(carrier, rack, b2Vec2(2.3f, 8.0f), b2Vec2(0.0f, 1.0f));
    slide.enableLimit = true;
    slide.lowerTranslation = -1.5f;
    slide.upperTranslation = 1.5f;
    b2Joint* shaft = scene.world->CreateJoint(&slide);
    b2RevoluteJointDef drive;
    drive.Initialize(carrier, small, b2Vec2(-3.0f, 8.0f));
    drive.enableMotor = true;
    drive.motorSpeed = 1.0f;
    drive.maxMotorTorque = 100.0f;
    auto* pin1 = static_cast<b2RevoluteJoint*>(scene.world->CreateJoint(&drive));
    b2RevoluteJointDef idler;
    idler.Initialize(carrier, big, b2Vec2(0.0f, 8.0f));
    b2Joint* pin2 = scene.world->CreateJoint(&idler);
    b2GearJointDef mesh;
    mesh.bodyA = small;
    mesh.bodyB = big;
    mesh.joint1 = pin1;
    mesh.joint2 = pin2;
    mesh.ratio = 2.0f;
    b2Joint* gear1 = scene.world->CreateJoint(&mesh);
    b2GearJointDef pinion;
    pinion.bodyA = big;
    pinion.bodyB = rack;
    pinion.joint1 = pin2;
    pinion.joint2 = shaft;
    pinion.ratio = 0.5f;
    b2Joint* gear2 = scene.world->CreateJoint(&pinion);

    scene.bodies = {small, big, rack};
    scene.joints = {shaft, pin1, pin2, gear1, gear2};
    scene.beforeStep = [pin1](Box2dScene&, int step) {
        if (step == 0 || step % 240 != 0) return;  // as the pivot2d scene
        pin1->SetMotorSpeed(-pin1->GetMotorSpeed());
    };
    return scene;
}

Box2dScene buildWeldBeam(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2Body* previous = staticBody(*scene.world);
    for (int i = 0; i <= 10; ++i) {
        const bool load = i == 10;
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(0.5f + static_cast<float>(i), 5.0f);
        b2Body* body = scene.world->CreateBody(&def);
        b2PolygonShape shape;
        shape.SetAsBox(0.5f, load ? 0.5f : 0.125f);
        b2FixtureDef fixture;
        fixture.shape = &shape;
        fixture.density = load ? 5.0f : 1.0f;
        fixture.filter.groupIndex = -1;  // one object: its parts never collide
        body->CreateFixture(&fixture);
        b2WeldJointDef jd;  // stiffness 0: rigid
        jd.Initialize(previous, body, b2Vec2(static_cast<float>(i), 5.0f));
        scene.joints.push_back(scene.world->CreateJoint(&jd));
        scene.bodies.push_back(body);
        previous = body;
    }
    return scene;
}

Box2dScene buildCar(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2Body* groundBody = ground(*scene.world);
    b2FixtureDef fixture;
    b2PolygonShape bump;
    fixture.shape = &bump;
    fixture.friction = 0.6f;
    for (int i = -5; i <= 5; ++i) {
        bump.SetAsBox(0.5f, 0.15f, b2Vec2(3.0f * static_cast<float>(i), 0.0f), 0.0f);
        groundBody->CreateFixture(&fixture);
    }
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(0.0f, 1.3f);
    b2Body* chassis = scene.world->CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(1.25f, 0.25f);
    fixture.shape = &box;
    fixture.friction = 0.6f;  // pivot2d's default
    fixture.density = 1.0f;
    chassis->CreateFixture(&fixture);
    scene.bodies.push_back(chassis);
    b2CircleShape tyre;
    tyre.m_radius = 0.4f;
    fixture.shape = &tyre;
    fixture.friction = 0.9f;
    for (float x : {-0.9f, 0.9f}) {
        def.position.Set(x, 0.55f);
        b2Body* wheel = scene.world->CreateBody(&def);
        wheel->CreateFixture(&fixture);
        b2WheelJointDef jd;
        jd.Initialize(chassis, wheel, b2Vec2(x, 0.55f), b2Vec2(0.0f, 1.0f));
        // The suspension row's effective mass: anchor B is x across from the chassis's centre.
        const float k =
            1.0f / chassis->GetMass() + 1.0f / wheel->GetMass() + x * x / chassis->GetInertia();
        const float omega = 2.0f * b2_pi * 4.0f;
        jd.stiffness = omega * omega / k;
        jd.damping = 2.0f * 0.7f * omega / k;
        jd.enableLimit = true;
        jd.lowerTranslation = -0.25f;
        jd.upperTranslation = 0.25f;
        jd.enableMotor = x < 0.0f;
        jd.motorSpeed = -10.0f;
        jd.maxMotorTorque = 20.0f;
        scene.joints.push_back(scene.world->CreateJoint(&jd));
        scene.bodies.push_back(wheel);
    }
    auto* drive = static_cast<b2WheelJoint*>(scene.joints.front());
    scene.beforeStep = [drive, chassis](Box2dScene&, int) {  // as the pivot2d scene
        const float speed = drive->GetMotorSpeed();
        const float x = chassis->GetPosition().x;
        if ((x > 12.0f && speed < 0.0f) || (x < -12.0f && speed > 0.0f)) {
            drive->SetMotorSpeed(-speed);
        }
    };
    return scene;
}

Box2dScene buildLimitedPendulum(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    const b2Vec2 pivot(0.0f, 10.0f);
    b2Body* anchor = staticBody(*scene.world);
    b2Body* body = ball(*scene.world, pivot + b2Vec2(5.0f, 0.0f), 0.5f, 1.0f);
    b2RevoluteJointDef jd;
    jd.Initialize(anchor, body, pivot);
    jd.enableLimit = true;
    jd.lowerAngle = -b2_pi / 3.0f;
    jd.upperAngle = b2_pi / 3.0f;
    scene.joints.push_back(scene.world->CreateJoint(&jd));
    scene.bodies.push_back(body);
    return scene;
}

Box2dScene buildDoublePendulum(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    const b2Vec2 pivot(0.0f, 10.0f);
    b2Body* previous = staticBody(*scene.world);
    b2Vec2 anchor = pivot;
    for (int i = 1; i <= 2; ++i) {
        b2Vec2 position = pivot + b2Vec2(2.5f * static_cast<float>(i), 0.0f);
        b2Body* body = ball(*scene.world, position, 0.5f, 1.0f);
        pin(scene, previous, body, anchor);
        scene.bodies.push_back(body);
        previous = body;
        anchor = position;
    }
    return scene;
}

Box2dScene buildMotorWheel(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    const b2Vec2 center(0.0f, 5.0f);
    b2Body* anchor = staticBody(*scene.world);
    b2Body* wheel = ball(*scene.world, center, 1.0f, 1.0f);
    b2CircleShape weight;
    weight.m_radius = 0.2f;
    weight.m_p.Set(0.7f, 0.0f);
    wheel->CreateFixture(&weight, 20.0f);
    b2RevoluteJointDef jd;
    jd.Initialize(anchor, wheel, center);
    jd.enableMotor = true;
    jd.motorSpeed = 2.0f;
    jd.maxMotorTorque = 30.0f;
    scene.joints.push_back(scene.world->CreateJoint(&jd));
    scene.bodies.push_back(wheel);
    return scene;
}

Box2dScene buildBridge(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2Body* groundBody = ground(*scene.world);
    b2PolygonShape plank;
    plank.SetAsBox(0.5f, 0.125f);
    b2FixtureDef fixture;
    fixture.shape = &plank;
    fixture.density = 20.0f;
    fixture.friction = 0.2f;
    b2Body* previous = groundBody;
    for (int i = 0; i < 30; ++i) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(-14.5f + 1.0f * static_cast<float>(i), 5.0f);
        b2Body* body = scene.world->CreateBody(&def);
        body->CreateFixture(&fixture);
        pin(scene, previous, body, b2Vec2(-15.0f + 1.0f * static_cast<float>(i), 5.0f));
        scene.bodies.push_back(body);
        previous = body;
    }
    pin(scene, previous, groundBody, b2Vec2(-15.0f + 30.0f, 5.0f));
    return scene;
}

Box2dScene buildBridgeHeavy(bool continuous) {
    Box2dScene scene = buildBridge(continuous);
    scene.beforeStep = [](Box2dScene& s, int step) {
        if (step != 120) return;  // 2 s at 60 Hz
        float bridgeMass = 0.0f;
        for (b2Body* plank : s.bodies) bridgeMass += plank->GetMass();
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(0.0f, 10.0f);
        b2Body* box = s.world->CreateBody(&def);
        b2PolygonShape shape;
        shape.SetAsBox(0.5f, 0.5f);
        b2FixtureDef fixture;
        fixture.shape = &shape;
        fixture.density = 4.0f * bridgeMass;
        fixture.friction = 0.6f;
        box->CreateFixture(&fixture);
        s.bodies.push_back(box);
    };
    return scene;
}

Box2dScene buildChain(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    Chain chain = addChain(*scene.world, ground(*scene.world), 0.0f, 25.0f);
    scene.bodies = std::move(chain.links);
    scene.joints = std::move(chain.joints);
    return scene;
}

Box2dScene buildMassRatio(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    b2Body* previous = staticBody(*scene.world);
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.1f);
    const float y = 25.0f;
    for (int i = 0; i <= 20; ++i) {
        const bool isBall = i == 20;
        b2Body* body = isBall ? ball(*scene.world, b2Vec2(22.0f, y), 2.0f, 50.0f) : nullptr;
        if (!isBall) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(0.5f + static_cast<float>(i), y);
            body = scene.world->CreateBody(&def);
            body->CreateFixture(&box, 1.0f);
        }
        pin(scene, previous, body, b2Vec2(static_cast<float>(i), y));
        scene.bodies.push_back(body);
        previous = body;
    }
    return scene;
}

Box2dScene buildBullets(bool continuous) {
    Box2dScene scene = emptyScene(continuous);
    ground(*scene.world);
    scene.bodies = addPyramid(*scene.world, scenes::Volley::pyramid());
    // As scenes::addRange (created after the pyramid, as there).
    b2Body* walls = staticBody(*scene.world);
    const float half = 0.5f * scenes::Volley::kWallHeight;
    for (float side : {-1.0f, 1.0f}) {
        b2PolygonShape wall;
        wall.SetAsBox(0.5f, half, b2Vec2(side * (scenes::Volley::kWallX + 0.5f), half), 0.0f);
        walls->CreateFixture(&wall, 0.0f);
    }
    scene.beforeStep = [](Box2dScene& s, int step) {
        const scenes::Volley volley;
        const int shot = volley.shotAt(step);
        if (shot < 0) return;
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(volley.x, volley.height(shot));
        def.linearVelocity.Set(volley.speed, 0.0f);
        def.bullet = true;
        b2Body* bullet = s.world->CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = volley.radius;
        b2FixtureDef fixture;
        fixture.shape = &circle;
        fixture.density = volley.density;
        fixture.friction = volley.friction;
        bullet->CreateFixture(&fixture);
        s.bodies.push_back(bullet);
    };
    return scene;
}

}  // namespace pivot::box2d
