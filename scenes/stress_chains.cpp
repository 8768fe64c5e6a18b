// Chains that stress position correction (after Solver2D's suite): one whose joints all start
// 1 m apart, and one holding a ball about 600 times heavier than a link. Both are 40 links
// (boxes 1 x 0.2 m, density 1: 0.2 kg) hung from a static body at (0, 45) and released
// horizontally; neither touches anything.
#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

namespace {
constexpr int kLinks = 40;
constexpr float kHeight = 45.0f;

BodyId addLink(World& world, Vec2 centre) {
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = centre;
    BodyId link = world.createBody(def);
    world.createShape(link, ShapeDef{}, Polygon::box(0.5f, 0.1f));
    return link;
}
}  // namespace

void buildStretchedChain(Scene& scene, const SceneOptions& options) {
    // Link i spans [2i, 2i + 1] m and each joint ties the end of one link (or the ground's
    // anchor at x = -1) to the start of the next: every joint starts 1 m apart. How fast, and
    // whether, each strategy closes them is what the scene shows (its recovery time).
    World& world = *scene.world;
    BodyId previous = world.createBody(BodyDef{});
    Vec2 previousEnd{-1.0f, kHeight};  // in the previous body's frame: the ground's anchor
    for (int i = 0; i < kLinks; ++i) {
        const float start = 2.0f * static_cast<float>(i);
        BodyId link = addLink(world, {start + 0.5f, kHeight});
        RevoluteJointDef jd;
        jd.bodyA = previous;
        jd.bodyB = link;
        jd.localAnchorA = previousEnd;
        jd.localAnchorB = {-0.5f, 0.0f};  // the link's start, 1 m from the previous end
        jd.positionSolver = options.solver;
        jd.biasFactor = options.biasFactor;
        scene.joints.push_back(world.createJoint(jd));
        scene.bodies.push_back(link);
        previous = link;
        previousEnd = {0.5f, 0.0f};  // the link's end
    }
    scene.disturbanceEndStep = 0;  // the gaps are the disturbance
}

void buildHangingStretchedChain(Scene& scene, const SceneOptions& options) {
    // Solver2D's chain under tension: the stretched chain hung straight down from its anchor,
    // link i spanning [2i, 2i + 1] m below it, every joint 1 m open, released at rest. Gravity
    // pulls every gap open while the joints close it; no swing helps or hinders.
    World& world = *scene.world;
    BodyId previous = world.createBody(BodyDef{});
    Vec2 previousEnd{0.0f, kHeight + 1.0f};  // in the ground's frame: the anchor
    for (int i = 0; i < kLinks; ++i) {
        const float top = kHeight - 2.0f * static_cast<float>(i);
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {0.0f, top - 0.5f};
        BodyId link = world.createBody(def);
        world.createShape(link, ShapeDef{}, Polygon::box(0.1f, 0.5f));
        RevoluteJointDef jd;
        jd.bodyA = previous;
        jd.bodyB = link;
        jd.localAnchorA = previousEnd;
        jd.localAnchorB = {0.0f, 0.5f};  // the link's top, 1 m below the previous bottom
        jd.positionSolver = options.solver;
        jd.biasFactor = options.biasFactor;
        scene.joints.push_back(world.createJoint(jd));
        scene.bodies.push_back(link);
        previous = link;
        previousEnd = {0.0f, -0.5f};  // the link's bottom
    }
    scene.disturbanceEndStep = 0;  // the gaps are the disturbance
}

void buildBallChain(Scene& scene, const SceneOptions& options) {
    // The last link holds, by a point on its rim, a ball of radius 1 m and 600 times a link's
    // mass (120 kg).
    World& world = *scene.world;
    BodyId previous = world.createBody(BodyDef{});
    for (int i = 0; i <= kLinks; ++i) {
        const float x = static_cast<float>(i);
        BodyId body;
        if (i == kLinks) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {x + 1.0f, kHeight};
            body = world.createBody(def);
            ShapeDef heavy;
            heavy.density = 600.0f * 0.2f / kPi;
            world.createShape(body, heavy, Circle{{0.0f, 0.0f}, 1.0f});
        } else {
            body = addLink(world, {x + 0.5f, kHeight});
        }
        scene.joints.push_back(world.createJoint(options.jointAt(previous, body, {x, kHeight})));
        scene.bodies.push_back(body);
        previous = body;
    }
    scene.disturbanceEndStep = 0;  // the release is the disturbance
}

// Solver2D's joint grid (Box2D v3's joint_grid benchmark) at a size the report can run nine
// times per strategy: 12 x 12 circles (0.4 m, density 1) 1 m apart, each pinned to its neighbours
// above and on its left, hanging from the three middle bodies of its top row (static), released
// at rest. It sags under its own weight and its free corners swing in; every body is held by up
// to four pins pulling different ways. The full 100 x 100 grid is the benchmark's.
void buildJointGrid(Scene& scene, const SceneOptions& options) {
    World& world = *scene.world;
    JointGridSpec spec;
    spec.size = 12;
    spec.pinnedHalfWidth = 1;
    const Vec2 topLeft{-5.5f, 20.0f};
    std::vector<BodyId> bodies(static_cast<std::size_t>(spec.size * spec.size));
    ShapeDef shape;
    shape.filter = {kGridCategory, static_cast<std::uint16_t>(0xFFFF & ~kGridCategory), 0};
    const Circle circle{{0.0f, 0.0f}, 0.4f};
    layJointGrid(
        spec,
        [&](int index, Vec2 position, bool pinned) {
            BodyDef def;
            def.type = pinned ? BodyType::Static : BodyType::Dynamic;
            def.position = topLeft + position;
            const BodyId body = world.createBody(def);
            shape.density = pinned ? 0.0f : 1.0f;
            world.createShape(body, shape, circle);
            bodies[static_cast<std::size_t>(index)] = body;
            if (!pinned) scene.bodies.push_back(body);
        },
        [&](int a, int b, Vec2 anchor) {
            scene.joints.push_back(world.createJoint(
                options.jointAt(bodies[static_cast<std::size_t>(a)],
                                bodies[static_cast<std::size_t>(b)], topLeft + anchor)));
        });
    scene.origin = topLeft + Vec2{5.5f, -5.5f};
}

}  // namespace pivot::scenes
