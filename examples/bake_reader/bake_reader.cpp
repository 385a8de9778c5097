// bake_reader — an engine's reader of an `aerial bake` directory, written
// from manifest.json's words and the OpenEXR format alone: it links no Aerial
// code (OpenEXR and nlohmann/json only). It answers, for a step of the bake,
// the sky's radiance in a direction, the global fog along a segment and the
// ambient irradiance on a surface, as an engine's shaders would compute
// them from the bake's textures and numbers.
//
// Usage:
//   bake_reader BAKE_DIR < queries
// one query per line, one answer per line:
//   sky STEP x y z                  -> r g b        (sky-view map, bilinear)
//   fog STEP px py pz qx qy qz      -> T r g b      (the fog formula: T, and the in-scatter S)
//   fogcolour STEP x y z s          -> r g b        (L_fog(v, s), before the colour mode)
//   irradiance STEP nx ny nz        -> r g b        (sky_irradiance_sh9)
// STEP is the step's index in manifest.json. Lines starting with # are skipped.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

using Vec3 = std::array<double, 3>;

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // line 0 first

    Vec3 texel(int x, int y) const {
        x = ((x % width) + width) % width;  // azimuth repeats
        y = std::clamp(y, 0, height - 1);  // lines clamp
        const std::size_t at = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
        return {rgb[at], rgb[at + 1], rgb[at + 2]};
    }
    /// Bilinear at texture coordinates (u, v) in [0, 1], texel centres at (i + 0.5) / size.
    Vec3 sample(double u, double v) const {
        const double x = u * width - 0.5, y = v * height - 0.5;
        const double fx = std::floor(x), fy = std::floor(y), ax = x - fx, ay = y - fy;
        const int ix = int(fx), iy = int(fy);
        Vec3 out{};
        for (int c = 0; c < 3; ++c)
            out[c] = (1 - ay) * ((1 - ax) * texel(ix, iy)[c] + ax * texel(ix + 1, iy)[c]) +
                     ay * ((1 - ax) * texel(ix, iy + 1)[c] + ax * texel(ix + 1, iy + 1)[c]);
        return out;
    }
};

/// Channels R, G, B of a bake's map, read as 32-bit float (manifest:
/// pixel_type float; half float could not hold a moonless sky).
Image readExr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    Image image;
    image.width = dw.max.x - dw.min.x + 1;
    image.height = dw.max.y - dw.min.y + 1;
    image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    Imf::FrameBuffer frame;
    const std::size_t xStride = sizeof(float) * 3, yStride = xStride * std::size_t(image.width);
    char* origin = reinterpret_cast<char*>(image.rgb.data()) - dw.min.x * long(xStride) - dw.min.y * long(yStride);
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
        frame.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(frame);
    file.readPixels(dw.min.y, dw.max.y);
    return image;
}

