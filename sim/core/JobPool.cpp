#include "sim/core/JobPool.h"

#include <algorithm>
#include <stdexcept>

#include "sim/core/FloatEnvironment.h"

namespace sim {

namespace {
std::pair<size_t, size_t> slice(size_t n, int parts, int i) {
    size_t base = n / size_t(parts), extra = n % size_t(parts);
    size_t begin = size_t(i) * base + std::min(size_t(i), extra);
    return {begin, begin + base + (size_t(i) < extra ? 1 : 0)};
}
}  // namespace

JobPool::JobPool(int threads) {
    if (threads < 1 || threads > 64)
        throw std::invalid_argument("sim thread count must be between 1 and 64, got " +
                                    std::to_string(threads));
    require_float_environment();  // the workers inherit this thread's
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { worker_loop(i); });
}

JobPool::~JobPool() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
    }
    start_cv_.notify_all();
    for (auto& t : workers_) t.join();
}

void JobPool::parallel_for(size_t n, const std::function<void(size_t, size_t)>& fn) {
    if (workers_.empty() || n < 2) {
        if (n) fn(0, n);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        job_ = &fn;
        job_size_ = n;
        pending_ = int(workers_.size());
        ++generation_;
    }
    start_cv_.notify_all();
    auto [b, e] = slice(n, threads(), 0);
    if (b < e) fn(b, e);
    std::unique_lock lock(mutex_);
    done_cv_.wait(lock, [this] { return pending_ == 0; });
    job_ = nullptr;
}

void JobPool::worker_loop(int index) {
    unsigned seen = 0;
    for (;;) {
        const std::function<void(size_t, size_t)>* job;
        size_t n;
        {
            std::unique_lock lock(mutex_);
            start_cv_.wait(lock, [&] { return quit_ || generation_ != seen; });
            if (quit_) return;
            seen = generation_;
            job = job_;
            n = job_size_;
        }
        auto [b, e] = slice(n, threads(), index);
        if (b < e) (*job)(b, e);
        {
            std::lock_guard lock(mutex_);
            --pending_;
        }
        done_cv_.notify_one();
    }
}

}  // namespace sim
