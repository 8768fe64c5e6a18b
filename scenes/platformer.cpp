// A small platform game, to use the game-facing API together: chain-shape terrain with a pit, a
// capsule character driven by setting its velocity with a ray-cast ground check, two one-way
// platforms (a pre-solve callback lets the character jump up through them and land on them), a
// coin (a sensor) picked up by its sensor event, a plank bridge over the pit whose joints break
// (break force, let-go events) when a heavy crate is dropped on it after the character crossed,
// and, halfway, a snapshot restored into a second world on two workers that must hash the same.
//
// Everything the script decides is read from the world (the step index, the character's pose,
// the last step's events, the coin's existence), never kept on the side, so that a world restored
// from a snapshot continues as the original (tests/engine/platformer_test.cpp rolls it back).
#include <stdexcept>
#include <string>

#include "scene.h"

namespace pivot::scenes {

namespace {

constexpr std::uint16_t kCharacterCategory = 0x0002;
constexpr std::uint16_t kCoinCategory = 0x0004;
constexpr float kRunSpeed = 4.0f;    // m/s
constexpr float kJumpSpeed = 7.5f;   // m/s: about 2.8 m up
constexpr float kHalfHeight = 0.7f;  // the capsule's centre to its foot, m
constexpr float kBridgeLeft = 6.0f;  // the pit's edges, m
constexpr float kBridgeRight = 12.0f;
constexpr float kGap = 0.1f;  // m between the bridge's end pins and the pit's edges
constexpr int kPlanks = 8;
constexpr float kBreakForce = 1200.0f;  // N: the character crosses (under 600 N), the crate not

// The character's script for the step about to be made.
void drive(World& world, BodyId character) {
    const Vec2 p = world.bodyPosition(character);
    const Vec2 v = world.bodyLinearVelocity(character);
    QueryFilter solid;
    solid.maskBits = static_cast<std::uint16_t>(~(kCharacterCategory | kCoinCategory));
    const bool grounded = world.castRayClosest(p, {0.0f, -(kHalfHeight + 0.1f)}, solid).has_value();
    float vx = p.x < 22.0f ? kRunSpeed : 0.0f;
    float vy = v.y;
    // Jump from under each platform's left end: up through it, down onto it.
    const bool takeOff = (p.x > -13.8f && p.x < -13.5f) || (p.x > -5.8f && p.x < -5.5f);
    if (grounded && takeOff && v.y < 0.5f) vy = kJumpSpeed;
    world.setBodyLinearVelocity(character, {vx, vy});
}

}  // namespace

void buildPlatformer(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    scene.origin = {0.0f, 0.0f};
    const BodyId ground = world.createBody(BodyDef{});
    ShapeDef terrain;
    terrain.density = 0.0f;
    terrain.friction = 0.6f;
    // Right to left (solid side up): a floor, the pit under the bridge, a hill, a wall at the end.
    world.createChain(ground, terrain,
                      Chain{{{26.0f, 4.0f},
                             {25.0f, 3.0f},
                             {24.0f, 0.0f},
                             {kBridgeRight + kGap, 0.0f},
                             {kBridgeRight + kGap, -4.0f},
                             {kBridgeLeft - kGap, -4.0f},
                             {kBridgeLeft - kGap, 0.0f},
                             {2.0f, 0.0f},
                             {0.0f, 0.4f},
                             {-2.0f, 0.0f},
                             {-20.0f, 0.0f},
                             {-20.0f, 6.0f},
                             {-21.0f, 7.0f}},
                            false});

    // Solid rock under the chain: a chain is one-sided, and a plank swinging on its pin or
    // pressed by the crate could put its centre below the surface and fall out of the world.
    ShapeDef rock;
    rock.density = 0.0f;
    world.createShape(ground, rock, Polygon::box(12.95f, 6.0f, {-7.05f, -6.0f}, 0.0f));
    world.createShape(ground, rock, Polygon::box(5.95f, 6.0f, {18.05f, -6.0f}, 0.0f));
    world.createShape(ground, rock, Polygon::box(3.1f, 4.0f, {9.0f, -8.0f}, 0.0f));

    // Two one-way platforms: solid from above only, through the pre-solve callback below.
    ShapeDef platformDef;
    platformDef.enablePreSolve = true;
    const ShapeId platform1 =
        world.createShape(ground, platformDef, Polygon::box(3.0f, 0.1f, {-11.0f, 1.8f}, 0.0f));
    const ShapeId platform2 =
        world.createShape(ground, platformDef, Polygon::box(3.0f, 0.1f, {-3.0f, 2.6f}, 0.0f));
    World* w = &world;
    world.setPreSolveCallback([w, platform1, platform2](const ContactData& c) {
        const bool aIsPlatform = c.shapeA == platform1 || c.shapeA == platform2;
        const ShapeId other = aIsPlatform ? c.shapeB : c.shapeA;
        const Vec2 up = aIsPlatform ? c.normal : -c.normal;  // from the platform to the other
        return up.y > 0.7f && w->bodyLinearVelocity(w->shapeBody(other)).y <= 0.5f;
    });

    // The character: an upright capsule that does not turn.
    BodyDef characterDef;
    characterDef.type = BodyType::Dynamic;
    characterDef.position = {-18.0f, kHalfHeight + 0.05f};
    characterDef.fixedRotation = true;
    const BodyId character = world.createBody(characterDef);
    ShapeDef body;
    body.density = 10.0f;
    body.friction = 0.0f;  // it is driven by its velocity, not by friction
    body.filter.categoryBits = kCharacterCategory;
    world.createShape(character, body, Capsule{{0.0f, -0.4f}, {0.0f, 0.4f}, 0.3f});
    scene.bodies.push_back(character);

    // The coin: a sensor on a static body, destroyed when the character's begin event comes.
    const BodyId coin = world.createBody(BodyDef{});
    ShapeDef coinDef;
    coinDef.isSensor = true;
    coinDef.filter.categoryBits = kCoinCategory;
    world.createShape(coin, coinDef, Circle{{3.5f, 1.0f}, 0.3f});

    // The bridge: planks pinned end to end across the pit, each joint breakable.
    const float plank = (kBridgeRight - kBridgeLeft) / static_cast<float>(kPlanks);
    BodyId previous = ground;
    for (int i = 0; i <= kPlanks; ++i) {
        const float x = kBridgeLeft + plank * static_cast<float>(i);
        BodyId next = ground;
        if (i < kPlanks) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {x + 0.5f * plank, -0.125f};
            next = world.createBody(def);
            ShapeDef wood;
            wood.density = 6.0f;
            world.createShape(next, wood, Polygon::box(0.5f * plank, 0.125f));
            scene.bodies.push_back(next);
        }
        RevoluteJointDef pin = options.jointAt(previous, next, {x, -0.125f});
        pin.breakForce = kBreakForce;
        // A let-go joint still keeps its bodies from colliding: the end planks must meet the
        // ground once their pins break, or they would fall through the level.
        pin.collideConnected = previous == ground || next == ground;
        scene.joints.push_back(world.createJoint(pin));
        previous = next;
    }

