// Contact bookkeeping: contacts are made when the broad phase reports a new pair of
// overlapping boxes, updated (narrow phase) at the start of every step, and destroyed when the
// boxes part or a shape goes. Touching begins and ends are recorded as events. The manager owns
// the broad phase and the pair map; the world owns the pools it works on.
#pragma once

#include <array>
#include <cstdint>
#include <exception>
#include <vector>

#include "collision/broad_phase.h"
#include "core/pair_map.h"
#include "core/slot_pool.h"
#include "core/task_pool.h"
#include "joints/joint.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/contact_census.h"
#include "model/shape.h"
#include "pivot/world.h"
#include "world/world_access.h"

namespace pivot {

class ContactManager {
public:
    ContactManager(SlotPool<Body>& bodies, SlotPool<Shape>& shapes, SlotPool<Joint>& joints,
                   SlotPool<Contact>& contacts, IslandRevision& islandRevision, TaskPool& pool,
                   WorldAccess& access, const std::uint32_t& worldId)
        : bodies_(bodies),
          shapes_(shapes),
          joints_(joints),
          contacts_(contacts),
          islandRevision_(islandRevision),
          pool_(pool),
          access_(access),
          worldId_(worldId) {}

    /// Counts the changes to the islands (touch events, pre-solve answers, wakings).
    IslandRevision& islandRevision() { return islandRevision_; }

    /// Whether two solid shapes could stop each other: on different bodies, their filters, the
    /// joints between their bodies and the custom filter allowing a contact (what addPair asks
    /// of a pair, sensors aside). For continuous collision's sweeps, which meet shapes without a
    /// contact.
    bool solidShapesMayCollide(std::int32_t shapeA, std::int32_t shapeB);
    BroadPhase& broadPhase() { return broadPhase_; }
    const BroadPhase& broadPhase() const { return broadPhase_; }

    /// Shapes were added or moved outside a step: their pairs are found before the next
    /// step's contact update.
    void markNewShapes() { newShapes_ = true; }
    bool hasNewShapes() const { return newShapes_; }

    /// Keeps count of the shapes carrying each category bit (delta +1 on creation, -1 on
    /// destruction): a moved shape whose mask admits none of the categories present, and no
    /// group can override, has nothing to meet and is not queried.
    void countCategories(const Filter& filter, int delta);

    /// Keeps count of the shapes on bodies that move and can stop another in mid-step
    /// (movesAndStopsTunnelling: kinematic bodies and bullets): delta +-1 as such a body gains or
    /// loses a shape, +-its shape count as a body takes up or drops the role. While there are
    /// none, an ordinary dynamic body's sweep is paired with static shapes only.
    void countMovingStoppers(int delta) { movingStopperShapes_ += delta; }

    /// The start of a step: forgets the last step's events, finds the pairs of new shapes,
    /// re-filters flagged contacts, drops those whose boxes parted and recomputes the manifolds
    /// of contacts with an awake body.
    void update();
    /// The end of a step: sweeps the boxes of the bodies solved (`solvedBodies`, static ones
    /// skipped) and makes contacts of the new overlapping pairs, and (if `continuous`, the
    /// world's continuous collision) of those a fast body's sweep passed through that
    /// continuous collision could stop it at.
    void afterSolve(const std::vector<std::int32_t>& solvedBodies, bool continuous);

    void destroyContact(std::int32_t contactIndex);
    /// Makes contacts of the new overlapping pairs the broad phase has found.
    void findNewContacts();
    /// The narrow phase for one contact at its bodies' current transforms, outside the step's
    /// contact update (continuous collision): a change of touching is recorded as an event
    /// and wakes both bodies; the pre-solve callback is asked. Returns whether the contact
    /// touches and is enabled.
    bool updateContactNow(std::int32_t contactIndex);
    /// Moves a body's broad-phase boxes to cover its motion from `from` to its current
    /// transform (a body continuous collision moved within the step).
    void synchronizeShapesFrom(std::int32_t bodyIndex, const Transform& from);
    /// Moves a body's broad-phase boxes to its current transform, covering the whole motion
    /// since the last sync when `swept` (a step), or not (a teleport).
    void synchronizeShapes(std::int32_t bodyIndex, bool swept);
    /// Flags the contacts between two bodies for re-filtering and makes the broad phase report
    /// their shapes again (after a joint between them appeared or went).
    void refilterBodyPair(std::int32_t bodyA, std::int32_t bodyB);
    /// Flags every contact of a body for re-filtering, wakes the bodies it touches or is jointed
    /// to, and makes the broad phase report its shapes again (after its type changed).
    void refilterBody(std::int32_t body);
    /// Flags one contact for re-filtering before the next update (its shape's filter changed).
    void refilterContact(std::int32_t contactIndex);

    /// Every contact slot's summary (model/contact_census.h), kept true by this manager: a
    /// contact's touching, sensor, enabled and filtering flags change only through it.
    const ContactCensus& census() const { return census_; }
    /// For tests: when on, every update() and afterSolve() first checks the census against the
    /// contacts, and the count of countMovingStoppers against the shapes, and throws
    /// std::logic_error if either is out of date. Process-wide; off by default.
    static void setCensusChecks(bool on);

    /// Contacts touching, sensors left out (StepStats::touchingCount): counted as they begin
    /// and end, so that no step has to pass over every contact for it.
    int touchingCount() const { return touchingCount_; }
    /// Touching began and ended since the last step began (shape destruction included).
    const std::vector<ContactEvent>& beginEvents() const { return beginEvents_; }
    const std::vector<ContactEvent>& endEvents() const { return endEvents_; }
    const std::vector<SensorEvent>& sensorBeginEvents() const { return sensorBeginEvents_; }
    const std::vector<SensorEvent>& sensorEndEvents() const { return sensorEndEvents_; }

