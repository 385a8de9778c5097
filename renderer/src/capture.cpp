// capture.cpp — writing read-back frames: scene-linear half-float OpenEXR,
// and an 8-bit PNG with the plain sRGB transfer curve (Debian's libstb).
#include <aerial/renderer/display.hpp>
#include <aerial/renderer/image.hpp>

#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace aerial::renderer {
namespace {

bool checkImage(const Image& image, const std::string& path, std::string& error) {
    const bool ok =
        image.width > 0 && image.height > 0 && image.channels >= 1 && image.channels <= 4 &&
        image.pixels.size() == static_cast<std::size_t>(image.width) * image.height * image.channels;
    if (!ok) error = path + ": empty or inconsistent image";
    return ok;
}

float channelOf(const Image& image, std::size_t pixel, int c) {
    if (image.channels < 3) {
        return c < 3 ? image.pixels[pixel * image.channels] : 1.0f;
    }
    return c < image.channels ? image.pixels[pixel * image.channels + c] : 1.0f;
}

float finiteOrZero(float v) { return std::isfinite(v) ? v : 0.0f; }

double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

bool writeExr(const Image& image, const std::string& path, std::string& error) {
    if (!checkImage(image, path, error)) return false;
    try {
        const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
        std::vector<Imf::Rgba> pixels(count);
        for (std::size_t i = 0; i < count; ++i) {
            auto half = [&](int c) {
                return Imath::half(std::clamp(finiteOrZero(channelOf(image, i, c)), -65504.0f, 65504.0f));
            };
            pixels[i] = Imf::Rgba(half(0), half(1), half(2), half(3));
        }
        Imf::RgbaOutputFile file(path.c_str(), image.width, image.height, Imf::WRITE_RGBA, 1.0f,
                                 Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, Imf::ZIP_COMPRESSION);
        file.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(image.width));
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        error = path + ": cannot write EXR: " + e.what();
        return false;
    }
    return true;
}

bool writePng(const Image& image, const std::string& path, double exposure, std::string& error) {
    if (!checkImage(image, path, error)) return false;
    if (!std::isfinite(exposure) || exposure < 0.0) exposure = 1.0;
    const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
    std::vector<unsigned char> bytes(count * 3);
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double v = std::clamp(finiteOrZero(channelOf(image, i, c)) * exposure, 0.0, 1.0);
            bytes[i * 3 + c] = static_cast<unsigned char>(std::lround(srgbEncode(v) * 255.0));
        }
    }
    if (stbi_write_png(path.c_str(), image.width, image.height, 3, bytes.data(), image.width * 3) == 0) {
        error = path + ": cannot write PNG";
        return false;
    }
    return true;
}

bool writePng(const Image& image, const std::string& path, const DisplayTransform& display,
              std::string& error) {
    if (!checkImage(image, path, error)) return false;
    if (!display.valid()) {
        error = path + ": invalid display transform: " + display.error();
        return false;
    }
    const Image shown = display.applyCpu(image);
    const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
    if (shown.pixels.size() != count * 4) {
        error = path + ": the display transform failed";
        return false;
    }
    std::vector<unsigned char> bytes(count * 3);
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double v = std::clamp(static_cast<double>(finiteOrZero(shown.pixels[i * 4 + c])), 0.0, 1.0);
            bytes[i * 3 + c] = static_cast<unsigned char>(std::lround(v * 255.0));
        }
    }
    if (stbi_write_png(path.c_str(), image.width, image.height, 3, bytes.data(), image.width * 3) == 0) {
        error = path + ": cannot write PNG";
        return false;
    }
    return true;
}

}  // namespace aerial::renderer
