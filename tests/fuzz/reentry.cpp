#include "reentry.h"

#include <functional>
#include <thread>
#include "one_substep_def.h"

namespace pivot::fuzz {

ChangeKind makeRandomChange(World& w, Random& r, const Targets& t, bool structureOnly) {
    const BodyId body = t.body;
    switch (r.below(structureOnly ? 11 : 20)) {
        case 0: w.createBody(BodyDef{}); return ChangeKind::Structure;
        case 1: w.destroyBody(body); return ChangeKind::Structure;
        case 2:
            w.createShape(body, ShapeDef{}, Circle{{0.2f, 0.0f}, 0.1f});
            return ChangeKind::Structure;
        case 3: w.destroyShape(t.shape); return ChangeKind::Structure;
        case 4: w.setBodyType(body, BodyType::Static); return ChangeKind::Structure;
        case 5: w.setBodyTransform(body, {1.0f, 2.0f}, 0.5f); return ChangeKind::Structure;
        case 6: w.setShapeSensor(t.shape, true); return ChangeKind::Structure;
        case 7:
            w.createJoint(RevoluteJointDef::atWorldAnchor(w.createBody(BodyDef{}), body, {0, 0}));
            return ChangeKind::Structure;
        case 8: w.destroyJoint(t.joint); return ChangeKind::Structure;
        case 9: w.restore(t.snapshot); return ChangeKind::Structure;
        case 10: w.step(1.0f / 60.0f); return ChangeKind::Structure;
        case 11: w.setBodyLinearVelocity(body, {1.0f, 0.0f}); return ChangeKind::State;
        case 12: w.applyLinearImpulse(body, {0.1f, 0.0f}, {0.0f, 0.0f}); return ChangeKind::State;
        case 13: w.setBodyUserData(body, 7); return ChangeKind::State;
        case 14: w.setBodyAwake(body, false); return ChangeKind::State;
        case 15: w.setShapeFriction(t.shape, 0.3f); return ChangeKind::State;
        case 16: w.setShapeUserData(t.shape, 9); return ChangeKind::State;
        case 17: w.setJointUserData(t.joint, 3); return ChangeKind::State;
        case 18: w.setGravity({0.0f, -9.0f}); return ChangeKind::State;
        default: w.setSleepEnabled(true); return ChangeKind::State;
    }
}

namespace {

void addCrowd(World& world) {
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(40.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    for (int row = 0; row < 30; ++row) {
        for (int i = 0; i < 30 - row; ++i) {
            BodyDef def;
            def.type = BodyType::Dynamic;
            def.position = {-15.0f + 0.5f * float(row) + float(i), 0.5f + float(row)};
            world.createShape(world.createBody(def), ShapeDef{}, Polygon::box(0.45f, 0.45f));
        }
    }
}

}  // namespace

struct MeddlingCrowd::State {
    World* world = nullptr;
    Random* random = nullptr;
    Targets targets;
    int calls = 0;  // per callback while armed
    int refused = 0;
    std::vector<std::string>* failures = nullptr;
    std::unique_ptr<World> crowd;
    std::unique_ptr<World> twin;

    // Changing calls and a read, each of which must be refused: the step is under way.
    void meddle(const char* where) {
        if (calls == 0) return;
        for (int i = 0; i < calls; ++i) {
            try {
                makeRandomChange(*world, *random, targets);
                failures->push_back(std::string("a change from ") + where +
                                    " during a step was not refused");
            } catch (const Error&) {
                ++refused;
            }
        }
        try {
            world->bodyPosition(targets.body);
            failures->push_back(std::string("a read from ") + where +
                                " during a step was not refused");
        } catch (const Error&) {
            ++refused;
        }
    }
};

MeddlingCrowd::MeddlingCrowd() : state_(std::make_unique<State>()) {
    State* s = state_.get();
    WorldDef def = oneSubstepDef();
    def.workerCount = 2;
    def.adaptWorkerCount = false;
    def.enqueueTask = [s](StepTask task) -> void* {
        s->meddle("enqueueTask");
        // A thread of the game's, while the step runs.
        std::thread other([s] { s->meddle("another thread"); });
        other.join();
        task();
        return nullptr;
    };
    def.finishTask = [s](void*) { s->meddle("finishTask"); };
    s->crowd = std::make_unique<World>(def);
    s->twin = std::make_unique<World>(oneSubstepDef());
    addCrowd(*s->crowd);
    addCrowd(*s->twin);
    s->world = s->crowd.get();
    const std::vector<BodyId> bodies = s->crowd->bodyIds();
    s->targets.body = bodies.back();
    s->targets.shape = s->crowd->bodyShapes(bodies.back())[0];
    s->targets.snapshot = s->crowd->snapshot();
}

MeddlingCrowd::~MeddlingCrowd() = default;

int MeddlingCrowd::step(Random& random, int calls, std::vector<std::string>& failures) {
    State& s = *state_;
    s.random = &random;
    s.calls = calls;
    s.refused = 0;
    s.failures = &failures;
    try {
        s.crowd->step(1.0f / 60.0f);
    } catch (const std::exception& e) {
        failures.push_back(std::string("a meddled crowd's step threw: ") + e.what());
    }
    s.calls = 0;
    s.twin->step(1.0f / 60.0f);
    if (s.crowd->stateHash() != s.twin->stateHash()) {
        failures.push_back("the calls refused during a step changed the world");
    }
    return s.refused;
}

}  // namespace pivot::fuzz
