// A game's own task system running the step's shared work (WorldDef::enqueueTask and
// finishTask, pivot/step_tasks.h; src/core/task_pool.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/task_pool.h"
#include "islands/team.h"
#include "pivot/pivot.h"
#include "scenes/parts.h"
#include "one_substep_def.h"

using namespace pivot;

namespace {

constexpr float kDt = 1.0f / 60.0f;

// A game's task system in miniature: its own threads take the tasks from a queue in order;
// finish waits for a task to have run (or, with `dropUnstarted`, takes it off the queue).
class ThreadScheduler {
public:
    explicit ThreadScheduler(int threads, bool dropUnstarted = false)
        : dropUnstarted_(dropUnstarted) {
        for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { serve(); });
    }
    ~ThreadScheduler() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        for (std::thread& t : threads_) t.join();
    }

    void* enqueue(StepTask task) {
        auto ticket = std::make_shared<Ticket>(Ticket{task});
        {
            std::lock_guard<std::mutex> lock(mutex_);
            queue_.push_back(ticket);
            ++enqueued_;
        }
        wake_.notify_one();
        return ticket.get();
    }

    void finish(void* handle) {
        std::unique_lock<std::mutex> lock(mutex_);
        const auto queued = std::find_if(queue_.begin(), queue_.end(),
                                         [&](const auto& t) { return t.get() == handle; });
        if (dropUnstarted_ && queued != queue_.end()) {
            queue_.erase(queued);
            ++dropped_;
            return;
        }
        auto* ticket = static_cast<Ticket*>(handle);
        // The ticket lives while queued or running: `running_` holds it.
        done_.wait(lock, [&] {
            return std::none_of(queue_.begin(), queue_.end(),
                                [&](const auto& t) { return t.get() == ticket; }) &&
                   running_.count(ticket) == 0;
        });
    }

    int enqueued() const { return enqueued_; }
    int dropped() const { return dropped_; }
    // Tasks run on a thread other than the one that called enqueue.
    int ranElsewhere() const { return ranElsewhere_; }

private:
    struct Ticket {
        StepTask task;
    };

    void serve() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
            if (stopping_) return;
            std::shared_ptr<Ticket> ticket = queue_.front();
            queue_.pop_front();
            running_.insert(ticket.get());
            ++ranElsewhere_;
            lock.unlock();
            ticket->task();
            lock.lock();
            running_.erase(ticket.get());
            done_.notify_all();
        }
    }

    bool dropUnstarted_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    std::deque<std::shared_ptr<Ticket>> queue_;
    std::set<Ticket*> running_;
    std::vector<std::thread> threads_;
    bool stopping_ = false;
    int enqueued_ = 0;
    int dropped_ = 0;
    int ranElsewhere_ = 0;
};

void useScheduler(WorldDef& def, ThreadScheduler& scheduler) {
    def.enqueueTask = [&scheduler](StepTask task) { return scheduler.enqueue(task); };
    def.finishTask = [&scheduler](void* handle) { scheduler.finish(handle); };
}

