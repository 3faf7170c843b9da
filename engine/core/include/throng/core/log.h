#pragma once
// Minimal leveled logging to stderr. Errors meant for the user are printed by the CLI
// directly; this is for diagnostics (verbosity raised with THRONG_LOG=debug).

#include <string_view>

namespace throng::log {

enum class Level { Debug = 0, Info = 1, Warning = 2, Error = 3 };

/// Messages below this level are dropped. Default Warning, or from env THRONG_LOG
/// (debug|info|warning|error), read once on first use.
Level threshold();
void setThreshold(Level level);

void write(Level level, std::string_view message);
inline void debug(std::string_view m) { write(Level::Debug, m); }
inline void info(std::string_view m) { write(Level::Info, m); }
inline void warning(std::string_view m) { write(Level::Warning, m); }
inline void error(std::string_view m) { write(Level::Error, m); }

}  // namespace throng::log
