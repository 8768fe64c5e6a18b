// A small pool of worker threads for the parallel stages of World::step. parallelFor splits an
// index range into chunks that the workers and the calling thread take, each its own stretch of
// them first; it returns once every chunk is done. Stages only use it where the chunks are
// independent, and merge their results in index order afterwards, so results never depend on the
// number of workers or on scheduling. The workers are threads of the pool's own, or tasks handed to
// a game's task system (pivot/step_tasks.h), which join a job the same way a woken thread does.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/stage_board.h"
#include "pivot/step_tasks.h"

namespace pivot {

/// A game's task system (WorldDef::enqueueTask, WorldDef::finishTask): both set, or neither.
struct TaskSystem {
    EnqueueTaskFunction enqueue;
    FinishTaskFunction finish;
    bool present() const { return static_cast<bool>(enqueue); }
};

class TaskPool {
public:
    /// `workers` in all, the caller included (1: everything runs on the caller): threads of
    /// the pool's own, or with `tasks` present, tasks handed to it for each job.
    explicit TaskPool(int workers, TaskSystem tasks = {});
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int workerCount() const { return workerCount_; }

    /// The first exception the task system let out since the last call (nullptr if none).
    std::exception_ptr takeTaskError() {
        std::exception_ptr error = taskError_;
        taskError_ = nullptr;
        return error;
    }

    /// Workers the next jobs may use, the caller included, in [1, workerCount()]: the others stay
    /// out of them (and sleep once their spin runs out). Set between jobs, by the caller.
    void setActiveWorkers(int count);
    int activeWorkers() const { return active_; }

    /// Calls body(begin, end, worker) over [0, count) in chunks of at least minChunk indices;
    /// `worker` is in [0, workerCount()) and identifies per-worker scratch. Allocates nothing.
    template <typename Body>
    void parallelFor(int count, int minChunk, Body&& body) {
        if (count <= 0) return;
        if (active_ == 1 || count <= minChunk) {
            body(0, count, 0);
            return;
        }
        run(count, minChunk, &body, [](void* context, int begin, int end, int worker) {
            (*static_cast<Body*>(context))(begin, end, worker);
        });
    }

    /// Runs body(worker) on the caller (worker 0) and on every worker that joins while the
    /// caller is still in its own body(0), and returns when all of them have returned. Inside,
    /// members share out stages through stages() (islands/team.h): the island solver solves
    /// one graph colour at a time that way, with whoever is there.
    template <typename Body>
    void region(Body&& body) {
        if (active_ == 1) {
            body(0);
            return;
        }
        run(-1, 1, &body,
            [](void* context, int, int, int worker) { (*static_cast<Body*>(context))(worker); });
    }

    /// Inside region(): where its members claim the blocks of its stages (cleared for each).
    StageBoard& stages() { return *stages_; }

private:
    using Trampoline = void (*)(void*, int, int, int);
    /// count < 0: a region, the trampoline called once per worker.
    void run(int count, int minChunk, void* context, Trampoline trampoline);
    void workerLoop(int worker);
    void takeChunks(int worker);
    /// A worker joining job `generation`, if it is still the current one and open to it;
    /// false if it stayed out.
    bool join(int worker, std::uint64_t generation);
    bool joinLocked(int worker, std::uint64_t generation);  // with mutex_ held
    void leave();
    // With a task system: hands it a task per helper, and after the caller's part, every
    // handle back.
    void enqueueHelpers();
    void finishHelpers();
    void holdTaskError();
    // A helper task's ticket: the job it was handed for (so that a task the game runs late
    // joins no later job) and its worker index, below kMaxWorkers.
    static constexpr std::uint64_t kMaxWorkers = 64;
    static void runHelper(void* pool, std::uint64_t ticket);

    int workerCount_;
    std::vector<std::thread> threads_;
    TaskSystem tasks_;
    std::vector<void*> handles_;  // of the current job's tasks
    std::exception_ptr taskError_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    // The current job. generation_ counts jobs, so a worker can tell a new job from a spurious
    // wake-up; busy_ counts workers inside the job (joined while it was open_: a worker that
    // wakes after the caller has done its part stays out, so it never holds the caller up).
    // Both are atomic so that a worker can watch for the next job, and the caller for the end
    // of this one, without the lock.
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<int> busy_{0};
    bool open_ = false;
    bool stopping_ = false;
    int active_ = 1;  // workers with an index below it join jobs (written under the lock)
    void* context_ = nullptr;
    Trampoline trampoline_ = nullptr;
    int count_ = 0;
    int chunk_ = 1;
    // The job's chunks are dealt into a stretch per active worker (up to kMaxStretches, then
    // shared), in order: a worker takes the chunks of its own stretch first, then what the
    // others left. So a worker that has its core does the same part of a job at every step
    // (the same contacts, bodies, islands), with their data still in its own cache, and a
    // worker that is late or never comes holds nobody up: the others take its stretch.
    static constexpr int kMaxStretches = 8;
    struct alignas(64) Cursor {
        std::atomic<int> next{0};  // chunks taken of the stretch, counting from its first
    };
    std::array<Cursor, kMaxStretches> cursors_;
    int chunkCount_ = 0;
    int stretches_ = 1;
    // How long a waiting thread spins before it sleeps. The stages of a step follow each other
    // within tens of microseconds, less than a wake-up costs, so a worker waiting for the next
    // job, or the caller for the end of one, watches for about kJobSpin.
    static constexpr std::chrono::microseconds kJobSpin{100};
    // 37 KB, a cache line a word: kept apart, so that the world that holds the pool keeps its
    // other parts close together.
    std::unique_ptr<StageBoard> stages_ = std::make_unique<StageBoard>();
};

}  // namespace pivot
