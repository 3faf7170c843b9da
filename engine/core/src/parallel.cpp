#include "throng/core/parallel.h"

#include <algorithm>
#include <chrono>

#include "throng/core/environment.h"

namespace throng {
namespace {

constexpr std::size_t kChunksPerThread = 8;
constexpr std::uint64_t kIndexMask = 0xffffffffULL;
// How long an idle worker watches for the next job before it sleeps. The crowd step calls
// parallelFor up to four times in a row, and waking a sleeping thread takes tens of
// microseconds on a virtual machine; after the step's last loop it calls rest(), and workers
// sleep at once and leave the cores to the renderer (on lavapipe, whose threads start on the
// frame as the step ends, watching held one of a 2-core machine's two cores for 100 µs: the
// 2000-character frame took about 0.3 ms longer in two of five alternated runs, within the
// noise in the others).
constexpr auto kSpinTime = std::chrono::microseconds(100);

void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#else
    std::this_thread::yield();
#endif
}

}  // namespace

unsigned defaultThreadCount() {
    // A value that is not a count from 1 to 256 is refused (ThrongException), not ignored.
    if (const auto threads = wholeNumberFromEnvironment("THRONG_THREADS", 1, 256, "a thread count")) return static_cast<unsigned>(*threads);
    return std::max(1U, std::thread::hardware_concurrency());
}

ThreadPool::ThreadPool(unsigned threads) {
    const unsigned total = threads == 0 ? defaultThreadCount() : threads;
    // More threads than cores: a spinning worker would hold a core another thread needs.
    spins_ = total <= std::max(1U, std::thread::hardware_concurrency());
    for (unsigned i = 1; i < total; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
        const auto spinEnd = std::chrono::steady_clock::now() + kSpinTime;
        for (unsigned spin = 1; spins_ && generation_.load(std::memory_order_acquire) == seen; ++spin) {
            if (resting_.load(std::memory_order_relaxed)) break;  // a hint: the wait below decides
            relax();
            if (spin % 64 == 0 && std::chrono::steady_clock::now() > spinEnd) break;
        }
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_.load(std::memory_order_relaxed) != seen; });
        if (stopping_) return;
        seen = generation_.load(std::memory_order_relaxed);
        const Body* body = body_;
        const std::size_t count = count_, chunks = chunks_;
        lock.unlock();
        runChunks(seen, *body, count, chunks);
    }
}

void ThreadPool::runChunks(std::uint64_t generation, const Body& body, std::size_t count, std::size_t chunks) {
    const std::uint64_t tag = (generation & kIndexMask) << 32;
    for (;;) {
        std::uint64_t claim = claim_.load(std::memory_order_relaxed);
        do {
            // A chunk of this job, while any is left: a worker that wakes after its job ended
            // (or was replaced) claims nothing, so it never calls a body that is gone.
            if ((claim & ~kIndexMask) != tag || (claim & kIndexMask) >= chunks) return;
        } while (!claim_.compare_exchange_weak(claim, claim + 1, std::memory_order_acq_rel, std::memory_order_relaxed));
        const std::size_t index = claim & kIndexMask;
        body(count * index / chunks, count * (index + 1) / chunks);
        finished_.fetch_add(1, std::memory_order_acq_rel);
    }
}

void ThreadPool::parallelFor(std::size_t count, const Body& body) {
    if (workers_.empty() || count < 2) {
        if (count > 0) body(0, count);
        return;
    }
    const std::size_t chunks = std::min(count, threadCount() * kChunksPerThread);
    std::uint64_t generation = 0;
    {
        const std::lock_guard lock(mutex_);
        body_ = &body;
        count_ = count;
        chunks_ = chunks;
        finished_.store(0, std::memory_order_relaxed);
        resting_.store(false, std::memory_order_relaxed);
        generation = generation_.load(std::memory_order_relaxed) + 1;
        claim_.store((generation & kIndexMask) << 32, std::memory_order_relaxed);
        generation_.store(generation, std::memory_order_release);
    }
    wake_.notify_all();
    runChunks(generation, body, count, chunks);
    // Only chunks a worker claimed are left: they end within a chunk's time (unless the
    // system takes its core away, so after a while this thread gives its core up too).
    for (unsigned spin = 1; finished_.load(std::memory_order_acquire) < chunks; ++spin) {
        if (spin % 1024 == 0) std::this_thread::yield();
        else relax();
    }
}

void ThreadPool::rest() { resting_.store(true, std::memory_order_relaxed); }

}  // namespace throng