    /// The contact as World::contacts reports it, at its bodies' current transforms.
    ContactData contactData(const Contact& contact) const;

    // The user's callbacks (World::setPreSolveCallback, setCustomFilterCallback). They run on
    // the thread that steps, in contact order, each in a WorldAccess::CallbackScope (it may
    // read the world, not change it: world_access.h). An exception a callback throws is kept (the
    // callback counts as having said yes) until takeCallbackError.
    void setPreSolve(PreSolveCallback callback) { preSolve_ = std::move(callback); }
    void setCustomFilter(CustomFilterCallback callback) { customFilter_ = std::move(callback); }
    /// Snapshots (world/world_snapshot.cpp): the broad phase, the pair bookkeeping that is not
    /// derived from the contacts and the last step's events. loadState decodes and checks into a
    /// State that adoptState then takes (after the pools it refers to are in place): a snapshot
    /// that fails a check changes nothing.
    struct State {
        BroadPhase broadPhase;
        bool newShapes = false;
        std::uint64_t contactsMade = 0;
        std::vector<ContactEvent> beginEvents, endEvents;
        std::vector<SensorEvent> sensorBeginEvents, sensorEndEvents;
    };
    void saveState(SnapshotWriter& out) const;
    static State loadState(SnapshotReader& in, std::uint32_t worldId);
    /// Takes the state and rebuilds what follows from the pools (checked already): the pair map
    /// and the category counts.
    void adoptState(const State& state);
    /// Reserves the buffers a step sizes by the contact pool, for its present capacity: update
    /// does, and restore, so that the steps after a restore allocate nothing.
    void reserveForPools();

    /// The first exception a callback threw since the last call, or null.
    std::exception_ptr takeCallbackError() {
        std::exception_ptr error = callbackError_;
        callbackError_ = nullptr;
        return error;
    }

private:
    /// A broad-phase pair: makes a contact unless one exists or the pair may not collide.
    void addPair(std::int32_t shapeA, std::int32_t shapeB);
    void updateContacts();
    void checkCensus(const char* when) const;
    /// synchronizeShapes for every body solved this step, with the boxes computed and the
    /// containment tests made on every worker; only the re-insertions are made in turn. A
    /// body's sweeps are kept when `continuous` and the body takes part in it.
    void synchronizeSolvedBodies(const std::vector<std::int32_t>& solvedBodies, bool continuous);
    /// Where a body's fast shapes' sweeps are paired: with whatever continuous collision could
    /// stop the body at (nowhere if it takes no part, or `continuous` is off).
    SweepReach sweepReach(const Body& body, bool continuous) const;
    /// Whether two bodies may collide at all: one must be dynamic, and no joint between them
    /// may forbid it.
    bool bodiesMayCollide(std::int32_t bodyA, std::int32_t bodyB) const;
    // Whether two shapes may make a contact (their filters aside): bodiesMayCollide, or for a
    // sensor pair one sensor and one body that is not static (and not two segments).
    bool mayPair(const Shape& a, const Shape& b) const;
    // A touching contact's begin or end, as a contact event or a sensor event.
    void reportTouch(const Contact& contact, bool began);
    // After reportTouch of a begin within the step (continuous collision): if the pair's end
    // event was recorded earlier in the step, both events are taken back.
    void takeBackEndOfThisStep(const Contact& contact);
    // Whether the pre-solve callback is to be asked about the contact: set, and the contact is a
    // touching non-sensor one with a shape that asks for it.
    bool wantsPreSolve(const Contact& contact) const;
    // The callbacks' answers (true when none is set).
    bool askPreSolve(const Contact& contact);
    bool askCustomFilter(std::int32_t shapeA, std::int32_t shapeB);
    std::uint16_t presentCategories() const;
    ShapeId shapeId(std::int32_t index) const {
        return {index, shapes_.generation(index), worldId_};
    }

    SlotPool<Body>& bodies_;
    SlotPool<Shape>& shapes_;
    SlotPool<Joint>& joints_;
    SlotPool<Contact>& contacts_;
    IslandRevision& islandRevision_;
    TaskPool& pool_;
    WorldAccess& access_;  // the step's callbacks run in its CallbackScope
    // The world's id, read where it is kept: a restore of another world's snapshot changes it.
    const std::uint32_t& worldId_;

    BroadPhase broadPhase_;
    PairMap pairs_;  // shape pair -> contact index
    ContactCensus census_;
    std::array<std::int32_t, 16> categoryCounts_{};
    bool newShapes_ = false;
    std::uint64_t contactsMade_ = 0;  // Contact::serial of the last contact made
    int touchingCount_ = 0;           // touching non-sensor contacts (touchingCount)
    std::vector<ContactEvent> beginEvents_;
    std::vector<ContactEvent> endEvents_;
    std::vector<SensorEvent> sensorBeginEvents_;
    std::vector<SensorEvent> sensorEndEvents_;
    std::vector<std::uint8_t> contactOutcomes_;  // updateContacts' first phase, per contact slot
    struct ShapeMove {
        AABB from;  // the shape's box at the start of the step
        bool needed = false;
        SweepReach reach = SweepReach::None;  // its body's sweepReach, for the move in turn
    };
    std::vector<ShapeMove> shapeMoves_;    // per shape slot, for synchronizeSolvedBodies
    std::vector<std::uint8_t> bodyMoves_;  // per solved body: a shape of it needs a move
    int movingStopperShapes_ = 0;          // countMovingStoppers

    PreSolveCallback preSolve_;
    CustomFilterCallback customFilter_;
    std::exception_ptr callbackError_;
};

}  // namespace pivot
