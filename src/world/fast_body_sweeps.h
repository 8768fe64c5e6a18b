// Continuous collision as Box2D v3 has it (ContinuousCollision::FastBodies): after the discrete
// step, only bodies that moved far are swept, and a hit stops the body without a solve.
//
// A dynamic body (awake, not opted out with BodyDef::continuous) is fast when its farthest
// point may have moved more than half its thinnest shape's depth in the step:
//   |c - c0| + |a - a0| maxExtent  >  minExtent / 2          (Body::minExtent, maxExtent)
// Each solid shape of a fast body sweeps the box of its start and end poses through the broad
// phase. Every static shape it meets (for a bullet, every shape of a body that is not a bullet)
// that it may collide with (filters, joints, the custom filter) gives a time of impact t along
// the fast body's sweep, the other body standing at its pose; the earliest t in (0, 1) is the
// hit. Shapes that touch at the start (t = 0) are swept again as a circle of a quarter of the
// fast shape's depth around its centroid: a body sliding along a wall is not held by it, and
// one that starts the step in it still cannot pass through. A chain segment is not swept
// against when the shape's centroid starts behind it or comes towards its line by less than
// minExtent / 4 (Box2D v3's rule): one-sided chains let bodies through from behind, and a body
// sliding fast along a chain does not stop at the joins it brushes.
//
// A hit puts the body where its sweep was at t (centre and angle interpolated, never past
// either end), its velocity kept: nothing is solved, and the next step's contacts stop it. Its
// shapes' boxes follow, and the new pairs are found once, after every fast body is swept. The
// origin follows the centre and the angle: a body spinning at the world's edge, its centre of
// mass off its origin, can have its origin put past the edge although both ends of its sweep
// were within it, and is then held at the edge (holdAtWorldEdge) like a body the solver moved
// there (bodiesHeldAtEdge).
//
// Bullets are swept after the other fast bodies, so they meet those where their sweeps left
// them. A sweep moves only its own body and reads only bodies no sweep of its round moves
// (static ones, or for a bullet the bodies that are not bullets), so the order of the bodies
// changes nothing: the same bits on every worker count.
#pragma once

#include <cstdint>
#include <vector>

#include "core/slot_pool.h"
#include "model/body.h"
#include "model/shape.h"
#include "world/contact_manager.h"

namespace pivot {

class FastBodySweeps {
public:
    /// Sweeps the fast bodies among `solvedBodies` (the step's, in island order; static ones
    /// are skipped). Returns how many were stopped at a hit.
    int solve(const std::vector<std::int32_t>& solvedBodies, SlotPool<Body>& bodies,
              const SlotPool<Shape>& shapes, ContactManager& contactManager);
    /// The bodies the last solve held at the world's edge, in the order it stopped them.
    const std::vector<std::int32_t>& bodiesHeldAtEdge() const { return heldAtEdge_; }

private:
    /// The earliest hit of body `index`'s sweep in (0, 1), or 1 when there is none.
    float earliestHit(std::int32_t index, const SlotPool<Body>& bodies,
                      const SlotPool<Shape>& shapes, ContactManager& contactManager) const;

    std::vector<std::int32_t> bullets_;     // fast bullets, swept after the rest
    std::vector<std::int32_t> heldAtEdge_;  // stopped past the world's edge, held there
};

}  // namespace pivot
