// editor/editor_script_weather.cpp — the actions only scripts run for the
// Weather panel and the viewport's weather preview: entries of the editor's
// action table (see editor_script.cpp), each through the functions the
// panel calls (weather_edit.hpp, one undo step per edit; weather_preview.hpp,
// view state only). States are named; parameters are addressed as
// everywhere else ("clouds.coverage", "volume[0].density_per_m").
#include "editor.hpp"
#include "script_args.hpp"
#include "weather_edit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aerial::editor {
namespace {

/// The value of `ref` in an evaluated state (what the viewport draws).
void readStateValue(const PresetState& state, const ParamRef& ref, double out[4]) {
    const ParamDesc& p = *ref.desc;
    const std::size_t i = std::size_t(std::max(ref.object, 0));
    switch (p.scope) {
        case ParamScope::Volume:
            readParam(p, state.volumes.at(i), out);
            break;
        case ParamScope::Emitter:
            readParam(p, state.emitters.at(i), out);
            break;
        case ParamScope::CloudVolume:
            readParam(p, state.cloudVolumes.at(i), out);
            break;
        case ParamScope::Global:
            readParam(p, state.environment, out);
            break;
    }
}

}  // namespace

void Editor::declareWeatherScriptCommands() {
    ActionTable& table = actions_;
    using W = const ActionArgs&;
    using E = std::string&;
    // The index of state `name`, or -1 with `error` set.
    const auto stateOf = [this](const std::string& command, const std::string& name, std::string& error) {
        const int index = weatherStateIndex(doc_.preset(), name);
        if (index < 0) error = command + ": no weather state \"" + name + "\"";
        return index;
    };
    // An override read from STATE PARAM MODE VALUE...: its state's index, or -1 with `error`.
    const auto overrideOf = [this, stateOf](W w, WeatherOverride& o, std::string& error) {
        const int state = stateOf(w[0], w[1], error);
        if (state < 0) return -1;
        const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[2], &error);
        if (!ref) return -1;
        if (!ref->desc->animatable) {
            error = w[0] + ": " + w[2] +
                    " does not change with the weather (only a parameter a track may key does)";
            return -1;
        }
        o.target = trackTargetOf(doc_.preset(), *ref);
        if (!weatherModeFromName(w[3], o.mode)) {
            error = w[0] + ": MODE \"" + w[3] + "\" is not one of set|add|scale";
            return -1;
        }
        const int n = ref->desc->type == ParamType::Scalar ? 1 : ref->desc->components();
        if (int(w.size()) - 4 != n) {
            error = w[0] + ": " + w[2] + " takes " + std::to_string(n) + " value(s)";
            return -1;
        }
        o.value = glm::dvec3(0.0);
        for (int c = 0; c < n; ++c)
            if (!toNumber(w[std::size_t(4 + c)], o.value[c])) {
                error = w[0] + ": \"" + w[std::size_t(4 + c)] + "\" is not a number";
                return -1;
            }
        return state;
    };
    const std::vector<ArgSpec> overrideArgs = {word("STATE"), word("PARAM"),
                                               choice("MODE", {"set", "add", "scale"}), rest("VALUE")};

    // --- the preview (view state: the document never changes) ---------------------------
    table.add("weather_preview")
        .takes({word("none|STATE|FROM:TO:F")})
        .helps(
            "what the viewport shows of the weather: the keyed values, a state, or F (0..1) of a transition")
        .handles([this](W w, E error) {
            if (parseWeatherPreview(doc_.preset(), w[1], edit_.weather.preview, error)) {
                const glm::dvec3 eye = view_.camera.eye();
                edit_.weather.preview.update(doc_.preset(), nowSeconds(), &eye);
                return true;
            }
            error = "weather_preview: " + error;
            return false;
        });
    table.add("weather_play")
        .takes({word("FROM"), word("TO"), number("SECONDS")})
        .helps("play the transition FROM -> TO over SECONDS on the editor's clock (Play transition)")
        .handles([this](W w, E error) {
            if (!edit_.weather.preview.play(doc_.preset(), w[1], w[2], w.number(3), nowSeconds(), error)) {
                error = "weather_play: " + error;
                return false;
            }
            edit_.weather.from = w[1];
            edit_.weather.to = w[2];
            edit_.weather.playSeconds = w.number(3);
            return true;
        });
    table.add("weather_wait")
        .ignoresExtraWords()
        .helps("wait until the transition being played has ended")
        .handles([this](W, E) {
            runner_.waitsForWeather = true;
            return true;
        });

    // --- edits (one undo step each) ------------------------------------------------------
    table.add("weather_add_state")
        .takes({word("NAME")})
        .oneUndoStep()
        .helps("a new, empty weather state")
        .handles([this](W w, E error) {
            if (!applyAddWeatherState(doc_, w[1], error)) {
                error = "weather_add_state: " + error;
                return false;
            }
            edit_.weather.selectedState = int(doc_.preset().weather.size()) - 1;
            return true;
        });
    table.add("weather_rename_state")
        .takes({word("NAME"), word("NEW")})
        .oneUndoStep()
        .helps("rename a weather state")
        .handles([this, stateOf](W w, E error) {
            const int state = stateOf(w[0], w[1], error);
            if (state < 0) return false;
            if (!applyRenameWeatherState(doc_, state, w[2], error)) {
                error = "weather_rename_state: " + error;
                return false;
            }
            return true;
        });
    table.add("weather_remove_state")
        .takes({word("NAME")})
        .oneUndoStep()
        .helps("remove a weather state and its overrides")
        .handles([this, stateOf](W w, E error) {
            const int state = stateOf(w[0], w[1], error);
            return state >= 0 && applyRemoveWeatherState(doc_, state, error);
        });
    table.add("weather_add_override")
        .takes(overrideArgs, "weather_add_override STATE PARAM set|add|scale VALUE...")
        .oneUndoStep()
        .helps("a state overrides a parameter it does not override yet")
        .handles([this, overrideOf](W w, E error) {
            WeatherOverride o;
            const int state = overrideOf(w, o, error);
            if (state < 0) return false;
            if (!applyAddWeatherOverride(doc_, state, o, error)) {
                error = "weather_add_override: " + error;
                return false;
            }
            edit_.weather.selectedState = state;
            return true;
        });
    table.add("weather_set_override")
        .takes(overrideArgs, "weather_set_override STATE PARAM set|add|scale VALUE...")
        .oneUndoStep()
        .helps("change the mode and value of a state's override of a parameter")
        .handles([this, overrideOf](W w, E error) {
            WeatherOverride o;
            const int state = overrideOf(w, o, error);
            if (state < 0) return false;
            const int index = weatherOverrideIndex(doc_.preset().weather[std::size_t(state)], o.target);
            if (index < 0) {
                error = "weather_set_override: " + w[1] + " does not override " + w[2];
                return false;
            }
            if (!applySetWeatherOverride(doc_, state, index, o.mode, o.value, false, error)) {
                error = "weather_set_override: " + error;
                return false;
            }
            return true;
        });
    table.add("weather_remove_override")
        .takes({word("STATE"), word("PARAM")})
        .oneUndoStep()
        .helps("a state no longer overrides a parameter")
        .handles([this, stateOf](W w, E error) {
            const int state = stateOf(w[0], w[1], error);
            if (state < 0) return false;
            const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[2], &error);
            if (!ref) return false;
            const int index = weatherOverrideIndex(doc_.preset().weather[std::size_t(state)],
                                                   trackTargetOf(doc_.preset(), *ref));
            if (index < 0) {
                error = "weather_remove_override: " + w[1] + " does not override " + w[2];
                return false;
            }
            return applyRemoveWeatherOverride(doc_, state, index, error);
        });

    // --- regions (one undo step each) ----------------------------------------------------
    // The index of region `id`, or -1 with `error` set.
    const auto regionOf = [this](const std::string& command, const std::string& id, std::string& error) {
        const int index = weatherRegionIndex(doc_.preset(), id);
        if (index < 0) error = command + ": no weather region \"" + id + "\"";
        return index;
    };
    table.add("weather_add_region")
        .takes({word("ID"), choice("SHAPE", {"box", "ellipsoid"}), word("STATE")})
        .oneUndoStep()
        .helps("a new weather region holding STATE (or none) around the camera's target, 2 x 1 x 2 km")
        .handles([this](W w, E error) {
            WeatherRegion r;
            weatherRegionShapeFromName(w[2], r.shape);
            r = newWeatherRegion(doc_.preset(), r.shape, w[3], view_.camera.state().target);
            r.id = w[1];
            if (!applyAddWeatherRegion(doc_, r, error)) {
                error = "weather_add_region: " + error;
                return false;
            }
            edit_.weather.selectedRegion = int(doc_.preset().weatherRegions.size()) - 1;
            return true;
        });
    table.add("weather_set_region")
        .takes({word("ID"), word("FIELD"), rest("VALUE")}, "weather_set_region ID FIELD VALUE...")
        .oneUndoStep()
        .helps(
            "set a region's field: id, name, shape, position_m X Y Z, half_extents_m X Y Z, yaw_deg, "
            "blend_m, priority or state")
        .handles([this, regionOf](W w, E error) {
            const int index = regionOf(w[0], w[1], error);
            if (index < 0) return false;
            WeatherRegion r = doc_.preset().weatherRegions[std::size_t(index)];
            const std::vector<std::string> values(w.words().begin() + 3, w.words().end());
            if (!setWeatherRegionField(r, w[2], values, error) ||
                !applySetWeatherRegion(doc_, index, r, false, error)) {
                error = "weather_set_region: " + error;
                return false;
            }
            return true;
        });
    table.add("weather_remove_region")
        .takes({word("ID")})
        .oneUndoStep()
        .helps("remove a weather region")
        .handles([this, regionOf](W w, E error) {
            const int index = regionOf(w[0], w[1], error);
            return index >= 0 && applyRemoveWeatherRegion(doc_, index, error);
        });
    table.add("expect_weather_region")
        .takes({word("ID"), number("WEIGHT").opt(), number("TOL").opt()})
        .helps("the preset has the weather region ID (with that weight at the camera, within TOL)")
        .handles([this, regionOf](W w, E error) {
            const int index = regionOf(w[0], w[1], error);
            if (index < 0) return false;
            if (!w.has(2)) return true;
            const double have =
                weatherRegionWeight(doc_.preset().weatherRegions[std::size_t(index)], view_.camera.eye());
            const double tol = w.has(3) ? w.number(3) : 0.0;
            if (std::abs(have - w.number(2)) <= tol) return true;
            error = "expect_weather_region " + w[1] + ": weight " + std::to_string(have) +
                    " at the camera, want " + w[2];
            return false;
        });

    // --- checks and printing -------------------------------------------------------------
    table.add("print_weather")
        .ignoresExtraWords()
        .helps("print the preview, and every state's overrides as the panel shows them at the current time")
        .handles([this](W, E) {
            const Preset& preset = doc_.preset();
            std::printf("weather preview: %s\n", edit_.weather.preview.describe().c_str());
            for (const WeatherState& s : preset.weather) {
                std::printf("weather state %s: %zu overrides\n", s.name.c_str(), s.overrides.size());
                for (const WeatherOverride& o : s.overrides) {
                    double keyed[4] = {0, 0, 0, 0};
                    if (const std::optional<ParamRef> ref = paramRefOf(preset, o.target))
                        displayedValueAt(preset, edit_.pending, *ref, playback_.timeHours, keyed);
                    std::printf("  %s\n", weatherOverrideText(preset, o, s.name, keyed).c_str());
                }
            }
            const glm::dvec3 eye = view_.camera.eye();
            for (const WeatherRegion& r : preset.weatherRegions)
                std::printf(
                    "weather region %s: %s at (%.6g, %.6g, %.6g) m, half extents (%.6g, %.6g, %.6g) m, "
                    "yaw %.6g deg, blend %.6g m, priority %d, state %s; weight %.4f at the camera\n",
                    r.id.c_str(), weatherRegionShapeName(r.shape), r.position.x, r.position.y, r.position.z,
                    r.halfExtents.x, r.halfExtents.y, r.halfExtents.z, weatherRegionYawDeg(r), r.blend,
                    r.priority, r.state.c_str(), weatherRegionWeight(r, eye));
            std::fflush(stdout);
            return true;
        });
    table.add("expect_weather_state")
        .takes({word("NAME"), count("OVERRIDES").opt()})
        .helps("the preset has the weather state NAME (with that many overrides)")
        .handles([this, stateOf](W w, E error) {
            const int state = stateOf(w[0], w[1], error);
            if (state < 0) return false;
            const std::size_t have = doc_.preset().weather[std::size_t(state)].overrides.size();
            if (w.has(2) && double(have) != w.number(2)) {
                error = "expect_weather_state " + w[1] + ": has " + std::to_string(have) + " overrides";
                return false;
            }
            return true;
        });
    table.add("expect_no_weather_state")
        .takes({word("NAME")})
        .helps("the preset has no weather state NAME")
        .handles([this](W w, E error) {
            if (weatherStateIndex(doc_.preset(), w[1]) < 0) return true;
            error = "expect_no_weather_state: " + w[1] + " exists";
            return false;
        });
    table.add("expect_weather_preview")
        .takes({word("TEXT")})
        .helps(
            "the preview, as print_weather says it (\"none\", \"storm\", \"clear -> storm 1.00\" as "
            "clear:storm:1)")
        .handles([this](W w, E error) {
            const WeatherPreview& have = edit_.weather.preview;
            WeatherPreview want;
            std::string why;
            if (!parseWeatherPreview(doc_.preset(), w[1], want, why)) {
                error = "expect_weather_preview: " + why;
                return false;
            }
            // The words compared without "(playing)": a played transition counts by where it is.
            // Nor the regions at the camera (print_weather lists them): the preview's own words.
            std::string haveText = have.describe(), wantText = want.describe();
            if (const std::size_t p = haveText.find(" + regions "); p != std::string::npos) haveText.erase(p);
            if (const std::size_t p = haveText.find(" (playing)"); p != std::string::npos) haveText.erase(p);
            if (haveText == wantText) return true;
            error = "expect_weather_preview: have \"" + have.describe() + "\", want \"" + wantText + "\"";
            return false;
        });
    table.add("expect_viewport_param")
        .takes({word("KEY"), number("V"), number("TOL"), rest("V").opt()},
               "expect_viewport_param KEY V... TOL")
        .helps("a parameter's value as the viewport draws it now (the weather preview applied), within TOL")
        .handles([this](W w, E error) {
            const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[1], &error);
            if (!ref) return false;
            const int n = valueCount(*ref->desc);
            if (int(w.size()) - 1 != n + 2) {
                error = "expect_viewport_param: " + w[1] + " has " + std::to_string(n) + " values, then TOL";
                return false;
            }
            double want[4] = {0, 0, 0, 0}, tol = 0.0, have[4];
            for (int i = 0; i <= n; ++i)
                if (!toNumber(w[std::size_t(2 + i)], i < n ? want[i] : tol)) {
                    error = "expect_viewport_param: \"" + w[std::size_t(2 + i)] + "\" is not a number";
                    return false;
                }
            updateEvaluation();
            readStateValue(sky_.state, *ref, have);
            for (int i = 0; i < n; ++i)
                if (!(std::abs(have[i] - want[i]) <= tol)) {
                    error = "expect_viewport_param " + w[1] + ": have " + formatValues(have, n) + ", want " +
                            formatValues(want, n) + " (tolerance " + w.back() + ")";
                    return false;
                }
            return true;
        });
}

}  // namespace aerial::editor
