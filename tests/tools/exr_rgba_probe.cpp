// exr_rgba_probe.cpp — reads an EXR through OpenEXR's RGBA-only interface
// (Imf::RgbaInputFile, what simple engine loaders use) and prints the
// requested pixels, so the end-to-end tests check that a baked radiance EXR
// opens in such a reader and holds the radiance it should.
//   exr_rgba_probe FILE.exr X,Y [X,Y ...]
// Prints one line "width height", then "x y r g b a" per pixel. Exit 1 when
// the file does not open or a pixel is outside it.
#include <ImfArray.h>
#include <ImfRgbaFile.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: exr_rgba_probe FILE.exr X,Y...\n");
        return 2;
    }
    try {
        Imf::RgbaInputFile file(argv[1]);
        const Imath::Box2i window = file.dataWindow();
        const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
        Imf::Array2D<Imf::Rgba> pixels(height, width);
        file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, std::size_t(width));
        file.readPixels(window.min.y, window.max.y);
        std::printf("%d %d\n", width, height);
        for (int i = 2; i < argc; ++i) {
            int x = -1, y = -1;
            if (std::sscanf(argv[i], "%d,%d", &x, &y) != 2 || x < 0 || y < 0 || x >= width || y >= height) {
                std::fprintf(stderr, "exr_rgba_probe: pixel %s is not in %dx%d\n", argv[i], width, height);
                return 1;
            }
            const Imf::Rgba& p = pixels[y][x];
            std::printf("%d %d %.9g %.9g %.9g %.9g\n", x, y, float(p.r), float(p.g), float(p.b), float(p.a));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "exr_rgba_probe: %s: %s\n", argv[1], e.what());
        return 1;
    }
    return 0;
}
