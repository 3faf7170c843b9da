#pragma once
// Helpers shared by the command-line parser's translation units.

#include <span>
#include <string>

#include "throng/app/cli.h"

namespace throng::app::detail {

/// A usage error: BadInput, with a pointer to --help.
inline Error usage(const std::string& message) {
    return Error{Error::Kind::BadInput, message + " (see 'throng --help')", {}};
}

Result<Command> parseRender(std::span<const std::string> args);
Result<Command> parseBench(std::span<const std::string> args);
Result<Command> parseDemo(std::span<const std::string> args);
/// Options render and demo share; false when `option` is not one of them.
Result<bool> parseCrowdOption(const std::string& option, const std::string& value, CrowdOptions& command);

}  // namespace throng::app::detail
