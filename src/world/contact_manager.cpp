#include "world/contact_manager.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include "core/buffer.h"
#include "core/prefetch.h"
#include "model/body_edge.h"

namespace pivot {

bool ContactManager::bodiesMayCollide(std::int32_t a, std::int32_t b) const {
    if (bodies_[a].type != BodyType::Dynamic && bodies_[b].type != BodyType::Dynamic) return false;
    for (std::int32_t key = bodies_[b].jointList; key != -1;) {
        const Joint& joint = joints_[edgeOwner(key)];
        int side = edgeSide(key);
        if (joint.edges[1 - side].body == a && !joint.collideConnected) return false;
        key = joint.edges[side].nextKey;
    }
    return true;
}

bool ContactManager::mayPair(const Shape& a, const Shape& b) const {
    if (!a.sensor && !b.sensor) return bodiesMayCollide(a.body, b.body);
    if (a.sensor && b.sensor) return false;
    if (isSegmentLike(a.type) && isSegmentLike(b.type)) return false;  // no routine for it
    return bodies_[a.body].type != BodyType::Static || bodies_[b.body].type != BodyType::Static;
}

void ContactManager::reportTouch(const Contact& contact, bool began) {
    if (contact.sensor) {
        // A sensor pushes nothing, so its overlaps wake nothing either.
        const bool aIsSensor = shapes_[contact.shapeA].sensor;
        const SensorEvent event{shapeId(aIsSensor ? contact.shapeA : contact.shapeB),
                                shapeId(aIsSensor ? contact.shapeB : contact.shapeA)};
        (began ? sensorBeginEvents_ : sensorEndEvents_).push_back(event);
        return;
    }
    // Whatever rested on the contact, or is pushed by it now, must notice; and the contact
    // joins or leaves the islands.
    islandRevision_.bump();
    touchingCount_ += began ? 1 : -1;
    wakeUp(bodies_[contact.bodyA()], islandRevision_);
    wakeUp(bodies_[contact.bodyB()], islandRevision_);
    (began ? beginEvents_ : endEvents_)
        .push_back({shapeId(contact.shapeA), shapeId(contact.shapeB)});
}

// Continuous collision measures contacts again within the step, after the step's contact update:
// one the update saw stop touching may touch again. Its end event and this begin event would
// then both be reported although it touched before and after the step, and the two lists do not
// say in which order they happened. The pair's end event is taken back instead, with the begin
// just recorded, so that a step's events are the change it made: its begin events and then its
// end events, applied to the contacts touching before it, give those touching after it. (One
// that begins and then ends within a step is in both lists, in that order.)
void ContactManager::takeBackEndOfThisStep(const Contact& contact) {
    const ShapeId a = shapeId(contact.shapeA);
    const ShapeId b = shapeId(contact.shapeB);
    if (contact.sensor) {
        const bool aIsSensor = shapes_[contact.shapeA].sensor;
        const ShapeId sensor = aIsSensor ? a : b;
        const ShapeId visitor = aIsSensor ? b : a;
        for (auto e = sensorEndEvents_.rbegin(); e != sensorEndEvents_.rend(); ++e) {
            if (e->sensor == sensor && e->visitor == visitor) {
                sensorEndEvents_.erase(std::next(e).base());
                sensorBeginEvents_.pop_back();
                return;
            }
        }
        return;
    }
    for (auto e = endEvents_.rbegin(); e != endEvents_.rend(); ++e) {
        if (e->shapeA == a && e->shapeB == b) {
            endEvents_.erase(std::next(e).base());
            beginEvents_.pop_back();
            return;
        }
    }
}

ContactData ContactManager::contactData(const Contact& c) const {
    const Shape& a = shapes_[c.shapeA];
    const Shape& b = shapes_[c.shapeB];
    const WorldManifold wm = computeWorldManifold(
        c.manifold, bodies_[a.body].xf, collisionRadius(a), bodies_[b.body].xf, collisionRadius(b));
    ContactData data;
    data.shapeA = shapeId(c.shapeA);
    data.shapeB = shapeId(c.shapeB);
    data.normal = wm.normal;
    data.pointCount = c.manifold.pointCount;
    for (int i = 0; i < data.pointCount; ++i) {
        data.points[i] = {wm.points[i], wm.separations[i], c.manifold.points[i].normalImpulse,
                          c.manifold.points[i].tangentImpulse};
    }
    return data;
}

bool ContactManager::wantsPreSolve(const Contact& c) const {
    return preSolve_ && c.touching && !c.sensor &&
           (shapes_[c.shapeA].preSolve || shapes_[c.shapeB].preSolve);
}

// The scope lets the callback read the world during the step (it may not change it); an
// exception is held rather than let through a half-done step.
bool ContactManager::askPreSolve(const Contact& contact) {
    bool keep = true;
    const WorldAccess::CallbackScope scope(access_);
    try {
        keep = preSolve_(contactData(contact));
    } catch (...) {
        if (!callbackError_) callbackError_ = std::current_exception();
    }
    return keep;
}

bool ContactManager::askCustomFilter(std::int32_t shapeA, std::int32_t shapeB) {
    if (!customFilter_) return true;
    bool allow = true;
    const WorldAccess::CallbackScope scope(access_);
    try {
        allow = customFilter_(shapeId(shapeA), shapeId(shapeB));
    } catch (...) {
        if (!callbackError_) callbackError_ = std::current_exception();
    }
    return allow;
}

bool ContactManager::solidShapesMayCollide(std::int32_t shapeA, std::int32_t shapeB) {
    const Shape& a = shapes_[shapeA];
    const Shape& b = shapes_[shapeB];
    return a.body != b.body && !a.sensor && !b.sensor && filtersAllowContact(a.filter, b.filter) &&
           bodiesMayCollide(a.body, b.body) && askCustomFilter(shapeA, shapeB);
}

void ContactManager::addPair(std::int32_t shapeA, std::int32_t shapeB) {
    const Shape& a = shapes_[shapeA];
    const Shape& b = shapes_[shapeB];
    // Cheapest rejections first: most reported pairs that make no contact are filtered out.
    if (a.body == b.body || !filtersAllowContact(a.filter, b.filter)) return;
    std::uint64_t key = PairMap::key(shapeA, shapeB);
    if (pairs_.contains(key)) return;
    if (!mayPair(a, b)) return;
    if (!askCustomFilter(shapeA, shapeB)) return;

    // The narrow phase has segment-polygon, segment-circle and polygon-circle (capsules go as
    // polygons), not the reverse: segments first, then polygons and capsules, then circles.
    auto order = [](ShapeType type) {
        return isSegmentLike(type) ? 0 : type == ShapeType::Circle ? 2 : 1;
    };
    if (order(a.type) > order(b.type)) std::swap(shapeA, shapeB);

    Contact contact;
    contact.shapeA = shapeA;
    contact.shapeB = shapeB;
    contact.edges[0].body = shapes_[shapeA].body;
    contact.edges[1].body = shapes_[shapeB].body;
    contact.friction = mixFriction(shapes_[shapeA].friction, shapes_[shapeB].friction);
    contact.restitution = mixRestitution(shapes_[shapeA].restitution, shapes_[shapeB].restitution);
    contact.radiusA = collisionRadius(shapes_[shapeA]);
    contact.radiusB = collisionRadius(shapes_[shapeB]);
    contact.serial = ++contactsMade_;
    contact.sensor = a.sensor || b.sensor;
    std::int32_t index = contacts_.insert(contact);
    linkEdges(contacts_, bodies_, &Body::contactList, index);
    pairs_.insert(key, index);
    census_.grow(contacts_.capacity());
    census_.record(index, contacts_[index]);
}

void ContactManager::destroyContact(std::int32_t index) {
    Contact& contact = contacts_[index];
    if (contact.touching) reportTouch(contact, false);
    unlinkEdges(contacts_, bodies_, &Body::contactList, index);
    pairs_.erase(PairMap::key(contact.shapeA, contact.shapeB));
    contacts_.erase(index);
    census_.forget(index);
}

// Two phases, so the narrow phase can run on every worker: first each contact decides its own
// fate from what it can read (its shapes_, bodies_ and boxes) and updates its own manifold; then,
// in contact order, the consequences that touch shared state (destruction, waking, events) are
// applied. A contact's fate never depends on another's consequences within the same step.
void ContactManager::updateContacts() {
    // A contact's fate, plus flags for the callbacks to be asked in the second phase.
    enum : std::uint8_t {
        kKeep,
        kDestroy,
        kBegan,
        kEnded,
        kFate = 3,
        kAskFilter = 4,
        kUpdated = 8,
        kWasDisabled = 16  // updated, and the last pre-solve answer had disabled it
    };
    reserveForPools();
    pool_.parallelFor(contacts_.capacity(), 1024, [&](int begin, int end, int) {
        for (std::int32_t index = begin; index < end; ++index) {
            std::uint8_t& outcome = contactOutcomes_[index];
            outcome = kKeep;
            // The census first: a contact whose bodies both sleep (or are static), with no
            // filter to check, is not loaded at all.
            const ContactSummary& summary = census_[index];
            if (!summary.alive()) continue;
            const Body& bodyA = bodies_[summary.bodies[0]];
            const Body& bodyB = bodies_[summary.bodies[1]];
            const bool activeA = bodyA.awake && bodyA.type != BodyType::Static;
            const bool activeB = bodyB.awake && bodyB.type != BodyType::Static;
            if (!activeA && !activeB && !summary.needsFiltering()) continue;
            Contact& contact = contacts_[index];
            if (contact.needsFiltering) {
                const Shape& shapeA = shapes_[contact.shapeA];
                const Shape& shapeB = shapes_[contact.shapeB];
                if (!mayPair(shapeA, shapeB) ||
                    !filtersAllowContact(shapeA.filter, shapeB.filter)) {
                    outcome = kDestroy;
                    continue;
                }
                contact.needsFiltering = false;
                census_.record(index, contact);
                if (customFilter_) outcome = kAskFilter;
            }
            if (!activeA && !activeB) continue;  // both asleep (or static): nothing changed
            // The shapes only now: a shape spans several cache lines, and a contact whose bodies
            // sleep needs neither.
            const Shape& shapeA = shapes_[contact.shapeA];
            const Shape& shapeB = shapes_[contact.shapeB];
            if (!broadPhase_.testOverlap(shapeA.proxyId, shapeB.proxyId)) {
                outcome = kDestroy;
                continue;
            }
            bool wasTouching = contact.touching;
            bool touching = updateContact(contact, shapeA, bodyA.xf, shapeB, bodyB.xf);
            if (!contact.enabled) outcome |= kWasDisabled;
            contact.enabled = true;  // until the pre-solve callback says otherwise
            census_.record(index, contact);
            outcome |= kUpdated;
            if (touching != wasTouching) outcome |= touching ? kBegan : kEnded;
        }
    });
    // Without a pre-solve callback only a fate, a filter question or a contact enabled again
    // (the callback was taken away) needs this loop.
    const std::uint8_t interesting =
        preSolve_ ? 0xFF : std::uint8_t(kFate | kAskFilter | kWasDisabled);
    for (std::int32_t index = 0; index < contacts_.capacity(); ++index) {
        const std::uint8_t outcome = contactOutcomes_[index];
        if ((outcome & interesting) == 0) continue;
        Contact& contact = contacts_[index];
        const std::uint8_t fate = outcome & kFate;
        if (fate == kDestroy) {
            destroyContact(index);
            continue;
        }
        if ((outcome & kAskFilter) && !askCustomFilter(contact.shapeA, contact.shapeB)) {
            // Refused before its begin was told: it goes without an end either; an end this
            // update found is told.
            if (fate == kBegan) contact.touching = false;
            if (fate == kEnded) reportTouch(contact, false);
            destroyContact(index);
            continue;
        }
        if (fate == kBegan || fate == kEnded) reportTouch(contact, fate == kBegan);
        // Asked only about contacts this update recomputed (a sleeping pair keeps its answer).
        if ((outcome & kUpdated) && wantsPreSolve(contact)) {
            contact.enabled = askPreSolve(contact);
            census_.record(index, contact);
        }
        const bool wasEnabled = (outcome & kWasDisabled) == 0;
        if ((outcome & kUpdated) && contact.enabled != wasEnabled) islandRevision_.bump();
    }
}

bool ContactManager::updateContactNow(std::int32_t index) {
    Contact& contact = contacts_[index];
    const bool wasTouching = contact.touching;
    const bool touching =
        updateContact(contact, shapes_[contact.shapeA], bodies_[contact.bodyA()].xf,
                      shapes_[contact.shapeB], bodies_[contact.bodyB()].xf);
    if (touching != wasTouching) {
        reportTouch(contact, touching);
        if (touching) takeBackEndOfThisStep(contact);
    }
    const bool wasEnabled = contact.enabled;
    contact.enabled = true;
    if (wantsPreSolve(contact)) contact.enabled = askPreSolve(contact);
    census_.record(index, contact);
    if (contact.enabled != wasEnabled) islandRevision_.bump();
    return touching && contact.enabled;
}

namespace {
std::atomic<bool> censusChecks{false};
}  // namespace

void ContactManager::setCensusChecks(bool on) {
    censusChecks = on;
}

void ContactManager::checkCensus(const char* when) const {
    if (!censusChecks.load(std::memory_order_relaxed)) return;
    if (!census_.matches(contacts_)) {
        throw std::logic_error(std::string("pivot2d: the contact census is out of date ") + when);
    }
    int movingStoppers = 0;
    shapes_.forEach([&](std::int32_t, const Shape& s) {
        if (movesAndStopsTunnelling(bodies_[s.body])) ++movingStoppers;
    });
    if (movingStoppers != movingStopperShapes_) {
        throw std::logic_error(
            std::string("pivot2d: the count of kinematic and bullet shapes is out of date ") +
            when);
    }
}

void ContactManager::update() {
    checkCensus("before the contact update");
    beginEvents_.clear();
    endEvents_.clear();
    sensorBeginEvents_.clear();
    sensorEndEvents_.clear();
    if (newShapes_) {
        findNewContacts();
        newShapes_ = false;
    }
    updateContacts();
}

void ContactManager::afterSolve(const std::vector<std::int32_t>& solvedBodies, bool continuous) {
    checkCensus("after the solve");
    // Every non-static body solved this step moved: sweep its broad-phase boxes.
    synchronizeSolvedBodies(solvedBodies, continuous);
    findNewContacts();
}

void ContactManager::countCategories(const Filter& filter, int delta) {
    for (int bit = 0; bit < 16; ++bit) {
        if (filter.categoryBits & (1u << bit)) categoryCounts_[bit] += delta;
    }
}

std::uint16_t ContactManager::presentCategories() const {
    std::uint16_t present = 0;
    for (int bit = 0; bit < 16; ++bit) {
        if (categoryCounts_[bit] > 0) present = static_cast<std::uint16_t>(present | (1u << bit));
    }
    return present;
}

void ContactManager::findNewContacts() {
    // addPair's read-only tests run inside the (parallel) queries, the pair map's and the
    // joints' included (nothing writes them until addPair): most pairs a moved box reports have
    // their contact already, or are bodies a joint keeps apart (every link of a chain finds its
    // two neighbours at every query), and dropping them here spares the merge, the sort and
    // addPair. Only the custom filter, the user's code, waits for addPair. The new pairs keep
    // their order, so contacts are made as before.
    auto worthPairing = [this](std::int32_t a, std::int32_t b) {
        const Shape& shapeA = shapes_[a];
        const Shape& shapeB = shapes_[b];
        return shapeA.body != shapeB.body && filtersAllowContact(shapeA.filter, shapeB.filter) &&
               !pairs_.contains(PairMap::key(a, b)) && mayPair(shapeA, shapeB);
    };
    // A sweep is kept for continuous collision, which takes back a body that passed through
    // static, kinematic or bullet bodies (a bullet through any).
    auto mayImpact = [this](std::int32_t a, std::int32_t b) {
        const Body& bodyA = bodies_[shapes_[a].body];
        const Body& bodyB = bodies_[shapes_[b].body];
        return (stopsTunnelling(bodyA) || stopsTunnelling(bodyB)) && !optedOutOfContinuous(bodyA) &&
               !optedOutOfContinuous(bodyB);
    };
    const std::uint16_t present = presentCategories();
    auto mayMeetAnything = [this, present](std::int32_t s) {
        const Filter& filter = shapes_[s].filter;
        return filter.groupIndex > 0 || (filter.maskBits & present) != 0;
    };
    broadPhase_.updatePairs(pool_, mayMeetAnything, worthPairing, mayImpact,
                            [this](std::int32_t a, std::int32_t b) { addPair(a, b); });
}

void ContactManager::synchronizeShapes(std::int32_t bodyIndex, bool swept) {
    const Body& body = bodies_[bodyIndex];
    for (std::int32_t s = body.shapeList; s != -1; s = shapes_[s].next) {
        Shape& shape = shapes_[s];
        // The box kept from the last sync is the box at the start of this step's motion.
        const AABB after = computeShapeBox(shape, body.xf);
        const AABB before = swept ? shape.box : after;
        shape.box = after;
        broadPhase_.moveProxy(shape.proxyId, before, after);
    }
}

void ContactManager::synchronizeShapesFrom(std::int32_t bodyIndex, const Transform& from) {
    const Body& body = bodies_[bodyIndex];
    const SweepReach reach = sweepReach(body, true);
    for (std::int32_t s = body.shapeList; s != -1; s = shapes_[s].next) {
        Shape& shape = shapes_[s];
        const AABB before = computeShapeBox(shape, from);
        shape.box = computeShapeBox(shape, body.xf);
        broadPhase_.moveProxy(shape.proxyId, before, shape.box, reach);
    }
}

SweepReach ContactManager::sweepReach(const Body& body, bool continuous) const {
    if (!continuous || optedOutOfContinuous(body)) return SweepReach::None;
    // An ordinary dynamic body is stopped by static, kinematic and bullet bodies, the last two
    // in the moving tree, where its sweep would meet mostly bodies it could never be stopped by.
    if (!stopsTunnelling(body) && movingStopperShapes_ == 0) return SweepReach::StaticTree;
    return SweepReach::EveryTree;
}

void ContactManager::synchronizeSolvedBodies(const std::vector<std::int32_t>& solvedBodies,
                                             bool continuous) {
    resizeBuffer(shapeMoves_, static_cast<std::size_t>(shapes_.capacity()));
    const int count = static_cast<int>(solvedBodies.size());
    // By position in the list, which may hold a static body once per island it touches.
    resizeBuffer(bodyMoves_, static_cast<std::size_t>(std::max(count, bodies_.capacity())));
    // The bodies come in island order, scattered over the pools, and each is a cache miss, and
    // so are its first shape and that shape's node in the tree: all three are asked for ahead,
    // each when what leads to it has arrived.
    constexpr int kBodyAhead = 12;
    constexpr int kShapeAhead = 6;
    constexpr int kNodeAhead = 3;
    // A box costs about a tenth of a microsecond, a hand-off to the workers tens: share out
    // only big batches.
    pool_.parallelFor(count, 1024, [&](int begin, int end, int) {
        for (int i = begin; i < end; ++i) {
            if (i + kBodyAhead < end)
                prefetch(&bodies_[solvedBodies[i + kBodyAhead]], sizeof(Body));
            if (i + kShapeAhead < end) {
                const std::int32_t s = bodies_[solvedBodies[i + kShapeAhead]].shapeList;
                if (s != -1) prefetch(&shapes_[s], sizeof(Shape));
            }
            if (i + kNodeAhead < end) {
                const std::int32_t s = bodies_[solvedBodies[i + kNodeAhead]].shapeList;
                if (s != -1) prefetch(&broadPhase_.fatBox(shapes_[s].proxyId));
            }
            const Body& body = bodies_[solvedBodies[i]];
            bool moved = false;
            if (body.type != BodyType::Static) {
                const SweepReach reach = sweepReach(body, continuous);
                for (std::int32_t s = body.shapeList; s != -1; s = shapes_[s].next) {
                    Shape& shape = shapes_[s];
                    const AABB after = computeShapeBox(shape, body.xf);
                    ShapeMove& move = shapeMoves_[s];
                    move.from = shape.box;
                    move.needed = broadPhase_.needsMove(shape.proxyId, shape.box, after, reach);
                    move.reach = reach;
                    shape.box = after;
                    moved = moved || move.needed;
                }
            }
            bodyMoves_[static_cast<std::size_t>(i)] = moved;
        }
    });
    // New boxes change the tree: one at a time, in a fixed order. Most bodies' boxes stay
    // inside their fattened ones, and their bodies are not read again.
    for (int i = 0; i < count; ++i) {
        if (!bodyMoves_[static_cast<std::size_t>(i)]) continue;
        const Body& body = bodies_[solvedBodies[i]];
        for (std::int32_t s = body.shapeList; s != -1; s = shapes_[s].next) {
            const ShapeMove& move = shapeMoves_[s];
            if (move.needed) {
                broadPhase_.moveProxy(shapes_[s].proxyId, move.from, shapes_[s].box, move.reach);
            }
        }
    }
}

void ContactManager::refilterBodyPair(std::int32_t a, std::int32_t b) {
    for (std::int32_t key = bodies_[b].contactList; key != -1;) {
        const Contact& contact = contacts_[edgeOwner(key)];
        int side = edgeSide(key);
        if (contact.edges[1 - side].body == a) refilterContact(edgeOwner(key));
        key = contact.edges[side].nextKey;
    }
    for (std::int32_t body : {a, b}) {
        for (std::int32_t s = bodies_[body].shapeList; s != -1; s = shapes_[s].next) {
            broadPhase_.touchProxy(shapes_[s].proxyId);
        }
    }
    newShapes_ = true;
}

void ContactManager::refilterContact(std::int32_t contactIndex) {
    Contact& contact = contacts_[contactIndex];
    contact.needsFiltering = true;
    census_.record(contactIndex, contact);
}

void ContactManager::refilterBody(std::int32_t bodyIndex) {
    Body& body = bodies_[bodyIndex];
    for (std::int32_t key = body.contactList; key != -1;) {
        const Contact& contact = contacts_[edgeOwner(key)];
        int side = edgeSide(key);
        refilterContact(edgeOwner(key));
        wakeUp(bodies_[contact.edges[1 - side].body], islandRevision_);
        key = contact.edges[side].nextKey;
    }
    for (std::int32_t key = body.jointList; key != -1;) {
        const Joint& joint = joints_[edgeOwner(key)];
        int side = edgeSide(key);
        wakeUp(bodies_[joint.edges[1 - side].body], islandRevision_);
        key = joint.edges[side].nextKey;
    }
    for (std::int32_t s = body.shapeList; s != -1; s = shapes_[s].next) {
        broadPhase_.touchProxy(shapes_[s].proxyId);
    }
    newShapes_ = true;
}

void ContactManager::reserveForPools() {
    resizeBuffer(contactOutcomes_, static_cast<std::size_t>(contacts_.capacity()));
    // A contact begins or ends once in the narrow phase and seldom more than once in continuous
    // collision's impacts: room for twice every one, so that a step with more events than any
    // before does not allocate (only a contact pool that has doubled does).
    const auto contactSlots = static_cast<std::size_t>(contacts_.capacity());
    reserveBuffer(beginEvents_, 2 * contactSlots);
    reserveBuffer(endEvents_, 2 * contactSlots);
    reserveBuffer(sensorBeginEvents_, contactSlots);
    reserveBuffer(sensorEndEvents_, contactSlots);
}

void ContactManager::saveState(SnapshotWriter& out) const {
    broadPhase_.save(out);
    out.value(newShapes_);
    out.value(contactsMade_);
    for (const auto* list : {&beginEvents_, &endEvents_}) {
        out.sequence(*list, [&](const ContactEvent& e) {
            snapshotHandle(out, e.shapeA, worldId_);
            snapshotHandle(out, e.shapeB, worldId_);
        });
    }
    for (const auto* list : {&sensorBeginEvents_, &sensorEndEvents_}) {
        out.sequence(*list, [&](const SensorEvent& e) {
            snapshotHandle(out, e.sensor, worldId_);
            snapshotHandle(out, e.visitor, worldId_);
        });
    }
}

ContactManager::State ContactManager::loadState(SnapshotReader& in, std::uint32_t worldId) {
    State state;
    state.broadPhase.load(in);
    in.value(state.newShapes);
    in.value(state.contactsMade);
    for (auto* list : {&state.beginEvents, &state.endEvents}) {
        in.sequence(*list, [&](ContactEvent& e) {
            snapshotHandle(in, e.shapeA, worldId);
            snapshotHandle(in, e.shapeB, worldId);
        });
    }
    for (auto* list : {&state.sensorBeginEvents, &state.sensorEndEvents}) {
        in.sequence(*list, [&](SensorEvent& e) {
            snapshotHandle(in, e.sensor, worldId);
            snapshotHandle(in, e.visitor, worldId);
        });
    }
    return state;
}

void ContactManager::adoptState(const State& state) {
    // Copied into this manager's storage, which keeps its capacity, rather than moved: a
    // rollback's steps then find their buffers as warm as before (reserveForPools).
    broadPhase_.adopt(state.broadPhase);
    newShapes_ = state.newShapes;
    contactsMade_ = state.contactsMade;
    beginEvents_ = state.beginEvents;
    endEvents_ = state.endEvents;
    sensorBeginEvents_ = state.sensorBeginEvents;
    sensorEndEvents_ = state.sensorEndEvents;
    pairs_.clear();
    touchingCount_ = 0;
    contacts_.forEach([&](std::int32_t index, const Contact& c) {
        pairs_.insert(PairMap::key(c.shapeA, c.shapeB), index);
        if (c.touching && !c.sensor) ++touchingCount_;
    });
    census_.rebuild(contacts_);
    categoryCounts_ = {};
    movingStopperShapes_ = 0;
    shapes_.forEach([&](std::int32_t, const Shape& s) {
        countCategories(s.filter, +1);
        if (movesAndStopsTunnelling(bodies_[s.body])) ++movingStopperShapes_;
    });
    reserveForPools();
}

}  // namespace pivot
