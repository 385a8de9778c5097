// golden_compare.cpp — `aerial_golden_compare GOLDEN.png CANDIDATE.png
// MIN_PSNR_DB [NAME]`: the peak signal-to-noise ratio of two 8-bit PNGs over
// their RGB channels, PSNR = 10 log10(255^2 / MSE) [dB] (infinite when
// identical), and the largest per-channel difference. Prints one line; exit
// 0 when PSNR >= MIN_PSNR_DB, 1 when lower, 2 on a usage error or an image
// that cannot be read or whose size differs. Used by the golden-image test
// (tests/golden/check_golden.sh) and scripts/update_golden.sh.
#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>

namespace {

struct Png {
    int width = 0, height = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};
};

bool load(const char* path, Png& png) {
    int channels = 0;
    png.pixels.reset(stbi_load(path, &png.width, &png.height, &channels, 3));
    if (!png.pixels) {
        std::fprintf(stderr, "aerial_golden_compare: %s: %s\n", path, stbi_failure_reason());
        return false;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: aerial_golden_compare GOLDEN.png CANDIDATE.png MIN_PSNR_DB [NAME]\n");
        return 2;
    }
    char* end = nullptr;
    const double minPsnr = std::strtod(argv[3], &end);
    if (end == argv[3] || !std::isfinite(minPsnr)) {
        std::fprintf(stderr, "aerial_golden_compare: MIN_PSNR_DB \"%s\" is not a number\n", argv[3]);
        return 2;
    }
    const char* name = argc > 4 ? argv[4] : argv[2];
    Png golden, candidate;
    if (!load(argv[1], golden) || !load(argv[2], candidate)) return 2;
    if (golden.width != candidate.width || golden.height != candidate.height) {
        std::fprintf(stderr, "aerial_golden_compare: %s: %dx%d, the golden is %dx%d\n", name, candidate.width,
                     candidate.height, golden.width, golden.height);
        return 2;
    }
    const std::size_t n = std::size_t(golden.width) * std::size_t(golden.height) * 3;
    double sum = 0.0;
    int largest = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int d = int(golden.pixels.get()[i]) - int(candidate.pixels.get()[i]);
        sum += double(d) * d;
        largest = std::max(largest, std::abs(d));
    }
    const double mse = sum / double(n);
    const double psnr =
        mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
    std::printf("golden %s: PSNR %.2f dB (minimum %.1f), largest difference %d/255\n", name, psnr, minPsnr,
                largest);
    return psnr >= minPsnr ? 0 : 1;
}
