// worker_pool.cpp — the persistent worker pool (worker_pool.hpp).
//
// Dispatch. The caller publishes a job under the mutex and bumps the epoch;
// workers wake, copy the job and pull items from an atomic counter, as does
// the caller. The caller then waits only for the items that were taken (a
// worker the OS has not scheduled yet costs nothing: it finds the counter
// exhausted when it wakes). Such a straggler may still be inside runItems
// when the next job starts, so run() first waits until no worker is active.
#include "worker_pool.hpp"

namespace aerial::detail {

WorkerPool::WorkerPool(int threadCount) {
    for (int i = 1; i < threadCount; ++i) threads_.emplace_back([this, i] { workerMain(i); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quit_ = true;
    }
    wakeCv_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::workerMain(int worker) {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wakeCv_.wait(lock, [&] { return quit_ || epoch_ != seen; });
        if (quit_) return;
        seen = epoch_;
        const Job j = job_;
        ++active_;
        lock.unlock();
        runItems(j, worker);
        lock.lock();
        if (--active_ == 0) doneCv_.notify_all();
    }
}

void WorkerPool::runItems(const Job& job, int worker) {
    for (;;) {
        const int item = nextItem_.fetch_add(1, std::memory_order_relaxed);
        if (item >= job.count) return;
        job.fn(job.context, item, worker);
        if (itemsDone_.fetch_add(1, std::memory_order_acq_rel) + 1 == job.count) {
            std::lock_guard<std::mutex> lock(mutex_);
            doneCv_.notify_all();
        }
    }
}

void WorkerPool::run(int count, TaskFn fn, void* context) {
    if (count <= 0) return;
    const Job j{count, fn, context};
    if (threads_.empty()) {
        nextItem_.store(0);
        itemsDone_.store(0);
        runItems(j, 0);
        return;
    }
    {
        std::unique_lock<std::mutex> lock(mutex_);
        doneCv_.wait(lock, [&] { return active_ == 0; });  // stragglers of the last job have left
        job_ = j;
        nextItem_.store(0);
        itemsDone_.store(0);
        if (count > 1) ++epoch_;  // a single item runs on the caller alone
    }
    if (count > 1) wakeCv_.notify_all();
    runItems(j, 0);
    if (itemsDone_.load(std::memory_order_acquire) < count) {
        std::unique_lock<std::mutex> lock(mutex_);
        doneCv_.wait(lock, [&] { return itemsDone_.load(std::memory_order_acquire) >= count; });
    }
}

}  // namespace aerial::detail
