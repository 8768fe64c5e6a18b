// The messages of WorldAccess's refusals: each says what is under way and when the call can be
// made instead.
#include "world/world_access.h"

#include "core/validation.h"

namespace pivot {

void WorldAccess::requireChange(const char* call, Change change) const {
    if (stepping_.load(std::memory_order_acquire)) {
        if (inStepCallback()) {
            fail(call,
                 "called from inside a step's callback (pre-solve or custom filter: it may read "
                 "the world; change it after World::step returns)");
        }
        fail(call,
             "called while World::step runs (from a task callback, WorldDef::enqueueTask or "
             "finishTask, or from another thread): nothing may change the world until the step "
             "returns");
    }
    if (drawDepth_ > 0) {
        fail(call,
             "called from inside World::debugDraw's drawing calls (they may read the world; "
             "change it after debugDraw returns)");
    }
    if (change == Change::Structure && queryDepth_ > 0) {
        fail(call,
             "called from inside a query's callback (a query may read the world and change its "
             "bodies' motion and settings, but not create or destroy anything, teleport or "
             "re-type a body, switch a sensor, restore or step: do that after the query "
             "returns)");
    }
}

void WorldAccess::refuseRead(const char* call) const {
    fail(call,
         "called while World::step runs (from a task callback, WorldDef::enqueueTask or "
         "finishTask, or from another thread): the step's workers are writing the world; read "
         "it from the pre-solve or custom-filter callback, or after the step returns");
}

}  // namespace pivot
