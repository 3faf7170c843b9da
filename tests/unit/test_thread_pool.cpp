// The thread pool runs every index exactly once, whoever claims its chunk, whether its workers
// are watching for work, asleep or sent to sleep by rest(), and however many threads it has.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <ctime>
#include <thread>
#include <vector>

#include "throng/core/parallel.h"

namespace throng {
namespace {

// Runs parallelFor over `count` indices and checks each was visited once, by ranges that
// tile [0, count).
void expectEveryIndexOnce(ThreadPool& pool, std::size_t count) {
    std::vector<std::atomic<int>> visits(count);
    std::atomic<std::size_t> covered{0};
    pool.parallelFor(count, [&](std::size_t begin, std::size_t end) {
        ASSERT_LT(begin, end);
        ASSERT_LE(end, count);
        for (std::size_t i = begin; i < end; ++i) visits[i].fetch_add(1);
        covered.fetch_add(end - begin);
    });
    EXPECT_EQ(covered.load(), count);
    for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << count;
}

TEST(ThreadPool, EveryIndexOnceForAnyCountAndThreadCount) {
    for (const unsigned threads : {1U, 2U, 3U, 8U}) {
        ThreadPool pool(threads);
        EXPECT_EQ(pool.threadCount(), threads);
        for (const std::size_t count : {0UL, 1UL, 2UL, 3UL, 7UL, 16UL, 17UL, 64UL, 1000UL, 10007UL}) expectEveryIndexOnce(pool, count);
    }
}

TEST(ThreadPool, ManyJobsBackToBack) {
    // Workers still watching for the next job when it comes (the crowd step's pattern).
    ThreadPool pool(2);
    for (int job = 0; job < 3000; ++job) expectEveryIndexOnce(pool, 1 + static_cast<std::size_t>(job % 97));
}

TEST(ThreadPool, JobsAfterTheWorkersHaveGoneToSleep) {
    // Long enough between jobs that idle workers stop watching and sleep: they must still wake.
    ThreadPool pool(3);
    for (int job = 0; job < 5; ++job) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        expectEveryIndexOnce(pool, 1000);
    }
}

TEST(ThreadPool, JobsAfterRest) {
    // rest() sends idle workers to sleep at once (the crowd step's end); the next job wakes
    // them, whether they were still finishing the last one, watching or asleep.
    ThreadPool pool(3);
    for (int job = 0; job < 2000; ++job) {
        expectEveryIndexOnce(pool, 1 + static_cast<std::size_t>(job % 131));
        if (job % 3 != 0) pool.rest();
        if (job % 500 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

// CPU time of the whole process, and of the calling thread, in milliseconds.
double cpuMs(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

TEST(ThreadPool, RestLeavesTheCoresToOthers) {
    // After rest(), an idle worker sleeps instead of watching up to 100 µs for the next job, so
    // the workers use next to no CPU between a job and the next; watching, the one worker of
    // this pool would take about 100 µs of each of the 200 gaps (20 ms in all, on two cores).
    // The bound is half that: resting costs 0-2 ms in Release, but a sleeping worker's wake-ups
    // under ThreadSanitizer on a loaded machine took 6.5 ms.
    ThreadPool pool(2);
    double workersMs = 0.0;
    for (int job = 0; job < 200; ++job) {
        expectEveryIndexOnce(pool, 64);
        pool.rest();
        const double process = cpuMs(CLOCK_PROCESS_CPUTIME_ID), self = cpuMs(CLOCK_THREAD_CPUTIME_ID);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        workersMs += (cpuMs(CLOCK_PROCESS_CPUTIME_ID) - process) - (cpuMs(CLOCK_THREAD_CPUTIME_ID) - self);
    }
    EXPECT_LT(workersMs, 10.0) << "idle workers used " << workersMs << " ms of CPU between jobs after rest()";
}

TEST(ThreadPool, ResultsDoNotDependOnTheThreadCount) {
    // Each index writes its own slot from its own value: any split gives the same array.
    const auto run = [](unsigned threads) {
        ThreadPool pool(threads);
        std::vector<double> out(5000);
        for (int round = 0; round < 20; ++round)
            pool.parallelFor(out.size(), [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) out[i] = out[i] * 0.5 + static_cast<double>(i * round);
            });
        return out;
    };
    const std::vector<double> one = run(1);
    EXPECT_EQ(run(2), one);
    EXPECT_EQ(run(5), one);
}

}  // namespace
}  // namespace throng
