#include "bench/bench_scenes.h"

#include "box2d/box2d_scenes.h"
#include "box2d/parts.h"
#include "scenes/parts.h"
#include "scenes/scene.h"

namespace pivot::bench {

namespace {

constexpr float kDt = 1.0f / 60.0f;

bool continuous = true;  // setContinuousCollision

Stepper stepperOf(std::unique_ptr<World> world, const PivotSetup& setup) {
    std::shared_ptr<World> owned = std::move(world);
    const int velocity = setup.velocityIterations, position = setup.positionIterations;
    return [owned, velocity, position](int) { owned->step(kDt, velocity, position); };
}

Stepper stepperOf(std::unique_ptr<b2World> world) {
    std::shared_ptr<b2World> owned = std::move(world);
    return [owned](int) { owned->Step(kDt, 8, 3); };
}

WorldDef noSleep(const PivotSetup& setup, int workers) {
    WorldDef def;
    def.enableSleep = false;
    def.defaultPositionSolver = setup.solver;
    def.contactCorrection = setup.contacts;
    def.substepCount = setup.substeps;
    def.workerCount = workers;
    def.enableContinuous = continuous;
    return def;
}

std::unique_ptr<b2World> box2dWorld() {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    world->SetAllowSleeping(false);
    world->SetContinuousPhysics(continuous);
    return world;
}

// For manyPyramids, which builds in either engine.
using box2d::addPyramid;
using box2d::addShelf;
using scenes::addPyramid;
using scenes::addShelf;

// many_pyramids: rows of shelves 12 m apart, each carrying pyramids of base 10 side by side.
constexpr float kPyramidPitch = 12.0f;

template <typename World_>
void manyPyramids(World_& world, int across, int up, int base) {
    for (int r = 0; r < up; ++r) {
        float top = float(r) * kPyramidPitch;
        addShelf(world, -1.0f, float(across) * kPyramidPitch, top);
        for (int c = 0; c < across; ++c) {
            scenes::PyramidSpec pyramid;
            pyramid.rows = base;
            pyramid.floor = top;
            pyramid.start = scenes::RowStart::FromLeft;
            pyramid.left = float(c) * kPyramidPitch;
            addPyramid(world, pyramid);
        }
    }
}

BenchScene pyramidScene(const std::string& name, const std::string& description, int steps,
                        int across, int up, int base) {
    BenchScene scene;
    scene.name = name;
    scene.description = description;
    scene.steps = steps;
    scene.buildPivot = [=](const PivotSetup& setup, int workers) {
        auto world = std::make_unique<World>(noSleep(setup, workers));
        manyPyramids(*world, across, up, base);
        return stepperOf(std::move(world), setup);
    };
    scene.buildBox2d = [=]() {
        auto world = box2dWorld();
        manyPyramids(*world, across, up, base);
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
    scene.buildPivot = [=](const PivotSetup& setup, int workers) {
        auto world = std::make_unique<World>(noSleep(setup, workers));
        scenes::addChains(*world, count);
        return stepperOf(std::move(world), setup);
    };
    scene.buildBox2d = [=]() {
        auto world = box2dWorld();
        box2d::addChains(*world, count);
        return stepperOf(std::move(world));
    };
    return scene;
}

// A testbed scene (with its script) as the bench steps it: sleeping off, continuous collision
// as setContinuousCollision says (the two scenes used have it on by default).
Stepper sceneStepper(const char* name, const PivotSetup& setup, int workers) {
    scenes::SceneOptions options;
    options.solver = setup.solver;
    options.contactCorrection = setup.contacts;
    options.substepCount = setup.substeps;
    options.workerCount = workers;
    options.continuous = continuous;
    auto scene =
        std::make_shared<scenes::Scene>(scenes::buildScene(*scenes::findScene(name), options));
    scene->world->setSleepEnabled(false);
    const int velocity = setup.velocityIterations, position = setup.positionIterations;
    return [scene, velocity, position](int i) {
        if (scene->beforeStep) scene->beforeStep(*scene, i);
        scene->world->step(kDt, velocity, position);
    };
}

// Its Box2D twin, built with continuous collision as setContinuousCollision says.
Stepper box2dSceneStepper(box2d::Box2dScene built) {
    auto scene = std::make_shared<box2d::Box2dScene>(std::move(built));
    scene->world->SetAllowSleeping(false);
    return [scene](int i) {
        if (scene->beforeStep) scene->beforeStep(*scene, i);
        scene->world->Step(kDt, 8, 3);
    };
}

}  // namespace

void setContinuousCollision(bool on) {
    continuous = on;
}

bool continuousCollision() {
    return continuous;
}

const std::vector<PivotSetup>& pivotSetups() {
    static const std::vector<PivotSetup> setups = {
        {"full_ngs", PositionSolver::FullNGS, ContactCorrection::NGS, 1, 8, 3},
        {"baumgarte", PositionSolver::Baumgarte, ContactCorrection::NGS, 1, 8, 3},
        {"soft_step", PositionSolver::SoftStep, ContactCorrection::Soft, 4, 1, 1},
    };
    return setups;
}

std::vector<BenchScene> benchScenes() {
    std::vector<BenchScene> scenes;
    BenchScene grid;
    grid.name = "joint_grid";
    grid.description = "100 x 100 circles, each jointed to its neighbours above and to the left";
    grid.steps = 500;
    grid.buildPivot = [](const PivotSetup& setup, int workers) {
        auto world = std::make_unique<World>(noSleep(setup, workers));
        scenes::addJointGrid(*world, scenes::JointGridSpec{});
        return stepperOf(std::move(world), setup);
    };
    grid.buildBox2d = [] {
        auto world = box2dWorld();
        box2d::addJointGrid(*world, scenes::JointGridSpec{});
        return stepperOf(std::move(world));
    };
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
    heavy.buildPivot = [](const PivotSetup& setup, int workers) {
        return sceneStepper("bridge_heavy", setup, workers);
    };
    heavy.buildBox2d = [] { return box2dSceneStepper(box2d::buildBridgeHeavy(continuous)); };
    scenes.push_back(heavy);
    BenchScene bullets;
    bullets.name = "bullets";
    bullets.description =
        "the testbed scene: a pyramid of 55 boxes shot at by ten bullets (continuous collision)";
    bullets.steps = 600;
    bullets.buildPivot = [](const PivotSetup& setup, int workers) {
        return sceneStepper("bullets", setup, workers);
    };
    bullets.buildBox2d = [] { return box2dSceneStepper(box2d::buildBullets(continuous)); };
    scenes.push_back(bullets);
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
