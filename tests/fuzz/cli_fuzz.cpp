// libFuzzer entry point for the command-line parser: the input is split at NUL and newline
// bytes into arguments. Any command or any usage error is fine; an exception escaping the
// parser (libFuzzer reports it as a crash), an empty error or one longer than a line is not.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "throng/app/cli.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args(1);
    for (std::size_t i = 0; i < size && args.size() < 64; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\0' || c == '\n') args.emplace_back();
        else args.back() += c;
    }
    if (args.size() == 1 && args.front().empty()) args.clear();
    auto command = throng::app::parseCommandLine(args);
    if (!command) {
        const std::string& message = command.error().message;
        if (message.empty()) std::abort();
        if (message.find('\n') != std::string::npos) std::abort();  // errors are one line
    }
    return 0;
}
