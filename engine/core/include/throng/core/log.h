#pragma once
// Everything Throng says on stderr goes through here, one whole line at a time (lines from
// worker threads never interleave). report() is for what the user asked to see: errors and
// results, always printed. The levelled calls are diagnostics, filtered by THRONG_LOG.

#include <string_view>

namespace throng::log {

enum class Level { Debug = 0, Info = 1, Warning = 2, Error = 3 };

/// Messages below this level are dropped. Default Warning, or from env THRONG_LOG
/// (debug|info|warning|error), read once on first use.
Level threshold();
void setThreshold(Level level);

/// "throng: <level>: message", if `level` passes the threshold.
void write(Level level, std::string_view message);
/// "throng: message", always: errors (whose text names their own kind) and results.
void report(std::string_view message);
inline void debug(std::string_view m) { write(Level::Debug, m); }
inline void info(std::string_view m) { write(Level::Info, m); }
inline void warning(std::string_view m) { write(Level::Warning, m); }
inline void error(std::string_view m) { write(Level::Error, m); }

}  // namespace throng::log
