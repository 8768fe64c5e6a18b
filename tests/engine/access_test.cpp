// Who may change a world, and when (src/world/world_access.h): every call that changes the
// world (world_calls.h) is refused while a step runs, from its callbacks, from the task
// system's callbacks and from other threads; refused while debugDraw draws; and, if it changes
// the world's structure, refused from a query's callback, where every other change works.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "pivot/pivot.h"
#include "scenes/parts.h"
#include "world_calls.h"
#include "one_substep_def.h"

using namespace pivot;
using namespace pivot::test_support;

namespace {

constexpr float kDt = 1.0f / 60.0f;

bool hasCall(const std::string& name) {
    for (const ChangingCall& call : everyChangingCall()) {
        const std::string base = call.name.substr(0, call.name.find('('));
        if (base == name) return true;
    }
    return false;
}

/// The error a call throws, or "" if it throws none.
std::string errorOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A pyramid of 820 boxes beside the fixture: a step with work to hand to helpers (over 1,024
// contacts).
void addCrowd(World& world) {
    scenes::addShelf(world, 25.0f, 80.0f, 0.0f);
    scenes::PyramidSpec spec;
    spec.rows = 40;
    spec.start = scenes::RowStart::FromLeft;
    spec.left = 30.0f;
    scenes::addPyramid(world, spec);
}

}  // namespace

// Every non-const World member in the public header is in the list the tests below go through.
TEST(WorldAccess, EveryChangingCallIsListed) {
    std::ifstream header(PIVOT_SOURCE_DIR "/include/pivot/world.h");
    ASSERT_TRUE(header) << "cannot read include/pivot/world.h";
    std::stringstream text;
    text << header.rdbuf();
    std::string source = text.str();
    source = source.substr(source.find("class World {"));
    source = std::regex_replace(source, std::regex("//[^\n]*"), "");
    // A declaration: a name, its arguments, and whether it is const.
    const std::regex declaration(R"((\w+)\(([^;{)]*)\)\s*(const)?\s*;)");
    std::set<std::string> changing;
    for (auto it = std::sregex_iterator(source.begin(), source.end(), declaration);
         it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1];
        if ((*it)[3].matched || name == "World" || name == "operator") continue;
        changing.insert(name);
    }
    EXPECT_GT(changing.size(), 70u);
    for (const std::string& name : changing) {
        EXPECT_TRUE(hasCall(name))
            << "World::" << name << " changes the world but is not in world_calls.h";
    }
}

// Each call works, on its own, between steps: the list's arguments are valid, so a refusal in
// the tests below is the rule's.
TEST(WorldAccess, EveryListedCallWorksBetweenSteps) {
    for (const ChangingCall& call : everyChangingCall()) {
        World world{oneSubstepDef()};
        const Everything e = buildEverything(world);
        world.step(kDt);
        EXPECT_EQ(errorOf([&] { call.make(world, e); }), "") << call.name;
        world.step(kDt);
    }
}

TEST(WorldAccess, EveryChangeIsRefusedFromTheStepsCallbacks) {
    for (const bool filter : {false, true}) {
        World reference, world;
        buildEverything(reference);
        const Everything e = buildEverything(world);
        int asked = 0;
        auto tryEverything = [&] {
            if (asked++ > 0) return;
            for (const ChangingCall& call : everyChangingCall()) {
                const std::string error = errorOf([&] { call.make(world, e); });
                EXPECT_TRUE(contains(error, "inside a step's callback"))
                    << call.name << ": " << error;
            }
            // Reading is fine.
            EXPECT_NO_THROW(world.bodyPosition(e.a));
            EXPECT_NO_THROW(world.contacts());
            EXPECT_NO_THROW(world.stateHash());
        };
        if (filter) {
            world.setCustomFilterCallback([&](ShapeId, ShapeId) {
                tryEverything();
                return true;
            });
            reference.setCustomFilterCallback([](ShapeId, ShapeId) { return true; });
        } else {
            world.setPreSolveCallback([&](const ContactData&) {
                tryEverything();
                return true;
            });
            reference.setPreSolveCallback([](const ContactData&) { return true; });
        }
        for (int i = 0; i < 3; ++i) {
            world.step(kDt);
            reference.step(kDt);
        }
        EXPECT_GT(asked, 0) << (filter ? "custom filter" : "pre-solve");
        EXPECT_EQ(world.stateHash(), reference.stateHash());
    }
}

