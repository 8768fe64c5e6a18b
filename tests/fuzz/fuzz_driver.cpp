#include "fuzz_driver.h"

#include "journal.h"
#include "reentry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <typeinfo>
#include <utility>
#include "one_substep_def.h"

namespace pivot::fuzz {

namespace {

// Sizes the driver keeps a world within: large enough for stacks, chains and islands that
// sleep and wake, small enough that hashing the world before every call stays cheap.
constexpr int kMaxBodies = 40;
constexpr int kMaxShapesPerBody = 4;
constexpr int kMaxJoints = 48;
constexpr int kMaxMouseJoints = 4;
constexpr std::size_t kRememberedIds = 64;  // per kind, for stale ids

// Whether the API must accept a call: Bad must throw, Valid must return, Unknown either (a
// random polygon, say, that the driver does not judge itself).
enum class Verdict { Valid, Bad, Unknown };

Verdict verdict(bool bad) {
    return bad ? Verdict::Bad : Verdict::Valid;
}

struct Snapshot {
    std::uint64_t hash = 0;
    int bodies = 0, shapes = 0, joints = 0;
    bool operator==(const Snapshot& o) const {
        return hash == o.hash && bodies == o.bodies && shapes == o.shapes && joints == o.joints;
    }
};

template <typename Id>
std::string idText(Id id) {
    return "{" + std::to_string(id.index) + "," + std::to_string(id.generation) + "," +
           std::to_string(id.world) + "}";
}

std::string text(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(v));
    return buffer;
}
std::string text(Vec2 v) {
    return "(" + text(v.x) + "," + text(v.y) + ")";
}

/// A remembered set of ids of one kind, for picking stale ones: the oldest is overwritten.
template <typename Id>
struct IdMemory {
    std::vector<Id> ids;
    std::size_t next = 0;
    void remember(Id id) {
        if (ids.size() < kRememberedIds) {
            ids.push_back(id);
        } else {
            ids[next] = id;
            next = (next + 1) % kRememberedIds;
        }
    }
    void clear() {
        ids.clear();
        next = 0;
    }
};

class Driver {
public:
    explicit Driver(const Options& options) : options_(options), random_(options.seed) {}

    Report run() {
        newWorld();
        long worldEnd = operation_ + random_.between(500, 20000);
        for (operation_ = 0; operation_ < options_.operations; ++operation_) {
            if (operation_ >= worldEnd) {
                newWorld();
                worldEnd = operation_ + random_.between(500, 20000);
            }
            if (nonFinite_ && worldEnd > nonFiniteSeen_ + 200) worldEnd = nonFiniteSeen_ + 200;
            hostile_ = random_.chance(0.3f) ? 0.25f : 0.0f;
            Values values(random_, hostile_, options_.extremes);
            values_ = &values;
            if (operation_ == options_.dumpBefore) dump();
            pickOperation();
            ++report_.operations;
            if (options_.checkEveryOperation) checkInvariants("any operation");
            if (!report_.failures.empty() && options_.stopAtFirstFailure) break;
        }
        if (report_.failures.empty() || !options_.stopAtFirstFailure) checkInvariants("the end");
        return report_;
    }

private:
    // --- bookkeeping --------------------------------------------------------------------------

    void failure(const std::string& what) {
        report_.failures.push_back("operation " + std::to_string(operation_) + ": " + what);
        writeJournal();
        if (options_.trace) std::printf("FAILURE: %s\n", report_.failures.back().c_str());
    }

    // A non-finite number in a world made only of accepted input: a failure if the options ask
    // for it, otherwise counted once per world.
    void nonFinite(const std::string& what) {
        if (options_.requireFinite) {
            failure(what);
            return;
        }
        if (nonFinite_) return;
        nonFinite_ = true;
        nonFiniteSeen_ = operation_;
        report_.nonFiniteWorlds.push_back(operation_);
        writeJournal();
        trace("NON-FINITE: " + what);
    }

    // The calls that built the current world, for replaying and reducing what just happened.
    void writeJournal() {
        if (options_.journalPrefix.empty()) return;
        std::string path = options_.journalPrefix + "-" + std::to_string(options_.seed) + "-" +
                           std::to_string(operation_) + ".journal";
        if (journal_.write(path)) report_.journals.push_back(path);
    }

    void trace(const std::string& line) {
        if (options_.trace) std::printf("%ld %s\n", operation_, line.c_str());
    }

    Snapshot snapshot() const {
        return {world_->stateHash(), world_->bodyCount(), world_->shapeCount(),
                world_->jointCount()};
    }

    /// Makes the call and checks the outcome against the verdict. Returns whether it returned.
    template <typename Call>
    bool attempt(const std::string& name, Verdict expected, Call&& call) {
        OperationCount& count = report_.byOperation[name];
        Snapshot before = snapshot();
        try {
            call();
        } catch (const Error& e) {
            ++count.rejected;
            ++report_.rejected;
            std::string message = e.what();
            trace("  -> Error: " + message);
            if (!(snapshot() == before)) {
                failure(name + " threw \"" + message + "\" but changed the world");
            }
            if (message.compare(0, name.size() + 1, name + ":") != 0) {
                failure(name + " threw a message that does not name the call: \"" + message + "\"");
            }
            if (expected == Verdict::Valid) {
                failure(name + " refused a valid call: \"" + message + "\"");
            }
            return false;
        } catch (const std::exception& e) {
            failure(name + " threw " + typeid(e).name() + " (not pivot::Error): " + e.what());
            return false;
        } catch (...) {
            failure(name + " threw something that is not a std::exception");
            return false;
        }
        ++count.accepted;
        ++report_.accepted;
        if (expected == Verdict::Bad) failure(name + " accepted an argument it must refuse");
        return true;
    }

    void newWorld() {
        pending_.clear();
        ++report_.worlds;
        nonFinite_ = false;
        bodies_.clear();
        shapes_.clear();
        joints_.clear();
        mice_.clear();
        liveMice_.clear();
        tag_ = 0;
        // A WorldDef now and then has a bad field: the constructor must refuse it.
        Values values(random_, random_.chance(0.2f) ? 0.3f : 0.0f, options_.extremes);
        WorldDef def = oneSubstepDef();
        Arg<Vec2> gravity = random_.chance(0.8f) ? Arg<Vec2>{{0.0f, -10.0f}} : values.gravity();
        def.gravity = gravity.value;
        bool bad = gravity.bad;
        if (random_.chance(0.05f)) {
            def.defaultPositionSolver =
                static_cast<PositionSolver>(random_.between(kPositionSolverCount, 255));
            bad = true;
        } else {
            def.defaultPositionSolver =
                static_cast<PositionSolver>(random_.below(kPositionSolverCount));
        }
        if (random_.chance(0.05f)) {
            def.contactCorrection = static_cast<ContactCorrection>(random_.between(3, 255));
            bad = true;
        } else {
            def.contactCorrection = static_cast<ContactCorrection>(random_.below(3));
        }
        Arg<float> bias =
            random_.chance(0.7f) ? Arg<float>{kDefaultContactBias} : values.fraction();
        def.contactBiasFactor = bias.value;
        Arg<float> threshold =
            random_.chance(0.7f) ? Arg<float>{kRestitutionThreshold} : values.nonNegative(5);
        def.restitutionThreshold = threshold.value;
        def.warmStarting = random_.chance(0.9f);
        def.enableSleep = random_.chance(0.8f);
        // Letting joints go beyond a distance is opt-in: most worlds never do.
        Arg<float> letGo =
            random_.chance(0.8f) ? Arg<float>{0.0f} : values.nonNegativeUpTo(20.0f, kMaxMagnitude);
        def.jointLetGoSeparation = letGo.value;
        bad = bad || bias.bad || threshold.bad || letGo.bad;
        trace("new World gravity=" + text(def.gravity) + " bad=" + std::to_string(bad));
        world_.reset();
        preSolveInstalled_ = filterInstalled_ = false;
        try {
            world_ = std::make_unique<World>(def);
            if (bad) failure("World::World accepted a bad WorldDef");
        } catch (const Error& e) {
            if (!bad) failure(std::string("World::World refused a valid WorldDef: ") + e.what());
            def = oneSubstepDef();
            world_ = std::make_unique<World>(def);
        }
        journal_.begin(*world_, def);
        if (random_.chance(0.7f)) {
            // Most worlds have ground for things to land, stack and slide on; without it,
            // bodies fall away and meet nothing.
            BodyDef ground;
            ground.position = {0.0f, -12.0f};
            BodyId id = journal_.createBody(ground);
            noteTag(id);
            journal_.createShape(id, ShapeDef{}, Polygon::box(30.0f, 1.0f));
        }
        // Another world, whose ids this one must refuse.
        other_ = std::make_unique<World>(oneSubstepDef());
        BodyDef bd;
        bd.type = BodyType::Dynamic;
        otherBody_ = other_->createBody(bd);
        otherShape_ = other_->createShape(otherBody_, ShapeDef{}, Circle{});
        otherJoint_ = other_->createJoint(
            RevoluteJointDef::atWorldAnchor(other_->createBody(BodyDef{}), otherBody_, {0, 0}));
        MouseJointDef md;
        md.body = otherBody_;
        otherMouse_ = other_->createMouseJoint(md);
    }

    // --- picking ids --------------------------------------------------------------------------

    std::vector<ShapeId> liveShapes() const {
        std::vector<ShapeId> all;
        for (BodyId b : world_->bodyIds()) {
            for (ShapeId s : world_->bodyShapes(b)) all.push_back(s);
        }
        return all;
    }

    /// A live id from `live` most of the time; otherwise (or when there is none) a null,
    /// foreign, remembered (mostly stale) or made-up one. Bad exactly when the world says the
    /// id is not valid.
    template <typename Id>
    Arg<Id> pick(const std::vector<Id>& live, const IdMemory<Id>& memory, Id foreign) {
        bool wantBad = live.empty() || random_.chance(hostile_ > 0.0f ? 0.3f : 0.02f);
        Id id{};
        if (!wantBad) {
            id = live[random_.below(static_cast<int>(live.size()))];
        } else {
            switch (random_.below(4)) {
                case 0: id = Id{}; break;
                case 1: id = foreign; break;
                case 2:
                    if (!memory.ids.empty()) {
                        id = memory.ids[random_.below(static_cast<int>(memory.ids.size()))];
                        break;
                    }
                    [[fallthrough]];
                default:
                    id.index = random_.chance(0.8f) ? random_.below(80) : -random_.between(1, 5);
                    id.generation = static_cast<std::uint32_t>(random_.below(4));
                    id.world = tag_ != 0 ? tag_ : 12345u;
                    break;
            }
        }
        return {id, !world_->isValid(id)};
    }

    Arg<BodyId> pickBody() { return pick(world_->bodyIds(), bodies_, otherBody_); }
    Arg<ShapeId> pickShape() { return pick(liveShapes(), shapes_, otherShape_); }
    Arg<JointId> pickJoint() { return pick(world_->jointIds(), joints_, otherJoint_); }
    Arg<MouseJointId> pickMouse() {
        std::vector<MouseJointId> live;
        std::vector<LiveMouse> stillLive;
        for (const LiveMouse& m : liveMice_) {
            if (!world_->isValid(m.id)) continue;
            live.push_back(m.id);
            stillLive.push_back(m);
        }
        liveMice_ = stillLive;
        return pick(live, mice_, otherMouse_);
    }

    template <typename Id>
    void noteTag(Id id) {
        tag_ = id.world;
    }

    // --- generated arguments --------------------------------------------------------------------

    Filter filter() {
        Filter f;
        f.categoryBits = static_cast<std::uint16_t>(1u << random_.below(4));
        f.maskBits = random_.chance(0.8f) ? 0xFFFF : static_cast<std::uint16_t>(random_.next());
        f.groupIndex = static_cast<std::int16_t>(random_.chance(0.8f) ? 0 : random_.between(-2, 2));
        return f;
    }

    Arg<ShapeDef> shapeDef(bool zeroDensityAllowed) {
        ShapeDef def;
        Arg<float> density = values_->density(zeroDensityAllowed);
        Arg<float> friction = values_->nonNegativeUpTo(1.0f, kMaxFriction);
        Arg<float> restitution = values_->fraction();
        def.density = density.value;
        def.friction = friction.value;
        def.restitution = restitution.value;
        def.filter = filter();
        def.userData = random_.next();
        def.isSensor = random_.chance(0.1f);
        return {def, density.bad || friction.bad || restitution.bad};
    }

    /// A polygon and whether it must be refused; Unknown for random point sets.
    std::pair<Polygon, Verdict> polygon() {
        Polygon p;
        int kind = random_.below(100);
        if (hostile_ > 0.0f && kind < 35) {
            // Bad on purpose.
            p = Polygon::box(1.0f, 0.5f);
            switch (random_.below(8)) {
                case 0: {
                    const int counts[] = {-1, 0, 1, 2, kMaxPolygonVertices + 1, 1000000};
                    p.count = counts[random_.below(6)];
                    break;
                }
                case 1: p.vertices[2] = p.vertices[1]; break;  // repeated
                case 2:                                        // a vertex in the middle of an edge
                    p = Polygon::fromPoints(
                        {{-1.0f, -0.5f}, {0.0f, -0.5f}, {1.0f, -0.5f}, {0.0f, 0.5f}});
                    break;
                case 3: p.vertices[1] = {0.0f, 0.2f}; break;  // dent
                case 4: p.vertices[random_.below(4)].x = values_->garbage(); break;
                case 5: p.vertices[3] = {-1.0f, 2.0f * kMaxCoordinate}; break;
                case 6: {  // a rounding that is negative, not finite or too big
                    const float radii[] = {-0.1f, std::numeric_limits<float>::quiet_NaN(),
                                           std::numeric_limits<float>::infinity(),
                                           2.0f * kMaxCoordinate, 1e-40f};
                    p.radius = radii[random_.below(5)];
                    break;
                }
                default:  // all in a line
                    p = Polygon::fromPoints({{0, 0}, {1, 1}, {2, 2}, {3, 3}});
                    break;
            }
            return {p, Verdict::Bad};
        }
        if (kind < 45) {
            // Random points: convex or not, the driver does not judge.
            p.count = random_.between(3, kMaxPolygonVertices);
            for (int i = 0; i < p.count; ++i) {
                p.vertices[i] = {random_.uniform(-1, 1), random_.uniform(-1, 1)};
            }
            return {p, Verdict::Unknown};
        }
        // A convex polygon: a regular one stretched, turned and moved, in either winding.
        p.count = random_.between(3, kMaxPolygonVertices);
        float radius =
            values_->edge(0.03f) ? random_.uniform(100.0f, 1000.0f) : random_.uniform(0.1f, 2.0f);
        float sx = random_.uniform(0.4f, 1.0f), sy = random_.uniform(0.4f, 1.0f);
        Rot turn(random_.uniform(-kPi, kPi));
        Vec2 offset{random_.uniform(-2, 2), random_.uniform(-2, 2)};
        bool clockwise = random_.chance(0.5f);
        for (int i = 0; i < p.count; ++i) {
            float a = 2.0f * kPi * float(clockwise ? p.count - i : i) / float(p.count);
            Vec2 v{radius * sx * std::cos(a), radius * sy * std::sin(a)};
            p.vertices[i] = offset + rotate(turn, v);
        }
        if (random_.chance(0.2f)) p.radius = random_.uniform(0.0f, 0.3f);  // rounded
        return {p, Verdict::Valid};
    }

    Arg<JointLimit> limit() {
        JointLimit l;
        l.enabled = random_.chance(0.5f);
        Arg<float> lower = values_->magnitude(2.0f);
        l.lower = lower.value;
        l.upper = lower.value + random_.uniform(0.0f, 3.0f);
        bool bad = lower.bad;
        if (!bad && hostile_ > 0.0f && random_.chance(0.3f)) {
            // Upper below lower, by enough to show at any magnitude.
            l.upper = l.lower - random_.uniform(0.1f, 1.0f) - 0.5f * std::fabs(l.lower);
            bad = true;
        }
        if (!bad && hostile_ > 0.0f && random_.chance(0.2f)) {
            l.upper = values_->garbage();
            bad = true;
        }
        return {l, bad};
    }

