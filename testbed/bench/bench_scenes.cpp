#include "bench/bench_scenes.h"

#include "box2d/box2d_scenes.h"
#include "scenes/scene.h"

namespace pivot::bench {

namespace {

constexpr float kDt = 1.0f / 60.0f;

Stepper stepperOf(std::unique_ptr<World> world) {
    std::shared_ptr<World> owned = std::move(world);
    return [owned](int) { owned->step(kDt, 8, 3); };
}

Stepper stepperOf(std::unique_ptr<b2World> world) {
    std::shared_ptr<b2World> owned = std::move(world);
    return [owned](int) { owned->Step(kDt, 8, 3); };
}

WorldDef noSleep(PositionSolver solver, int workers) {
    WorldDef def;
    def.enableSleep = false;
    def.defaultPositionSolver = solver;
    def.workerCount = workers;
    return def;
}

std::unique_ptr<b2World> box2dWorld() {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    world->SetAllowSleeping(false);
    return world;
}

// --- joint_grid: a 100 x 100 grid of circles (radius 0.4, density 1) at unit spacing, each
// jointed to its neighbour above and to its left; the 7 middle bodies of the top row static;
// the circles do not collide with each other.
constexpr int kGrid = 100;
constexpr std::uint16_t kGridCategory = 0x0002;

bool gridStatic(int column, int row) {
    return row == 0 && column >= kGrid / 2 - 3 && column <= kGrid / 2 + 3;
}

std::unique_ptr<World> pivotJointGrid(PositionSolver solver, int workers) {
    auto world = std::make_unique<World>(noSleep(solver, workers));
    std::vector<BodyId> bodies(kGrid * kGrid);
    ShapeDef shape;
    shape.filter = {kGridCategory, static_cast<std::uint16_t>(0xFFFF & ~kGridCategory), 0};
    for (int k = 0; k < kGrid; ++k) {
        for (int i = 0; i < kGrid; ++i) {
            BodyDef def;
            def.type = gridStatic(k, i) ? BodyType::Static : BodyType::Dynamic;
            def.position = {float(k), -float(i)};
            BodyId body = world->createBody(def);
            shape.density = def.type == BodyType::Static ? 0.0f : 1.0f;
            world->createShape(body, shape, Circle{{0.0f, 0.0f}, 0.4f});
            bodies[k * kGrid + i] = body;
            if (i > 0) {
                world->createJoint(RevoluteJointDef::atWorldAnchor(bodies[k * kGrid + i - 1], body,
                                                                   {float(k), -float(i) + 0.5f}));
            }
            if (k > 0) {
                world->createJoint(RevoluteJointDef::atWorldAnchor(
                    bodies[(k - 1) * kGrid + i], body, {float(k) - 0.5f, -float(i)}));
            }
        }
    }
    return world;
}

std::unique_ptr<b2World> box2dJointGrid() {
    auto world = box2dWorld();
    std::vector<b2Body*> bodies(kGrid * kGrid);
    b2CircleShape circle;
    circle.m_radius = 0.4f;
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.filter.categoryBits = kGridCategory;
    fixture.filter.maskBits = static_cast<std::uint16_t>(0xFFFF & ~kGridCategory);
    for (int k = 0; k < kGrid; ++k) {
        for (int i = 0; i < kGrid; ++i) {
            b2BodyDef def;
            def.type = gridStatic(k, i) ? b2_staticBody : b2_dynamicBody;
            def.position.Set(float(k), -float(i));
            b2Body* body = world->CreateBody(&def);
            fixture.density = def.type == b2_staticBody ? 0.0f : 1.0f;
            body->CreateFixture(&fixture);
            bodies[k * kGrid + i] = body;
            b2RevoluteJointDef jd;
            if (i > 0) {
                jd.Initialize(bodies[k * kGrid + i - 1], body, b2Vec2(float(k), -float(i) + 0.5f));
                world->CreateJoint(&jd);
            }
            if (k > 0) {
                jd.Initialize(bodies[(k - 1) * kGrid + i], body,
                              b2Vec2(float(k) - 0.5f, -float(i)));
                world->CreateJoint(&jd);
            }
        }
    }
    return world;
}

// --- pyramids of 1 m boxes (density 1, friction 0.6) on static shelves. Boxes start at their
// resting gap (polygons collide with a 1 cm skin in both engines).
constexpr float kRestGap = 2.0f * kPolygonRadius - kLinearSlop;

template <typename AddBox>
void pyramidLayout(int base, float left, float bottom, AddBox&& addBox) {
    for (int row = 0; row < base; ++row) {
        int count = base - row;
        float x0 = left + 0.5f * float(row) * (1.0f + kRestGap);
        for (int i = 0; i < count; ++i) {
            addBox(x0 + float(i) * (1.0f + kRestGap),
                   bottom + 0.5f + kRestGap + float(row) * (1.0f + kRestGap));
        }
    }
}

// A shelf is a static box whose top face is at `top`, spanning [left, right].
void pivotShelf(World& world, float left, float right, float top) {
    BodyId shelf = world.createBody(BodyDef{});
    ShapeDef def;
    def.density = 0.0f;
    def.friction = 0.6f;
    world.createShape(
        shelf, def,
        Polygon::box(0.5f * (right - left), 0.5f, {0.5f * (left + right), top - 0.5f}, 0.0f));
}

void box2dShelf(b2World& world, float left, float right, float top) {
    b2BodyDef def;
    b2Body* shelf = world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(0.5f * (right - left), 0.5f, b2Vec2(0.5f * (left + right), top - 0.5f), 0.0f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.friction = 0.6f;
    shelf->CreateFixture(&fixture);
}

void pivotPyramid(World& world, int base, float left, float bottom) {
    ShapeDef def;
    def.density = 1.0f;
    def.friction = 0.6f;
    Polygon box = Polygon::box(0.5f, 0.5f);
    pyramidLayout(base, left, bottom, [&](float x, float y) {
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        bd.position = {x, y};
        world.createShape(world.createBody(bd), def, box);
    });
}

void box2dPyramid(b2World& world, int base, float left, float bottom) {
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.5f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = 1.0f;
    fixture.friction = 0.6f;
    pyramidLayout(base, left, bottom, [&](float x, float y) {
        b2BodyDef bd;
        bd.type = b2_dynamicBody;
        bd.position.Set(x, y);
        world.CreateBody(&bd)->CreateFixture(&fixture);
    });
}

// many_pyramids: rows of shelves 12 m apart, each carrying pyramids of base 10 side by side.
constexpr float kPyramidPitch = 12.0f;

template <typename World_, typename Shelf, typename Pyramid>
void manyPyramids(World_& world, int across, int up, int base, Shelf&& shelf, Pyramid&& pyramid) {
    for (int r = 0; r < up; ++r) {
        float top = float(r) * kPyramidPitch;
        shelf(world, -1.0f, float(across) * kPyramidPitch, top);
        for (int c = 0; c < across; ++c) pyramid(world, base, float(c) * kPyramidPitch, top);
    }
}

// Chains: the testbed chain (30 links of 1.2 x 0.25 m, density 20, joints 1 m apart), roots
// 32 m apart so neighbouring chains never meet, all above one ground.
constexpr float kChainPitch = 32.0f;

std::unique_ptr<World> pivotChains(PositionSolver solver, int workers, int count) {
    auto world = std::make_unique<World>(noSleep(solver, workers));
    pivotShelf(*world, -10.0f, float(count) * kChainPitch + 10.0f, 0.0f);
    ShapeDef link;
    link.density = 20.0f;
    link.friction = 0.2f;
    Polygon box = Polygon::box(0.6f, 0.125f);
    for (int c = 0; c < count; ++c) {
        float x0 = float(c) * kChainPitch;
        BodyId previous = world->createBody(BodyDef{});
        world->setBodyTransform(previous, {x0, 25.0f}, 0.0f);
        for (int i = 0; i < 30; ++i) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {x0 + 0.5f + float(i), 25.0f};
            BodyId body = world->createBody(def);
            world->createShape(body, link, box);
            world->createJoint(
                RevoluteJointDef::atWorldAnchor(previous, body, {x0 + float(i), 25.0f}));
            previous = body;
        }
    }
    return world;
}

std::unique_ptr<b2World> box2dChains(int count) {
    auto world = box2dWorld();
    box2dShelf(*world, -10.0f, float(count) * kChainPitch + 10.0f, 0.0f);
    b2PolygonShape box;
    box.SetAsBox(0.6f, 0.125f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = 20.0f;
    fixture.friction = 0.2f;
    for (int c = 0; c < count; ++c) {
        float x0 = float(c) * kChainPitch;
        b2BodyDef anchorDef;
        anchorDef.position.Set(x0, 25.0f);
        b2Body* previous = world->CreateBody(&anchorDef);
        for (int i = 0; i < 30; ++i) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(x0 + 0.5f + float(i), 25.0f);
            b2Body* body = world->CreateBody(&def);
            body->CreateFixture(&fixture);
            b2RevoluteJointDef jd;
            jd.Initialize(previous, body, b2Vec2(x0 + float(i), 25.0f));
            world->CreateJoint(&jd);
            previous = body;
        }
    }
    return world;
}

BenchScene pyramidScene(const std::string& name, const std::string& description, int steps,
                        int across, int up, int base) {
    BenchScene scene;
    scene.name = name;
    scene.description = description;
    scene.steps = steps;
    scene.buildPivot = [=](PositionSolver solver, int workers) {
        auto world = std::make_unique<World>(noSleep(solver, workers));
        manyPyramids(*world, across, up, base, pivotShelf, pivotPyramid);
        return stepperOf(std::move(world));
    };
    scene.buildBox2d = [=]() {
        auto world = box2dWorld();
        manyPyramids(*world, across, up, base, box2dShelf, box2dPyramid);
        return stepperOf(std::move(world));
    };
    return scene;
}

BenchScene chainScene(const std::string& name, int steps, int count) {
    BenchScene scene;
    scene.name = name;
    scene.description = std::to_string(count) + (count == 1 ? " chain" : " chains") +
                        " of 30 links, released horizontally";
    scene.steps = steps;
    scene.buildPivot = [=](PositionSolver solver, int workers) {
        return stepperOf(pivotChains(solver, workers, count));
    };
    scene.buildBox2d = [=]() { return stepperOf(box2dChains(count)); };
    return scene;
}

}  // namespace

std::vector<BenchScene> benchScenes() {
    std::vector<BenchScene> scenes;
    BenchScene grid;
    grid.name = "joint_grid";
    grid.description = "100 x 100 circles, each jointed to its neighbours above and to the left";
    grid.steps = 500;
    grid.buildPivot = [](PositionSolver solver, int workers) {
        return stepperOf(pivotJointGrid(solver, workers));
    };
    grid.buildBox2d = [] { return stepperOf(box2dJointGrid()); };
    scenes.push_back(grid);
    scenes.push_back(
        pyramidScene("large_pyramid", "a pyramid of 5050 boxes, base 100", 500, 1, 1, 100));
    scenes.push_back(pyramidScene("many_pyramids",
                                  "20 x 20 pyramids of base 10 (22000 boxes) on 20 shelves", 200,
                                  20, 20, 10));
    scenes.push_back(chainScene("many_chains", 600, 100));
    BenchScene heavy;
    heavy.name = "bridge_heavy";
    heavy.description = "the testbed scene: the bridge, and at 2 s a 600 kg box falls on it";
    heavy.steps = 600;
    heavy.buildPivot = [](PositionSolver solver, int workers) {
        scenes::SceneOptions options;
        options.solver = solver;
        options.workerCount = workers;
        auto scene = std::make_shared<scenes::Scene>(
            scenes::buildScene(*scenes::findScene("bridge_heavy"), options));
        scene->world->setSleepEnabled(false);
        return Stepper([scene](int i) {
            scene->beforeStep(*scene, i);
            scene->world->step(kDt, 8, 3);
        });
    };
    heavy.buildBox2d = [] {
        auto scene = std::make_shared<box2d::Box2dScene>(box2d::buildBridgeHeavy(false));
        scene->world->SetAllowSleeping(false);
        return Stepper([scene](int i) {
            scene->beforeStep(*scene, i);
            scene->world->Step(kDt, 8, 3);
        });
    };
    scenes.push_back(heavy);
    // Scaling: cost per step as the work grows.
    scenes.push_back(chainScene("chains_1", 600, 1));
    scenes.push_back(chainScene("chains_10", 600, 10));
    scenes.push_back(chainScene("chains_100", 600, 100));
    for (int rows : {10, 20, 40}) {
        scenes.push_back(pyramidScene("pyramid_" + std::to_string(rows),
                                      "a pyramid " + std::to_string(rows) + " rows high", 500, 1, 1,
                                      rows));
    }
    return scenes;
}

}  // namespace pivot::bench
