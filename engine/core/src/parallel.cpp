#include "throng/core/parallel.h"

#include <algorithm>
#include <cstdlib>

namespace throng {
namespace {
// Chunk `index` of `chunks` over [0, count): contiguous, sizes differ by at most one.
std::pair<std::size_t, std::size_t> chunk(std::size_t count, unsigned chunks, unsigned index) {
    return {count * index / chunks, count * (index + 1) / chunks};
}
}  // namespace

unsigned defaultThreadCount() {
    if (const char* value = std::getenv("THRONG_THREADS")) {
        const long parsed = std::strtol(value, nullptr, 10);
        if (parsed >= 1 && parsed <= 256) return static_cast<unsigned>(parsed);
    }
    return std::max(1U, std::thread::hardware_concurrency());
}

ThreadPool::ThreadPool(unsigned threads) {
    const unsigned total = threads == 0 ? defaultThreadCount() : threads;
    for (unsigned i = 1; i < total; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
}

ThreadPool::~ThreadPool() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::workerLoop(unsigned index) {
    std::uint64_t seen = 0;
    for (;;) {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        const auto* body = body_;
        const std::size_t count = count_;
        lock.unlock();
        const auto [begin, end] = chunk(count, threadCount(), index);
        if (begin < end) (*body)(begin, end);
        lock.lock();
        if (--pending_ == 0) done_.notify_one();
    }
}

void ThreadPool::parallelFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    if (workers_.empty() || count < 2) {
        if (count > 0) body(0, count);
        return;
    }
    {
        const std::lock_guard lock(mutex_);
        body_ = &body;
        count_ = count;
        pending_ = static_cast<unsigned>(workers_.size());
        ++generation_;
    }
    wake_.notify_all();
    const auto [begin, end] = chunk(count, threadCount(), 0);
    if (begin < end) body(begin, end);
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
}

}  // namespace throng