    Arg<JointMotor> motor() {
        JointMotor m;
        m.enabled = random_.chance(0.5f);
        Arg<float> speed = values_->angularSpeed(10.0f);
        Arg<float> torque = values_->nonNegative(200.0f);
        m.speed = speed.value;
        m.maxTorque = torque.value;
        return {m, speed.bad || torque.bad};
    }

    Arg<PositionSolver> solver() {
        if (hostile_ > 0.0f && random_.chance(0.2f)) {
            return {static_cast<PositionSolver>(random_.between(kPositionSolverCount, 255)), true};
        }
        return {static_cast<PositionSolver>(random_.below(kPositionSolverCount))};
    }

    bool hasZeroDensityShape(BodyId body) const {
        for (ShapeId s : world_->bodyShapes(body)) {
            if (world_->shapeDensity(s) == 0.0f) return true;
        }
        return false;
    }

    bool hasSegment(BodyId body) const {
        for (ShapeId s : world_->bodyShapes(body)) {
            const ShapeType type = world_->shapeType(s);
            if (type == ShapeType::Segment || type == ShapeType::ChainSegment) return true;
        }
        return false;
    }

    // A call that changes a body's mass moves its centre of mass, by up to about 3e5 m, and the
    // centre's velocity by w x that shift: it is refused if that would pass kMaxSpeed. Where it
    // might, either outcome is allowed; elsewhere the call's own verdict stands.
    Verdict afterMassChange(BodyId body, Verdict v) const {
        if (v != Verdict::Valid || !world_->isValid(body)) return v;
        const Vec2 velocity = world_->bodyLinearVelocity(body);
        const float reach = std::fabs(world_->bodyAngularVelocity(body)) * 3.0e5f +
                            std::max(std::fabs(velocity.x), std::fabs(velocity.y));
        return reach < 0.99f * kMaxSpeed ? v : Verdict::Unknown;
    }
    Verdict afterMassChange(ShapeId shape, Verdict v) const {
        if (v != Verdict::Valid || !world_->isValid(shape)) return v;
        return afterMassChange(world_->shapeBody(shape), v);
    }

    bool isDynamic(const Arg<BodyId>& body) const {
        return !body.bad && world_->bodyType(body.value) == BodyType::Dynamic;
    }
    bool isStatic(const Arg<BodyId>& body) const {
        return !body.bad && world_->bodyType(body.value) == BodyType::Static;
    }

    // --- operations -----------------------------------------------------------------------------

    void pickOperation() {
        using Op = void (Driver::*)();
        struct Entry {
            int weight;
            Op op;
        };
        static const Entry kOperations[] = {
            {10, &Driver::createBody},
            {6, &Driver::createCircle},
            {8, &Driver::createPolygon},
            {3, &Driver::createSegment},
            {2, &Driver::createChain},
            {3, &Driver::createCapsule},
            {7, &Driver::createJoint},
            {3, &Driver::createDistanceJoint},
            {2, &Driver::createPulleyJoint},
            {3, &Driver::createPrismaticJoint},
            {3, &Driver::createWeldJoint},
            {3, &Driver::createWheelJoint},
            {2, &Driver::createGearJoint},
            {2, &Driver::createVelocityJoint},
            {2, &Driver::createMouseJoint},
            {3, &Driver::destroyBody},
            {2, &Driver::destroyShape},
            {2, &Driver::destroyJoint},
            {1, &Driver::destroyMouseJoint},
            {6, &Driver::moveBody},
            {6, &Driver::pushBody},
            {2, &Driver::sleepCalls},
            {3, &Driver::setBodyType},
            {2, &Driver::setShapeDensity},
            {2, &Driver::setShapeFilter},
            {2, &Driver::setShapeMaterial},
            {3, &Driver::setBodyProperties},
            {1, &Driver::setJointBreak},
            {5, &Driver::changeJoint},
            {2, &Driver::moveMouse},
            {1, &Driver::worldSettings},
            {16, &Driver::step},
            {8, &Driver::query},
            {4, &Driver::worldQueries},
            {2, &Driver::freeFunctions},
            {1, &Driver::destroyWhileIterating},
            {1, &Driver::snapshots},
            {1, &Driver::reentry},
        };
        int total = 0;
        for (const Entry& e : kOperations) total += e.weight;
        int r = random_.below(total);
        for (const Entry& e : kOperations) {
            if (r < e.weight) {
                (this->*e.op)();
                return;
            }
            r -= e.weight;
        }
    }

    void createBody() {
        if (world_->bodyCount() >= kMaxBodies) {
            destroyBody();
            return;
        }
        BodyDef def;
        bool bad = false;
        if (hostile_ > 0.0f && random_.chance(0.1f)) {
            def.type = static_cast<BodyType>(random_.between(3, 255));
            bad = true;
        } else {
            int t = random_.below(20);
            def.type =
                t < 12 ? BodyType::Dynamic : (t < 17 ? BodyType::Static : BodyType::Kinematic);
        }
        Arg<Vec2> position = values_->coordinate(15.0f);
        Arg<float> angle = values_->magnitude(4.0f);
        Arg<Vec2> velocity = values_->speed2(5.0f);
        Arg<float> omega = values_->angularSpeed(3.0f);
        Arg<float> linearDamping = values_->nonNegative(1.0f);
        Arg<float> angularDamping = values_->nonNegative(1.0f);
        Arg<float> gravityScale = values_->gravityScale();
        def.position = position.value;
        def.angle = angle.value;
        def.linearVelocity = velocity.value;
        def.angularVelocity = omega.value;
        def.linearDamping = linearDamping.value;
        def.angularDamping = angularDamping.value;
        def.gravityScale = gravityScale.value;
        def.fixedRotation = random_.chance(0.1f);
        def.allowSleep = random_.chance(0.85f);
        def.isAwake = random_.chance(0.9f);
        def.userData = random_.next();
        bad = bad || position.bad || angle.bad || velocity.bad || omega.bad || linearDamping.bad ||
              angularDamping.bad || gravityScale.bad;
        if (def.fixedRotation && def.angularVelocity != 0.0f && !bad) {
            // A body that never turns takes no angular velocity; now and then it is given one.
            if (hostile_ > 0.0f && random_.chance(0.3f)) {
                bad = true;
            } else {
                def.angularVelocity = 0.0f;
            }
        }
        if (def.type == BodyType::Static && !bad) {
            // A static body may not move; now and then it is asked to.
            if (hostile_ > 0.0f && random_.chance(0.3f) &&
                (def.linearVelocity != Vec2{} || def.angularVelocity != 0.0f)) {
                bad = true;
            } else {
                def.linearVelocity = Vec2{};
                def.angularVelocity = 0.0f;
            }
        }
        trace("createBody type=" + std::to_string(int(def.type)) + " p=" + text(def.position) +
              " v=" + text(def.linearVelocity) + " w=" + text(def.angularVelocity));
        attempt("World::createBody", verdict(bad), [&] {
            BodyId id = journal_.createBody(def);
            noteTag(id);
            bodies_.remember(id);
            if (world_->bodyType(id) != def.type) failure("createBody made the wrong type");
        });
    }

    template <typename Shape>
    void createShape(const Shape& geometry, Verdict geometryVerdict, const std::string& what) {
        Arg<BodyId> body = pickBody();
        if (!body.bad && world_->bodyShapes(body.value).size() >= kMaxShapesPerBody) {
            destroyShape();
            return;
        }
        Arg<ShapeDef> def = shapeDef(!isDynamic(body));
        Verdict v = geometryVerdict;
        if (body.bad || def.bad) v = Verdict::Bad;
        if constexpr (std::is_same_v<Shape, Segment> || std::is_same_v<Shape, ChainSegment>) {
            if (isDynamic(body)) v = Verdict::Bad;  // a segment has no mass
        }
        if (!body.bad) v = afterMassChange(body.value, v);
        trace("createShape(" + what + ") body=" + idText(body.value) +
              " density=" + text(def.value.density));
        attempt("World::createShape", v, [&] {
            ShapeId id = journal_.createShape(body.value, def.value, geometry);
            noteTag(id);
            shapes_.remember(id);
            if (world_->shapeBody(id) != body.value) failure("createShape: wrong body");
            if (isDynamic(body) && !(world_->bodyMass(body.value) > 0.0f)) {
                failure("createShape: a dynamic body has mass " +
                        text(world_->bodyMass(body.value)));
            }
        });
    }

    void createCircle() {
        Arg<Vec2> center = values_->coordinate(1.0f);
        Arg<float> radius = values_->radius();
        createShape(Circle{center.value, radius.value}, verdict(center.bad || radius.bad),
                    "circle r=" + text(radius.value));
    }

    // Mostly a valid capsule, now and then one whose centres are too close (a circle) or whose
    // radius or points are bad.
    void createCapsule() {
        Arg<Vec2> center1 = values_->coordinate(3.0f);
        Arg<Vec2> center2 = values_->coordinate(3.0f);
        Arg<float> radius = values_->radius();
        if (random_.chance(0.05f)) center2.value = center1.value + Vec2{0.5f * kLinearSlop, 0.0f};
        const Vec2 d = center2.value - center1.value;
        const bool bad =
            center1.bad || center2.bad || radius.bad || !isFinite(d) || !(length(d) >= kLinearSlop);
        createShape(Capsule{center1.value, center2.value, radius.value}, verdict(bad),
                    "capsule r=" + text(radius.value));
    }

    // Mostly a valid segment, now and then a degenerate one (too short, or a bad point). The
    // body's type decides the rest: createShape refuses a segment on a dynamic body.
    void createSegment() {
        Arg<Vec2> point1 = values_->coordinate(10.0f);
        Arg<Vec2> point2 = values_->coordinate(10.0f);
        if (random_.chance(0.05f)) point2.value = point1.value + Vec2{0.5f * kLinearSlop, 0.0f};
        const Vec2 d = point2.value - point1.value;
        const bool bad = point1.bad || point2.bad || !isFinite(d) || !(length(d) >= kLinearSlop);
        const Segment segment{point1.value, point2.value};
        createShape(segment, verdict(bad), "segment");
    }

    // A short chain of one-sided segments (an open one of 4 to 6 points, or a loop of 3), mostly
    // valid, now and then with a repeated point or a bad coordinate; or now and then a lone
    // chain segment. createChain makes all of its segments or none.
    void createChain() {
        Arg<Vec2> start = values_->coordinate(10.0f);
        Chain chain;
        chain.loop = random_.chance(0.3f);
        const int count = chain.loop ? 3 : random_.between(4, 6);
        chain.points.push_back(start.value);
        for (int i = 1; i < count; ++i) {
            const float angle = random_.uniform(-kPi, kPi);
            const float step = random_.uniform(0.3f, 3.0f);
            Vec2 next = chain.points.back() + step * Vec2{std::cos(angle), std::sin(angle)};
            if (random_.chance(0.03f)) next = chain.points.back();  // a repeated point
            chain.points.push_back(next);
        }
        // Whether the first n points (closed into a loop or not) are refused: a bad start, a
        // point out of range, or a step shorter than the slop (a repeated point; or round-off at
        // the edge of the coordinate range bringing two together).
        auto refused = [&](int n, bool closed) {
            if (start.bad) return true;
            for (int i = 0; i < n; ++i) {
                const Vec2 p = chain.points[i];
                if (!isFinite(p) || std::fabs(p.x) > kMaxCoordinate ||
                    std::fabs(p.y) > kMaxCoordinate) {
                    return true;
                }
            }
            for (int i = 1; i < n + (closed ? 1 : 0); ++i) {
                if (!(length(chain.points[i % n] - chain.points[i - 1]) >= kLinearSlop))
                    return true;
            }
            return false;
        };
        if (random_.chance(0.3f) && count >= 4) {
            const ChainSegment one{
                chain.points[0], {chain.points[1], chain.points[2]}, chain.points[3]};
            createShape(one, verdict(refused(4, false)), "chain segment");
            return;
        }
        const bool bad = refused(count, chain.loop);
        Arg<BodyId> body = pickBody();
        const int made = chain.loop ? count : count - 3;
        if (!body.bad &&
            static_cast<int>(world_->bodyShapes(body.value).size()) + made > kMaxShapesPerBody) {
            destroyShape();
            return;
        }
        Arg<ShapeDef> def = shapeDef(true);
        Verdict v = verdict(bad || body.bad || def.bad || isDynamic(body));
        trace("createChain body=" + idText(body.value) + " points=" + std::to_string(count) +
              " loop=" + std::to_string(chain.loop));
        attempt("World::createChain", v, [&] {
            const std::vector<ShapeId> ids = journal_.createChain(body.value, def.value, chain);
            if (static_cast<int>(ids.size()) != made) failure("createChain: wrong segment count");
            for (ShapeId id : ids) {
                noteTag(id);
                shapes_.remember(id);
                if (world_->shapeType(id) != ShapeType::ChainSegment) {
                    failure("createChain made another type");
                }
            }
        });
    }

    void createPolygon() {
        auto [p, v] = polygon();
        createShape(p, v, "polygon n=" + std::to_string(p.count));
    }