// The task system's callbacks are the game's code too, run in the middle of a step: on the
// stepping thread (enqueueTask, finishTask), or on the game's threads (the tasks). Every change
// from them is refused, and so is every read but the few a step cannot disturb.
TEST(WorldAccess, EveryChangeIsRefusedFromTaskCallbacksAndOtherThreads) {
    World* stepping = nullptr;
    const Everything* ids = nullptr;
    int enqueued = 0;
    int refused = 0;
    std::vector<std::string> accepted;
    auto tryEverything = [&](const char* where) {
        for (const ChangingCall& call : everyChangingCall()) {
            const std::string error = errorOf([&] { call.make(*stepping, *ids); });
            if (contains(error, "while World::step runs")) {
                ++refused;
            } else {
                accepted.push_back(std::string(where) + " " + call.name + ": " + error);
            }
        }
        for (const auto& read : std::vector<std::function<void()>>{
                 [&] { stepping->bodyPosition(ids->a); },
                 [&] { stepping->contacts(); },
                 [&] { stepping->bodyIds(); },
                 [&] { stepping->stateHash(); },
                 [&] { stepping->snapshot(); },
                 [&] { stepping->lastStepStats(); },
                 [&] {
                     stepping->castRayClosest({-5.0f, 1.0f}, {10.0f, 0.0f});
                 },
                 [&] {
                     stepping->queryAABB({{-1, -1}, {1, 1}}, {}, [](ShapeId) { return true; });
                 },
             }) {
            const std::string error = errorOf(read);
            if (contains(error, "while World::step runs")) {
                ++refused;
            } else {
                accepted.push_back(std::string(where) + " a read: " + error);
            }
        }
        // What a step does not change may be read: settings, counts, whether an id is live.
        EXPECT_NO_THROW(stepping->gravity());
        EXPECT_NO_THROW(stepping->bodyCount());
        EXPECT_NO_THROW(stepping->isValid(ids->a));
    };
    WorldDef def = oneSubstepDef();
    def.workerCount = 2;
    def.adaptWorkerCount = false;
    def.enqueueTask = [&](StepTask task) -> void* {
        if (enqueued++ == 0) {
            tryEverything("enqueueTask");
            // A thread of the game's, while the step runs.
            std::thread other([&] { tryEverything("another thread"); });
            other.join();
        }
        task();
        return nullptr;
    };
    def.finishTask = [&](void*) {
        if (enqueued == 1) tryEverything("finishTask");
    };
    World world(def);
    const Everything e = buildEverything(world);
    addCrowd(world);
    stepping = &world;
    ids = &e;
    World reference{oneSubstepDef()};
    buildEverything(reference);
    addCrowd(reference);
    for (int i = 0; i < 10; ++i) {
        world.step(kDt);
        reference.step(kDt);
    }
    EXPECT_GT(enqueued, 0);
    const int perTry = static_cast<int>(everyChangingCall().size()) + 8;
    EXPECT_EQ(refused, 3 * perTry);
    EXPECT_TRUE(accepted.empty()) << accepted.size() << " accepted, the first: " << accepted[0];
    EXPECT_EQ(world.stateHash(), reference.stateHash());
    // After the step, the same calls work.
    EXPECT_NO_THROW(world.setBodyUserData(e.a, 5));
    EXPECT_NO_THROW(world.bodyPosition(e.a));
}

TEST(WorldAccess, EveryChangeIsRefusedWhileDrawing) {
    struct Drawing : DebugDraw {
        std::function<void()> onPolygon;
        void drawPolygon(const Vec2*, int, DebugColor) override {}
        void drawSolidPolygon(const Vec2*, int, float, DebugColor) override {
            if (onPolygon) onPolygon();
            onPolygon = nullptr;
        }
        void drawSolidCircle(Vec2, float, Vec2, DebugColor) override {}
        void drawSolidCapsule(Vec2, Vec2, float, DebugColor) override {}
        void drawSegment(Vec2, Vec2, DebugColor) override {}
        void drawPoint(Vec2, float, DebugColor) override {}
    };
    World world{oneSubstepDef()};
    const Everything e = buildEverything(world);
    const std::uint64_t before = world.stateHash();
    Drawing draw;
    int tried = 0;
    draw.onPolygon = [&] {
        for (const ChangingCall& call : everyChangingCall()) {
            const std::string error = errorOf([&] { call.make(world, e); });
            EXPECT_TRUE(contains(error, "debugDraw")) << call.name << ": " << error;
            ++tried;
        }
    };
    world.debugDraw(draw);
    EXPECT_EQ(tried, static_cast<int>(everyChangingCall().size()));
    EXPECT_EQ(world.stateHash(), before);
}

