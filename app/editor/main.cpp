// aerial-editor — the time-of-day sky and fog editor (GLFW + Dear ImGui).
//
//   aerial-editor [PRESET] [--scene FILE.gltf] [--script FILE] [--bench N]
//                 [--size WxH] [--recover yes|no] [--autosave-seconds S]
//
// Exit codes: 0 success; 1 a script failed or a file given on the command
// line could not be read; 2 bad command line, or no display (the message
// names the headless CLI commands to use instead).
#include "editor.hpp"

#include <aerial/renderer/egl_context.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#ifndef AERIAL_VERSION
#define AERIAL_VERSION "unknown"
#endif

// Leaks inside Mesa's GL drivers, X11/xcb and GLFW's own one-time
// allocations are not Aerial's: LeakSanitizer reads these suppressions in a
// sanitizer build (ASan itself stays on for all of our code).
extern "C" __attribute__((used)) const char* __lsan_default_suppressions() {
    static const std::string suppressions = std::string(aerial::renderer::kMesaLeakSuppressions) +
                                            "leak:libGLX\nleak:libGL.so\nleak:libX11\nleak:libxcb\n"
                                            "leak:libglfw\nleak:libdbus\nleak:libxkbcommon\n";
    return suppressions.c_str();
}

// In a sanitizer build the editor keeps the X connection, and with it Mesa's
// GLX driver and LLVM, loaded until exit (editor.cpp). ASan's interception of
// __tls_get_addr then records dynamic-TLS ranges that LeakSanitizer's exit
// scan cannot read: under load its tracer crashed ("Tracer caught signal 11"
// in ScanRangeForPointers at an address below 0x2000, exit 134) in 11 of 28
// end-to-end test runs (4 editor tests at once, after every check had
// passed); with the interception off, in none of 48.
// Leak checking stays on: dynamic TLS blocks stay reachable through each
// thread's DTV, which lies in the static TLS that LeakSanitizer scans. An
// ASAN_OPTIONS setting in the environment still overrides this.
extern "C" __attribute__((used)) const char* __asan_default_options() { return "intercept_tls_get_addr=0"; }

int main(int argc, char** argv) {
    aerial::editor::EditorOptions options;
    CLI::App app{"aerial-editor — tune a day of sky and fog, place fog volumes and emitters, save presets.",
                 "aerial-editor"};
    app.set_version_flag("--version", "aerial-editor " AERIAL_VERSION);
    app.add_option("preset", options.preset, "Preset to open (JSON); default: the built-in preset")
        ->type_name("PRESET");
    app.add_option("--scene", options.scene, "glTF 2.0 scene (.gltf/.glb) instead of the built-in one")
        ->type_name("FILE");
    app.add_option("--script", options.script,
                   "Automation: run the commands of FILE, one per frame (see app/editor/editor_script.cpp)")
        ->type_name("FILE");
    app.add_option("--bench", options.benchFrames,
                   "Render N frames (scrubbing through the day) and print frame-time statistics")
        ->type_name("N")
        ->check(CLI::Range(1, 100000));
    std::string size;
    app.add_option("--size", size, "Window size in pixels (default 1280x720)")->type_name("WxH");
    app.add_option("--recover", options.recover,
                   "After a crash: recover the unsaved work (yes) or discard it (no) without asking")
        ->check(CLI::IsMember({"yes", "no"}));
    app.add_option("--autosave-seconds", options.autosaveSeconds,
                   "Seconds of unsaved work before the recovery file is written (default 30)")
        ->check(CLI::Range(0.01, 86400.0));
    app.footer(
        "\nExamples:\n"
        "  aerial-editor\n"
        "  aerial-editor presets/hazy_sunset.json --scene valley.glb\n"
        "  aerial-editor --bench 200 --size 1280x720\n"
        "\nWithout a display use the headless CLI: aerial render, aerial day, aerial bake (aerial "
        "--help).\n");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : aerial::editor::kExitUsage;
    }
    if (!size.empty()) {
        int w = 0, h = 0;
        char extra = 0;
        if (std::sscanf(size.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 320 || h < 200 || w > 16384 ||
            h > 16384) {
            std::fprintf(stderr, "aerial-editor: --size: \"%s\" is not WxH with W >= 320 and H >= 200\n",
                         size.c_str());
            return aerial::editor::kExitUsage;
        }
        options.width = w;
        options.height = h;
    }
    return aerial::editor::runEditor(options);
}