    const int dropStep = stepAt(options, 8.0f);
    const int checkStep = stepAt(options, 5.0f);
    scene.beforeStep = [character, coin, dropStep, checkStep](Scene& s, int step) {
        World& world = *s.world;
        if (world.isValid(coin)) {
            for (const SensorEvent& e : world.sensorBeginEvents()) {
                if (world.shapeBody(e.visitor) == character) {
                    world.destroyBody(coin);  // picked up
                    break;
                }
            }
        }
        if (step == dropStep) {
            BodyDef crate;
            crate.type = BodyType::Dynamic;
            crate.position = {0.5f * (kBridgeLeft + kBridgeRight), 6.0f};
            const BodyId box = world.createBody(crate);
            ShapeDef heavy;
            heavy.density = 100.0f;  // 256 kg
            world.createShape(box, heavy, Polygon::box(0.8f, 0.8f));
            s.bodies.push_back(box);
        }
        if (step == checkStep) {
            // Save halfway and restore into a second world on two workers: the same state.
            const std::vector<std::uint8_t> saved = world.snapshot();
            WorldDef def;
            def.workerCount = 2;
            World copy(def);
            copy.restore(saved);
            if (copy.stateHash() != world.stateHash()) {
                throw std::logic_error("platformer: the restored snapshot hashes differently");
            }
        }
        drive(world, character);
    };
    scene.disturbanceEndStep = dropStep;
}

}  // namespace pivot::scenes
