#include "world/continuous_solver.h"

#include <algorithm>
#include <limits>

#include "collision/time_of_impact.h"
#include "core/buffer.h"
#include "model/body_edge.h"

namespace pivot {

namespace {

// Box2D 2.4.1's limits and gains for impacts (b2_maxSubSteps, b2_maxTOIContacts,
// b2_toiBaumgarte and the position iterations of b2World::SolveTOI).
constexpr int kMaxImpactsPerContact = 8;
constexpr std::size_t kMaxIslandContacts = 32;
constexpr std::size_t kMaxIslandBodies = 2 * kMaxIslandContacts;
constexpr float kImpactBias = 0.75f;
constexpr int kImpactPositionIterations = 20;
// The position sweeps stop once no point is deeper than this: they only push to -kLinearSlop,
// so a stricter bound could never be met.
constexpr float kImpactTolerance = -1.5f * kLinearSlop;
// An impact this close to the end of the step is left to the next step.
constexpr float kLatestImpact = 1.0f - 10.0f * std::numeric_limits<float>::epsilon();

// Moves the start of the body's sweep to `alpha` of the step; the body stays where it is.
void advanceSweep(Body& b, float alpha) {
    Sweep s = sweepOf(b);
    s.advance(alpha);
    b.center0 = s.c0;
    b.angle0 = s.a0;
    b.alpha0 = s.alpha0;
}

// Puts the body at `alpha` of the step, with nothing of its motion left behind it.
void advanceBody(Body& b, float alpha) {
    advanceSweep(b, alpha);
    b.center = b.center0;
    b.angle = b.angle0;
    synchronizeTransform(b);
}

Transform sweepStart(const Body& b) {
    Transform xf;
    xf.q = Rot(b.angle0);
    xf.p = b.center0 - rotate(xf.q, b.localCenter);
    return xf;
}

bool isActive(const Body& b) {
    return b.awake && b.type != BodyType::Static;
}

// What mayImpact asks of a body, in a byte per body: every contact is asked each pass, and
// reading two whole bodies per contact from all over memory cost more than the rest of the
// continuous solve in a resting pile.
constexpr std::uint8_t kActive = 1, kOptedOut = 2, kStopsTunnelling = 4;

std::uint8_t tunnelFlags(const Body& b) {
    return static_cast<std::uint8_t>((isActive(b) ? kActive : 0) |
                                     (optedOutOfContinuous(b) ? kOptedOut : 0) |
                                     (stopsTunnelling(b) ? kStopsTunnelling : 0));
}

// Whether the contact can be an impact: something moves, and one side is static, kinematic or
// a bullet (two ordinary dynamic bodies are left to the discrete step). `flags`: tunnelFlags of
// every body.
bool mayImpact(const ContactSummary& c, const std::vector<std::uint8_t>& flags) {
    if (!c.blocking()) return false;  // a sensor stops nothing, nor a disabled contact
    const std::uint8_t a = flags[static_cast<std::size_t>(c.bodies[0])];
    const std::uint8_t b = flags[static_cast<std::size_t>(c.bodies[1])];
    if (((a | b) & kActive) == 0) return false;
    if ((a | b) & kOptedOut) return false;
    return ((a | b) & kStopsTunnelling) != 0;
}

bool inPlay(const ContinuousSolver::ImpactTime& t) {
    return !t.disabled && t.count <= kMaxImpactsPerContact;
}

}  // namespace

ContinuousSolver::Motion::Motion(const Body& b)
    : center0(b.center0), center(b.center), angle0(b.angle0), angle(b.angle), alpha0(b.alpha0) {}

void ContinuousSolver::Motion::restore(Body& b) const {
    b.center0 = center0;
    b.center = center;
    b.angle0 = angle0;
    b.angle = angle;
    b.alpha0 = alpha0;
    synchronizeTransform(b);
}

void ContinuousSolver::keepPath(std::int32_t index, const Body& body) {
    if (body.type == BodyType::Kinematic) kinematicPaths_.push_back({index, Motion(body)});
}

void ContinuousSolver::computeImpact(std::int32_t index, const Contact& contact,
                                     SlotPool<Body>& bodies, const SlotPool<Shape>& shapes) {
    Body& a = bodies[contact.bodyA()];
    Body& b = bodies[contact.bodyB()];
    // Both sweeps must start at the same moment.
    float alpha0 = a.alpha0;
    if (a.alpha0 < b.alpha0) {
        alpha0 = b.alpha0;
        advanceSweep(a, alpha0);
    } else if (b.alpha0 < a.alpha0) {
        alpha0 = a.alpha0;
        advanceSweep(b, alpha0);
    }
    const ImpactResult impact =
        timeOfImpact(contactProxy(shapes[contact.shapeA]), sweepOf(a),
                     contactProxy(shapes[contact.shapeB]), sweepOf(b), 1.0f);
    ImpactTime& time = impactTimes_[static_cast<std::size_t>(index)];
    time.toi = impact.state == ImpactState::Touching
                   ? std::min(alpha0 + (1.0f - alpha0) * impact.t, 1.0f)
                   : 1.0f;
    time.known = true;
}

std::int32_t ContinuousSolver::earliestImpact(SlotPool<Body>& bodies, const SlotPool<Shape>& shapes,
                                              SlotPool<Contact>& contacts,
                                              const ContactCensus& census, float& alpha) {
    std::int32_t best = -1;
    float bestAlpha = 1.0f;
    auto consider = [&](std::int32_t index) {
        const float toi = timeOf(index).toi;
        if (toi < bestAlpha ||
            (best != -1 && toi == bestAlpha && census[index].serial > census[best].serial)) {
            best = index;
            bestAlpha = toi;
        }
    };
    // The contacts whose impact is unknown (made or moved since the last pass), newest first:
    // computing an impact may move the start of a sweep another computation then reads, and
    // Box2D lists its contacts newest first.
    unknown_.clear();
    for (std::int32_t index : dirty_) {
        const ContactSummary& c = census[index];
        if (!c.alive()) continue;
        const ImpactTime& t = timeOf(index);
        if (inPlay(t) && !t.known && mayImpact(c, tunnelFlags_)) unknown_.push_back(index);
    }
    dirty_.clear();
    std::sort(unknown_.begin(), unknown_.end(),
              [&](std::int32_t x, std::int32_t y) { return census[x].serial > census[y].serial; });
    unknown_.erase(std::unique(unknown_.begin(), unknown_.end()), unknown_.end());
    for (std::int32_t index : unknown_) {
        computeImpact(index, contacts[index], bodies, shapes);
        if (timeOf(index).toi < 1.0f && !isCandidate_[static_cast<std::size_t>(index)]) {
            isCandidate_[static_cast<std::size_t>(index)] = 1;
            candidates_.push_back(index);
        }
    }
    // Only a known impact before the end of the step can be the earliest; the list drops the
    // rest as it goes.
    std::size_t kept = 0;
    for (std::int32_t index : candidates_) {
        const ImpactTime& t = timeOf(index);
        if (!census[index].alive() || !inPlay(t) || !t.known || !(t.toi < 1.0f)) {
            isCandidate_[static_cast<std::size_t>(index)] = 0;
            continue;
        }
        candidates_[kept++] = index;
        consider(index);
    }
    candidates_.resize(kept);
    alpha = bestAlpha;
    if (best == -1 || kLatestImpact < bestAlpha) return -1;
    return best;
}

void ContinuousSolver::buildIsland(std::int32_t contactIndex, float alpha, SlotPool<Body>& bodies,
                                   SlotPool<Contact>& contacts, ContactManager& contactManager) {
    const std::int32_t first[2] = {contacts[contactIndex].bodyA(), contacts[contactIndex].bodyB()};
    islandBodies_.assign(first, first + 2);
    bodySlot_[first[0]] = 0;
    bodySlot_[first[1]] = 1;
    islandContacts_.assign(1, contactIndex);
    inIsland_[contactIndex] = 1;

    for (std::int32_t bodyIndex : first) {
        const Body& body = bodies[bodyIndex];
        if (body.type != BodyType::Dynamic) continue;
        for (std::int32_t key = body.contactList; key != -1;) {
            if (islandBodies_.size() == kMaxIslandBodies) break;
            if (islandContacts_.size() == kMaxIslandContacts) break;
            const std::int32_t index = edgeOwner(key);
            const int side = edgeSide(key);
            key = contacts[index].edges[side].nextKey;
            if (inIsland_[index] || contacts[index].sensor) continue;
            const std::int32_t otherIndex = contacts[index].edges[1 - side].body;
            Body& other = bodies[otherIndex];
            // Only what can stop the body: static, kinematic and bullet bodies (a bullet's
            // contacts take ordinary dynamic bodies in too).
            if (other.type == BodyType::Dynamic && !body.bullet && !other.bullet) continue;
            if (optedOutOfContinuous(other)) continue;
            const Motion before(other);
            if (bodySlot_[otherIndex] < 0) {
                keepPath(otherIndex, other);
                advanceBody(other, alpha);
            }
            if (!contactManager.updateContactNow(index)) {
                before.restore(other);
                if (bodySlot_[otherIndex] < 0 && other.type == BodyType::Kinematic) {
                    kinematicPaths_.pop_back();
                }
                continue;
            }
            inIsland_[index] = 1;
            islandContacts_.push_back(index);
            if (bodySlot_[otherIndex] >= 0) continue;
            bodySlot_[otherIndex] = static_cast<std::int32_t>(islandBodies_.size());
            islandBodies_.push_back(otherIndex);
            wakeUp(other, contactManager.islandRevision());
            tunnelFlags_[static_cast<std::size_t>(otherIndex)] = tunnelFlags(other);
        }
    }
}

void ContinuousSolver::solveIsland(SlotPool<Body>& bodies, const SlotPool<Contact>& contacts,
                                   const StepContext& step, float alpha) {
    const std::size_t bodyCount = islandBodies_.size();
    const int contactCount = static_cast<int>(islandContacts_.size());
    resizeBuffer(positions_, bodyCount);
    resizeBuffer(velocities_, bodyCount);
    resizeBuffer(inputs_, bodyCount);
    for (std::size_t i = 0; i < bodyCount; ++i) {
        const Body& b = bodies[islandBodies_[i]];
        positions_[i] = {b.center, b.angle};
        velocities_[i] = {b.linearVelocity, b.angularVelocity};
        inputs_[i] = {b.localCenter, b.invMass, b.invInertia, velocities_[i]};
    }
    resizeBuffer(islandPairs_, islandContacts_.size());
    for (std::size_t k = 0; k < islandContacts_.size(); ++k) {
        const Contact& c = contacts[islandContacts_[k]];
        islandPairs_[k] = {bodySlot_[c.bodyA()], bodySlot_[c.bodyB()]};
    }

    // The rest of the step, solved as one rigid step without warm starting (the discrete step
    // applied this step's warm start already).
    StepContext rest = step;
    rest.dt = (1.0f - alpha) * step.stepDt;
    rest.invDt = 1.0f / rest.dt;
    rest.dtRatio = 1.0f;
    rest.warmStarting = false;
    rest.contactCorrection = ContactCorrection::NGS;
    const IndexRange all{0, contactCount};
    contactSolver_.reset(contactCount, rest);
    contactSolver_.prepare(all, islandContacts_.data(), islandPairs_.data(), contacts,
                           inputs_.data(), rest, positions_.data());
    // The impact's contact is the island's first: how fast it closed, before anything pushed.
    Impact impact{islandContacts_[0], 0, 0.0f};
    for (int j = 0; j < contacts[impact.contact].manifold.pointCount; ++j) {
        const float speed = contactSolver_.approachSpeed(0, j);
        if (j == 0 || speed > impact.approachSpeed) impact = {impact.contact, j, speed};
    }
    impacts_.push_back(impact);
    for (int i = 0; i < kImpactPositionIterations; ++i) {
        const float deepest =
            contactSolver_.solveImpactPositions(all, positions_.data(), 0, 1, kImpactBias);
        if (deepest >= kImpactTolerance) break;
    }
    // Where the two bodies were pushed to is where the rest of their step starts.
    for (int slot : {0, 1}) {
        Body& b = bodies[islandBodies_[static_cast<std::size_t>(slot)]];
        b.center0 = positions_[static_cast<std::size_t>(slot)].c;
        b.angle0 = positions_[static_cast<std::size_t>(slot)].a;
    }
    // Velocity constraints at the corrected poses.
    contactSolver_.prepare(all, islandContacts_.data(), islandPairs_.data(), contacts,
                           inputs_.data(), rest, positions_.data());
    for (int i = 0; i < step.velocityIterations; ++i) {
        contactSolver_.solveVelocities(all, velocities_.data());
    }

    const float h = rest.dt;
    for (std::size_t i = 0; i < bodyCount; ++i) {
        Vec2 v = velocities_[i].v;
        float w = velocities_[i].w;
        const Vec2 translation = h * v;
        if (dot(translation, translation) > kMaxTranslation * kMaxTranslation) {
            v *= kMaxTranslation / length(translation);
        }
        const float rotation = h * w;
        if (rotation * rotation > kMaxRotation * kMaxRotation) {
            w *= kMaxRotation / std::fabs(rotation);
        }
        Body& b = bodies[islandBodies_[i]];
        const Vec2 reached = positions_[i].c + h * v;
        const float turned = positions_[i].a + h * w;
        if (b.type != BodyType::Static &&
            !(isFinite(v) && std::isfinite(w) && isFinite(reached) && std::isfinite(turned))) {
            // As the discrete step does with a non-finite solve: the body keeps its pose (here,
            // where the impact found it) and a dynamic one stops.
            if (b.type == BodyType::Dynamic) {
                b.linearVelocity = Vec2{};
                b.angularVelocity = 0.0f;
            }
            discarded_.push_back(islandBodies_[i]);
            continue;
        }
        // An impact's solve may push a light body hard: hold what it leaves within the speeds
        // the API takes, as the discrete step does.
        holdLinearSpeed(v);
        holdAngularSpeed(w);
        b.center = flushDenormal(positions_[i].c + h * v);
        b.angle = flushDenormal(angleWithinLimits(positions_[i].a + h * w));
        b.linearVelocity = flushDenormal(v);
        b.angularVelocity = flushDenormal(w);
        synchronizeTransform(b);
        if (b.type != BodyType::Static && holdAtWorldEdge(b))
            heldAtEdge_.push_back(islandBodies_[i]);
    }
}

int ContinuousSolver::solve(SlotPool<Body>& bodies, const SlotPool<Shape>& shapes,
                            SlotPool<Contact>& contacts, ContactManager& contactManager,
                            TaskPool& pool, const StepContext& step) {
    heldAtEdge_.clear();
    discarded_.clear();
    impacts_.clear();
    resizeBuffer(tunnelFlags_, static_cast<std::size_t>(bodies.capacity()), std::uint8_t{0});
    bodies.forEach([this](std::int32_t index, Body& b) {
        b.alpha0 = 0.0f;
        tunnelFlags_[static_cast<std::size_t>(index)] = tunnelFlags(b);
    });
    // Before the first impact every sweep starts at 0, so no computation moves one: each
    // contact's impact depends on its own bodies only, and the workers share them out. Each
    // worker keeps the earliest impact it found: when none is before the end of the step, the
    // search below (a pass over every contact) would find none either, and is skipped. Shared
    // out only from 1,024 contacts: below that, handing a chunk to another worker cost more than
    // the pass (pyramid_10 and chains_10 ran twice as long on two workers as on one).
    earliestByWorker_.assign(static_cast<std::size_t>(pool.workerCount()), 1.0f);
    // The census says which contacts may be impacts; only those are loaded. Every slot's time
    // is reset, dead ones too: a contact made in a free slot in mid-step starts unknown.
    const ContactCensus& census = contactManager.census();
    resizeBuffer(impactTimes_, static_cast<std::size_t>(contacts.capacity()));
    pool.parallelFor(contacts.capacity(), 1024, [&](int begin, int end, int worker) {
        float& earliest = earliestByWorker_[static_cast<std::size_t>(worker)];
        for (std::int32_t index = begin; index < end; ++index) {
            impactTimes_[static_cast<std::size_t>(index)] = ImpactTime{};
            const ContactSummary& c = census[index];
            if (!c.alive() || !mayImpact(c, tunnelFlags_)) continue;
            computeImpact(index, contacts[index], bodies, shapes);
            earliest = std::min(earliest, timeOf(index).toi);
        }
    });
    const float earliest = *std::min_element(earliestByWorker_.begin(), earliestByWorker_.end());

    resizeBuffer(bodySlot_, static_cast<std::size_t>(bodies.capacity()), std::int32_t{-1});
    // Room for the most an impact can involve, so that a warm step does not allocate.
    const auto contactSlots = static_cast<std::size_t>(contacts.capacity());
    reserveBuffer(unknown_, 2 * contactSlots);
    reserveBuffer(dirty_, 2 * contactSlots);  // a contact per side
    reserveBuffer(candidates_, contactSlots);
    islandBodies_.reserve(kMaxIslandBodies);
    islandContacts_.reserve(kMaxIslandContacts);
    islandPairs_.reserve(kMaxIslandContacts);
    positions_.reserve(kMaxIslandBodies);
    velocities_.reserve(kMaxIslandBodies);
    inputs_.reserve(kMaxIslandBodies);
    kinematicPaths_.reserve(kMaxIslandBodies);
    contactSolver_.reserve(kMaxIslandContacts, 0);  // unbatched: no tiles
    // Most contacts have one impact a step at most; twice that is room for the busiest steps.
    reserveBuffer(impacts_, 2 * contactSlots);
    if (!(earliest <= kLatestImpact)) return 0;
    // There are impacts: list the contacts that may be the earliest (a known impact before the
    // end of the step), so that each search after an impact reads those and the contacts the
    // impact touched (dirty_), not every contact.
    resizeBuffer(isCandidate_, static_cast<std::size_t>(contacts.capacity()), std::uint8_t{0});
    std::fill(isCandidate_.begin(), isCandidate_.end(), std::uint8_t{0});
    candidates_.clear();
    dirty_.clear();
    for (std::int32_t index = 0; index < contacts.capacity(); ++index) {
        const ImpactTime& t = timeOf(index);  // a dead slot's is unknown
        if (t.known && t.toi < 1.0f) {
            isCandidate_[static_cast<std::size_t>(index)] = 1;
            candidates_.push_back(index);
        }
    }
    int impacts = 0;
    for (;;) {
        float alpha = 1.0f;
        const std::int32_t contactIndex = earliestImpact(bodies, shapes, contacts, census, alpha);
        if (contactIndex < 0) break;
        resizeBuffer(inIsland_, static_cast<std::size_t>(contacts.capacity()), std::uint8_t{0});

        Body& a = bodies[contacts[contactIndex].bodyA()];
        Body& b = bodies[contacts[contactIndex].bodyB()];
        const Motion beforeA(a), beforeB(b);
        kinematicPaths_.clear();
        keepPath(contacts[contactIndex].bodyA(), a);
        keepPath(contacts[contactIndex].bodyB(), b);
        advanceBody(a, alpha);
        advanceBody(b, alpha);
        const bool touching = contactManager.updateContactNow(contactIndex);
        ImpactTime& time = impactTimes_[static_cast<std::size_t>(contactIndex)];
        time.known = false;
        ++time.count;
        if (!touching) {
            // The sweep said touching, the manifold found no point: skip the contact this step.
            time.disabled = true;
            beforeA.restore(a);
            beforeB.restore(b);
            continue;
        }
        wakeUp(a, contactManager.islandRevision());
        wakeUp(b, contactManager.islandRevision());
        tunnelFlags_[static_cast<std::size_t>(contacts[contactIndex].bodyA())] = tunnelFlags(a);
        tunnelFlags_[static_cast<std::size_t>(contacts[contactIndex].bodyB())] = tunnelFlags(b);

        buildIsland(contactIndex, alpha, bodies, contacts, contactManager);
        solveIsland(bodies, contacts, step, alpha);
        for (const KinematicPath& path : kinematicPaths_) path.motion.restore(bodies[path.body]);
        ++impacts;

        // The moved bodies' boxes cover the rest of their step; their contacts' impacts are
        // out of date.
        for (std::int32_t k : islandContacts_) inIsland_[k] = 0;
        for (std::int32_t bodyIndex : islandBodies_) {
            bodySlot_[bodyIndex] = -1;
            const Body& body = bodies[bodyIndex];
            if (body.type != BodyType::Dynamic) continue;
            contactManager.synchronizeShapesFrom(bodyIndex, sweepStart(body));
            for (std::int32_t key = body.contactList; key != -1;) {
                impactTimes_[static_cast<std::size_t>(edgeOwner(key))].known = false;
                key = contacts[edgeOwner(key)].edges[edgeSide(key)].nextKey;
            }
        }
        contactManager.findNewContacts();
        // New contacts in new slots start unknown (ImpactTime{}).
        resizeBuffer(impactTimes_, static_cast<std::size_t>(contacts.capacity()));
        // What the next search must look at: every contact of a body the impact moved or woke
        // (their impacts were reset above, or may now be wanted), new contacts among them (each
        // has a moved body). A static body's contacts changed only on their other side.
        resizeBuffer(isCandidate_, static_cast<std::size_t>(contacts.capacity()), std::uint8_t{0});
        for (std::int32_t bodyIndex : islandBodies_) {
            const Body& body = bodies[bodyIndex];
            if (body.type == BodyType::Static) continue;
            for (std::int32_t key = body.contactList; key != -1;) {
                dirty_.push_back(edgeOwner(key));
                key = contacts[edgeOwner(key)].edges[edgeSide(key)].nextKey;
            }
        }
    }
    return impacts;
}

}  // namespace pivot
