// Who may call into a World while something of the world's is under way: the one rule every
// public call goes through (World::Impl::requireChange, requireRead).
//
// A World is used from one thread at a time, but for three stretches in which its own code runs
// the game's:
// - World::step. Its workers, or the game's tasks (WorldDef::enqueueTask), work on the world
//   meanwhile, so no call may change it, from any thread: the pre-solve and custom-filter
//   callbacks, the task callbacks (enqueueTask, finishTask, the tasks themselves) and every
//   other thread are refused alike. Reads are safe only from the two step callbacks, which the
//   step runs on its own thread while no worker touches the world; from anywhere else during a
//   step they are refused too (a read there would race with the workers' writes).
// - A query's callback (castRay, queryAABB, queryShape, ...). The query is walking the broad
//   phase's trees and hands out the shapes it meets, so a call that would change the trees or
//   free what the walk hands out (Change::Structure: creating or destroying anything, a body's
//   type or teleport, a shape's sensor flag, restore, step) is refused; every other change is
//   allowed (a query that pushes what it finds is a common game pattern: an explosion).
// - World::debugDraw's drawing calls: the world is being drawn, so nothing may change.
#pragma once

#include <atomic>
#include <thread>

namespace pivot {

class WorldAccess {
public:
    /// What a call that changes the world would change. Structure: the broad phase's trees or
    /// the objects a query hands out (refused during a query's callback as well); State:
    /// anything else (refused only during a step and while drawing).
    enum class Change { State, Structure };

    /// Throws pivot::Error naming `call` if the world may not be changed now.
    void requireChange(const char* call, Change change) const;
    /// Throws pivot::Error naming `call` if the world may not be read now (during a step, from
    /// anywhere but its two callbacks).
    void requireRead(const char* call) const {
        if (stepping_.load(std::memory_order_acquire) && !inStepCallback()) refuseRead(call);
    }

    /// Marks World::step under way on the calling thread for as long as it lives.
    class StepScope {
    public:
        explicit StepScope(WorldAccess& access) : access_(access) {
            access_.stepThread_.store(std::this_thread::get_id(), std::memory_order_relaxed);
            access_.stepping_.store(true, std::memory_order_release);
        }
        ~StepScope() { access_.stepping_.store(false, std::memory_order_release); }
        StepScope(const StepScope&) = delete;
        StepScope& operator=(const StepScope&) = delete;

    private:
        WorldAccess& access_;
    };

    /// One of the step's callbacks (pre-solve, custom filter) under way: it may read the world.
    class CallbackScope {
    public:
        explicit CallbackScope(WorldAccess& access) : depth_(access.callbackDepth_) { ++depth_; }
        ~CallbackScope() { --depth_; }
        CallbackScope(const CallbackScope&) = delete;
        CallbackScope& operator=(const CallbackScope&) = delete;

    private:
        int& depth_;
    };

    /// A query under way (its walk of the trees), or World::debugDraw's drawing: both read the
    /// world (refused during a step) and are const calls, hence the counts are mutable.
    class QueryScope {
    public:
        QueryScope(const WorldAccess& access, const char* call) : depth_(access.queryDepth_) {
            access.requireRead(call);
            ++depth_;
        }
        ~QueryScope() { --depth_; }
        QueryScope(const QueryScope&) = delete;
        QueryScope& operator=(const QueryScope&) = delete;

    private:
        int& depth_;
    };
    class DrawScope {
    public:
        DrawScope(const WorldAccess& access, const char* call) : depth_(access.drawDepth_) {
            access.requireRead(call);
            ++depth_;
        }
        ~DrawScope() { --depth_; }
        DrawScope(const DrawScope&) = delete;
        DrawScope& operator=(const DrawScope&) = delete;

    private:
        int& depth_;
    };

private:
    /// Whether the calling thread is in one of the step's callbacks (only then may it read
    /// during a step). The thread is compared first: the depth is the stepping thread's.
    bool inStepCallback() const {
        return stepThread_.load(std::memory_order_relaxed) == std::this_thread::get_id() &&
               callbackDepth_ > 0;
    }
    [[noreturn]] void refuseRead(const char* call) const;

    // Set for the whole of World::step; read by any thread (a task callback on another one).
    std::atomic<bool> stepping_{false};
    std::atomic<std::thread::id> stepThread_{};
    // Written and read on the stepping thread only (inStepCallback compares the thread first).
    int callbackDepth_ = 0;
    // The world's one thread's (queries and drawing are not run during a step: requireRead).
    mutable int queryDepth_ = 0;
    mutable int drawDepth_ = 0;
};

}  // namespace pivot
