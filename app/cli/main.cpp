// aerial — the runtime library from the shell. This file only dispatches;
// each subcommand lives in its own command_*.cpp:
//
//   aerial validate PRESET...                       command_validate.cpp
//   aerial eval PRESET [--time T] [--json]          command_eval.cpp
//   aerial sky PRESET --dir x,y,z [--time T]        command_sky.cpp
//   aerial fog PRESET --from P --to P [--time T]    command_fog.cpp
//   aerial bake PRESET --out DIR [--step 0.5h]      command_bake.cpp
//   aerial day [PRESET] [--step 1] [--json]         command_day.cpp
//   aerial render PRESET --out F.exr|png [--time T] command_render.cpp
//                                                   (builds with the renderer only)
//
// Exit codes: 0 success, 1 bad input or data, 2 bad command line; every
// error is one line on stderr ("aerial <command>: <reason>").
#include "cli_common.hpp"

#include <aerial/detail/file_system.hpp>

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <optional>

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#ifndef AERIAL_VERSION
#define AERIAL_VERSION "unknown"
#endif

#ifdef AERIAL_HAVE_RENDERER
#include <aerial/renderer/egl_context.hpp>

// Leaks inside Mesa's drivers (llvmpipe's JIT, the DRI loader) are not ours:
// LeakSanitizer reads these suppressions in a sanitizer build; otherwise the
// function is never called.
extern "C" __attribute__((used)) const char* __lsan_default_suppressions() {
    return aerial::renderer::kMesaLeakSuppressions;
}
#endif

namespace {

/// One line: CLI11 messages may span several.
std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace aerial::cli;
#ifdef AERIAL_TEST_HOOKS
    // Test hook (tests/cli/cli_test.py), compiled in only with the CMake
    // option AERIAL_TEST_HOOKS: AERIAL_TEST_FILE_FAULT=missing-directory |
    // not-writable | disk-full | sync | rename | crash makes every file this
    // run writes fail at that step (aerial/detail/file_system.hpp).
    static std::optional<aerial::detail::FaultyFileSystem> faulty;
    static std::optional<aerial::detail::ScopedFileSystem> useFaulty;
    if (const char* fault = std::getenv("AERIAL_TEST_FILE_FAULT"); fault && *fault) {
        aerial::detail::FileFault f{};
        if (!aerial::detail::parseFileFault(fault, f)) {
            std::cerr << "aerial: AERIAL_TEST_FILE_FAULT=" << fault << " is not a known fault\n";
            return kExitUsageError;
        }
        faulty.emplace(f);
        useFaulty.emplace(*faulty);
    }
#endif
    CLI::App app{
        "aerial — the Aerial sky and fog runtime from the shell: validate and evaluate presets, "
        "sample the sky, query fog, bake sky tables for games"
#ifdef AERIAL_HAVE_RENDERER
        ", render a frame headless"
#endif
        ".",
        "aerial"};
    app.footer(
        helpFooter("  aerial validate presets/*.json\n"
                   "  aerial eval presets/hazy_sunset.json --time 18:30 --json\n"
                   "  aerial sky presets/clear_summer_day.json --time 12:00 --dir 0,1,0\n"
                   "  aerial fog presets/foggy_valley_morning.json --time 7 --from 0,2,0 --to 0,2,-500\n"
                   "  aerial clouds presets/clear_summer_day.json --time 14:00 --at 0,0,0\n"
                   "  aerial bake presets/hazy_sunset.json --out bake/ --step 0.5h\n"
                   "  aerial day"
#ifdef AERIAL_HAVE_RENDERER
                   "\n  aerial render presets/clear_summer_day.json --time 12:00 --out noon.png"
#endif
                   ));
    app.set_version_flag("--version", "aerial " AERIAL_VERSION);
    app.require_subcommand(1);

    std::vector<Command> commands = {addValidateCommand(app), addEvalCommand(app), addSkyCommand(app),
                                     addFogCommand(app),      addCloudsCommand(app), addBakeCommand(app),
                                     addDayCommand(app)};
#ifdef AERIAL_HAVE_RENDERER
    commands.push_back(addRenderCommand(app));
#endif
    // A first word that is neither an option nor a command: say so plainly.
    if (argc > 1 && argv[1][0] != '-') {
        bool known = false;
        for (const Command& c : commands) known = known || c.app->check_name(argv[1]);
        if (!known) {
            std::string names;
            for (const Command& c : commands) names += (names.empty() ? "" : ", ") + c.app->get_name();
            std::cerr << "aerial: unknown command \"" << argv[1] << "\" (commands: " << names
                      << "; see aerial --help)\n";
            return kExitUsageError;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string where = "aerial";
        for (const Command& c : commands)
            if (c.app->parsed()) where += " " + c.app->get_name();
        std::cerr << where << ": " << oneLine(e.what()) << " (see " << where << " --help)\n";
        return kExitUsageError;
    }

    for (const Command& c : commands) {
        if (!c.app->parsed()) continue;
        const std::string where = "aerial " + c.app->get_name();
        try {
            return c.run();
        } catch (const CommandError& e) {
            std::cerr << where << ": " << oneLine(e.what()) << "\n";
            return e.exitCode();
        } catch (const std::bad_alloc&) {
            std::cerr << where << ": out of memory\n";
            return kExitDataError;
        } catch (const std::exception& e) {
            std::cerr << where << ": " << oneLine(e.what()) << "\n";
            return kExitDataError;
        }
    }
    std::cerr << "aerial: no command given (see aerial --help)\n";
    return kExitUsageError;
}
