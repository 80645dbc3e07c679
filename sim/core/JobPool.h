#pragma once
// A fixed set of worker threads for Jacobi-style sim work: each index of a
// parallel_for is written by exactly one thread and reads only inputs that no one
// writes during the loop, so results are the same for any thread count.
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sim {

class JobPool {
public:
    explicit JobPool(int threads = 1);
    ~JobPool();
    JobPool(const JobPool&) = delete;
    JobPool& operator=(const JobPool&) = delete;

    int threads() const { return int(workers_.size()) + 1; }

    // Calls fn(begin, end) over [0, n) split into contiguous ranges, one per thread;
    // the calling thread takes the first range. Returns when all are done.
    void parallel_for(size_t n, const std::function<void(size_t, size_t)>& fn);

private:
    void worker_loop(int index);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable start_cv_, done_cv_;
    const std::function<void(size_t, size_t)>* job_ = nullptr;
    size_t job_size_ = 0;
    unsigned generation_ = 0;
    int pending_ = 0;
    bool quit_ = false;
};

}  // namespace sim
