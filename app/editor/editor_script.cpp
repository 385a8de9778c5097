// editor/editor_script.cpp — automation (`aerial-editor --script FILE`): one
// command per frame, through the same code paths as the menus, the
// inspector, the timeline and the viewport (the gizmo gets synthetic mouse
// presses, moves and releases, one per frame, exactly as from ImGui). A
// failing command prints "FILE:LINE: reason" and exits 1; the script ends
// the editor (exit 0) after its last command.
//
// The language is the editor's one action table (actions.hpp): a script
// line runs the action of its first word with the rest as its typed
// arguments, so every menu item and shortcut is a script command of the
// same name (request_new, undo, delete, game_view, ...). This file
// declares the actions that only scripts run: files, prompts and checks;
// editor_script_edit.cpp those that edit the preset, the layout and the
// time, editor_script_view.cpp those of the viewport and
// editor_script_curves.cpp those of the timeline's curve view and
// editor_script_weather.cpp those of the Weather panel.
//
// Parameters are addressed as in preset_edit.hpp: "fog.density_per_m",
// "volume[0].density_per_m", "emitter[1].intensity_cd". Times are hours
// or HH:MM.
#include "editor.hpp"
#include "script_args.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace aerial::editor {

void Editor::stepScript() {
    if (frames_.frameIndex < 2) return;  // the first frames lay out the window and render once
    if (runner_.waitFrames > 0) {
        --runner_.waitFrames;
        return;
    }
    if (!runner_.guiMouse.empty()) return;
    if (runner_.waitsForMouse) {
        if (!view_.scriptedMouse.empty() || view_.scriptedMouseActive) return;
        runner_.waitsForMouse = false;
    }
    if (!runner_.times.empty()) {
        playback_.timeHours = runner_.times.front();
        runner_.times.pop_front();
        return;
    }
    if (runner_.waitsForWeather) {
        if (edit_.weather.preview.playing()) return;
        runner_.waitsForWeather = false;
        std::printf("weather %s\n", edit_.weather.preview.describe().c_str());
        std::fflush(stdout);
    }
    if (runner_.waitsForAutosave) {
        if (autosave_ && autosave_->writes() > runner_.autosaveWrites) {
            runner_.waitsForAutosave = false;
            std::printf("autosaved %s\n", autosave_->recoveryFile().c_str());
            std::fflush(stdout);
        }
        return;
    }
    if (export_.running()) return;
    if (runner_.next >= runner_.commands.size()) {
        quit_ = true;
        return;
    }
    const ScriptCommand& command = runner_.commands[runner_.next++];
    std::string error;
    if (!runScriptCommand(command, error)) {
        std::fprintf(stderr, "aerial-editor: %s:%d: %s\n", options_.script.c_str(), command.line,
                     error.c_str());
        exitCode_ = kExitFailure;
        quit_ = true;
    }
}

bool Editor::runScriptCommand(const ScriptCommand& command, std::string& error) {
    std::printf("script:%d: %s\n", command.line, command.words[0].c_str());
    std::fflush(stdout);
    return actions_.runScript(command.words, error);
}