Vec3 vec3(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalised(Vec3 v) {
    const double n = std::sqrt(dot(v, v));
    if (!(n > 0.0)) return {0.0, 1.0, 0.0};
    return {v[0] / n, v[1] / n, v[2] / n};
}
double azimuthOf(const Vec3& v) {  // from north (-Z) towards east (+X)
    double az = std::atan2(v[0], -v[2]);
    return az < 0.0 ? az + 2.0 * kPi : az;
}

/// P_M(mu, g) as the manifest's table.phase_mie.
double phaseMie(double mu, double g) {
    const double g2 = g * g;
    return 3.0 / (8.0 * kPi) * (1.0 - g2) * (1.0 + mu * mu) / ((2.0 + g2) * std::pow(1.0 + g2 - 2.0 * g * mu, 1.5));
}

class Bake {
public:
    explicit Bake(std::string dir) : dir_(std::move(dir)) {
        std::ifstream in(dir_ + "/manifest.json");
        if (!in) throw std::runtime_error(dir_ + "/manifest.json: cannot open");
        manifest_ = nlohmann::json::parse(in);
        if (manifest_.at("format") != "aerial-bake" || manifest_.at("format_version") != 3)
            throw std::runtime_error(dir_ + "/manifest.json: format_version: this reader reads version 3");
    }

    const nlohmann::json& step(int index) const { return manifest_.at("steps").at(std::size_t(index)); }

    /// The sky-view map: u = phi / (2 pi), v = ((H - 1) sqrt(el / (pi/2)) + 0.5) / H.
    Vec3 sky(int index, const Vec3& direction) {
        const Image& map = image(step(index).at("sky_view_file"));
        const Vec3 v = normalised(direction);
        const double el = std::asin(std::clamp(v[1], 0.0, 1.0));
        return map.sample(azimuthOf(v) / (2.0 * kPi),
                          ((map.height - 1) * std::sqrt(el / (kPi / 2.0)) + 0.5) / map.height);
    }

    /// L_fog(v, s) before the colour mode (manifest: fog.formula.colour).
    Vec3 fogColour(int index, const Vec3& direction, double s) {
        const nlohmann::json& fog = step(index).at("fog");
        const Vec3 v = normalised(direction);
        const double g = fog.at("anisotropy").get<double>();
        const Vec3 l0 = vec3(fog.at("sky_l0_rgb"));
        const nlohmann::json& l1 = fog.at("sky_l1_rgb");
        Vec3 lit{};
        for (int c = 0; c < 3; ++c)
            lit[c] = std::max(l0[c] + vec3(l1[0])[c] * v[0] + vec3(l1[1])[c] * v[1] + vec3(l1[2])[c] * v[2], 0.0);
        for (const nlohmann::json& light : fog.at("direct")) {
            const double p = phaseMie(std::clamp(dot(v, vec3(light.at("direction"))), -1.0, 1.0), g);
            const Vec3 e = vec3(light.at("illuminance_rgb"));
            for (int c = 0; c < 3; ++c) lit[c] += e[c] * p;
        }
        const Image& far = image(fog.at("far_fog_file"));
        const double el = std::asin(std::clamp(v[1], -1.0, 1.0));
        const Vec3 horizon = far.sample(azimuthOf(v) / (2.0 * kPi), (kPi / 2.0 - el) / kPi);
        const double x = s / fog.at("horizon_distance_m").get<double>();
        const double w = s > 0.0 ? -std::expm1(-x * x) : 0.0;
        Vec3 out{};
        for (int c = 0; c < 3; ++c) out[c] = (1.0 - w) * lit[c] + w * horizon[c];
        return out;
    }

    /// The global fog from p to q: transmittance and in-scatter (fog.formula).
    std::pair<double, Vec3> fog(int index, const Vec3& p, const Vec3& q) {
        const nlohmann::json& fog = step(index).at("fog");
        const Vec3 d{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        const double s = std::sqrt(dot(d, d));
        const double b = fog.at("density_per_m").get<double>(), c = fog.at("falloff_per_m").get<double>();
        const double h0 = fog.at("base_height_m").get<double>();
        const double x = c * std::abs(d[1]);
        const double factor = x > 0.0 ? -std::expm1(-x) / x : 1.0;
        const double tau = std::min(b * s * std::exp(-c * (std::min(p[1], q[1]) - h0)) * factor, 1e4);
        const double t = std::exp(-tau);
        Vec3 colour = fogColour(index, d, s);
        const std::string mode = fog.at("colour_mode");
        const Vec3 tint = vec3(fog.at("colour_rgb"));
        for (int k = 0; k < 3; ++k) {
            if (mode == "tinted") colour[k] *= tint[k];
            if (mode == "custom") colour[k] = tint[k];
            colour[k] *= 1.0 - t;
        }
        return {t, colour};
    }

    /// E(n) = sum c_i Y_i(n) (manifest: sky_irradiance_sh9).
    Vec3 irradiance(int index, const Vec3& normal) {
        const nlohmann::json& sh = step(index).at("sky_irradiance_sh9");
        const Vec3 n = normalised(normal);
        const double x = n[0], y = n[1], z = n[2];
        const double basis[9] = {0.282095,         0.488603 * y,     0.488603 * z,
                                 0.488603 * x,     1.092548 * x * y, 1.092548 * y * z,
                                 0.315392 * (3.0 * z * z - 1.0), 1.092548 * x * z, 0.546274 * (x * x - y * y)};
        Vec3 e{};
        for (int i = 0; i < 9; ++i)
            for (int c = 0; c < 3; ++c) e[c] += vec3(sh.at(std::size_t(i)))[c] * basis[i];
        for (double& v : e) v = std::max(v, 0.0);
        return e;
    }

private:
    const Image& image(const std::string& file) {
        auto it = images_.find(file);
        if (it == images_.end()) it = images_.emplace(file, readExr(dir_ + "/" + file)).first;
        return it->second;
    }

    std::string dir_;
    nlohmann::json manifest_;
    std::map<std::string, Image> images_;
};

void print(const Vec3& v) { std::printf("%.9g %.9g %.9g\n", v[0], v[1], v[2]); }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: bake_reader BAKE_DIR < queries\n");
        return 2;
    }
    try {
        Bake bake(argv[1]);
        std::string line;
        while (std::getline(std::cin, line)) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream in(line);
            std::string what;
            int step = 0;
            in >> what >> step;
            Vec3 a{}, b{};
            if (what == "sky" && in >> a[0] >> a[1] >> a[2]) {
                print(bake.sky(step, a));
            } else if (what == "fog" && in >> a[0] >> a[1] >> a[2] >> b[0] >> b[1] >> b[2]) {
                const auto [t, s] = bake.fog(step, a, b);
                std::printf("%.9g %.9g %.9g %.9g\n", t, s[0], s[1], s[2]);
            } else if (what == "fogcolour" && in >> a[0] >> a[1] >> a[2] >> b[0]) {
                print(bake.fogColour(step, a, b[0]));
            } else if (what == "irradiance" && in >> a[0] >> a[1] >> a[2]) {
                print(bake.irradiance(step, a));
            } else {
                std::fprintf(stderr, "bake_reader: cannot read the query \"%s\"\n", line.c_str());
                return 2;
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bake_reader: %s\n", e.what());
        return 1;
    }
    return 0;
}
