// Entry point of `throng`: parse the command line, run the command, map failures to exit codes.

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <variant>
#include <vector>

#include "bench_command.h"
#include "bvh_commands.h"
#include "demo_command.h"
#include "output.h"
#include "render_commands.h"
#include "simulate_command.h"
#include "throng/app/cli.h"
#include "throng/core/parallel.h"

namespace {

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;  // clang 14 lacks aggregate deduction

int run(const throng::app::Command& command) {
    using namespace throng::app;
    return std::visit(Overloaded{
                          [](const HelpCommand& c) {
                              std::fputs(c.text.c_str(), stdout);
                              return 0;
                          },
                          [](const VersionCommand&) {
                              std::printf("throng %s\n", THRONG_VERSION);
                              return 0;
                          },
                          [](const BvhInfoCommand& c) { return runBvhInfo(c); },
                          [](const BvhBakeCommand& c) { return runBvhBake(c); },
                          [](const BvhBenchCommand& c) { return runBvhBench(c); },
                          [](const RenderCommand& c) { return runRender(c); },
                          [](const DevicesCommand& c) { return runDevices(c); },
                          [](const BenchCommand& c) { return runBench(c); },
                          [](const DemoCommand& c) { return runDemo(c); },
                          [](const SimulateCommand& c) { return runSimulate(c); },
                      },
                      command);
}

// Commands that step a crowd read THRONG_THREADS where their thread pool is made, after the
// device and the crowd: checked here, a bad value is refused before any of that work.
bool stepsACrowd(const throng::app::Command& command) {
    using namespace throng::app;
    return std::holds_alternative<RenderCommand>(command) || std::holds_alternative<BenchCommand>(command) ||
           std::holds_alternative<DemoCommand>(command) || std::holds_alternative<SimulateCommand>(command);
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        auto command = throng::app::parseCommandLine(args);
        if (!command) return throng::app::reportError(command.error());
        if (stepsACrowd(command.value())) (void)throng::defaultThreadCount();  // throws for a bad THRONG_THREADS
        return run(command.value());
    } catch (const throng::ThrongException& e) {
        return throng::app::reportError(e.error());
    } catch (const std::bad_alloc&) {
        return throng::app::reportError(throng::Error{throng::Error::Kind::Runtime, "out of memory", {}});
    } catch (const std::exception& e) {
        // Inputs are read where their errors can name them (scene, BVH, outputs); this is the
        // last net, still one line and never an abort.
        return throng::app::reportError(throng::Error{throng::Error::Kind::Runtime, e.what(), {}});
    } catch (...) {
        return throng::app::reportError(throng::Error{throng::Error::Kind::Runtime, "unknown failure", {}});
    }
}