// A query's callback may change what its walk does not depend on, and nothing else: each
// structural change is refused with nothing changed; every other change works, to the same bits
// as made after the query.
TEST(WorldAccess, AQueryCallbackMayChangeMotionAndSettingsButNotStructure) {
    for (const ChangingCall& call : everyChangingCall()) {
        World world, reference;
        const Everything e = buildEverything(world);
        const Everything r = buildEverything(reference);
        const std::uint64_t before = world.stateHash();
        int visits = 0;
        std::string error = "not called";
        world.queryAABB({{-30.0f, -5.0f}, {30.0f, 10.0f}}, {}, [&](ShapeId) {
            if (visits++ == 0) error = errorOf([&] { call.make(world, e); });
            return true;
        });
        EXPECT_EQ(visits, world.shapeCount()) << call.name;
        if (call.structure) {
            EXPECT_TRUE(contains(error, "inside a query's callback")) << call.name << ": " << error;
            EXPECT_EQ(world.stateHash(), before) << call.name;
        } else {
            EXPECT_EQ(error, "") << call.name;
            call.make(reference, r);
            EXPECT_EQ(world.stateHash(), reference.stateHash()) << call.name;
        }
    }
}

// Every kind of query refuses a structural change from its callback (the issue's case: a body
// turned static moves its proxies between trees mid-walk), and its walk still meets every
// shape once, with live ids.
TEST(WorldAccess, EveryQueryRefusesStructuralChangesAndFinishesItsWalk) {
    World world{oneSubstepDef()};
    const BodyId ground = world.createBody(BodyDef{});
    world.createShape(ground, ShapeDef{}, Polygon::box(100.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    for (int i = 0; i < 120; ++i) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {-60.0f + float(i), 0.5f};
        world.createShape(world.createBody(def), ShapeDef{}, Polygon::box(0.4f, 0.4f));
    }
    const std::uint64_t before = world.stateHash();
    const AABB everywhere{{-100.0f, -1.0f}, {100.0f, 1.0f}};
    std::set<std::int32_t> seen;
    int refused = 0;
    auto visit = [&](ShapeId shape) {
        EXPECT_TRUE(world.isValid(shape));
        EXPECT_TRUE(seen.insert(shape.index).second) << "shape " << shape.index << " twice";
        const BodyId body = world.shapeBody(shape);
        if (world.bodyType(body) == BodyType::Dynamic) {
            if (contains(errorOf([&] { world.setBodyType(body, BodyType::Static); }),
                         "inside a query's callback")) {
                ++refused;
            }
        }
    };
    const Polygon wide = Polygon::box(100.0f, 1.0f);
    const Transform origin{{0.0f, 0.0f}, Rot(0.0f)};
    const std::vector<std::function<void()>> queries = {
        [&] {
            world.queryAABB(everywhere, {}, [&](ShapeId s) {
                visit(s);
                return true;
            });
        },
        [&] {
            world.queryShape(wide, origin, {}, [&](ShapeId s) {
                visit(s);
                return true;
            });
        },
        [&] {
            world.castRay({-100.0f, 0.2f}, {200.0f, 0.0f}, {}, [&](const RayHit& hit) {
                visit(hit.shape);
                return -1.0f;  // ignore it, go on
            });
        },
        [&] {
            world.castShape(Circle{{}, 0.1f}, Transform{{-100.0f, 0.2f}, Rot(0.0f)}, {200.0f, 0.0f},
                            {}, [&](const RayHit& hit) {
                                visit(hit.shape);
                                return -1.0f;
                            });
        },
    };
    for (std::size_t q = 0; q < queries.size(); ++q) {
        seen.clear();
        refused = 0;
        queries[q]();
        EXPECT_EQ(refused, 120) << "query " << q;
        EXPECT_GE(seen.size(), 120u) << "query " << q;
        EXPECT_EQ(world.stateHash(), before) << "query " << q;
    }
}
