// editor/weather_preview.hpp — what the viewport shows of a preset's
// weather (aerial/weather.hpp) while the Weather panel previews it: the
// keyed values alone, one state, a transition A -> B at a fraction, or a
// transition played on the editor's clock with aerial::Weather. View state
// only (no GUI, unit-tested): it never edits the document, is never saved
// and is not in the undo history.
//
// The preset's weather regions are applied at the viewport's camera on top
// of what the preview shows (as a game does with regionalWeather), unless
// turned off.
//
//   WeatherPreview preview;
//   preview.play(doc.preset(), "clear", "storm", 10.0, nowSeconds, error);
//   preview.update(doc.preset(), nowSeconds, &cameraEye);  // every frame
//   compiled.evaluate(t, preview.mix(), state);             // SkyService::evaluate
#pragma once

#include <aerial/preset.hpp>
#include <aerial/weather.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace aerial::editor {

/// What the viewport shows of the weather: view state, never saved, never in
/// the undo history. The mix (weather.hpp) goes to CompiledPreset::evaluate.
class WeatherPreview {
public:
    enum class Mode { None, State, Transition };

    /// The keyed values alone.
    void showNone();
    /// State `name` fully ("none": showNone); false with `error` for an unknown name.
    bool showState(const Preset& preset, const std::string& name, std::string& error);
    /// `fraction` (clamped to 0..1) of the way from `from` to `to` (names or
    /// "none"); stops a transition being played.
    bool showTransition(const Preset& preset, const std::string& from, const std::string& to, double fraction,
                        std::string& error);
    /// Plays `from` -> `to` over `seconds` (> 0) from the clock's
    /// `nowSeconds` on, with aerial::Weather; update() moves it on.
    bool play(const Preset& preset, const std::string& from, const std::string& to, double seconds,
              double nowSeconds, std::string& error);
    /// Stops playing where the transition is (its fraction stays).
    void stop();

    /// Recomputes the mix for `preset` at the clock's `nowSeconds` (a
    /// played transition ends at `to`, fraction 1), then applies the
    /// preset's weather regions at `camera` [m, world] when it is given and
    /// regionsAtCamera(); a state that was removed or renamed ends the
    /// preview (None). True when the mix changed.
    bool update(const Preset& preset, double nowSeconds, const glm::dvec3* camera = nullptr);

    /// Whether update() applies the weather regions at the camera (default on).
    void setRegionsAtCamera(bool on) { regionsAtCamera_ = on; }
    bool regionsAtCamera() const { return regionsAtCamera_; }
    /// The regions that weighed at the camera in the last update: "ridge_storm
    /// 0.42, valley 1.00"; "" when none did.
    const std::string& regionsShown() const { return regionsShown_; }

    Mode mode() const { return mode_; }
    const std::string& state() const { return state_; }
    const std::string& from() const { return from_; }
    const std::string& to() const { return to_; }
    /// The transition's progress 0..1 (while played, as of the last update).
    double fraction() const { return fraction_; }
    bool playing() const { return playing_; }
    double playSeconds() const { return playSeconds_; }
    /// What the viewport evaluates with (empty: the keyed values).
    const WeatherMix& mix() const { return mix_; }
    /// Bumped whenever the mix changes (what the viewport compares).
    std::uint64_t revision() const { return revision_; }
    /// "none", "storm", "clear -> storm 0.50" (the script's and the viewport's
    /// words), then " + regions ridge_storm 0.42" while a region weighs at the camera.
    std::string describe() const;

private:
    Mode mode_ = Mode::None;
    std::string state_, from_ = "none", to_ = "none";
    double fraction_ = 0.0;
    bool playing_ = false;
    std::optional<Weather> weather_;
    std::vector<std::string> playNames_;  ///< the preset's state names when play() made weather_
    double playStart_ = 0.0, playSeconds_ = 0.0;
    WeatherMix mix_;
    std::uint64_t revision_ = 0;
    bool regionsAtCamera_ = true;
    std::string regionsShown_;
};

/// Reads a preview as the script writes it: "none", a state's name, or
/// "A:B:F" (a transition from A to B at the fraction F). False with `error`.
bool parseWeatherPreview(const Preset& preset, const std::string& text, WeatherPreview& preview,
                         std::string& error);

}  // namespace aerial::editor
