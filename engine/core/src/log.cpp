#include "throng/core/log.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace throng::log {
namespace {

Level levelFromEnvironment() {
    const char* value = std::getenv("THRONG_LOG");
    if (value == nullptr) return Level::Warning;
    if (std::strcmp(value, "debug") == 0) return Level::Debug;
    if (std::strcmp(value, "info") == 0) return Level::Info;
    if (std::strcmp(value, "error") == 0) return Level::Error;
    return Level::Warning;
}

std::atomic<int>& thresholdStorage() {
    static std::atomic<int> storage{static_cast<int>(levelFromEnvironment())};
    return storage;
}

}  // namespace

Level threshold() { return static_cast<Level>(thresholdStorage().load()); }
void setThreshold(Level level) { thresholdStorage().store(static_cast<int>(level)); }

namespace {
// One lock so lines from worker threads never interleave mid-line.
void writeLine(std::string_view prefix, std::string_view message) {
    static std::mutex mutex;
    const std::lock_guard lock(mutex);
    std::fprintf(stderr, "throng: %.*s%.*s\n", static_cast<int>(prefix.size()), prefix.data(), static_cast<int>(message.size()),
                 message.data());
}
}  // namespace

void write(Level level, std::string_view message) {
    if (static_cast<int>(level) < static_cast<int>(threshold())) return;
    static constexpr std::string_view kPrefixes[] = {"debug: ", "info: ", "warning: ", "error: "};
    writeLine(kPrefixes[static_cast<int>(level)], message);
}

void report(std::string_view message) { writeLine("", message); }

}  // namespace throng::log
