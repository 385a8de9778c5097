// aerial/renderer/image.hpp — a float image read back from the renderer, and
// writing it to disk: scene-linear EXR (half float) and a display PNG.
//
// Usage:
//   aerial::renderer::Image hdr = renderer.readColour();
//   std::string error;
//   if (!aerial::renderer::writeExr(hdr, "frame.exr", error)) log(error);
//   aerial::renderer::writePng(hdr, "frame.png", 1.0, error);   // plain sRGB curve
//   aerial::renderer::DisplayTransform display({});             // display.hpp (OCIO)
//   aerial::renderer::writePng(hdr, "frame.png", display, error);
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace aerial::renderer {

class DisplayTransform;  // display.hpp

/// Pixels row by row, the TOP row first, `channels` floats per pixel
/// (scene-linear Rec.709 radiance for colour; normalised linear depth for
/// depth).
struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;

    float at(int x, int y, int channel) const {
        return pixels[(static_cast<std::size_t>(y) * width + x) * channels + channel];
    }
};

/// Writes RGBA (or RGB; alpha 1) as a scene-linear half-float OpenEXR file
/// (ZIP compression). Non-finite values are written as 0 and values beyond
/// the half range clamp to +-65504. Returns false and sets `error` (naming
/// the file and the reason) on failure.
bool writeExr(const Image& image, const std::string& path, std::string& error);

/// Writes an 8-bit sRGB PNG: colour * exposure, clamped to [0, 1], encoded
/// with the sRGB transfer curve (alpha dropped). A plain encoding, not a
/// display transform with tone mapping. Returns false and sets `error` on
/// failure.
bool writePng(const Image& image, const std::string& path, double exposure, std::string& error);

/// Writes an 8-bit PNG of the display-referred image: `display` (its
/// exposure, display and view; DisplayTransform::applyCpu) maps the
/// scene-linear colour, which is then clamped to [0, 1] and quantised
/// (alpha dropped). Returns false and sets `error` on failure (including an
/// invalid transform).
bool writePng(const Image& image, const std::string& path, const DisplayTransform& display,
              std::string& error);

}  // namespace aerial::renderer
