#pragma once
// A small fixed pool of worker threads for data-parallel loops. Work is split into the same
// contiguous chunks every time, and callers write only their own indices, so results never
// depend on scheduling.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace throng {

class ThreadPool {
public:
    /// `threads` workers including the calling thread; 0 means the machine's core count
    /// (or THRONG_THREADS from the environment when set).
    explicit ThreadPool(unsigned threads = 0);
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;
    ~ThreadPool();

    [[nodiscard]] unsigned threadCount() const { return static_cast<unsigned>(workers_.size()) + 1; }

    /// Calls body(begin, end) over [0, count) in one chunk per thread and returns when all
    /// are done. The calling thread takes the first chunk.
    void parallelFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body);

private:
    void workerLoop(unsigned index);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(std::size_t, std::size_t)>* body_ = nullptr;
    std::size_t count_ = 0;
    std::uint64_t generation_ = 0;
    unsigned pending_ = 0;
    bool stopping_ = false;
};

/// Core count from THRONG_THREADS, else std::thread::hardware_concurrency() (at least 1).
[[nodiscard]] unsigned defaultThreadCount();

}  // namespace throng
