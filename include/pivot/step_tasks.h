// A game's own task system running a step's shared work (WorldDef::enqueueTask and
// WorldDef::finishTask), in place of threads of the world's own.
//
// Each parallel stage of World::step is a job: the calling thread takes chunks of it, and so
// does every helper that joins while the caller is still taking them. With a task system the
// world starts no thread; for each job it hands enqueueTask one StepTask per helper, works on
// the job on the calling thread, and then hands every handle enqueueTask returned to
// finishTask. A task that starts after the caller has taken the last chunk finds the job closed
// and returns at once, so a task that never gets a thread costs the step nothing but the wait
// in finishTask: a finishTask that drops a task it has not started yet (instead of running it)
// never holds the step up. The step's results are the same bits whoever did which chunk.
//
// The callbacks and the tasks run in the middle of a step, while its workers write the world:
// from them (as from any thread while a step runs) a call that changes the world throws
// pivot::Error, and so does a read of anything a step changes (World, "callbacks", lists the
// few reads that are safe).
//
// With a job system that can cancel a job not yet started (names are the game's):
//
//     pivot::WorldDef def;
//     def.workerCount = 4;  // the calling thread and three tasks a job
//     def.enqueueTask = [&jobs](pivot::StepTask task) -> void* {
//         return jobs.submit([task] { task(); });
//     };
//     def.finishTask = [&jobs](void* handle) { jobs.cancelOrWait(handle); };
#pragma once

#include <cstdint>
#include <functional>

namespace pivot {

/// One helper's share of a job of World::step: call it once, from any thread, while the world
/// exists. It owns nothing and copies freely (24 bytes). It knows its job: run after that job
/// closed (finishTask returned early for it, or threw), it joins nothing and returns at once.
class StepTask {
public:
    StepTask(void (*run)(void* context, std::uint64_t ticket), void* context, std::uint64_t ticket)
        : run_(run), context_(context), ticket_(ticket) {}
    void operator()() const { run_(context_, ticket_); }

private:
    void (*run_)(void* context, std::uint64_t ticket);
    void* context_;
    std::uint64_t ticket_;
};

/// Asked to run `task` once, soon, on a thread of the game's; returns a handle (any value,
/// nullptr included) that WorldDef::finishTask is given back. Called on the thread that called
/// World::step. It may run the task before it returns (a scheduler with no thread to spare).
using EnqueueTaskFunction = std::function<void*(StepTask task)>;

/// Returns once the task behind `handle` has returned, or once it is sure never to start it
/// (dropping a task that has not started is allowed: the step does not need it). Called once
/// for every handle, on the thread that called World::step, before the step goes on.
using FinishTaskFunction = std::function<void(void* handle)>;

}  // namespace pivot