// A 40-row pyramid (a coloured island, solved by a team: TaskPool::region) beside 60 loose
// boxes (islands of their own, shared out whole: TaskPool::parallelFor).
std::unique_ptr<World> pileWorld(WorldDef def) {
    def.adaptWorkerCount = false;
    auto world = std::make_unique<World>(def);
    const BodyId ground = world->createBody(BodyDef{});
    world->createShape(ground, ShapeDef{}, Polygon::box(120.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    scenes::PyramidSpec spec;
    spec.rows = 40;
    scenes::addPyramid(*world, spec);
    for (int i = 0; i < 60; ++i) {
        BodyDef body;
        body.type = BodyType::Dynamic;
        body.position = {60.0f + 1.5f * float(i % 20), 2.0f + 2.0f * float(i / 20)};
        world->createShape(world->createBody(body), ShapeDef{}, Polygon::box(0.5f, 0.5f));
    }
    return world;
}

std::uint64_t pileHash(WorldDef def, int steps) {
    auto world = pileWorld(def);
    for (int i = 0; i < steps; ++i) world->step(kDt);
    return world->stateHash();
}

// Which worker did each chunk of a parallelFor over `count` items, and each block of a region
// of `stages` stages.
struct Workers {
    std::vector<int> chunks;
    std::vector<int> blocks;
};

Workers whoDidWhat(TaskPool& pool, int count, int stages) {
    Workers who;
    std::mutex mutex;
    pool.parallelFor(count, 1, [&](int, int, int worker) {
        std::lock_guard<std::mutex> lock(mutex);
        who.chunks.push_back(worker);
    });
    pool.region([&](int member) {
        const Team team(pool, member);
        for (int s = 0; s < stages; ++s) {
            team.forBlocks(1000, [&](IndexRange) {
                std::lock_guard<std::mutex> lock(mutex);
                who.blocks.push_back(member);
            });
            team.sync();
        }
    });
    return who;
}

}  // namespace

TEST(StepTasks, AGameSchedulerStepsToTheSameBitsAsOneThreadAndAsTheWorldsOwn) {
    WorldDef one = oneSubstepDef();
    const std::uint64_t expected = pileHash(one, 150);
    WorldDef own = oneSubstepDef();
    own.workerCount = 3;
    EXPECT_EQ(pileHash(own, 150), expected);

    ThreadScheduler scheduler(2);
    WorldDef tasks = oneSubstepDef();
    tasks.workerCount = 3;
    useScheduler(tasks, scheduler);
    auto world = pileWorld(tasks);
    for (int i = 0; i < 150; ++i) world->step(kDt);
    EXPECT_EQ(world->stateHash(), expected);
    EXPECT_EQ(world->lastStepStats().workersUsed, 3);
    // Two tasks a job, every one run by the scheduler's threads.
    EXPECT_GT(scheduler.enqueued(), 150 * 2);
    EXPECT_EQ(scheduler.enqueued() % 2, 0);
    EXPECT_EQ(scheduler.ranElsewhere(), scheduler.enqueued());
}

TEST(StepTasks, TasksDroppedUnstartedLeaveTheWholeStepToTheCaller) {
    WorldDef one = oneSubstepDef();
    const std::uint64_t expected = pileHash(one, 100);
    // Threads that never get to a task before finish drops it.
    ThreadScheduler scheduler(0, true);
    WorldDef tasks = oneSubstepDef();
    tasks.workerCount = 2;
    useScheduler(tasks, scheduler);
    EXPECT_EQ(pileHash(tasks, 100), expected);
    EXPECT_GT(scheduler.dropped(), 100);
    EXPECT_EQ(scheduler.dropped(), scheduler.enqueued());
}

TEST(StepTasks, ATaskRunInsideEnqueueDoesTheWholeJobBeforeTheCallerStarts) {
    // A scheduler with no thread to spare runs the task at once: the helper takes every chunk
    // and every block, and the caller finds them done.
    int finished = 0;
    TaskSystem inline_{[](StepTask task) -> void* {
                           task();
                           return nullptr;
                       },
                       [&](void*) { ++finished; }};
    TaskPool pool(2, inline_);
    const Workers who = whoDidWhat(pool, 64, 20);
    EXPECT_EQ(finished, 2);
    EXPECT_FALSE(who.chunks.empty());
    EXPECT_TRUE(std::all_of(who.chunks.begin(), who.chunks.end(), [](int w) { return w == 1; }));
    EXPECT_FALSE(who.blocks.empty());
    EXPECT_TRUE(std::all_of(who.blocks.begin(), who.blocks.end(), [](int w) { return w == 1; }));

    WorldDef one = oneSubstepDef();
    WorldDef tasks = oneSubstepDef();
    tasks.workerCount = 2;
    tasks.enqueueTask = inline_.enqueue;
    tasks.finishTask = [](void*) {};
    EXPECT_EQ(pileHash(tasks, 100), pileHash(one, 100));
}

TEST(StepTasks, ATaskRunAfterItsJobClosedJoinsNothing) {
    // finishTask breaking its promise (returning with the task still to run) must not let the
    // task into a later job, where its worker index could be taken twice.
    std::vector<StepTask> late;
    TaskSystem lateRunner{[&](StepTask task) -> void* {
                              late.push_back(task);
                              return nullptr;
                          },
                          [](void*) {}};
    TaskPool pool(3, lateRunner);
    const Workers first = whoDidWhat(pool, 64, 5);
    ASSERT_EQ(late.size(), 4u);  // two helpers, two jobs
    EXPECT_TRUE(
        std::all_of(first.chunks.begin(), first.chunks.end(), [](int w) { return w == 0; }));
    const std::vector<StepTask> old = late;
    late.clear();
    std::atomic<int> helped{0};
    bool ranOld = false;
    pool.parallelFor(1000, 1, [&](int, int, int worker) {
        // Inside the next job (whose own tasks wait in `late`): the old ones find it is not
        // theirs.
        if (worker == 0 && !ranOld) {
            for (const StepTask& task : old) task();
            ranOld = true;
        }
        if (worker != 0) ++helped;
    });
    EXPECT_TRUE(ranOld);
    EXPECT_EQ(helped.load(), 0);
    EXPECT_EQ(late.size(), 2u);
}

TEST(StepTasks, EnqueueAndFinishMustBeSetTogether) {
    WorldDef def = oneSubstepDef();
    def.workerCount = 2;
    def.enqueueTask = [](StepTask) -> void* { return nullptr; };
    try {
        World world(def);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("def.enqueueTask and def.finishTask"),
                  std::string::npos)
            << e.what();
    }
    def.enqueueTask = nullptr;
    def.finishTask = [](void*) {};
    EXPECT_THROW(World{def}, Error);
}