    void createJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        RevoluteJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        bool bad = a.bad || b.bad || a.value == b.value;
        const bool atWorldAnchor = random_.chance(0.7f);
        if (atWorldAnchor) {
            Arg<Vec2> anchor = values_->coordinate(15.0f);
            def.worldAnchor = anchor.value;
            bad = bad || anchor.bad;
        }
        // With a world anchor the local anchors and reference angle come from the poses, and a
        // def that also sets them is refused; now and then one does.
        if (!atWorldAnchor || (hostile_ > 0.0f && random_.chance(0.1f))) {
            Arg<Vec2> localA = values_->coordinate(2.0f);
            Arg<Vec2> localB = values_->coordinate(2.0f);
            Arg<float> reference = values_->magnitude(3.0f);
            def.localAnchorA = localA.value;
            def.localAnchorB = localB.value;
            def.referenceAngle = reference.value;
            bad = bad || localA.bad || localB.bad || reference.bad;
            if (atWorldAnchor && (def.localAnchorA != Vec2{} || def.localAnchorB != Vec2{} ||
                                  def.referenceAngle != 0.0f)) {
                bad = true;
            }
        }
        if (random_.chance(0.2f)) {
            Arg<float> letGo = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
            def.letGoSeparation = letGo.value;
            bad = bad || letGo.bad;
        }
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.4f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        Arg<JointLimit> l = limit();
        Arg<JointMotor> m = motor();
        def.limit = l.value;
        def.motor = m.value;
        def.collideConnected = random_.chance(0.3f);
        def.userData = random_.next();
        bad = bad || l.bad || m.bad;
        trace("createJoint a=" + idText(a.value) + " b=" + idText(b.value) +
              " solver=" + std::to_string(int(def.positionSolver.value_or(PositionSolver(99)))));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointBodyA(id) != a.value || world_->jointBodyB(id) != b.value) {
                failure("createJoint: wrong bodies");
            }
        });
    }

    Arg<LengthLimit> lengthLimit() {
        LengthLimit l;
        l.enabled = random_.chance(0.4f);
        Arg<float> min = values_->nonNegativeUpTo(3.0f, kMaxCoordinate);
        l.min = min.value;
        l.max = min.value + random_.uniform(0.0f, 4.0f);
        bool bad = min.bad || !(l.max <= kMaxCoordinate);
        if (!bad && hostile_ > 0.0f && random_.chance(0.2f)) {
            l.max = l.min - random_.uniform(0.1f, 1.0f) - 0.5f * l.min;  // below min
            bad = true;
        }
        return {l, bad};
    }

    Arg<JointSpring> spring() {
        JointSpring sp;
        sp.enabled = random_.chance(0.3f);
        Arg<float> hertz = values_->nonNegative(4.0f);
        Arg<float> damping = values_->nonNegative(1.0f);
        sp.hertz = hertz.value;
        sp.dampingRatio = damping.value;
        return {sp, hertz.bad || damping.bad || (sp.enabled && sp.hertz == 0.0f)};
    }

    /// Whether a rest length is one the API accepts.
    static bool badRestLength(float length) {
        return !(length >= kLinearSlop && length <= kMaxCoordinate);
    }

    /// Friction and motor joints: no strategy, so no solver or bias factor to set.
    bool velocityOnly(const Arg<JointId>& joint) const {
        return isType(joint, JointType::Friction) || isType(joint, JointType::Motor);
    }

    bool isType(const Arg<JointId>& joint, JointType type) const {
        return !joint.bad && world_->jointType(joint.value) == type;
    }

    void createDistanceJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        DistanceJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        bool bad = a.bad || b.bad || a.value == b.value;
        Arg<Vec2> localA = values_->coordinate(1.0f);
        Arg<Vec2> localB = values_->coordinate(1.0f);
        def.localAnchorA = localA.value;
        def.localAnchorB = localB.value;
        bad = bad || localA.bad || localB.bad;
        if (random_.chance(0.5f)) {
            Arg<float> length = values_->nonNegativeUpTo(5.0f, kMaxCoordinate);
            def.length = length.value;
            bad = bad || length.bad || badRestLength(length.value);
        } else if (!bad) {
            // The anchors' distance, as the world measures it.
            const Vec2 pA = transformPoint(world_->bodyTransform(a.value), def.localAnchorA);
            const Vec2 pB = transformPoint(world_->bodyTransform(b.value), def.localAnchorB);
            bad = badRestLength(distance(pA, pB));
        }
        Arg<LengthLimit> l = lengthLimit();
        Arg<JointSpring> sp = spring();
        def.limit = l.value;
        def.spring = sp.value;
        bad = bad || l.bad || sp.bad;
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.4f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        if (random_.chance(0.2f)) {
            Arg<float> letGo = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
            def.letGoSeparation = letGo.value;
            bad = bad || letGo.bad;
        }
        def.collideConnected = random_.chance(0.3f);
        def.userData = random_.next();
        trace("createDistanceJoint a=" + idText(a.value) + " b=" + idText(b.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointType(id) != JointType::Distance) {
                failure("createJoint: not a distance joint");
            }
        });
    }

    Arg<TranslationLimit> translationLimit() {
        TranslationLimit l;
        l.enabled = random_.chance(0.5f);
        Arg<float> lower = values_->bounded(2.0f, kMaxCoordinate);
        l.lower = lower.value;
        l.upper = lower.value + random_.uniform(0.0f, 3.0f);
        bool bad = lower.bad || !(l.upper <= kMaxCoordinate);
        if (!bad && hostile_ > 0.0f && random_.chance(0.2f)) {
            l.upper = l.lower - random_.uniform(0.1f, 1.0f) - 0.5f * std::fabs(l.lower);
            bad = true;
        }
        return {l, bad};
    }

    Arg<LinearMotor> linearMotor() {
        LinearMotor m;
        m.enabled = random_.chance(0.5f);
        Arg<float> speed = values_->bounded(5.0f, kMaxSpeed);
        Arg<float> force = values_->nonNegative(500.0f);
        m.speed = speed.value;
        m.maxForce = force.value;
        return {m, speed.bad || force.bad};
    }

    /// An axis: any length above kLinearSlop within kMaxMagnitude; now and then too short.
    Arg<Vec2> axis() {
        if (hostile_ > 0.0f && random_.chance(0.1f)) {
            return {random_.chance(0.5f) ? Vec2{} : Vec2{0.5f * kLinearSlop, 0.0f}, true};
        }
        Arg<Vec2> a = values_->magnitude2(1.0f);
        return {a.value, a.bad || !(length(a.value) > kLinearSlop)};
    }

    void createPrismaticJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        PrismaticJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        bool bad = a.bad || b.bad || a.value == b.value;
        const bool atWorldAnchor = random_.chance(0.6f);
        if (atWorldAnchor) {
            Arg<Vec2> anchor = values_->coordinate(15.0f);
            def.worldAnchor = anchor.value;
            bad = bad || anchor.bad;
        }
        if (!atWorldAnchor || (hostile_ > 0.0f && random_.chance(0.1f))) {
            Arg<Vec2> localA = values_->coordinate(2.0f);
            Arg<Vec2> localB = values_->coordinate(2.0f);
            Arg<float> reference = values_->magnitude(3.0f);
            def.localAnchorA = localA.value;
            def.localAnchorB = localB.value;
            def.referenceAngle = reference.value;
            bad = bad || localA.bad || localB.bad || reference.bad;
            if (atWorldAnchor && (def.localAnchorA != Vec2{} || def.localAnchorB != Vec2{} ||
                                  def.referenceAngle != 0.0f)) {
                bad = true;
            }
        }
        // The axis, in A's frame or the world's; setting both is refused.
        const bool worldAxis = random_.chance(0.5f);
        Arg<Vec2> ax = axis();
        (worldAxis ? def.worldAxis.emplace() : def.localAxisA) = ax.value;
        bad = bad || ax.bad;
        if (worldAxis && hostile_ > 0.0f && random_.chance(0.1f)) {
            def.localAxisA = {0.0f, 1.0f};
            bad = true;
        }
        Arg<TranslationLimit> l = translationLimit();
        Arg<LinearMotor> m = linearMotor();
        Arg<JointSpring> sp = spring();
        def.limit = l.value;
        def.motor = m.value;
        def.spring = sp.value;
        bad = bad || l.bad || m.bad || sp.bad;
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.4f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        if (random_.chance(0.2f)) {
            Arg<float> letGo = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
            def.letGoSeparation = letGo.value;
            bad = bad || letGo.bad;
        }
        def.collideConnected = random_.chance(0.3f);
        def.userData = random_.next();
        trace("createPrismaticJoint a=" + idText(a.value) + " b=" + idText(b.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointType(id) != JointType::Prismatic) {
                failure("createJoint: not a prismatic joint");
            }
            if (!(std::fabs(length(world_->prismaticJointAxis(id)) - 1.0f) < 1e-5f)) {
                failure("createJoint: the prismatic axis is not a unit vector");
            }
        });
    }

    void createWheelJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        WheelJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        bool bad = a.bad || b.bad || a.value == b.value;
        const bool atWorldAnchor = random_.chance(0.6f);
        if (atWorldAnchor) {
            Arg<Vec2> anchor = values_->coordinate(15.0f);
            def.worldAnchor = anchor.value;
            bad = bad || anchor.bad;
        }
        if (!atWorldAnchor || (hostile_ > 0.0f && random_.chance(0.1f))) {
            Arg<Vec2> localA = values_->coordinate(2.0f);
            Arg<Vec2> localB = values_->coordinate(2.0f);
            def.localAnchorA = localA.value;
            def.localAnchorB = localB.value;
            bad = bad || localA.bad || localB.bad;
            if (atWorldAnchor && (def.localAnchorA != Vec2{} || def.localAnchorB != Vec2{})) {
                bad = true;
            }
        }
        const bool worldAxis = random_.chance(0.5f);
        Arg<Vec2> ax = axis();
        (worldAxis ? def.worldAxis.emplace() : def.localAxisA) = ax.value;
        bad = bad || ax.bad;
        if (worldAxis && hostile_ > 0.0f && random_.chance(0.1f)) {
            def.localAxisA = {0.0f, 1.0f};
            bad = true;
        }
        Arg<JointSpring> sp = spring();
        Arg<TranslationLimit> l = translationLimit();
        Arg<JointMotor> m = motor();
        def.spring = sp.value;
        def.limit = l.value;
        def.motor = m.value;
        bad = bad || sp.bad || l.bad || m.bad;
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.4f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        if (random_.chance(0.2f)) {
            Arg<float> letGo = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
            def.letGoSeparation = letGo.value;
            bad = bad || letGo.bad;
        }
        def.collideConnected = random_.chance(0.3f);
        def.userData = random_.next();
        trace("createWheelJoint a=" + idText(a.value) + " b=" + idText(b.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointType(id) != JointType::Wheel)
                failure("createJoint: not a wheel joint");
        });
    }

    void createWeldJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        WeldJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        bool bad = a.bad || b.bad || a.value == b.value;
        const bool atWorldAnchor = random_.chance(0.6f);
        if (atWorldAnchor) {
            Arg<Vec2> anchor = values_->coordinate(15.0f);
            def.worldAnchor = anchor.value;
            bad = bad || anchor.bad;
        }
        if (!atWorldAnchor || (hostile_ > 0.0f && random_.chance(0.1f))) {
            Arg<Vec2> localA = values_->coordinate(2.0f);
            Arg<Vec2> localB = values_->coordinate(2.0f);
            Arg<float> reference = values_->magnitude(3.0f);
            def.localAnchorA = localA.value;
            def.localAnchorB = localB.value;
            def.referenceAngle = reference.value;
            bad = bad || localA.bad || localB.bad || reference.bad;
            if (atWorldAnchor && (def.localAnchorA != Vec2{} || def.localAnchorB != Vec2{} ||
                                  def.referenceAngle != 0.0f)) {
                bad = true;
            }
        }
        Arg<JointSpring> linear = spring();
        Arg<JointSpring> angular = spring();
        def.linearSpring = linear.value;
        def.angularSpring = angular.value;
        bad = bad || linear.bad || angular.bad;
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.4f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        if (random_.chance(0.2f)) {
            Arg<float> letGo = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
            def.letGoSeparation = letGo.value;
            bad = bad || letGo.bad;
        }
        def.collideConnected = random_.chance(0.3f);
        def.userData = random_.next();
        trace("createWeldJoint a=" + idText(a.value) + " b=" + idText(b.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointType(id) != JointType::Weld) failure("createJoint: not a weld joint");
        });
    }

    static bool badPulleyLength(float length) {
        return !(length >= kMinPulleyLength && length <= kMaxCoordinate);
    }

    void createPulleyJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        PulleyJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        bool bad = a.bad || b.bad || a.value == b.value;
        Arg<Vec2> groundA = values_->coordinate(15.0f);
        Arg<Vec2> groundB = values_->coordinate(15.0f);
        Arg<Vec2> localA = values_->coordinate(1.0f);
        Arg<Vec2> localB = values_->coordinate(1.0f);
        def.groundAnchorA = groundA.value;
        def.groundAnchorB = groundB.value;
        def.localAnchorA = localA.value;
        def.localAnchorB = localB.value;
        bad = bad || groundA.bad || groundB.bad || localA.bad || localB.bad;
        if (hostile_ > 0.0f && random_.chance(0.1f)) {
            def.ratio = random_.chance(0.5f) ? 0.0f : values_->garbage();
            bad = true;
        } else {
            def.ratio = random_.uniform(0.5f, 2.0f);
        }
        const auto length = [&](std::optional<float>& field, const Arg<BodyId>& body, Vec2 local,
                                Vec2 ground) {
            if (random_.chance(0.4f)) {
                Arg<float> l = values_->nonNegativeUpTo(8.0f, kMaxCoordinate);
                field = l.value;
                bad = bad || l.bad || badPulleyLength(l.value);
            } else if (!bad && !body.bad) {
                // The anchor's distance from its wheel, as the world measures it.
                const Vec2 p = transformPoint(world_->bodyTransform(body.value), local);
                bad = badPulleyLength(distance(p, ground));
            }
        };
        length(def.lengthA, a, def.localAnchorA, def.groundAnchorA);
        length(def.lengthB, b, def.localAnchorB, def.groundAnchorB);
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.3f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        def.collideConnected = random_.chance(0.7f);
        def.userData = random_.next();
        trace("createPulleyJoint a=" + idText(a.value) + " b=" + idText(b.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointType(id) != JointType::Pulley) {
                failure("createJoint: not a pulley joint");
            }
        });
    }

    // Whether a gear is built on the joint: World::destroyJoint refuses it then.
    bool carriesGear(JointId joint) const {
        for (JointId id : world_->jointIds()) {
            if (world_->jointType(id) != JointType::Gear) continue;
            if (world_->gearJointJoint1(id) == joint || world_->gearJointJoint2(id) == joint) {
                return true;
            }
        }
        return false;
    }

    void createGearJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        // Mostly among the joints a gear can couple, so that gears are built often enough to
        // be stepped, changed and destroyed.
        std::vector<JointId> coupleableIds;
        for (JointId id : world_->jointIds()) {
            const JointType type = world_->jointType(id);
            if (type == JointType::Revolute || type == JointType::Prismatic) {
                coupleableIds.push_back(id);
            }
        }
        const auto pickCoupleable = [&]() -> Arg<JointId> {
            if (coupleableIds.empty() || random_.chance(0.2f)) return pickJoint();
            return {coupleableIds[random_.below(static_cast<int>(coupleableIds.size()))], false};
        };
        Arg<JointId> joint1 = pickCoupleable();
        Arg<JointId> joint2 = random_.chance(0.05f) ? joint1 : pickCoupleable();
        GearJointDef def;
        def.joint1 = joint1.value;
        def.joint2 = joint2.value;
        const auto coupleable = [&](const Arg<JointId>& j) {
            return isType(j, JointType::Revolute) || isType(j, JointType::Prismatic);
        };
        bool bad = joint1.bad || joint2.bad || joint1.value == joint2.value ||
                   !coupleable(joint1) || !coupleable(joint2) ||
                   world_->jointBodyB(joint1.value) == world_->jointBodyB(joint2.value) ||
                   (world_->bodyType(world_->jointBodyB(joint1.value)) == BodyType::Static &&
                    world_->bodyType(world_->jointBodyB(joint2.value)) == BodyType::Static);
        if (hostile_ > 0.0f && random_.chance(0.1f)) {
            def.ratio = random_.chance(0.5f) ? 0.0f : values_->garbage();
            bad = true;
        } else {
            def.ratio = (random_.chance(0.5f) ? -1.0f : 1.0f) * random_.uniform(0.5f, 2.0f);
        }
        if (random_.chance(0.7f)) {
            Arg<PositionSolver> s = solver();
            def.positionSolver = s.value;
            bad = bad || s.bad;
        }
        if (random_.chance(0.3f)) {
            Arg<float> bias = values_->fraction();
            def.biasFactor = bias.value;
            bad = bad || bias.bad;
        }
        if (random_.chance(0.2f)) {
            Arg<float> letGo = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
            def.letGoSeparation = letGo.value;
            bad = bad || letGo.bad;
        }
        def.collideConnected = random_.chance(0.3f);
        def.userData = random_.next();
        trace("createGearJoint j1=" + idText(joint1.value) + " j2=" + idText(joint2.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
            if (world_->jointType(id) != JointType::Gear) failure("createJoint: not a gear joint");
        });
    }

    // A friction or a motor joint, at random.
    void createVelocityJoint() {
        if (world_->jointCount() >= kMaxJoints) {
            destroyJoint();
            return;
        }
        Arg<BodyId> a = pickBody();
        Arg<BodyId> b = random_.chance(0.05f) ? a : pickBody();
        bool bad = a.bad || b.bad || a.value == b.value;
        Arg<float> force = values_->nonNegative(50.0f);
        Arg<float> torque = values_->nonNegative(50.0f);
        bad = bad || force.bad || torque.bad;
        if (random_.chance(0.5f)) {
            FrictionJointDef def;
            def.bodyA = a.value;
            def.bodyB = b.value;
            Arg<Vec2> localA = values_->coordinate(1.0f);
            Arg<Vec2> localB = values_->coordinate(1.0f);
            def.localAnchorA = localA.value;
            def.localAnchorB = localB.value;
            def.maxForce = force.value;
            def.maxTorque = torque.value;
            def.userData = random_.next();
            bad = bad || localA.bad || localB.bad;
            trace("createFrictionJoint a=" + idText(a.value) + " b=" + idText(b.value));
            attempt("World::createJoint", verdict(bad), [&] {
                JointId id = journal_.createJoint(def);
                noteTag(id);
                joints_.remember(id);
            });
            return;
        }
        MotorJointDef def;
        def.bodyA = a.value;
        def.bodyB = b.value;
        def.maxForce = force.value;
        def.maxTorque = torque.value;
        Arg<float> factor = values_->fraction();
        def.correctionFactor = factor.value;
        bad = bad || factor.bad;
        if (random_.chance(0.5f)) {
            Arg<Vec2> offset = values_->coordinate(10.0f);
            Arg<float> angle = values_->magnitude(3.0f);
            def.linearOffset = offset.value;
            def.angularOffset = angle.value;
            bad = bad || offset.bad || angle.bad;
        } else if (!bad) {
            // The offsets come from the poses; far-apart bodies can put them out of range.
            const Transform xfA = world_->bodyTransform(a.value);
            const Vec2 offset = inverseTransformPoint(xfA, world_->bodyPosition(b.value));
            const float angle = world_->bodyAngle(b.value) - world_->bodyAngle(a.value);
            bad = !(std::fabs(offset.x) <= kMaxCoordinate &&
                    std::fabs(offset.y) <= kMaxCoordinate && std::fabs(angle) <= kMaxMagnitude);
        }
        def.userData = random_.next();
        trace("createMotorJoint a=" + idText(a.value) + " b=" + idText(b.value));
        attempt("World::createJoint", verdict(bad), [&] {
            JointId id = journal_.createJoint(def);
            noteTag(id);
            joints_.remember(id);
        });
    }

    void createMouseJoint() {
        if (liveMice_.size() >= kMaxMouseJoints) {
            destroyMouseJoint();
            return;
        }
        Arg<BodyId> body = pickBody();
        MouseJointDef def;
        def.body = body.value;
        Arg<Vec2> target = values_->coordinate(15.0f);
        Arg<float> force = values_->positive(1000.0f);
        Arg<float> hertz = values_->positive(20.0f);
        Arg<float> damping = values_->nonNegative(2.0f);
        def.target = target.value;
        def.maxForce = force.value;
        def.hertz = hertz.value;
        def.dampingRatio = damping.value;
        bool bad =
            body.bad || !isDynamic(body) || target.bad || force.bad || hertz.bad || damping.bad;
        trace("createMouseJoint body=" + idText(body.value) + " target=" + text(def.target) +
              " force=" + text(def.maxForce) + " hertz=" + text(def.hertz));
        attempt("World::createMouseJoint", verdict(bad), [&] {
            MouseJointId id = journal_.createMouseJoint(def);
            noteTag(id);
            mice_.remember(id);
            liveMice_.push_back({id, body.value});
        });
    }

    void destroyBody() {
        Arg<BodyId> body = pickBody();
        std::vector<ShapeId> shapes;
        std::vector<JointId> joints;
        if (!body.bad) {
            shapes = world_->bodyShapes(body.value);
            for (JointId j : world_->jointIds()) {
                if (world_->jointBodyA(j) == body.value || world_->jointBodyB(j) == body.value) {
                    joints.push_back(j);
                }
            }
            // And the gears built on those joints.
            const std::size_t attached = joints.size();
            for (JointId g : world_->jointIds()) {
                if (world_->jointType(g) != JointType::Gear) continue;
                if (std::find(joints.begin(), joints.end(), g) != joints.end()) continue;
                const auto begin = joints.begin();
                const auto end = joints.begin() + static_cast<std::ptrdiff_t>(attached);
                if (std::find(begin, end, world_->gearJointJoint1(g)) != end ||
                    std::find(begin, end, world_->gearJointJoint2(g)) != end) {
                    joints.push_back(g);
                }
            }
        }
        trace("destroyBody " + idText(body.value));
        int bodyCount = world_->bodyCount(), shapeCount = world_->shapeCount(),
            jointCount = world_->jointCount();
        attempt("World::destroyBody", verdict(body.bad), [&] { journal_.destroyBody(body.value); });
        if (body.bad) return;
        // Everything the body held went with it.
        if (world_->isValid(body.value)) failure("destroyBody: the body is still valid");
        for (ShapeId s : shapes) {
            if (world_->isValid(s)) failure("destroyBody: a shape of the body is still valid");
        }
        for (JointId j : joints) {
            if (world_->isValid(j)) failure("destroyBody: a joint of the body is still valid");
        }
        for (const LiveMouse& m : liveMice_) {
            if (m.body == body.value && world_->isValid(m.id)) {
                failure("destroyBody: a mouse joint of the body is still valid");
            }
        }
        if (world_->bodyCount() != bodyCount - 1 ||
            world_->shapeCount() != shapeCount - static_cast<int>(shapes.size()) ||
            world_->jointCount() != jointCount - static_cast<int>(joints.size())) {
            failure("destroyBody: counts do not add up");
        }
    }

    void destroyShape() {
        Arg<ShapeId> shape = pickShape();
        trace("destroyShape " + idText(shape.value));
        BodyId body;
        if (!shape.bad) body = world_->shapeBody(shape.value);
        attempt("World::destroyShape", afterMassChange(shape.value, verdict(shape.bad)), [&] {
            journal_.destroyShape(shape.value);
            if (world_->isValid(shape.value)) failure("destroyShape: the shape is still valid");
            if (world_->bodyType(body) == BodyType::Dynamic && !(world_->bodyMass(body) > 0.0f)) {
                failure("destroyShape: a dynamic body lost all its mass");
            }
        });
    }

    void destroyJoint() {
        Arg<JointId> joint = pickJoint();
        trace("destroyJoint " + idText(joint.value));
        const bool geared = !joint.bad && carriesGear(joint.value);
        attempt("World::destroyJoint", verdict(joint.bad || geared), [&] {
            journal_.destroyJoint(joint.value);
            if (world_->isValid(joint.value)) failure("destroyJoint: the joint is still valid");
        });
    }

    void destroyMouseJoint() {
        Arg<MouseJointId> mouse = pickMouse();
        trace("destroyMouseJoint " + idText(mouse.value));
        attempt("World::destroyMouseJoint", verdict(mouse.bad),
                [&] { journal_.destroyMouseJoint(mouse.value); });
    }

    void moveBody() {
        Arg<BodyId> body = pickBody();
        switch (random_.below(3)) {
            case 0: {
                Arg<Vec2> p = values_->coordinate(15.0f);
                Arg<float> a = values_->magnitude(4.0f);
                trace("setBodyTransform " + idText(body.value) + " " + text(p.value));
                attempt("World::setBodyTransform", verdict(body.bad || p.bad || a.bad),
                        [&] { journal_.setBodyTransform(body.value, p.value, a.value); });
                break;
            }
            case 1: {
                Arg<Vec2> v = values_->speed2(10.0f);
                trace("setBodyLinearVelocity " + idText(body.value) + " " + text(v.value));
                attempt("World::setBodyLinearVelocity",
                        verdict(body.bad || isStatic(body) || v.bad),
                        [&] { journal_.setBodyLinearVelocity(body.value, v.value); });
                break;
            }
            default: {
                Arg<float> w = values_->angularSpeed(10.0f);
                trace("setBodyAngularVelocity " + idText(body.value) + " " + text(w.value));
                const bool turns = body.bad || !world_->bodyFixedRotation(body.value);
                attempt("World::setBodyAngularVelocity",
                        verdict(body.bad || isStatic(body) || w.bad || (!turns && w.value != 0.0f)),
                        [&] { journal_.setBodyAngularVelocity(body.value, w.value); });
                break;
            }
        }
    }

    // Forces, torques and impulses: refused on static and kinematic bodies, torques on bodies
    // with fixed rotation, and whenever what the body accumulates would pass a limit (velocity,
    // pending force and torque, the accelerations they give). The driver predicts the last from
    // the body's mass and velocity: well inside every limit a call must be accepted; nearer,
    // where its rounding and the engine's may differ, or where a force piles onto pending ones
    // it does not track, either outcome is allowed (and a refusal must still change nothing).
    void pushBody() {
        Arg<BodyId> body = pickBody();
        Arg<Vec2> point = values_->coordinate(15.0f);
        const bool dynamic = isDynamic(body);
        const bool turns = !body.bad && !world_->bodyFixedRotation(body.value);
        float invMass = 0.0f, invInertia = 0.0f;
        Vec2 v, lever;
        float w = 0.0f;
        if (dynamic) {
            const float m = world_->bodyMass(body.value);
            const float i = world_->bodyRotationalInertia(body.value);
            invMass = m > 0.0f ? 1.0f / m : 0.0f;
            invInertia = i > 0.0f ? 1.0f / i : 0.0f;
            v = world_->bodyLinearVelocity(body.value);
            w = world_->bodyAngularVelocity(body.value);
            lever = point.value - world_->bodyWorldCenter(body.value);
        }
        // Well inside every limit (a thousandth of it): the call must be accepted.
        const auto inside = [](float value, float limit) {
            return std::fabs(value) <= 1e-3f * limit;
        };
        std::pair<float, float>& pending = pending_[{body.value.index, body.value.generation}];
        const auto judge = [&](bool bad, bool wellInside) {
            if (bad || !dynamic) return Verdict::Bad;
            return wellInside ? Verdict::Valid : Verdict::Unknown;
        };
        // What an accepted force or torque adds to the pile (an upper bound).
        const auto pile = [&](float force, float torque) {
            pending.first += force;
            pending.second += torque;
        };
        switch (random_.below(5)) {
            case 0: {
                Arg<Vec2> f = values_->magnitude2(200.0f);
                const float force = pending.first + length(f.value);
                const float torque = pending.second + std::fabs(cross(lever, f.value));
                const bool small =
                    inside(force, kMaxMagnitude) && inside(invMass * force, kMaxMagnitude) &&
                    (!turns ||
                     (inside(torque, kMaxMagnitude) && inside(invInertia * torque, kMaxMagnitude)));
                trace("applyForce " + idText(body.value) + " " + text(f.value));
                attempt("World::applyForce", judge(body.bad || f.bad || point.bad, small), [&] {
                    journal_.applyForce(body.value, f.value, point.value);
                    pile(length(f.value), std::fabs(cross(lever, f.value)));
                });
                break;
            }
            case 1: {
                Arg<Vec2> f = values_->magnitude2(200.0f);
                const float force = pending.first + length(f.value);
                const bool small =
                    inside(force, kMaxMagnitude) && inside(invMass * force, kMaxMagnitude);
                trace("applyForceToCenter " + idText(body.value) + " " + text(f.value));
                attempt("World::applyForceToCenter", judge(body.bad || f.bad, small), [&] {
                    journal_.applyForceToCenter(body.value, f.value);
                    pile(length(f.value), 0.0f);
                });
                break;
            }
            case 2: {
                Arg<float> t = values_->magnitude(100.0f);
                const float torque = pending.second + std::fabs(t.value);
                const bool small =
                    inside(torque, kMaxMagnitude) && inside(invInertia * torque, kMaxMagnitude);
                trace("applyTorque " + idText(body.value) + " " + text(t.value));
                attempt("World::applyTorque", judge(body.bad || t.bad || !turns, small), [&] {
                    journal_.applyTorque(body.value, t.value);
                    pile(0.0f, std::fabs(t.value));
                });
                break;
            }
            case 3: {
                Arg<Vec2> j = values_->magnitude2(10.0f);
                const Vec2 dv = invMass * j.value;
                const float dw = invInertia * cross(lever, j.value);
                const bool small = inside(std::fabs(v.x) + std::fabs(dv.x), kMaxSpeed) &&
                                   inside(std::fabs(v.y) + std::fabs(dv.y), kMaxSpeed) &&
                                   inside(std::fabs(w) + std::fabs(dw), kMaxAngularSpeed);
                trace("applyLinearImpulse " + idText(body.value) + " " + text(j.value));
                attempt("World::applyLinearImpulse", judge(body.bad || j.bad || point.bad, small),
                        [&] { journal_.applyLinearImpulse(body.value, j.value, point.value); });
                break;
            }
            default: {
                Arg<float> j = values_->magnitude(5.0f);
                const bool small =
                    inside(std::fabs(w) + std::fabs(invInertia * j.value), kMaxAngularSpeed);
                trace("applyAngularImpulse " + idText(body.value) + " " + text(j.value));
                attempt("World::applyAngularImpulse", judge(body.bad || j.bad || !turns, small),
                        [&] { journal_.applyAngularImpulse(body.value, j.value); });
                break;
            }
        }
    }

    void sleepCalls() {
        Arg<BodyId> body = pickBody();
        bool flag = random_.chance(0.5f);
        switch (random_.below(4)) {
            case 0:
                trace("setBodyAwake " + idText(body.value) + " " + std::to_string(flag));
                attempt("World::setBodyAwake", verdict(body.bad),
                        [&] { journal_.setBodyAwake(body.value, flag); });
                break;
            case 1:
                trace("setBodySleepAllowed " + idText(body.value) + " " + std::to_string(flag));
                attempt("World::setBodySleepAllowed", verdict(body.bad),
                        [&] { journal_.setBodySleepAllowed(body.value, flag); });
                break;
            case 2:
                // Continuous collision's switches; bullets exercise impacts between dynamic
                // bodies too.
                trace("setBodyBullet " + idText(body.value) + " " + std::to_string(flag));
                attempt("World::setBodyBullet", verdict(body.bad),
                        [&] { journal_.setBodyBullet(body.value, flag); });
                break;
            default:
                trace("setBodyContinuous " + idText(body.value) + " " + std::to_string(flag));
                attempt("World::setBodyContinuous", verdict(body.bad),
                        [&] { journal_.setBodyContinuous(body.value, flag); });
                break;
        }
    }

    void setBodyType() {
        Arg<BodyId> body = pickBody();
        BodyType type;
        bool bad = body.bad;
        if (hostile_ > 0.0f && random_.chance(0.15f)) {
            type = static_cast<BodyType>(random_.between(3, 255));
            bad = true;
        } else {
            type = static_cast<BodyType>(random_.below(3));
            if (type == BodyType::Dynamic && !body.bad &&
                (hasZeroDensityShape(body.value) || hasSegment(body.value))) {
                bad = true;
            }
        }
        trace("setBodyType " + idText(body.value) + " " + std::to_string(int(type)));
        attempt(
            "World::setBodyType", bad ? Verdict::Bad : afterMassChange(body.value, Verdict::Valid),
            [&] {
                journal_.setBodyType(body.value, type);
                if (world_->bodyType(body.value) != type) failure("setBodyType: type not set");
                if (type == BodyType::Static && (world_->bodyLinearVelocity(body.value) != Vec2{} ||
                                                 world_->bodyAngularVelocity(body.value) != 0.0f)) {
                    failure("setBodyType: a static body kept a velocity");
                }
            });
    }

    void setShapeDensity() {
        Arg<ShapeId> shape = pickShape();
        bool dynamic =
            !shape.bad && world_->bodyType(world_->shapeBody(shape.value)) == BodyType::Dynamic;
        Arg<float> density = values_->density(!dynamic);
        trace("setShapeDensity " + idText(shape.value) + " " + text(density.value));
        attempt("World::setShapeDensity",
                afterMassChange(shape.value, verdict(shape.bad || density.bad)),
                [&] { journal_.setShapeDensity(shape.value, density.value); });
    }

    void setShapeMaterial() {
        Arg<ShapeId> shape = pickShape();
        if (random_.chance(0.2f)) {
            const bool flag = random_.chance(0.5f);
            if (random_.chance(0.5f)) {
                const bool hits = random_.chance(0.5f);
                trace((hits ? "setShapeHitEvents " : "setShapePreSolve ") + idText(shape.value) +
                      " " + std::to_string(flag));
                attempt(hits ? "World::setShapeHitEventsEnabled" : "World::setShapePreSolveEnabled",
                        verdict(shape.bad), [&] {
                            if (hits) {
                                journal_.setShapeHitEvents(shape.value, flag);
                            } else {
                                journal_.setShapePreSolve(shape.value, flag);
                            }
                        });
                return;
            }
            trace("setShapeSensor " + idText(shape.value) + " " + std::to_string(flag));
            attempt("World::setShapeSensor", verdict(shape.bad),
                    [&] { journal_.setShapeSensor(shape.value, flag); });
        } else if (random_.chance(0.5f)) {
            Arg<float> friction = values_->nonNegativeUpTo(1.0f, kMaxFriction);
            trace("setShapeFriction " + idText(shape.value) + " " + text(friction.value));
            attempt("World::setShapeFriction", verdict(shape.bad || friction.bad),
                    [&] { journal_.setShapeFriction(shape.value, friction.value); });
        } else {
            Arg<float> restitution = values_->fraction();
            trace("setShapeRestitution " + idText(shape.value) + " " + text(restitution.value));
            attempt("World::setShapeRestitution", verdict(shape.bad || restitution.bad),
                    [&] { journal_.setShapeRestitution(shape.value, restitution.value); });
        }
    }

    void setBodyProperties() {
        Arg<BodyId> body = pickBody();
        switch (random_.below(4)) {
            case 0: {
                const bool flag = random_.chance(0.5f);
                trace("setBodyFixedRotation " + idText(body.value) + " " + std::to_string(flag));
                attempt("World::setBodyFixedRotation", verdict(body.bad),
                        [&] { journal_.setBodyFixedRotation(body.value, flag); });
                break;
            }
            case 1: {
                Arg<float> damping = values_->nonNegative(1.0f);
                trace("setBodyLinearDamping " + idText(body.value) + " " + text(damping.value));
                attempt("World::setBodyLinearDamping", verdict(body.bad || damping.bad),
                        [&] { journal_.setBodyLinearDamping(body.value, damping.value); });
                break;
            }
            case 2: {
                Arg<float> damping = values_->nonNegative(1.0f);
                trace("setBodyAngularDamping " + idText(body.value) + " " + text(damping.value));
                attempt("World::setBodyAngularDamping", verdict(body.bad || damping.bad),
                        [&] { journal_.setBodyAngularDamping(body.value, damping.value); });
                break;
            }
            default: {
                Arg<float> scale = values_->gravityScale();
                trace("setBodyGravityScale " + idText(body.value) + " " + text(scale.value));
                attempt("World::setBodyGravityScale", verdict(body.bad || scale.bad),
                        [&] { journal_.setBodyGravityScale(body.value, scale.value); });
                break;
            }
        }
    }

    // Break thresholds: mostly around the forces a scene sees, so joints do break.
    void setJointBreak() {
        Arg<JointId> joint = pickJoint();
        if (random_.chance(0.25f)) {
            const bool collide = random_.chance(0.5f);
            trace("setJointCollideConnected " + idText(joint.value) + " " +
                  std::to_string(collide));
            attempt("World::setJointCollideConnected", verdict(joint.bad),
                    [&] { journal_.setJointCollideConnected(joint.value, collide); });
            return;
        }
        Arg<float> value = values_->nonNegative(50.0f);
        const bool force = random_.chance(0.5f);
        trace((force ? "setJointBreakForce " : "setJointBreakTorque ") + idText(joint.value) + " " +
              text(value.value));
        attempt(force ? "World::setJointBreakForce" : "World::setJointBreakTorque",
                verdict(joint.bad || value.bad), [&] {
                    if (force) {
                        journal_.setJointBreakForce(joint.value, value.value);
                    } else {
                        journal_.setJointBreakTorque(joint.value, value.value);
                    }
                });
    }

    void setShapeFilter() {
        Arg<ShapeId> shape = pickShape();
        Filter f = filter();
        trace("setShapeFilter " + idText(shape.value));
        attempt("World::setShapeFilter", verdict(shape.bad),
                [&] { journal_.setShapeFilter(shape.value, f); });
    }

    void changeJoint() {
        Arg<JointId> joint = pickJoint();
        switch (random_.below(8)) {
            case 7: {
                const bool other = !joint.bad && !isType(joint, JointType::Distance);
                if (random_.chance(0.3f)) {
                    // The prismatic joint's setters.
                    const bool notPrismatic = !joint.bad && !isType(joint, JointType::Prismatic);
                    const bool notWeld = !joint.bad && !isType(joint, JointType::Weld);
                    const bool notWheel = !joint.bad && !isType(joint, JointType::Wheel);
                    const bool notGear = !joint.bad && !isType(joint, JointType::Gear);
                    if (random_.chance(0.15f)) {
                        float ratio =
                            (random_.chance(0.5f) ? -1.0f : 1.0f) * random_.uniform(0.5f, 2.0f);
                        bool badRatio = false;
                        if (hostile_ > 0.0f && random_.chance(0.2f)) {
                            ratio = random_.chance(0.5f) ? 0.0f : values_->garbage();
                            badRatio = true;
                        }
                        trace("setGearJointRatio " + idText(joint.value) + " " + text(ratio));
                        attempt("World::setGearJointRatio",
                                verdict(joint.bad || notGear || badRatio),
                                [&] { journal_.setGearJointRatio(joint.value, ratio); });
                        break;
                    }
                    if (random_.chance(0.3f)) {
                        if (random_.chance(0.5f)) {
                            Arg<JointSpring> sp = spring();
                            trace("setWheelJointSpring " + idText(joint.value));
                            attempt("World::setWheelJointSpring",
                                    verdict(joint.bad || notWheel || sp.bad),
                                    [&] { journal_.setWheelJointSpring(joint.value, sp.value); });
                        } else {
                            Arg<TranslationLimit> l = translationLimit();
                            trace("setWheelJointLimit " + idText(joint.value));
                            attempt("World::setWheelJointLimit",
                                    verdict(joint.bad || notWheel || l.bad),
                                    [&] { journal_.setWheelJointLimit(joint.value, l.value); });
                        }
                        break;
                    }
                    if (random_.chance(0.4f)) {
                        Arg<JointSpring> sp = spring();
                        const bool linear = random_.chance(0.5f);
                        trace("setWeldJointSpring " + idText(joint.value));
                        attempt(linear ? "World::setWeldJointLinearSpring"
                                       : "World::setWeldJointAngularSpring",
                                verdict(joint.bad || notWeld || sp.bad), [&] {
                                    if (linear) {
                                        journal_.setWeldJointLinearSpring(joint.value, sp.value);
                                    } else {
                                        journal_.setWeldJointAngularSpring(joint.value, sp.value);
                                    }
                                });
                        break;
                    }
                    switch (random_.below(3)) {
                        case 0: {
                            Arg<TranslationLimit> l = translationLimit();
                            trace("setPrismaticJointLimit " + idText(joint.value));
                            attempt("World::setPrismaticJointLimit",
                                    verdict(joint.bad || notPrismatic || l.bad),
                                    [&] { journal_.setPrismaticJointLimit(joint.value, l.value); });
                            break;
                        }
                        case 1: {
                            Arg<LinearMotor> m = linearMotor();
                            trace("setPrismaticJointMotor " + idText(joint.value));
                            attempt("World::setPrismaticJointMotor",
                                    verdict(joint.bad || notPrismatic || m.bad),
                                    [&] { journal_.setPrismaticJointMotor(joint.value, m.value); });
                            break;
                        }
                        default: {
                            Arg<JointSpring> sp = spring();
                            trace("setPrismaticJointSpring " + idText(joint.value));
                            attempt("World::setPrismaticJointSpring",
                                    verdict(joint.bad || notPrismatic || sp.bad), [&] {
                                        journal_.setPrismaticJointSpring(joint.value, sp.value);
                                    });
                            break;
                        }
                    }
                    break;
                }
                if (random_.chance(0.4f)) {
                    // The friction and motor joints' setters.
                    const bool notVelocity = !joint.bad && !velocityOnly(joint);
                    const bool notMotor = !joint.bad && !isType(joint, JointType::Motor);
                    Arg<float> force = values_->nonNegative(50.0f);
                    Arg<Vec2> offset = values_->coordinate(10.0f);
                    Arg<float> factor = values_->fraction();
                    switch (random_.below(3)) {
                        case 0:
                            attempt("World::setJointMaxForce",
                                    verdict(joint.bad || notVelocity || force.bad),
                                    [&] { journal_.setJointMaxForce(joint.value, force.value); });
                            break;
                        case 1:
                            attempt("World::setMotorJointLinearOffset",
                                    verdict(joint.bad || notMotor || offset.bad), [&] {
                                        journal_.setMotorJointLinearOffset(joint.value,
                                                                           offset.value);
                                    });
                            break;
                        default:
                            attempt("World::setMotorJointCorrectionFactor",
                                    verdict(joint.bad || notMotor || factor.bad), [&] {
                                        journal_.setMotorJointCorrectionFactor(joint.value,
                                                                               factor.value);
                                    });
                            break;
                    }
                    break;
                }
                switch (random_.below(3)) {
                    case 0: {
                        Arg<float> length = values_->nonNegativeUpTo(5.0f, kMaxCoordinate);
                        const bool bad = length.bad || badRestLength(length.value);
                        trace("setDistanceJointRestLength " + idText(joint.value));
                        attempt("World::setDistanceJointRestLength",
                                verdict(joint.bad || other || bad), [&] {
                                    journal_.setDistanceJointRestLength(joint.value, length.value);
                                });
                        break;
                    }
                    case 1: {
                        Arg<LengthLimit> l = lengthLimit();
                        trace("setDistanceJointLimit " + idText(joint.value));
                        attempt("World::setDistanceJointLimit",
                                verdict(joint.bad || other || l.bad),
                                [&] { journal_.setDistanceJointLimit(joint.value, l.value); });
                        break;
                    }
                    default: {
                        Arg<JointSpring> sp = spring();
                        trace("setDistanceJointSpring " + idText(joint.value));
                        attempt("World::setDistanceJointSpring",
                                verdict(joint.bad || other || sp.bad),
                                [&] { journal_.setDistanceJointSpring(joint.value, sp.value); });
                        break;
                    }
                }
                break;
            }
            case 0: {
                Arg<JointLimit> l = limit();
                trace("setJointLimit " + idText(joint.value) + " " + text(l.value.lower) + ".." +
                      text(l.value.upper));
                const bool other = !joint.bad && !isType(joint, JointType::Revolute);
                attempt("World::setJointLimit", verdict(joint.bad || other || l.bad),
                        [&] { journal_.setJointLimit(joint.value, l.value); });
                break;
            }
            case 1: {
                Arg<JointMotor> m = motor();
                trace("setJointMotor " + idText(joint.value) + " " + text(m.value.speed));
                const bool other = !joint.bad && !isType(joint, JointType::Revolute) &&
                                   !isType(joint, JointType::Wheel);
                attempt("World::setJointMotor", verdict(joint.bad || other || m.bad),
                        [&] { journal_.setJointMotor(joint.value, m.value); });
                break;
            }
            case 2: {
                Arg<PositionSolver> s = solver();
                trace("setJointPositionSolver " + idText(joint.value) + " " +
                      std::to_string(int(s.value)));
                attempt("World::setJointPositionSolver",
                        verdict(joint.bad || velocityOnly(joint) || s.bad),
                        [&] { journal_.setJointPositionSolver(joint.value, s.value); });
                break;
            }
            case 3: {
                if (random_.chance(0.3f)) {
                    Arg<float> hertz = values_->positive(30.0f);
                    Arg<float> ratio = values_->nonNegative(2.0f);
                    Arg<float> compliance = values_->nonNegative(1e-3f);
                    const JointSoftness softness{hertz.value, ratio.value, compliance.value};
                    trace("setJointSoftness " + idText(joint.value) + " " + text(hertz.value) +
                          " " + text(ratio.value));
                    attempt("World::setJointSoftness",
                            verdict(joint.bad || velocityOnly(joint) || hertz.bad || ratio.bad ||
                                    compliance.bad),
                            [&] { journal_.setJointSoftness(joint.value, softness); });
                    break;
                }
                if (random_.chance(0.2f)) {
                    // Mostly a count in range, now and then one outside it.
                    const bool outside = random_.chance(0.2f);
                    const int count = outside ? (random_.chance(0.5f) ? -1 : kMaxIterations + 1)
                                              : random_.below(7);
                    trace("setJointExtraPositionIterations " + idText(joint.value) + " " +
                          std::to_string(count));
                    attempt("World::setJointExtraPositionIterations",
                            verdict(joint.bad || velocityOnly(joint) || outside),
                            [&] { journal_.setJointExtraPositionIterations(joint.value, count); });
                    break;
                }
                std::optional<float> bias;
                bool bad = joint.bad || velocityOnly(joint);
                if (random_.chance(0.7f)) {
                    Arg<float> b = values_->fraction();
                    bias = b.value;
                    bad = bad || b.bad;
                }
                trace("setJointBiasFactor " + idText(joint.value));
                attempt("World::setJointBiasFactor", verdict(bad),
                        [&] { journal_.setJointBiasFactor(joint.value, bias); });
                break;
            }
            case 4: {
                std::optional<float> separation;
                bool bad = joint.bad;
                if (random_.chance(0.8f)) {
                    Arg<float> s = values_->nonNegativeUpTo(20.0f, kMaxMagnitude);
                    separation = s.value;
                    bad = bad || s.bad;
                }
                trace("setJointLetGoSeparation " + idText(joint.value));
                attempt("World::setJointLetGoSeparation", verdict(bad), [&] {
                    journal_.setJointLetGoSeparation(joint.value, separation);
                    if (separation && world_->jointLetGoSeparation(joint.value) != *separation) {
                        failure("setJointLetGoSeparation: the setting did not take");
                    }
                });
                break;
            }
            case 5: {
                trace("rearmJoint " + idText(joint.value));
                attempt("World::rearmJoint", verdict(joint.bad), [&] {
                    journal_.rearmJoint(joint.value);
                    if (world_->isJointLetGo(joint.value)) failure("rearmJoint: still let go");
                });
                break;
            }
            default: {
                const std::uint64_t value = random_.next();
                Arg<BodyId> body = pickBody();
                Arg<ShapeId> shape = pickShape();
                switch (random_.below(3)) {
                    case 0:
                        attempt("World::setJointUserData", verdict(joint.bad), [&] {
                            journal_.setJointUserData(joint.value, value);
                            if (world_->jointUserData(joint.value) != value) {
                                failure("setJointUserData: not read back");
                            }
                        });
                        break;
                    case 1:
                        attempt("World::setBodyUserData", verdict(body.bad), [&] {
                            journal_.setBodyUserData(body.value, value);
                            if (world_->bodyUserData(body.value) != value) {
                                failure("setBodyUserData: not read back");
                            }
                        });
                        break;
                    default:
                        attempt("World::setShapeUserData", verdict(shape.bad), [&] {
                            journal_.setShapeUserData(shape.value, value);
                            if (world_->shapeUserData(shape.value) != value) {
                                failure("setShapeUserData: not read back");
                            }
                        });
                        break;
                }
                break;
            }
        }
    }

    void moveMouse() {
        Arg<MouseJointId> mouse = pickMouse();
        Arg<Vec2> target = values_->coordinate(15.0f);
        trace("setMouseTarget " + idText(mouse.value) + " " + text(target.value));
        attempt("World::setMouseTarget", verdict(mouse.bad || target.bad),
                [&] { journal_.setMouseTarget(mouse.value, target.value); });
    }

    void worldSettings() {
        switch (random_.below(7)) {
            case 5: {
                const bool preSolve = random_.chance(0.6f);
                const bool filter = random_.chance(0.4f);
                trace("setCallbacks " + std::to_string(preSolve) + " " + std::to_string(filter));
                if (attempt("World::setPreSolveCallback", Verdict::Valid,
                            [&] { journal_.setCallbacks(preSolve, filter); })) {
                    preSolveInstalled_ = preSolve;
                    filterInstalled_ = filter;
                }
                break;
            }
            case 6: {
                Arg<float> speed = values_->nonNegativeUpTo(2.0f, kMaxSpeed);
                trace("setHitEventThreshold " + text(speed.value));
                attempt("World::setHitEventThreshold", verdict(speed.bad),
                        [&] { journal_.setHitEventThreshold(speed.value); });
                break;
            }
            case 0: {
                Arg<Vec2> g = random_.chance(0.5f) ? Arg<Vec2>{{0.0f, -10.0f}} : values_->gravity();
                trace("setGravity " + text(g.value));
                attempt("World::setGravity", verdict(g.bad), [&] { journal_.setGravity(g.value); });
                break;
            }
            case 1: {
                bool bad = hostile_ > 0.0f && random_.chance(0.3f);
                auto c = static_cast<ContactCorrection>(bad ? random_.between(3, 255)
                                                            : random_.below(3));
                trace("setContactCorrection " + std::to_string(int(c)));
                attempt("World::setContactCorrection", verdict(bad),
                        [&] { journal_.setContactCorrection(c); });
                break;
            }
            case 2: {
                // Mostly one substep (each substep is a whole solve), sometimes a few.
                bool bad = hostile_ > 0.0f && random_.chance(0.3f);
                const int badChoices[] = {0, -1, kMaxSubsteps + 1, std::numeric_limits<int>::min()};
                const int goodChoices[] = {1, 1, 2, 4, 8};
                const int n = bad ? badChoices[random_.below(4)] : goodChoices[random_.below(5)];
                trace("setSubstepCount " + std::to_string(n));
                attempt("World::setSubstepCount", verdict(bad),
                        [&] { journal_.setSubstepCount(n); });
                break;
            }
            case 3: {
                bool on = random_.chance(0.7f);
                trace("setSleepEnabled " + std::to_string(on));
                attempt("World::setSleepEnabled", Verdict::Valid,
                        [&] { journal_.setSleepEnabled(on); });
                break;
            }
            default: {
                bool on = random_.chance(0.8f);
                trace("setContinuousEnabled " + std::to_string(on));
                attempt("World::setContinuousEnabled", Verdict::Valid,
                        [&] { journal_.setContinuousEnabled(on); });
                if (random_.chance(0.5f)) {
                    const ContinuousCollision policy = random_.chance(0.5f)
                                                           ? ContinuousCollision::FastBodies
                                                           : ContinuousCollision::Substeps;
                    trace("setContinuousCollision " + std::to_string(static_cast<int>(policy)));
                    attempt("World::setContinuousCollision", Verdict::Valid,
                            [&] { journal_.setContinuousCollision(policy); });
                }
                break;
            }
        }
    }

    void step() {
        float dt = 1.0f / 60.0f;
        bool bad = false;
        int r = random_.below(100);
        if (hostile_ > 0.0f && r < 10) {
            const float choices[] = {0.0f, -1.0f / 60.0f, 1.001f * kMaxTimeStep, -0.0f,
                                     0.999f * kMinTimeStep};
            dt = random_.chance(0.5f) ? values_->garbage() : choices[random_.below(5)];
            bad = true;
        } else if (r < 20) {
            // Anywhere in [1e-40, 1] s, uniformly in its logarithm: refused below kMinTimeStep
            // (a driver that gives no bad values keeps to [kMinTimeStep, 1]).
            dt = std::pow(10.0f, random_.uniform(hostile_ > 0.0f ? -40.0f : -5.0f, 0.0f));
            bad = !(dt >= kMinTimeStep);
        } else if (r < 30) {
            const float choices[] = {1.0f / 30.0f,   1.0f / 120.0f, 1.0f / 240.0f,
                                     1.0f / 1000.0f, kMaxTimeStep,  kMinTimeStep};
            dt = choices[random_.below(options_.extremes ? 6 : 4)];
        } else if (r < 40) {
            dt = random_.uniform(1e-4f, 0.05f);
        }
        int velocityIterations = kBox2D241VelocityIterations;
        int positionIterations = kBox2D241PositionIterations;
        if (random_.chance(0.3f)) {
            velocityIterations = values_->edge(0.02f) ? 200 : random_.between(0, 12);
            positionIterations = values_->edge(0.02f) ? 200 : random_.between(0, 12);
        }
        if (hostile_ > 0.0f && random_.chance(0.15f)) {
            const int choices[] = {-1, kMaxIterations + 1, std::numeric_limits<int>::min(),
                                   std::numeric_limits<int>::max()};
            (random_.chance(0.5f) ? velocityIterations : positionIterations) =
                choices[random_.below(4)];
            bad = true;
        }
        // Each substep must be at least kMinTimeStep long too.
        bad = bad || !(dt / static_cast<float>(world_->substepCount()) >= kMinTimeStep);
        trace("step dt=" + text(dt) + " " + std::to_string(velocityIterations) + "/" +
              std::to_string(positionIterations));
        if (attempt("World::step", verdict(bad),
                    [&] { journal_.step(dt, velocityIterations, positionIterations); })) {
            pending_.clear();
            ++report_.steps;
            report_.letGoJoints += world_->lastStepStats().letGoJointCount;
            report_.discardedBodies += world_->lastStepStats().discardedBodyCount;
            checkStepEvents();
            checkInvariants("a step");
        }
    }

    void query() {
        Arg<BodyId> body = pickBody();
        Arg<ShapeId> shape = pickShape();
        Arg<JointId> joint = pickJoint();
        Arg<MouseJointId> mouse = pickMouse();
        Arg<Vec2> point = values_->coordinate(15.0f);
        World& w = *world_;
        std::vector<std::pair<const char*, std::function<void()>>> bodyQueries = {
            {"World::bodyShapes", [&] { w.bodyShapes(body.value); }},
            {"World::bodyType", [&] { w.bodyType(body.value); }},
            {"World::bodyPosition", [&] { w.bodyPosition(body.value); }},
            {"World::bodyAngle", [&] { w.bodyAngle(body.value); }},
            {"World::bodyTransform", [&] { w.bodyTransform(body.value); }},
            {"World::bodyWorldCenter", [&] { w.bodyWorldCenter(body.value); }},
            {"World::bodyLocalCenter", [&] { w.bodyLocalCenter(body.value); }},
            {"World::bodyLinearVelocity", [&] { w.bodyLinearVelocity(body.value); }},
            {"World::bodyAngularVelocity", [&] { w.bodyAngularVelocity(body.value); }},
            {"World::bodyMass", [&] { w.bodyMass(body.value); }},
            {"World::bodyRotationalInertia", [&] { w.bodyRotationalInertia(body.value); }},
            {"World::isBodyAwake", [&] { w.isBodyAwake(body.value); }},
            {"World::bodyFixedRotation", [&] { w.bodyFixedRotation(body.value); }},
            {"World::bodyUserData", [&] { w.bodyUserData(body.value); }},
        };
        std::vector<std::pair<const char*, std::function<void()>>> jointQueries = {
            {"World::jointBodyA", [&] { w.jointBodyA(joint.value); }},
            {"World::jointBodyB", [&] { w.jointBodyB(joint.value); }},
            {"World::jointAnchorA", [&] { w.jointAnchorA(joint.value); }},
            {"World::jointAnchorB", [&] { w.jointAnchorB(joint.value); }},
            {"World::jointSeparation", [&] { w.jointSeparation(joint.value); }},
            {"World::jointAngle", [&] { w.jointAngle(joint.value); }},
            {"World::jointSpeed", [&] { w.jointSpeed(joint.value); }},
            {"World::jointReactionForce", [&] { w.jointReactionForce(joint.value); }},
            {"World::jointReactionTorque", [&] { w.jointReactionTorque(joint.value); }},
            {"World::jointType", [&] { w.jointType(joint.value); }},
            {"World::jointLength", [&] { w.jointLength(joint.value); }},
            {"World::jointPositionSolver", [&] { w.jointPositionSolver(joint.value); }},
            {"World::jointBiasFactor", [&] { w.jointBiasFactor(joint.value); }},
            {"World::jointExtraPositionIterations",
             [&] { w.jointExtraPositionIterations(joint.value); }},
            {"World::isJointLetGo", [&] { w.isJointLetGo(joint.value); }},
            {"World::jointLetGoSeparation", [&] { w.jointLetGoSeparation(joint.value); }},
            {"World::jointUserData", [&] { w.jointUserData(joint.value); }},
        };
        std::vector<std::pair<const char*, std::function<void()>>> shapeQueries = {
            {"World::shapeBody", [&] { w.shapeBody(shape.value); }},
            {"World::shapeFilter", [&] { w.shapeFilter(shape.value); }},
            {"World::shapeType", [&] { w.shapeType(shape.value); }},
            {"World::shapeDensity", [&] { w.shapeDensity(shape.value); }},
            {"World::shapeUserData", [&] { w.shapeUserData(shape.value); }},
        };
        switch (random_.below(7)) {
            case 0: {
                auto& q = bodyQueries[random_.below(static_cast<int>(bodyQueries.size()))];
                attempt(q.first, verdict(body.bad), q.second);
                break;
            }
            case 1: {
                if (random_.chance(0.3f)) {
                    // Calls for one joint type, which refuse the others.
                    const bool notRevolute = !joint.bad && !isType(joint, JointType::Revolute);
                    const bool notDistance = !joint.bad && !isType(joint, JointType::Distance);
                    const bool notPulley = !joint.bad && !isType(joint, JointType::Pulley);
                    const bool notMotor = !joint.bad && !isType(joint, JointType::Motor);
                    const bool notVelocity = !joint.bad && !velocityOnly(joint);
                    const bool notPrismatic = !joint.bad && !isType(joint, JointType::Prismatic);
                    const bool notWeld = !joint.bad && !isType(joint, JointType::Weld);
                    const bool notWheel = !joint.bad && !isType(joint, JointType::Wheel);
                    const bool notGear = !joint.bad && !isType(joint, JointType::Gear);
                    const bool notSlide = notPrismatic && notWheel;
                    const bool notMotorised = notRevolute && notWheel;
                    std::vector<std::tuple<const char*, bool, std::function<void()>>> typed = {
                        {"World::wheelJointSpring", notWheel,
                         [&] { w.wheelJointSpring(joint.value); }},
                        {"World::wheelJointLimit", notWheel,
                         [&] { w.wheelJointLimit(joint.value); }},
                        {"World::weldJointLinearSpring", notWeld,
                         [&] { w.weldJointLinearSpring(joint.value); }},
                        {"World::weldJointAngularSpring", notWeld,
                         [&] { w.weldJointAngularSpring(joint.value); }},
                        {"World::jointTranslation", notSlide,
                         [&] { w.jointTranslation(joint.value); }},
                        {"World::jointTranslationSpeed", notSlide,
                         [&] { w.jointTranslationSpeed(joint.value); }},
                        {"World::prismaticJointAxis", notPrismatic,
                         [&] { w.prismaticJointAxis(joint.value); }},
                        {"World::prismaticJointLimit", notPrismatic,
                         [&] { w.prismaticJointLimit(joint.value); }},
                        {"World::prismaticJointMotorForce", notPrismatic,
                         [&] { w.prismaticJointMotorForce(joint.value); }},
                        {"World::jointMotorTorque", notMotorised,
                         [&] { w.jointMotorTorque(joint.value); }},
                        {"World::jointLimit", notRevolute, [&] { w.jointLimit(joint.value); }},
                        {"World::jointMotor", notMotorised, [&] { w.jointMotor(joint.value); }},
                        {"World::distanceJointRestLength", notDistance,
                         [&] { w.distanceJointRestLength(joint.value); }},
                        {"World::distanceJointLimit", notDistance,
                         [&] { w.distanceJointLimit(joint.value); }},
                        {"World::distanceJointSpring", notDistance,
                         [&] { w.distanceJointSpring(joint.value); }},
                        {"World::pulleyJointRatio", notPulley,
                         [&] { w.pulleyJointRatio(joint.value); }},
                        {"World::gearJointRatio", notGear, [&] { w.gearJointRatio(joint.value); }},
                        {"World::gearJointJoint1", notGear,
                         [&] { w.gearJointJoint1(joint.value); }},
                        {"World::pulleyJointLengthA", notPulley,
                         [&] { w.pulleyJointLengthA(joint.value); }},
                        {"World::pulleyJointGroundAnchorB", notPulley,
                         [&] { w.pulleyJointGroundAnchorB(joint.value); }},
                        {"World::jointMaxForce", notVelocity,
                         [&] { w.jointMaxForce(joint.value); }},
                        {"World::motorJointLinearOffset", notMotor,
                         [&] { w.motorJointLinearOffset(joint.value); }},
                    };
                    auto& q = typed[random_.below(static_cast<int>(typed.size()))];
                    attempt(std::get<0>(q), verdict(joint.bad || std::get<1>(q)), std::get<2>(q));
                    break;
                }
                auto& q = jointQueries[random_.below(static_cast<int>(jointQueries.size()))];
                attempt(q.first, verdict(joint.bad), q.second);
                break;
            }
            case 2: {
                auto& q = shapeQueries[random_.below(static_cast<int>(shapeQueries.size()))];
                attempt(q.first, verdict(shape.bad), q.second);
                break;
            }
            case 3: {
                const ShapeType type = shape.bad ? ShapeType::Circle : w.shapeType(shape.value);
                const int ask = random_.below(5);
                if (ask == 0) {
                    attempt("World::shapeCircle", verdict(shape.bad || type != ShapeType::Circle),
                            [&] { w.shapeCircle(shape.value); });
                } else if (ask == 1) {
                    attempt("World::shapeSegment", verdict(shape.bad || type != ShapeType::Segment),
                            [&] {
                                // What comes back must be accepted again as a segment.
                                const Segment g = w.shapeSegment(shape.value);
                                rayCast(g, Transform{{0.0f, 0.0f}, Rot(0.0f)}, {}, {1.0f, 1.0f});
                            });
                } else if (ask == 4) {
                    attempt("World::shapeCapsule", verdict(shape.bad || type != ShapeType::Capsule),
                            [&] {
                                // What comes back must be accepted again as a capsule.
                                computeMass(w.shapeCapsule(shape.value), 1.0f);
                            });
                } else if (ask == 3) {
                    attempt("World::shapeChainSegment",
                            verdict(shape.bad || type != ShapeType::ChainSegment), [&] {
                                // What comes back must be accepted again as a chain segment.
                                const ChainSegment g = w.shapeChainSegment(shape.value);
                                rayCast(g, Transform{{0.0f, 0.0f}, Rot(0.0f)}, {}, {1.0f, 1.0f});
                            });
                } else {
                    attempt("World::shapePolygon", verdict(shape.bad || type != ShapeType::Polygon),
                            [&] {
                                // What comes back must be accepted again as a shape's geometry.
                                Polygon p = w.shapePolygon(shape.value);
                                computeMass(p, 1.0f);
                            });
                }
                break;
            }
            case 4:
                attempt("World::bodyWorldPoint", verdict(body.bad || point.bad),
                        [&] { w.bodyWorldPoint(body.value, point.value); });
                attempt("World::bodyLocalPoint", verdict(body.bad || point.bad),
                        [&] { w.bodyLocalPoint(body.value, point.value); });
                break;
            case 5:
                attempt("World::mouseTarget", verdict(mouse.bad),
                        [&] { w.mouseTarget(mouse.value); });
                break;
            default:
                attempt("World::contacts", Verdict::Valid, [&] {
                    w.contacts();
                    w.contactBeginEvents();
                    w.contactEndEvents();
                    w.jointLetGoEvents();
                    w.worldEdgeEvents();
                    w.discardedBodies();
                    w.lastStepStats();
                    w.gravity();
                    w.defaultPositionSolver();
                    w.contactCorrection();
                    w.isSleepEnabled();
                });
                break;
        }
    }

    // Ray casts, box and point queries: arguments checked, every answer finite and where it
    // should be, callbacks answering anything (ignore, clip, stop, NaN) and now and then trying
    // to change the world, which must be refused without harm.
    // Debug drawing with every option: the counts must match the world, and every number drawn
    // must be finite when the world is.
    struct CountingDraw final : DebugDraw {
        int shapes = 0, joints = 0, boxes = 0;
        bool finite = true;
        void note(Vec2 p) { finite = finite && isFinite(p); }
        void drawPolygon(const Vec2* v, int n, DebugColor) override {
            ++boxes;
            for (int i = 0; i < n; ++i) note(v[i]);
        }
        void drawSolidPolygon(const Vec2* v, int n, float, DebugColor) override {
            ++shapes;
            for (int i = 0; i < n; ++i) note(v[i]);
        }
        void drawSolidCircle(Vec2 c, float, Vec2 axis, DebugColor) override {
            ++shapes;
            note(c);
            note(axis);
        }
        void drawSolidCapsule(Vec2 a, Vec2 b, float, DebugColor) override {
            ++shapes;
            note(a);
            note(b);
        }
        void drawSegment(Vec2 a, Vec2 b, DebugColor) override {
            note(a);
            note(b);
        }
        void drawPoint(Vec2 p, float, DebugColor) override { note(p); }
        void drawJoint(JointId, JointType, Vec2 a, Vec2 b, float, DebugColor) override {
            ++joints;
            note(a);
            note(b);
        }
    };
    void debugDrawCheck() {
        CountingDraw draw;
        DebugDrawOptions all;
        all.aabbs = all.contactPoints = all.contactNormals = all.centersOfMass = true;
        world_->debugDraw(draw, all);
        int segments = 0;
        for (BodyId b : world_->bodyIds()) {
            for (ShapeId s : world_->bodyShapes(b)) {
                const ShapeType t = world_->shapeType(s);
                segments += t == ShapeType::Segment || t == ShapeType::ChainSegment;
            }
        }
        if (draw.shapes + segments != world_->shapeCount() || draw.boxes != world_->shapeCount() ||
            draw.joints != world_->jointCount()) {
            failure("debugDraw drew " + std::to_string(draw.shapes) + " shapes, " +
                    std::to_string(draw.boxes) + " boxes and " + std::to_string(draw.joints) +
                    " joints of " + std::to_string(world_->shapeCount()) + " shapes and " +
                    std::to_string(world_->jointCount()) + " joints");
        }
        if (!draw.finite && options_.requireFinite) failure("debugDraw drew a non-finite point");
    }

    // A rotation: Rot(angle) as a rule; in hostile draws now and then one that is not a unit
    // one (scaled a little or a lot, zero, not finite), which every call must refuse.
    Arg<Rot> rotation() {
        Rot q(random_.uniform(-4.0f, 4.0f));
        if (hostile_ > 0.0f && random_.chance(0.3f)) {
            switch (random_.below(4)) {
                case 0: q.s = values_->garbage(); break;
                case 1: q.s = q.c = 0.0f; break;
                case 2: {
                    const float scale = 1.0f + random_.uniform(-1e-3f, 1e-3f);
                    q.s *= scale;
                    q.c *= scale;
                    break;
                }
                default: q.c = 1e20f; break;
            }
        }
        auto plain = [](float v) { return std::isfinite(v) && std::fpclassify(v) != FP_SUBNORMAL; };
        const double error = double(q.s) * q.s + double(q.c) * q.c - 1.0;
        return {q, !plain(q.s) || !plain(q.c) || !(std::fabs(error) <= kMaxRotationError)};
    }

    void worldQueries() {
        if (random_.chance(0.1f)) {
            trace("debugDraw");
            debugDrawCheck();
            return;
        }
        World& w = *world_;
        Arg<Vec2> origin = values_->coordinate(20.0f);
        Arg<Vec2> translation = values_->magnitude2(30.0f);
        Arg<ShapeId> shape = pickShape();
        QueryFilter filter;
        if (random_.chance(0.3f)) {
            filter.categoryBits = static_cast<std::uint16_t>(random_.below(0x10000));
            filter.maskBits = static_cast<std::uint16_t>(random_.below(0x10000));
        }
        auto checkHit = [&](const RayHit& hit) {
            if (!isFinite(hit.point) || !isFinite(hit.normal) || !(hit.fraction >= 0.0f) ||
                !(hit.fraction <= 1.0f) || std::fabs(length(hit.normal) - 1.0f) > 1e-3f) {
                failure("a ray hit is not a point on the ray with a unit normal");
            }
        };
        const float answers[] = {-1.0f, 0.0f, 0.5f, 1.0f, std::numeric_limits<float>::quiet_NaN()};
        switch (random_.below(5)) {
            case 0:
                attempt("World::castRayClosest", verdict(origin.bad || translation.bad), [&] {
                    if (auto hit = w.castRayClosest(origin.value, translation.value, filter)) {
                        checkHit(*hit);
                    }
                });
                break;
            case 1: {
                const float answer = answers[random_.below(5)];
                const bool meddle = random_.chance(0.2f);
                attempt("World::castRay", verdict(origin.bad || translation.bad), [&] {
                    w.castRay(origin.value, translation.value, filter, [&](const RayHit& hit) {
                        checkHit(hit);
                        if (!w.isValid(hit.shape)) failure("castRay reported a dead shape");
                        if (meddle)
                            refused("World::step inside castRay", [&] { w.step(1.0f / 60.0f); });
                        return answer;
                    });
                });
                break;
            }
            case 2:
                attempt("World::castRayOnShape",
                        verdict(shape.bad || origin.bad || translation.bad), [&] {
                            if (auto hit = w.castRayOnShape(shape.value, origin.value,
                                                            translation.value)) {
                                checkHit(*hit);
                            }
                        });
                break;
            case 3: {
                Arg<Vec2> corner = values_->coordinate(20.0f);
                Arg<Vec2> size = values_->coordinate(5.0f);
                const AABB box{corner.value, corner.value + size.value};
                // The call sees the box, not how it was made: a bad size (a denormal, say) may
                // still give a good box.
                const bool subnormal = std::fpclassify(box.upper.x) == FP_SUBNORMAL ||
                                       std::fpclassify(box.upper.y) == FP_SUBNORMAL;
                const bool bad = corner.bad || subnormal || !isFinite(box.upper) ||
                                 std::fabs(box.upper.x) > kMaxCoordinate ||
                                 std::fabs(box.upper.y) > kMaxCoordinate ||
                                 box.lower.x > box.upper.x || box.lower.y > box.upper.y;
                const bool meddle = random_.chance(0.2f);
                attempt("World::queryAABB", verdict(bad), [&] {
                    w.queryAABB(box, filter, [&](ShapeId found) {
                        if (!w.isValid(found)) failure("queryAABB reported a dead shape");
                        if (meddle) {
                            refused("World::destroyShape inside queryAABB",
                                    [&] { w.destroyShape(found); });
                        }
                        return random_.chance(0.9f);
                    });
                });
                break;
            }
            default: {
                const bool meddle = random_.chance(0.2f);
                attempt("World::queryPoint", verdict(origin.bad), [&] {
                    w.queryPoint(origin.value, filter, [&](ShapeId found) {
                        if (!w.isValid(found)) failure("queryPoint reported a dead shape");
                        if (meddle) {
                            refused("World::destroyBody inside queryPoint",
                                    [&] { w.destroyBody(w.shapeBody(found)); });
                        }
                        return true;
                    });
                });
                {
                    Arg<float> radius = values_->radius();
                    const Arg<Rot> q = rotation();
                    const Capsule capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f};
                    attempt("World::castShapeClosest",
                            verdict(origin.bad || q.bad || translation.bad), [&] {
                                if (auto hit = w.castShapeClosest(capsule,
                                                                  Transform{origin.value, q.value},
                                                                  translation.value, filter)) {
                                    if (!isFinite(hit->point) || !(hit->fraction >= 0.0f) ||
                                        !(hit->fraction <= 1.0f)) {
                                        failure("castShapeClosest gave a hit off its path");
                                    }
                                }
                            });
                    attempt("World::queryShape", verdict(origin.bad || radius.bad || q.bad), [&] {
                        w.queryShape(Circle{{0.0f, 0.0f}, radius.value},
                                     Transform{origin.value, q.value}, filter, [&](ShapeId found) {
                                         if (!w.isValid(found)) {
                                             failure("queryShape reported a dead shape");
                                         }
                                         return true;
                                     });
                    });
                }
                if (!shape.bad) {
                    attempt("World::shapeAABB", Verdict::Valid, [&] {
                        const AABB box = w.shapeAABB(shape.value);
                        if (!isFinite(box.lower) || !isFinite(box.upper) ||
                            box.lower.x > box.upper.x || box.lower.y > box.upper.y) {
                            failure("shapeAABB gave a box that is not one");
                        }
                    });
                }
                break;
            }
        }
    }

    /// A call that must throw pivot::Error (a change made from inside a query's callback).
    template <typename F>
    void refused(const char* what, F&& f) {
        try {
            f();
        } catch (const Error&) {
            return;
        }
        failure(std::string(what) + " was not refused");
    }

    void freeFunctions() {
        if (random_.chance(0.2f)) {
            // A cloud of points, some maybe bad: the hull is refused, or is a valid shape.
            std::vector<Vec2> cloud;
            bool bad = false;
            const int n = random_.below(20);
            const float scale = random_.chance(0.1f) ? 0.002f : 2.0f;
            for (int i = 0; i < n; ++i) {
                Arg<Vec2> p = values_->coordinate(scale);
                bad = bad || p.bad;
                cloud.push_back(p.value);
            }
            attempt("Polygon::convexHull", bad ? Verdict::Bad : Verdict::Unknown, [&] {
                const Polygon hull = Polygon::convexHull(cloud.data(), n);
                computeMass(hull, 1.0f);  // what it makes, createShape takes
            });
            return;
        }
        switch (random_.below(4)) {
            case 0: {
                // Not a structured binding: C++17 lambdas cannot capture one.
                const std::pair<Polygon, Verdict> generated = polygon();
                const Polygon& p = generated.first;
                const Verdict v = generated.second;
                Arg<float> density = values_->density(true);
                attempt("computeMass", density.bad ? Verdict::Bad : v, [&] {
                    MassData m = computeMass(p, density.value);
                    if (!std::isfinite(m.mass) || !std::isfinite(m.rotationalInertia) ||
                        !isFinite(m.center)) {
                        failure("computeMass gave a non-finite result");
                    }
                });
                break;
            }
            case 1: {
                Arg<Vec2> center = values_->coordinate(1.0f);
                Arg<float> radius = values_->radius();
                Arg<float> density = values_->density(true);
                attempt("computeMass", verdict(center.bad || radius.bad || density.bad), [&] {
                    computeMass(Circle{center.value, radius.value}, density.value);
                });
                break;
            }
            case 2: {
                Arg<float> hw = values_->positive(2.0f);
                Arg<float> hh = values_->positive(2.0f);
                bool bad =
                    hw.bad || hh.bad || hw.value > kMaxCoordinate || hh.value > kMaxCoordinate;
                attempt("Polygon::box", verdict(bad), [&] { Polygon::box(hw.value, hh.value); });
                break;
            }
            default: {
                bool tooMany = random_.chance(0.5f);
                attempt("Polygon::fromPoints", verdict(tooMany), [&] {
                    if (tooMany) {
                        Polygon::fromPoints({{0, 0},
                                             {1, 0},
                                             {2, 0},
                                             {3, 0},
                                             {4, 0},
                                             {5, 0},
                                             {6, 0},
                                             {7, 0},
                                             {8, 0}});
                    } else {
                        Polygon::fromPoints({{0, 0}, {1, 0}, {0, 1}});
                    }
                });
                break;
            }
        }
    }

    // Changing calls made where the world must refuse them (world_access.h): from a step's
    // task callbacks and another thread during it (a crowd on a meddling task system), and
    // structural ones from a query's callback on this world, where a change of state works.
    void reentry() {
        if (random_.chance(0.15f)) {
            if (!crowd_) crowd_ = std::make_unique<MeddlingCrowd>();
            trace("a step of the meddling crowd");
            std::vector<std::string> failures;
            const int refused = crowd_->step(random_, random_.between(1, 3), failures);
            report_.refusedDuringSteps += refused;
            for (const std::string& f : failures) failure(f);
            return;
        }
        World& w = *world_;
        Targets targets;
        targets.body = pickBody().value;
        targets.shape = pickShape().value;
        targets.joint = pickJoint().value;
        if (random_.chance(0.2f)) targets.snapshot = w.snapshot();
        trace("structural calls inside queryAABB");
        attempt("World::queryAABB", Verdict::Valid, [&] {
            w.queryAABB({{-40.0f, -40.0f}, {40.0f, 40.0f}}, {}, [&](ShapeId found) {
                if (!w.isValid(found)) failure("queryAABB reported a dead shape");
                try {
                    makeRandomChange(w, random_, targets, true);
                    failure("a structural change inside a query's callback was not refused");
                } catch (const Error&) {
                    ++report_.refusedInQueries;
                }
                // A change of state is fine there: the shape's own friction, set again.
                if (random_.chance(0.3f)) {
                    journal_.setShapeFriction(found, w.shapeFriction(found));
                }
                return random_.chance(0.8f);
            });
        });
    }

    // The lists the API returns are copies: destroying while iterating them must be safe.
    // Snapshots: a world restored from this one's snapshot (on 1 or 2 workers, with the same
    // callbacks) hashes the same and steps the same; damaged bytes, re-sealed past the checksum
    // or not, are refused with nothing changed, or restore a world that steps.
    void snapshots() {
        const std::vector<std::uint8_t> bytes = world_->snapshot();
        WorldDef def = oneSubstepDef();
        def.workerCount = random_.chance(0.5f) ? 1 : 2;
        World copy(def);
        // Ids the copy issued before the restore, one stale and one live: neither may name
        // anything after it (another world's snapshot takes the copy to a new id).
        const BodyId stale = copy.createBody(BodyDef{});
        copy.destroyBody(stale);
        const BodyId live = copy.createBody(BodyDef{});
        trace("snapshot round trip (" + std::to_string(bytes.size()) + " bytes)");
        try {
            copy.restore(bytes);
        } catch (const Error& e) {
            failure(std::string("World::restore refused a snapshot: ") + e.what());
            return;
        }
        ++report_.snapshots;
        if (copy.stateHash() != world_->stateHash()) failure("a restored world hashes differently");
        ++report_.staleIdsChecked;
        if (copy.isValid(stale) || copy.isValid(live)) {
            failure("an id a world issued before restoring another's snapshot names a body");
        }
        for (BodyId id : world_->bodyIds()) {
            if (copy.isValid(id)) failure("an id of the snapshotted world is valid in its copy");
        }
        for (BodyId id : copy.bodyIds()) {
            if (!copy.isValid(id)) failure("a restored world lists an id it refuses");
        }
        installFuzzCallbacks(copy, preSolveInstalled_, filterInstalled_);
        if (random_.chance(0.5f)) {
            trace("step both");
            if (attempt("World::step", Verdict::Valid,
                        [&] { journal_.step(1.0f / 60.0f, 8, 3); })) {
                copy.step(1.0f / 60.0f, 8, 3);
                if (copy.stateHash() != world_->stateHash()) {
                    failure("a restored world stepped differently from its original");
                }
            }
        } else if (world_->bodyCount() < kMaxBodies) {
            // Worlds that hash alike go on alike: the same calls make the same ids, and the
            // same steps the same states.
            trace("the same body made in both, then steps");
            BodyDef body;
            body.type = BodyType::Dynamic;
            body.position = {random_.uniform(-10.0f, 10.0f), random_.uniform(0.0f, 10.0f)};
            const BodyId mine = journal_.createBody(body);
            noteTag(mine);
            bodies_.remember(mine);
            const BodyId theirs = copy.createBody(body);
            journal_.createShape(mine, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.3f});
            copy.createShape(theirs, ShapeDef{}, Circle{{0.0f, 0.0f}, 0.3f});
            if (mine.index != theirs.index || mine.generation != theirs.generation) {
                failure("two worlds that hashed alike gave a new body different ids");
            }
            for (int i = 0; i < 3; ++i) {
                if (!attempt("World::step", Verdict::Valid,
                             [&] { journal_.step(1.0f / 60.0f, 8, 3); })) {
                    break;
                }
                copy.step(1.0f / 60.0f, 8, 3);
                if (copy.stateHash() != world_->stateHash()) {
                    failure("two worlds that hashed alike stepped apart");
                    break;
                }
            }
            ++report_.equalFuturesChecked;
        }

        std::vector<std::uint8_t> bad = bytes;
        const int damage = random_.between(1, 4);
        for (int i = 0; i < damage && !bad.empty(); ++i) {
            const auto at = static_cast<std::size_t>(random_.below(static_cast<int>(bad.size())));
            switch (random_.below(7)) {
                case 0:
                    bad[at] = static_cast<std::uint8_t>(bad[at] ^ (1u << random_.below(8)));
                    break;
                case 1: bad[at] = static_cast<std::uint8_t>(random_.below(256)); break;
                case 2: bad.resize(at); break;
                case 3: bad.insert(bad.begin() + static_cast<std::ptrdiff_t>(at), bad[at]); break;
                case 4:
                    // A setting (the state's first 59 bytes): any 32 bits in one of its fields.
                    if (bad.size() > kSnapshotState + 64) {
                        // Drawn one after the other: the order of a call's arguments is the
                        // compiler's, and the run must be the same under g++ and clang.
                        const std::size_t field = 4 * std::size_t(random_.below(15));
                        const auto bits = static_cast<std::int32_t>(random_.next());
                        putInt(bad, kSnapshotState + field, bits);
                    }
                    break;
                default:
                    // A cross-reference or a count: a small number (an index, a list key, a
                    // count) made another small one, or a huge one.
                    for (std::size_t k = at; k + 4 <= bad.size(); ++k) {
                        const std::int32_t v = getInt(bad, k);
                        if (v < -1 || v > 64) continue;
                        putInt(bad, k,
                               random_.chance(0.7f) ? random_.between(-1, 64)
                                                    : random_.between(1000, 1 << 30));
                        break;
                    }
                    break;
            }
        }
        if (bad.size() > 28 && random_.chance(0.7f)) resealSnapshot(bad);
        World scratch(def);
        const std::uint64_t empty = scratch.stateHash();
        try {
            scratch.restore(bad);
            ++report_.damagedSnapshotsRestored;
            for (int i = 0; i < 3; ++i) scratch.step(1.0f / 60.0f);
        } catch (const Error& e) {
            trace(std::string("  damaged snapshot refused: ") + e.what());
            ++report_.damagedSnapshotsRefused;
            if (scratch.stateHash() != empty) failure("a refused snapshot changed the world");
        }
    }

    // docs/snapshots.md: a 20-byte header, the 4-byte lineage, then the state.
    static constexpr std::size_t kSnapshotState = 24;
    static std::int32_t getInt(const std::vector<std::uint8_t>& bytes, std::size_t at) {
        std::uint32_t u = 0;
        for (int i = 0; i < 4; ++i) u |= std::uint32_t(bytes[at + std::size_t(i)]) << (8 * i);
        return static_cast<std::int32_t>(u);
    }
    static void putInt(std::vector<std::uint8_t>& bytes, std::size_t at, std::int32_t value) {
        const auto u = static_cast<std::uint32_t>(value);
        for (int i = 0; i < 4; ++i) bytes[at + std::size_t(i)] = std::uint8_t(u >> (8 * i));
    }

    // The checksum of docs/snapshots.md over a changed payload (header 20 bytes, checksum 8).
    static void resealSnapshot(std::vector<std::uint8_t>& bytes) {
        std::uint64_t h = 0xcbf29ce484222325ull;
        for (std::size_t i = 20; i + 8 < bytes.size(); ++i) {
            h ^= bytes[i];
            h *= 0x100000001b3ull;
        }
        for (int i = 0; i < 8; ++i) {
            bytes[bytes.size() - 8 + static_cast<std::size_t>(i)] =
                static_cast<std::uint8_t>(h >> (8 * i));
        }
    }

    void destroyWhileIterating() {
        switch (random_.below(4)) {
            case 0:
                trace("destroy bodies while iterating bodyIds");
                for (BodyId b : world_->bodyIds()) {
                    if (random_.chance(0.3f)) {
                        attempt("World::destroyBody", verdict(!world_->isValid(b)),
                                [&] { journal_.destroyBody(b); });
                    }
                }
                break;
            case 1:
                trace("destroy bodies while iterating contacts");
                for (const ContactData& c : world_->contacts()) {
                    if (!random_.chance(0.3f)) continue;
                    if (!world_->isValid(c.shapeA)) {
                        // An earlier destruction took this shape: its id is stale.
                        attempt("World::shapeBody", Verdict::Bad,
                                [&] { world_->shapeBody(c.shapeA); });
                        continue;
                    }
                    BodyId b = world_->shapeBody(c.shapeA);
                    attempt("World::destroyBody", Verdict::Valid, [&] { journal_.destroyBody(b); });
                }
                break;
            case 2:
                trace("destroy joints while iterating jointIds");
                for (JointId j : world_->jointIds()) {
                    if (!random_.chance(0.3f)) continue;
                    if (!world_->isValid(j)) {
                        // Its body went with an earlier destruction.
                        attempt("World::destroyJoint", Verdict::Bad,
                                [&] { journal_.destroyJoint(j); });
                        continue;
                    }
                    BodyId a = world_->jointBodyA(j);
                    attempt("World::destroyJoint", carriesGear(j) ? Verdict::Bad : Verdict::Valid,
                            [&] { journal_.destroyJoint(j); });
                    if (random_.chance(0.2f)) {
                        attempt("World::destroyBody", Verdict::Valid,
                                [&] { journal_.destroyBody(a); });
                    }
                }
                break;
            default:
                trace("destroy shapes while iterating events");
                for (const ContactEvent& e : world_->contactBeginEvents()) {
                    if (!random_.chance(0.5f)) continue;
                    attempt("World::destroyShape",
                            afterMassChange(e.shapeB, verdict(!world_->isValid(e.shapeB))),
                            [&] { journal_.destroyShape(e.shapeB); });
                }
                break;
        }
        checkInvariants("destroying while iterating");
    }

    void dump() const {
        const World& w = *world_;
        std::printf("world before operation %ld: gravity %s, %s contacts, sleep %d\n", operation_,
                    text(w.gravity()).c_str(),
                    w.contactCorrection() == ContactCorrection::NGS ? "NGS" : "Baumgarte",
                    int(w.isSleepEnabled()));
        for (BodyId b : w.bodyIds()) {
            std::printf("body %s type %d p %s a %s v %s w %s mass %s I %s awake %d\n",
                        idText(b).c_str(), int(w.bodyType(b)), text(w.bodyPosition(b)).c_str(),
                        text(w.bodyAngle(b)).c_str(), text(w.bodyLinearVelocity(b)).c_str(),
                        text(w.bodyAngularVelocity(b)).c_str(), text(w.bodyMass(b)).c_str(),
                        text(w.bodyRotationalInertia(b)).c_str(), int(w.isBodyAwake(b)));
            for (ShapeId s : w.bodyShapes(b)) {
                std::string geometry;
                if (w.shapeType(s) == ShapeType::Circle) {
                    Circle c = w.shapeCircle(s);
                    geometry = "circle " + text(c.center) + " r " + text(c.radius);
                } else {
                    Polygon p = w.shapePolygon(s);
                    geometry = "polygon";
                    for (int i = 0; i < p.count; ++i) geometry += " " + text(p.vertices[i]);
                }
                std::printf("  shape %s density %s %s\n", idText(s).c_str(),
                            text(w.shapeDensity(s)).c_str(), geometry.c_str());
            }
        }
        for (JointId j : w.jointIds()) {
            std::printf("joint %s %s %s-%s anchors %s %s solver %d bias %s", idText(j).c_str(),
                        jointTypeName(w.jointType(j)), idText(w.jointBodyA(j)).c_str(),
                        idText(w.jointBodyB(j)).c_str(), text(w.jointAnchorA(j)).c_str(),
                        text(w.jointAnchorB(j)).c_str(), int(w.jointPositionSolver(j)),
                        text(w.jointBiasFactor(j)).c_str());
            // The limit and motor calls are the revolute joint's.
            if (w.jointType(j) == JointType::Revolute) {
                JointLimit l = w.jointLimit(j);
                JointMotor m = w.jointMotor(j);
                std::printf(" limit %d %s %s motor %d %s %s", int(l.enabled), text(l.lower).c_str(),
                            text(l.upper).c_str(), int(m.enabled), text(m.speed).c_str(),
                            text(m.maxTorque).c_str());
            }
            std::printf("\n");
        }
        for (const LiveMouse& m : liveMice_) {
            if (w.isValid(m.id)) {
                std::printf("mouse %s on %s target %s\n", idText(m.id).c_str(),
                            idText(m.body).c_str(), text(w.mouseTarget(m.id)).c_str());
            }
        }
    }

    // --- invariants -----------------------------------------------------------------------------

    // What the step just reported: hits faster than the threshold with finite points and unit
    // normals between live shapes, and moved bodies where they now are.
    void checkStepEvents() {
        const World& w = *world_;
        for (const ContactHitEvent& e : w.contactHitEvents()) {
            if (!w.isValid(e.shapeA) || !w.isValid(e.shapeB) ||
                !(e.approachSpeed > w.hitEventThreshold()) || !isFinite(e.point) ||
                !(std::fabs(length(e.normal) - 1.0f) < 1e-3f)) {
                failure("a hit event is wrong: speed " + text(e.approachSpeed) + " point " +
                        text(e.point) + " normal " + text(e.normal));
            }
        }
        for (const BodyMoveEvent& e : w.bodyMoveEvents()) {
            if (!w.isValid(e.body)) failure("a move event names a body that is gone");
            const Transform xf = w.bodyTransform(e.body);
            if (!(xf.p == e.transform.p) || w.bodyType(e.body) == BodyType::Static ||
                e.fellAsleep == w.isBodyAwake(e.body)) {
                failure("a move event of body " + idText(e.body) + " is not what the body is");
            }
        }
    }

    void checkInvariants(const char* after) {
        const World& w = *world_;
        const std::string where = std::string(" after ") + after;
        if (w.stateHash() != w.stateHash()) failure("stateHash is not a function of the state");
        std::vector<BodyId> bodies = w.bodyIds();
        if (static_cast<int>(bodies.size()) != w.bodyCount()) {
            failure("bodyIds has " + std::to_string(bodies.size()) + " ids, bodyCount is " +
                    std::to_string(w.bodyCount()) + where);
        }
        report_.maxBodies = std::max<long>(report_.maxBodies, w.bodyCount());
        int shapes = 0;
        for (BodyId b : bodies) {
            if (!w.isValid(b)) failure("bodyIds lists an invalid id" + where);
            for (ShapeId s : w.bodyShapes(b)) {
                ++shapes;
                if (!w.isValid(s) || w.shapeBody(s) != b) {
                    failure("a body lists a shape that is not its own" + where);
                }
            }
            Vec2 p = w.bodyPosition(b), v = w.bodyLinearVelocity(b), c = w.bodyWorldCenter(b);
            float a = w.bodyAngle(b), omega = w.bodyAngularVelocity(b);
            if (!isFinite(p) || !isFinite(v) || !isFinite(c) || !std::isfinite(a) ||
                !std::isfinite(omega)) {
                nonFinite("body " + idText(b) + " is not finite: p=" + text(p) + " v=" + text(v) +
                          " a=" + text(a) + " w=" + text(omega) + where);
                continue;
            }
            float mass = w.bodyMass(b);
            bool dynamic = w.bodyType(b) == BodyType::Dynamic;
            if (dynamic ? !(mass > 0.0f && std::isfinite(mass)) : mass != 0.0f) {
                failure("body " + idText(b) + " has mass " + text(mass) + where);
            }
            if (w.bodyType(b) == BodyType::Static && (v != Vec2{} || omega != 0.0f)) {
                failure("static body " + idText(b) + " moves" + where);
            }
            // Whatever the engine did, the state is one the API would take back.
            if (std::fabs(p.x) > kMaxCoordinate || std::fabs(p.y) > kMaxCoordinate ||
                std::fabs(v.x) > kMaxSpeed || std::fabs(v.y) > kMaxSpeed ||
                std::fabs(omega) > kMaxAngularSpeed || std::fabs(a) > kMaxMagnitude) {
                failure("body " + idText(b) + " is beyond the input limits: p=" + text(p) +
                        " v=" + text(v) + " a=" + text(a) + " w=" + text(omega) + where);
            }
        }
        if (shapes != w.shapeCount()) {
            failure("bodies list " + std::to_string(shapes) + " shapes, shapeCount is " +
                    std::to_string(w.shapeCount()) + where);
        }
        std::vector<JointId> joints = w.jointIds();
        if (static_cast<int>(joints.size()) != w.jointCount()) {
            failure("jointIds does not match jointCount" + where);
        }
        for (JointId j : joints) {
            if (!w.isValid(j) || !w.isValid(w.jointBodyA(j)) || !w.isValid(w.jointBodyB(j)) ||
                w.jointBodyA(j) == w.jointBodyB(j)) {
                failure("joint " + idText(j) + " has invalid bodies" + where);
            }
            Vec2 force = w.jointReactionForce(j);
            float torque = w.jointReactionTorque(j);
            if (!isFinite(force) || !std::isfinite(torque) ||
                !std::isfinite(w.jointSeparation(j))) {
                nonFinite("joint " + idText(j) + " is not finite: force=" + text(force) + where);
            }
        }
        std::vector<ContactData> contacts = w.contacts();
        report_.maxContacts =
            std::max<long>(report_.maxContacts, static_cast<long>(contacts.size()));
        for (const ContactData& c : contacts) {
            if (!w.isValid(c.shapeA) || !w.isValid(c.shapeB)) {
                failure("a contact names an invalid shape" + where);
                continue;
            }
            if (w.shapeBody(c.shapeA) == w.shapeBody(c.shapeB)) {
                failure("a contact between two shapes of one body" + where);
            }
            if (c.pointCount < 1 || c.pointCount > 2) {
                failure("a touching contact with " + std::to_string(c.pointCount) + " points" +
                        where);
            }
            if (!isFinite(c.normal)) nonFinite("a contact normal is not finite" + where);
            for (int i = 0; i < c.pointCount && i < 2; ++i) {
                if (!isFinite(c.points[i].point) || !std::isfinite(c.points[i].separation) ||
                    !std::isfinite(c.points[i].normalImpulse)) {
                    nonFinite("a contact point is not finite" + where);
                }
            }
        }
        if (std::string(after) == "a step") {
            // Only right after a step: destroying bodies since leaves the statistics of a
            // larger world.
            const StepStats& stats = w.lastStepStats();
            if (stats.touchingCount > stats.contactCount ||
                stats.sleepingBodyCount > w.bodyCount() || stats.islandCount < 0 ||
                stats.positionIterations < 0) {
                failure("the step statistics do not add up" + where);
            }
            for (const auto& events : {w.contactBeginEvents(), w.contactEndEvents()}) {
                for (const ContactEvent& e : events) {
                    if (!w.isValid(e.shapeA) || !w.isValid(e.shapeB)) {
                        failure("an event of the last step names an invalid shape" + where);
                    }
                }
            }
            const std::vector<JointLetGoEvent> letGo = w.jointLetGoEvents();
            if (static_cast<int>(letGo.size()) != stats.letGoJointCount) {
                failure("the let-go events do not match the statistics" + where);
            }
            for (const JointLetGoEvent& e : letGo) {
                if (!w.isValid(e.joint) || !w.isJointLetGo(e.joint) ||
                    !std::isfinite(e.separation)) {
                    failure("a let-go event names a joint that is not let go" + where);
                }
            }
            const std::vector<BodyId> discarded = w.discardedBodies();
            if (static_cast<int>(discarded.size()) != stats.discardedBodyCount) {
                failure("the discarded bodies do not match the statistics" + where);
            }
            for (BodyId b : discarded) {
                if (!w.isValid(b)) failure("a discarded body is not valid" + where);
            }
            const std::vector<WorldEdgeEvent> edge = w.worldEdgeEvents();
            if (static_cast<int>(edge.size()) != stats.edgeBodyCount) {
                failure("the world edge events do not match the statistics" + where);
            }
            for (const WorldEdgeEvent& e : edge) {
                if (!w.isValid(e.body)) failure("an edge event names an invalid body" + where);
            }
        }
    }

    Options options_;
    Random random_;
    Values* values_ = nullptr;
    float hostile_ = 0.0f;
    long operation_ = 0;
    bool nonFinite_ = false;  // this world has reported a non-finite number
    long nonFiniteSeen_ = 0;
    Report report_;
    std::unique_ptr<World> world_;
    bool preSolveInstalled_ = false;  // the fuzz callbacks on world_ (installFuzzCallbacks)
    bool filterInstalled_ = false;
    Journal journal_;
    std::unique_ptr<World> other_;
    std::unique_ptr<MeddlingCrowd> crowd_;  // made at the first reentry that needs it
    std::uint32_t tag_ = 0;                 // the world field of this world's ids
    BodyId otherBody_;
    ShapeId otherShape_;
    JointId otherJoint_;
    MouseJointId otherMouse_;
    IdMemory<BodyId> bodies_;
    IdMemory<ShapeId> shapes_;
    IdMemory<JointId> joints_;
    IdMemory<MouseJointId> mice_;
    struct LiveMouse {
        MouseJointId id;
        BodyId body;
    };
    std::vector<LiveMouse> liveMice_;  // the mouse joints made, and their bodies
    // Per body (index, generation), an upper bound on the pending force's and torque's size
    // since the last step: forces pile up until a step clears them, and a small force is
    // refused once the pile passes a limit.
    std::map<std::pair<std::int32_t, std::uint32_t>, std::pair<float, float>> pending_;
};

}  // namespace

Report run(const Options& options) {
    Driver driver(options);
    return driver.run();
}

}  // namespace pivot::fuzz