void Editor::declareScriptCommands() {
    ActionTable& table = actions_;
    using W = const ActionArgs&;
    using E = std::string&;

    // --- files ---------------------------------------------------------------------
    table.add("new").helps("a new document on the built-in preset, without asking").handles([this](W, E) {
        dialogs_.pending = Pending::New;
        runPending();
        return true;
    });
    table.add("open")
        .takes({word("PATH")})
        .helps("open a preset, without asking")
        .handles([this](W w, E error) {
            if (!openPreset(w[1])) {
                error = "open " + w[1] + " failed:\n" + dialogs_.errorText;
                return false;
            }
            return true;
        });
    table.add("open_expect_error")
        .takes({word("PATH")})
        .helps("opening PATH fails, shows the loader's errors and changes nothing")
        .handles([this](W w, E error) {
            const std::uint64_t before = doc_.revision();
            const std::string beforePath = doc_.path();
            if (openPreset(w[1])) {
                error = "open_expect_error: " + w[1] + " loaded";
                return false;
            }
            if (doc_.revision() != before || doc_.path() != beforePath) {
                error = "open_expect_error: the document changed";
                return false;
            }
            std::printf("load error shown:\n%s", dialogs_.errorText.c_str());
            return true;
        });
    table.add("save")
        .takes({word("PATH").opt()})
        .helps("save to PATH or to the document's file")
        .handles([this](W w, E error) {
            const std::string path = w.size() == 2 ? w[1] : doc_.path();
            if (path.empty()) {
                error = "save: the document has no file yet; give a PATH";
                return false;
            }
            if (!savePresetTo(path)) {
                error = "save failed: " + dialogs_.errorText;
                return false;
            }
            return true;
        });
    table.add("drop")
        .takes({word("PATH"), choice("shift", {"shift"}).opt()})
        .helps(
            "drop a file on the window (a preset or a glTF scene; with shift a glTF becomes a mesh fog "
            "volume)")
        .handles([this](W w, E) {
            dialogs_.drops.push_back({w[1], w.size() > 2});
            return true;
        });
    table.add("load_scene").takes({word("PATH")}).helps("load a glTF scene").handles([this](W w, E error) {
        if (!loadScene(w[1])) {
            error = dialogs_.errorText;
            return false;
        }
        return true;
    });
    table.add("export")
        .takes({word("DIR"), number("STEP_H").opt(), word("WxH").opt()})
        .helps("Export for game (aerial bake) into DIR (step in hours, sky table size) and wait for it")
        .handles([this](W w, E error) {
            ExportOptions options;
            if (w.size() > 2 && !toNumber(w[2], options.stepHours)) {
                error = "export: \"" + w[2] + "\" is not a number of hours";
                return false;
            }
            if (w.size() > 3 &&
                std::sscanf(w[3].c_str(), "%dx%d", &options.azimuthCount, &options.elevationCount) != 2) {
                error = "export: \"" + w[3] + "\" is not a table size WxH";
                return false;
            }
            if (!export_.start(doc_.preset(), w[1], options, error)) return false;
            export_.wait();
            export_.poll();
            if (!export_.succeeded()) {
                error = "export failed: " + export_.summary();
                export_.acknowledge();
                return false;
            }
            std::printf("exported %s: %s\n", w[1].c_str(), export_.summary().c_str());
            setStatus(exportedStatus());  // as an export from the menu says it
            export_.acknowledge();
            return true;
        });

    // --- prompts and dialogs, as the menus and buttons use them -----------------------
    table.add("request_open")
        .takes({word("PATH")})
        .helps(
            "open PATH as the menus do: ask first when there is "
            "unsaved work")
        .handles([this](W w, E) {
            requestOpen(w[1]);
            return true;
        });
    table.add("answer")
        .takes({choice("ANSWER", {"save", "discard", "cancel"})})
        .helps("press a button of the unsaved-changes prompt")
        .handles([this](W w, E error) {
            if (!dialogs_.unsavedPromptShown()) {
                error = "answer: no unsaved-changes prompt is open";
                return false;
            }
            dialogs_.openUnsavedModal = false;
            if (w[1] == "save")
                resolveUnsaved(UnsavedChoice::Save);
            else if (w[1] == "discard")
                resolveUnsaved(UnsavedChoice::Discard);
            else if (w[1] == "cancel")
                resolveUnsaved(UnsavedChoice::Cancel);
            else {
                error = "answer: save, discard or cancel";
                return false;
            }
            return true;
        });
    table.add("dialog_submit")
        .takes({word("PATH")})
        .helps("confirm the open file dialog with PATH")
        .handles([this](W w, E error) {
            if (!dialogs_.fileDialog.isOpen()) {
                error = "dialog_submit: no file dialog is open";
                return false;
            }
            if (!dialogs_.fileDialog.submit(w[1])) {
                error = "dialog_submit: " + dialogs_.fileDialog.error();
                return false;
            }
            return true;
        });
    table.add("close_window")
        .ignoresExtraWords()
        .helps("the window manager's close button (asks first)")
        .handles([this](W, E) {
            glfwSetWindowShouldClose(window_, GLFW_TRUE);
            return true;
        });
    table.add("window_screenshot")
        .takes({word("PATH.png")})
        .helps("the whole window after the next frame")
        .handles([this](W w, E) {
            runner_.windowShotPath = w[1];
            return true;
        });

    // --- waiting and printing ---------------------------------------------------------
    table.add("wait_frames").takes({count("N")}).helps("let N frames pass").handles([this](W w, E) {
        runner_.waitFrames = int(w.number(1));
        return true;
    });
    table.add("wait_autosave")
        .ignoresExtraWords()
        .helps("wait until the recovery file is written")
        .handles([this](W, E error) {
            if (!autosave_) {
                error = "wait_autosave: autosave is off";
                return false;
            }
            runner_.waitsForAutosave = true;
            runner_.autosaveWrites = autosave_->writes();
            if (!doc_.dirty()) {
                error = "wait_autosave: the document has no unsaved work";
                return false;
            }
            return true;
        });
    table.add("print")
        .takes({word("KEY")})
        .helps("print a parameter's value at the current time")
        .handles([this](W w, E error) {
            const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[1], &error);
            if (!ref) return false;
            double v[4];
            readValueAt(doc_.preset(), *ref, playback_.timeHours, v);
            std::printf("%s = %s\n", w[1].c_str(), formatValues(v, valueCount(*ref->desc)).c_str());
            return true;
        });
    table.add("quit").ignoresExtraWords().helps("end the editor now (without asking)").handles([this](W, E) {
        quit_ = true;
        return true;
    });

    // --- checks -------------------------------------------------------------------------
    const auto dirtyCheck = [this](bool wantDirty) {
        return [this, wantDirty](W, E error) {
            if (doc_.dirty() == wantDirty) return true;
            error = std::string("the document is ") + (doc_.dirty() ? "dirty" : "clean") + " (title \"" +
                    doc_.title() + "\")";
            return false;
        };
    };
    table.add("expect_dirty")
        .ignoresExtraWords()
        .helps("the document has unsaved changes")
        .handles(dirtyCheck(true));
    table.add("expect_clean")
        .ignoresExtraWords()
        .helps("the document has no unsaved changes")
        .handles(dirtyCheck(false));
    table.add("print_status")
        .ignoresExtraWords()
        .helps("print the status bar's message")
        .handles([this](W, E) {
            std::printf("status %s\n", status_.c_str());
            return true;
        });
    table.add("expect_status")
        .takes({rest("TEXT")}, "expect_status TEXT")
        .helps("TEXT is part of the status bar's message")
        .handles([this](W w, E error) {
            std::string text = w[1];
            for (std::size_t i = 2; i < w.size(); ++i) text += " " + w[i];
            if (status_.find(text) != std::string::npos) return true;
            error = "expect_status: the status is \"" + status_ + "\", not containing \"" + text + "\"";
            return false;
        });
    const auto promptCheck = [this](bool wantOpen) {
        return [this, wantOpen](W, E error) {
            const bool open = dialogs_.unsavedPromptShown();
            if (open == wantOpen) return true;
            error = std::string("the unsaved-changes prompt is ") + (open ? "open" : "not open");
            return false;
        };
    };
    table.add("expect_prompt")
        .ignoresExtraWords()
        .helps("the unsaved-changes prompt is open")
        .handles(promptCheck(true));
    table.add("expect_no_prompt")
        .ignoresExtraWords()
        .helps("the unsaved-changes prompt is not open")
        .handles(promptCheck(false));
    table.add("expect_title").takes({word("TEXT")}).helps("the window title").handles([this](W w, E error) {
        if (doc_.title() == w[1]) return true;
        error = "expect_title: have \"" + doc_.title() + "\"";
        return false;
    });
    table.add("expect_param")
        .takes({word("KEY"), number("V"), number("TOL"), rest("V").opt()}, "expect_param KEY V... TOL")
        .helps("a parameter's value at the current time, within TOL")
        .handles([this](W w, E error) {
            const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[1], &error);
            if (!ref) return false;
            const int n = valueCount(*ref->desc);
            if (int(w.size()) - 1 != n + 2) {
                error = "expect_param: " + w[1] + " has " + std::to_string(n) + " values, then TOL";
                return false;
            }
            double want[4] = {0, 0, 0, 0}, tol = 0, have[4];
            for (int i = 0; i < n; ++i)
                if (!toNumber(w[std::size_t(2 + i)], want[i])) {
                    error = "expect_param: \"" + w[std::size_t(2 + i)] + "\" is not a number";
                    return false;
                }
            if (!toNumber(w.back(), tol)) {
                error = "expect_param: \"" + w.back() + "\" is not a number";
                return false;
            }
            displayedValueAt(doc_.preset(), edit_.pending, *ref, playback_.timeHours, have);
            for (int i = 0; i < n; ++i)
                if (!(std::abs(have[i] - want[i]) <= tol)) {
                    error = "expect_param " + w[1] + ": have " + formatValues(have, n) + ", want " +
                            formatValues(want, n) + " (tolerance " + w.back() + ")";
                    return false;
                }
            return true;
        });
    const auto countCheck = [this](std::size_t (*count)(const Document&)) {
        return [this, count](W w, E error) {
            const std::size_t have = count(doc_);
            if (double(have) == w.number(1)) return true;
            error = w[0] + ": have " + std::to_string(have);
            return false;
        };
    };
    table.add("expect_volumes")
        .takes({count("N")})
        .helps("the number of fog volumes")
        .handles(countCheck([](const Document& d) { return d.preset().volumes.size(); }));
    table.add("expect_emitters")
        .takes({count("N")})
        .helps("the number of emitters")
        .handles(countCheck([](const Document& d) { return d.preset().emitters.size(); }));
    table.add("expect_cloud_volumes")
        .takes({count("N")})
        .helps("the number of cloud volumes")
        .handles(countCheck([](const Document& d) { return d.preset().cloudVolumes.size(); }));
    table.add("expect_undo")
        .takes({count("N")})
        .helps("the number of undo steps")
        .handles(countCheck([](const Document& d) { return d.undoCount(); }));
    table.add("expect_keys")
        .takes({word("KEY"), count("N")})
        .helps("the number of keys of a parameter")
        .handles([this](W w, E error) {
            double n;
            if (!toNumber(w[2], n)) {
                error = "expect_keys: \"" + w[2] + "\" is not a count";
                return false;
            }
            const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[1], &error);
            if (!ref) return false;
            const Track* track = trackOf(doc_.preset(), *ref);
            const std::size_t have = track ? track->keys.size() : 0;
            if (double(have) == n) return true;
            error = "expect_keys " + w[1] + ": have " + std::to_string(have);
            return false;
        });
    table.add("expect_selected")
        .takes({choice("KIND", {"volume", "emitter", "cloud_volume", "none", "fog", "atmosphere", "lights",
                                "exposure", "clouds"}),
                count("N").opt()})
        .helps("what the outliner has selected")
        .handles([this](W w, E error) {
            // In Selection::Kind's order.
            static const char* kinds[] = {"none",    "atmosphere", "lights", "fog",         "volume",
                                          "emitter", "exposure",   "clouds", "cloud_volume"};
            static_assert(std::size(kinds) == std::size_t(Selection::Kind::CloudVolume) + 1);
            const std::string have = kinds[int(edit_.selection.kind)];
            double n = -1;
            if (w.size() == 3 && !toNumber(w[2], n)) {
                error = "expect_selected: \"" + w[2] + "\" is not an index";
                return false;
            }
            if (have != w[1] || (w.size() == 3 && edit_.selection.index != int(n))) {
                error = "expect_selected: have " + have + " " + std::to_string(edit_.selection.index);
                return false;
            }
            return true;
        });

    declareEditScriptCommands();
    declareCurveScriptCommands();
    declareViewScriptCommands();
    declareWeatherScriptCommands();
}

}  // namespace aerial::editor
