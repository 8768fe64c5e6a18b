// Continuous collision: after the discrete step has moved the bodies, a body that passed into
// or through static or kinematic geometry (or, for a bullet, any body) is taken back to the
// moment it first touched and stepped on from there.
//
// The step moved each body along a sweep from its start pose (center0, angle0) to its end pose
// (time_of_impact.h). For every contact that may tunnel (one side static, kinematic or a
// bullet; at least one side awake and movable) the time of impact alpha in [0, 1] of the step
// is computed; the earliest, if any is before the end, is an impact event:
//   1. the two bodies are advanced to alpha (their sweeps now start there) and the contact's
//      manifold is recomputed; if it does not touch after all, the bodies go back and the
//      contact is skipped for the rest of the step;
//   2. a small island is made of the two bodies, the contact, and the contacts (recomputed at
//      alpha) the two have with static, kinematic or bullet bodies, those advanced too;
//   3. that island is solved over the rest of the step, h = (1 - alpha) dt: position sweeps
//      (bias 0.75, up to 20) that move only the two bodies out of penetration, which becomes
//      their sweeps' new start; velocity iterations without warm starting; integration;
//   4. the moved bodies' broad-phase boxes cover their new sweeps, their contacts' times of
//      impact are recomputed, and new pairs become contacts;
// until no impact remains before the end of the step. A contact takes part in at most 8 impacts
// a step, an island at most 32 contacts and 64 bodies.
//
// Joints are not solved in an impact's island: a jointed body hit in mid-step is stopped by the
// contact alone and its joints catch up in the next step.
//
// One deliberate difference from Box2D: a kinematic body in an impact's island is put back on its
// own path afterwards. (Box2D integrates it again from the moment of impact, which rounds its
// position differently; a kinematic body's path should not depend on what touches it.)
//
// This is Box2D 2.4.1's b2World::SolveTOI, step for step, so that scenes with continuous
// collision agree with Box2D's bit for bit (docs/reference-agreement.md). Contacts are met in
// the order Box2D keeps them, newest first (Contact::serial), wherever that order matters: the
// earliest of equal times of impact, and the order of computations that move a sweep's start.
// The first pass, before any impact, moves no sweep and runs on every worker.
#pragma once

#include <cstdint>
#include <vector>

#include "constraints/contact_solver.h"
#include "constraints/solver_body.h"
#include "constraints/step_context.h"
#include "core/slot_pool.h"
#include "core/task_pool.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/shape.h"
#include "world/contact_manager.h"

namespace pivot {

class ContinuousSolver {
public:
    /// Solves the impact events of a step whose discrete part is done (bodies moved, their
    /// boxes swept, new pairs made into contacts). Returns the number of impacts solved.
    int solve(SlotPool<Body>& bodies, const SlotPool<Shape>& shapes, SlotPool<Contact>& contacts,
              ContactManager& contactManager, TaskPool& pool, const StepContext& step);

    /// Bodies an impact's motion took past the world's edge, held there (holdAtWorldEdge), in
    /// the order the impacts were solved.
    const std::vector<std::int32_t>& bodiesHeldAtEdge() const { return heldAtEdge_; }
    /// Bodies whose impact solve was not finite: each kept the pose the impact found it at, and
    /// a dynamic one was stopped.
    const std::vector<std::int32_t>& discardedBodies() const { return discarded_; }
    /// Each impact solved, in order: its contact and how fast its fastest point (`point`)
    /// approached when the impact was found (hit events).
    struct Impact {
        std::int32_t contact;
        int point;
        float approachSpeed;
    };
    const std::vector<Impact>& impacts() const { return impacts_; }

    /// A contact's time of impact this step, as far as known.
    struct ImpactTime {
        float toi = 1.0f;        // the fraction of the step; 1: none
        std::uint8_t count = 0;  // impacts solved this step
        bool known = false;
        bool disabled = false;  // its impact did not touch: skipped for the rest of the step
    };

private:
    /// The contact's time of impact as a fraction of the step (1: none), moving the start of
    /// whichever sweep starts earlier to the other's.
    void computeImpact(std::int32_t index, const Contact& contact, SlotPool<Body>& bodies,
                       const SlotPool<Shape>& shapes);
    /// The earliest known impact after computing the unknown ones, newest contact first; -1 if
    /// none is before the end of the step.
    std::int32_t earliestImpact(SlotPool<Body>& bodies, const SlotPool<Shape>& shapes,
                                SlotPool<Contact>& contacts, const ContactCensus& census,
                                float& alpha);
    /// Steps 2 and 3 for the event of `contactIndex` at `alpha`, whose bodies are advanced.
    void buildIsland(std::int32_t contactIndex, float alpha, SlotPool<Body>& bodies,
                     SlotPool<Contact>& contacts, ContactManager& contactManager);
    /// Remembers a kinematic body's motion before an impact moves it (none for other types).
    void keepPath(std::int32_t index, const Body& body);
    void solveIsland(SlotPool<Body>& bodies, const SlotPool<Contact>& contacts,
                     const StepContext& step, float alpha);

    const ImpactTime& timeOf(std::int32_t index) const {
        return impactTimes_[static_cast<std::size_t>(index)];
    }
    // Per contact slot, reset at the start of each solve: kept here, not in the contacts, so
    // that the reset streams 8 bytes a slot rather than every contact.
    std::vector<ImpactTime> impactTimes_;
    std::vector<std::int32_t> unknown_;     // contacts whose impact a pass must compute
    std::vector<std::int32_t> dirty_;       // contacts an impact touched: unknown_ comes from these
    std::vector<std::int32_t> candidates_;  // contacts with a known impact before the step's end
    std::vector<std::uint8_t> isCandidate_;     // per contact slot: in candidates_
    std::vector<std::int32_t> islandBodies_;    // body indices; the event's two first
    std::vector<std::int32_t> islandContacts_;  // contact indices; the event's first
    std::vector<BodyPair> islandPairs_;         // each island contact's solver slots
    std::vector<std::int32_t> bodySlot_;        // per body slot: its island slot, or -1
    std::vector<std::uint8_t> inIsland_;        // per contact slot
    std::vector<SolverPose> positions_;
    std::vector<SolverVelocity> velocities_;
    std::vector<SolverBodyInputs> inputs_;
    ContactSolver contactSolver_;
    std::vector<std::int32_t> heldAtEdge_;
    std::vector<std::int32_t> discarded_;
    std::vector<Impact> impacts_;
    /// What moving a body to an impact changes, to put it back.
    struct Motion {
        Vec2 center0, center;
        float angle0, angle, alpha0;
        explicit Motion(const Body& b);
        void restore(Body& b) const;
    };
    struct KinematicPath {
        std::int32_t body;
        Motion motion;
    };
    std::vector<KinematicPath> kinematicPaths_;  // the island's kinematic bodies, to put back
    std::vector<std::uint8_t> tunnelFlags_;      // per body: what mayImpact asks (the .cpp)
    std::vector<float> earliestByWorker_;        // the first pass's earliest impact, per worker
};

}  // namespace pivot
