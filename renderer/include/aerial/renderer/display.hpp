// aerial/renderer/display.hpp — the display transform: scene-linear Rec.709
// radiance to display-referred values through OpenColorIO (DESIGN.md "Units
// and axes": display encoding happens only here).
//
// The config is, in order: DisplayDesc::config when not empty, else the file
// named by $OCIO when set, else Aerial's built-in config
// (renderer/ocio/config.ocio, embedded at build time; display "sRGB -
// Display", views "ACES 1.0 - SDR Video" (the default: a filmic tone map,
// as a game shows it), "Un-tone-mapped" and "Raw"). A config that fails to
// load falls back to the built-in one with a warning through the logger
// (DisplayTransform::fellBack()).
//
// Night vision (on by default): before the exposure, each pixel takes the
// colour the eye sees at its luminance, aerial::nightVision (exposure.hpp:
// the rods' blue, colourless vision below 5 cd/m^2), with the input's
// radiance unit DisplayDesc::nitsPerUnit (Aerial's renderer: 5000 cd/m^2).
// Exposure is in EV: the scene-linear colour is multiplied by 2^EV before
// the view. Alpha passes through unchanged.
//
// Two paths that agree to ~1e-4: the CPU (OCIO's CPUProcessor; no GL
// needed, used for PNG capture) and the GPU (OCIO's GLSL 4.0 shader, run by
// applyGpu with a current OpenGL 4.5 context; its GL objects are created on
// first use and must be destroyed with the same context current).
//
// Usage:
//   aerial::renderer::DisplayDesc desc;
//   desc.view = "ACES 1.0 - SDR Video";
//   desc.exposureEv = 1.0;
//   aerial::renderer::DisplayTransform display(desc);
//   if (!display.valid()) log(display.error());
//   aerial::renderer::Image shown = display.applyCpu(hdr);  // RGBA, [0, 1] for an SDR display
#pragma once

#include <aerial/renderer/image.hpp>
#include <aerial/renderer/log.hpp>

#include <memory>
#include <string>
#include <vector>

namespace aerial::renderer {

struct DisplayDesc {
    std::string config;   ///< config file; "" = $OCIO when set, else the built-in config
    std::string display;  ///< "" = the config's default display
    std::string view;     ///< "" = the display's default view
    double exposureEv = 0.0;
    /// Night vision (the Purkinje shift, aerial::nightVision) before the view.
    bool nightVision = true;
    /// cd/m^2 per unit of the input (aerial::kNitsPerRadianceUnit).
    double nitsPerUnit = 5000.0;
    Logger logger;
};

/// Precision of the GPU target of applyGpu.
enum class DisplayTarget { Rgba8, Rgba16F, Rgba32F };

class DisplayTransform {
public:
    explicit DisplayTransform(const DisplayDesc& desc = {});
    ~DisplayTransform();
    DisplayTransform(const DisplayTransform&) = delete;
    DisplayTransform& operator=(const DisplayTransform&) = delete;

    /// False when the display or view is unknown (error() says which, and
    /// lists what there is) or OCIO cannot build the processor.
    bool valid() const;
    const std::string& error() const;

    /// Where the config came from: "built-in", or a file path.
    const std::string& configSource() const;
    /// True when DisplayDesc::config or $OCIO named a config that could not
    /// be loaded and the built-in config is used instead.
    bool fellBack() const;

    std::vector<std::string> displays() const;
    /// The views of `display` ("" = the current display).
    std::vector<std::string> views(const std::string& display = "") const;
    const std::string& display() const;
    const std::string& view() const;

    double exposureEv() const;
    void setExposureEv(double ev);
    /// The stops [EV] that make this view show scene-linear middle grey
    /// (aerial::kMiddleGrey, 0.18: where aerial/exposure.hpp puts the
    /// metered luminance) as the picture's middle grey, the display value of
    /// 0.18 through the sRGB curve (0.461, 118/255: ISO 12232's standard
    /// output sensitivity, what a camera's picture shows a metered grey
    /// card as). 0 for "Un-tone-mapped"; about +0.5 for "ACES 1.0 - SDR
    /// Video", whose tone curve shows 0.18 at 0.35. Add it to the exposure
    /// so a view reads like a camera; clamped to [-2, 2] (a view that cannot
    /// reach middle grey); 0 when not valid(). Night vision and exposureEv()
    /// do not enter.
    double middleGreyEv() const;
    bool nightVision() const;
    void setNightVision(bool on);

    /// Display-referred RGBA floats (alpha copied; 1 for RGB or grey input),
    /// the same size as `image`. Non-finite inputs are treated as 0.
    Image applyCpu(const Image& image) const;
    /// One colour (scene-linear in, display-referred out).
    void applyCpu(float rgb[3]) const;

    /// Runs the OCIO shader on the GPU: reads `sourceTexture` (an RGBA16F or
    /// RGBA32F 2D texture, texelFetch per pixel) and writes `targetTexture`
    /// (RGBA8 or RGBA16F, same size). Needs a current OpenGL 4.5 context.
    /// False (and logs an error) when the shader cannot be built.
    bool applyGpu(unsigned sourceTexture, unsigned targetTexture, int width, int height);
    /// Convenience for tests and capture: uploads `image`, runs applyGpu into
    /// a target of the given precision and reads it back (RGBA floats; RGBA8
    /// values are byte / 255). An empty image on failure.
    Image applyGpu(const Image& image, DisplayTarget target = DisplayTarget::Rgba8);

    /// The GLSL OCIO generated (function `vec4 OCIODisplay(vec4)`), for
    /// diagnostics.
    std::string shaderText() const;

    /// The text of the built-in config.
    static std::string builtinConfigText();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial::renderer
