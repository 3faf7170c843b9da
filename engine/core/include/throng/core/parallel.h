#pragma once
// A small fixed pool of worker threads for data-parallel loops. Work is split into fixed
// contiguous chunks that threads claim as they come, and callers write only their own
// indices, so results never depend on scheduling or on which thread ran a chunk.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace throng {

class ThreadPool {
public:
    using Body = std::function<void(std::size_t, std::size_t)>;

    /// `threads` workers including the calling thread; 0 means the machine's core count
    /// (or THRONG_THREADS from the environment when set).
    explicit ThreadPool(unsigned threads = 0);
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;
    ~ThreadPool();

    [[nodiscard]] unsigned threadCount() const { return static_cast<unsigned>(workers_.size()) + 1; }

    /// Calls body(begin, end) over [0, count) in contiguous chunks (a few per thread) and
    /// returns when all are done. The calling thread claims chunks too, so a worker that is
    /// slow to wake delays nothing but the chunks it takes.
    void parallelFor(std::size_t count, const Body& body);
    /// Says that no job follows soon (a crowd step's last loop is done): idle workers stop
    /// watching for one and sleep at once, leaving the cores to what runs next (on a CPU
    /// device, the renderer's threads). The next parallelFor wakes them as usual.
    void rest();

private:
    void workerLoop();
    /// Claims and runs chunks of job `generation` until none is left; returns at once when
    /// a newer job has replaced it.
    void runChunks(std::uint64_t generation, const Body& body, std::size_t count, std::size_t chunks);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    // The current job, published under mutex_ together with generation_.
    const Body* body_ = nullptr;
    std::size_t count_ = 0, chunks_ = 0;
    std::atomic<std::uint64_t> generation_{0};
    /// The job's generation (high 32 bits) and its next unclaimed chunk (low 32 bits): one
    /// compare-and-swap claims a chunk of this job and no other.
    std::atomic<std::uint64_t> claim_{0};
    std::atomic<std::size_t> finished_{0};  ///< Chunks of the current job done.
    bool stopping_ = false;
    bool spins_ = true;  ///< Whether idle workers watch for a job before sleeping (no more threads than cores).
    std::atomic<bool> resting_{false};  ///< rest() since the last job: idle workers don't watch.
};

/// Core count from THRONG_THREADS, else std::thread::hardware_concurrency() (at least 1).
[[nodiscard]] unsigned defaultThreadCount();

}  // namespace throng