TEST(StepTasks, AnExceptionFromEnqueueIsThrownOnceTheStepIsDone) {
    WorldDef one = oneSubstepDef();
    auto expected = pileWorld(one);
    int calls = 0;
    WorldDef def = oneSubstepDef();
    def.workerCount = 2;
    def.enqueueTask = [&](StepTask task) -> void* {
        if (++calls == 3) throw std::runtime_error("queue full");
        task();
        return nullptr;
    };
    def.finishTask = [](void*) {};
    auto world = pileWorld(def);
    expected->step(kDt);
    EXPECT_THROW(world->step(kDt), std::runtime_error);
    EXPECT_EQ(world->stateHash(), expected->stateHash());
    // Nothing held over: the next steps throw nothing and still hand out tasks.
    for (int i = 0; i < 20; ++i) {
        expected->step(kDt);
        world->step(kDt);
    }
    EXPECT_EQ(world->stateHash(), expected->stateHash());
    EXPECT_GT(calls, 20);
}

TEST(StepTasks, AnExceptionFromFinishIsThrownOnceTheStepIsDone) {
    WorldDef one = oneSubstepDef();
    auto expected = pileWorld(one);
    int enqueued = 0;
    int finished = 0;
    std::vector<StepTask> abandoned;
    WorldDef def = oneSubstepDef();
    def.workerCount = 2;
    def.enqueueTask = [&](StepTask task) -> void* {
        // Every other task is run at once; the others only if finish gets to them.
        if (++enqueued % 2 == 0) {
            task();
            return nullptr;
        }
        abandoned.push_back(task);
        return &abandoned.back();
    };
    def.finishTask = [&](void* handle) {
        if (++finished == 3) throw std::logic_error("lost track");
        if (handle) {
            abandoned.back()();
            abandoned.pop_back();
        }
    };
    auto world = pileWorld(def);
    expected->step(kDt);
    EXPECT_THROW(world->step(kDt), std::logic_error);
    EXPECT_EQ(world->stateHash(), expected->stateHash());
    // The task finish gave up on runs later, after other steps: it joins nothing.
    ASSERT_EQ(abandoned.size(), 1u);
    const StepTask late = abandoned.back();
    abandoned.clear();
    abandoned.reserve(8);
    const int before = enqueued;
    for (int i = 0; i < 20; ++i) {
        expected->step(kDt);
        world->step(kDt);
        if (i == 5) late();
    }
    EXPECT_EQ(world->stateHash(), expected->stateHash());
    EXPECT_GT(enqueued, before);
}
