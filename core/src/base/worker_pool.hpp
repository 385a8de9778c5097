// worker_pool.hpp — private: a persistent pool of worker threads that runs
// numbered items on the caller and the workers together (the sky solver's
// rows, sky_solver.cpp).
//
// Usage:
//   detail::WorkerPool pool(4);  // the caller + 3 threads, made once
//   auto task = [&](int item, int worker) { rows[item] = solveRow(item, scratch[worker]); };
//   pool.run(64, task);          // returns when all 64 items are done
//
// Items are pulled from an atomic counter, so which worker runs an item
// depends on scheduling; a task that writes only its item's output (and
// uses per-worker scratch, `worker` in 0..threadCount()-1, 0 the caller)
// gives the same result whatever the thread count. run() allocates nothing
// and takes no copy of the task; a single item runs on the caller alone.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace aerial::detail {

class WorkerPool {
public:
    /// Starts threadCount - 1 threads (none for 0 or 1); the caller of run()
    /// is the other worker.
    explicit WorkerPool(int threadCount);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    /// Workers including the caller.
    int threadCount() const { return int(threads_.size()) + 1; }

    /// Calls task(item, worker) once for every item in [0, count), on the
    /// caller and the workers, and returns when every call has returned.
    /// Not reentrant: one run at a time.
    template <class Task>
    void run(int count, Task& task) {
        run(
            count, [](void* context, int item, int worker) { (*static_cast<Task*>(context))(item, worker); },
            &task);
    }

private:
    using TaskFn = void (*)(void* context, int item, int worker);
    struct Job {
        int count = 0;
        TaskFn fn = nullptr;
        void* context = nullptr;
    };

    void run(int count, TaskFn fn, void* context);
    void runItems(const Job& job, int worker);
    void workerMain(int worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wakeCv_, doneCv_;
    std::uint64_t epoch_ = 0;  // bumped for every job the workers should join
    int active_ = 0;           // workers inside runItems (guarded by mutex_)
    bool quit_ = false;
    Job job_;  // guarded by mutex_; workers take a copy when they wake
    std::atomic<int> nextItem_{0};
    std::atomic<int> itemsDone_{0};
};

}  // namespace aerial::detail
