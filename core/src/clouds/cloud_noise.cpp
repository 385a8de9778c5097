// cloud_noise.cpp — the tileable noise the cloud layer is carved from
// (aerial/clouds.hpp, CloudNoise), after Schneider's Nubis (SIGGRAPH 2015
// "The real-time volumetric cloudscapes of Horizon: Zero Dawn", 2017 "Nubis"):
//   * shape (128^3): Perlin-Worley — Perlin fBm remapped to start at a
//     Worley billow, remap(perlin, 0, 1, worley, 1) — then carved by a Worley
//     fBm at three higher frequencies, remap(pw, wfbm - 1, 1, 0, 1), and
//     equalised so its values are uniform on [0, 1]: the fraction of the
//     layer's peak covered is then the coverage parameter itself;
//   * detail (32^3): a Worley fBm, the erosion that carves the edges.
// Every lattice is periodic in the tile, so both textures wrap seamlessly.
//
// Determinism: integer hashes of the lattice cell and the seed, IEEE double
// arithmetic (+, *, /, sqrt only — no libm transcendental), each texel
// written by exactly one task: the same floats whatever the thread count.
#include <aerial/clouds.hpp>

#include "base/worker_pool.hpp"
#include "cloud_noise_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <thread>

namespace aerial {
namespace {

std::uint32_t mix32(std::uint32_t x) {
    // Chris Wellons' "lowbias32" integer hash.
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

std::uint32_t hashCell(int x, int y, int z, std::uint32_t salt) {
    std::uint32_t h = mix32(salt);
    h = mix32(h ^ std::uint32_t(z));
    h = mix32(h ^ std::uint32_t(y));
    return mix32(h ^ std::uint32_t(x));
}

double unitFloat(std::uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }

/// Quintic fade of improved Perlin noise.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

int wrap(int i, int period) {
    const int m = i % period;
    return m < 0 ? m + period : m;
}

/// Periods are powers of two, so wrapping is a mask.
int wrapPow2(int i, int period) { return i & (period - 1); }

/// Improved Perlin noise (Perlin 2002) on a periodic lattice of `period`
/// (a power of two) cells, its gradient choices hashed once per lattice
/// point; noise(x) at x in lattice units is approximately in [-1, 1].
struct PerlinLattice {
    int period = 1;
    std::vector<std::uint8_t> gradient;  // index into kGradients per lattice point

    PerlinLattice(int period_, std::uint32_t salt)
        : period(period_), gradient(std::size_t(period_) * period_ * period_) {
        for (int z = 0; z < period; ++z)
            for (int y = 0; y < period; ++y)
                for (int x = 0; x < period; ++x)
                    gradient[std::size_t((z * period + y) * period + x)] =
                        std::uint8_t(hashCell(x, y, z, salt) % 12);
    }

    double noise(const glm::dvec3& x) const {
        static constexpr double kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                                     {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                                     {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
        const glm::dvec3 cell = glm::floor(x);
        const glm::dvec3 f = x - cell;
        const int ix = int(cell.x), iy = int(cell.y), iz = int(cell.z);
        double corner[8];
        for (int c = 0; c < 8; ++c) {
            const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
            const double* g = kGradients[gradient[std::size_t(
                (wrapPow2(iz + dz, period) * period + wrapPow2(iy + dy, period)) * period +
                wrapPow2(ix + dx, period))]];
            corner[c] = g[0] * (f.x - dx) + g[1] * (f.y - dy) + g[2] * (f.z - dz);
        }
        const double u = fade(f.x), v = fade(f.y), w = fade(f.z);
        const double x00 = corner[0] + u * (corner[1] - corner[0]);
        const double x10 = corner[2] + u * (corner[3] - corner[2]);
        const double x01 = corner[4] + u * (corner[5] - corner[4]);
        const double x11 = corner[6] + u * (corner[7] - corner[6]);
        const double y0 = x00 + v * (x10 - x00);
        const double y1 = x01 + v * (x11 - x01);
        return y0 + w * (y1 - y0);
    }
};

/// The feature points of a periodic Worley lattice (`period` a power of
/// two): one jittered point per cell, in cell units from the cell's corner.
struct WorleyLattice {
    int period = 1;
    std::vector<glm::dvec3> points;

    WorleyLattice(int period_, std::uint32_t salt)
        : period(period_), points(std::size_t(period_) * period_ * period_) {
        for (int z = 0; z < period; ++z)
            for (int y = 0; y < period; ++y)
                for (int x = 0; x < period; ++x) {
                    const std::uint32_t h = hashCell(x, y, z, salt);
                    points[std::size_t((z * period + y) * period + x)] =
                        glm::dvec3(unitFloat(h), unitFloat(mix32(h + 1U)), unitFloat(mix32(h + 2U)));
                }
    }

    /// 1 - F1 (distance to the nearest feature point, in cells, clamped to
    /// 1) at x in cell units: 1 at a feature point, billows around them.
    double billow(const glm::dvec3& x) const {
        double nearest2 = 0.0, out = 0.0;
        billowRow(&x.x, x.y, x.z, 1, &nearest2, &out);
        return out;
    }

    /// billow() at (x[i], y, z) for the n points of a row: the 27 candidates
    /// of each run of points in one cell (the cell and its neighbours) are
    /// set up once (their dx + jitter.x and the row's fixed squares ey^2,
    /// ez^2), then every point of the run goes through each candidate
    /// together, a loop over the points that vectorises. A point's result
    /// does not depend on the others in the row. `nearest2` is scratch of n
    /// doubles.
    void billowRow(const double* x, double y, double z, int n, double* nearest2, double* out) const {
        const double cy = std::floor(y), cz = std::floor(z);
        const double fy = y - cy, fz = z - cz;
        const int iy = int(cy), iz = int(cz);
        for (int begin = 0; begin < n;) {
            const double cx = std::floor(x[begin]);
            int end = begin + 1;
            while (end < n && std::floor(x[end]) == cx) ++end;
            const int ix = int(cx);
            for (int p = begin; p < end; ++p) nearest2[p] = 3.0;
            for (int dz = -1; dz <= 1; ++dz) {
                const int rowZ = wrapPow2(iz + dz, period) * period;
                for (int dy = -1; dy <= 1; ++dy) {
                    const int row = (rowZ + wrapPow2(iy + dy, period)) * period;
                    for (int dx = -1; dx <= 1; ++dx) {
                        const glm::dvec3& jitter = points[std::size_t(row + wrapPow2(ix + dx, period))];
                        const double ox = dx + jitter.x;
                        const double ey = dy + jitter.y - fy, ez = dz + jitter.z - fz;
                        const double ey2 = ey * ey, ez2 = ez * ez;
                        for (int p = begin; p < end; ++p) {
                            const double ex = ox - (x[p] - cx);
                            nearest2[p] = std::min(nearest2[p], ex * ex + ey2 + ez2);
                        }
                    }
                }
            }
            for (int p = begin; p < end; ++p) out[p] = 1.0 - std::min(1.0, std::sqrt(nearest2[p]));
            begin = end;
        }
    }
};

double remap(double v, double lo, double hi, double newLo, double newHi) {
    return newLo + (v - lo) / (hi - lo) * (newHi - newLo);
}

double saturate(double v) { return std::clamp(v, 0.0, 1.0); }

/// Replaces every value by its (interpolated) rank in [0, 1]: a histogram
/// of 65536 bins, the cumulative count at each value's position in its bin.
void equalise(std::vector<float>& values) {
    constexpr int kBins = 65536;
    std::vector<std::uint32_t> count(kBins + 1, 0);
    auto bin = [](double v, double& frac) {
        const double x = saturate(v) * kBins;
        const int b = std::min(kBins - 1, int(x));
        frac = x - b;
        return b;
    };
    double frac = 0.0;
    for (float v : values) ++count[std::size_t(bin(v, frac)) + 1];
    for (int b = 1; b <= kBins; ++b) count[std::size_t(b)] += count[std::size_t(b) - 1];
    const double n = double(values.size());
    for (float& v : values) {
        const int b = bin(v, frac);
        const double below = count[std::size_t(b)], inBin = count[std::size_t(b) + 1] - below;
        v = float(saturate((below + frac * inBin) / n));
    }
}

int machineThreads() { return int(std::max(1u, std::min(8u, std::thread::hardware_concurrency()))); }

}  // namespace

namespace detail {

struct CloudNoiseFields::Lattices {
    // Lattices in cells per tile; each octave its own salt.
    PerlinLattice perlin4, perlin8, perlin16;
    WorleyLattice billow4, worley8, worley16, worley32;
    WorleyLattice erosion4, erosion8, erosion16;

    explicit Lattices(std::uint32_t s)
        : perlin4(4, s ^ 0x3001U),
          perlin8(8, s ^ 0x3002U),
          perlin16(16, s ^ 0x3003U),
          billow4(4, s ^ 0x1001U),
          worley8(8, s ^ 0x1002U),
          worley16(16, s ^ 0x1003U),
          worley32(32, s ^ 0x1004U),
          erosion4(4, s ^ 0x2001U),
          erosion8(8, s ^ 0x2002U),
          erosion16(16, s ^ 0x2003U) {}
};

CloudNoiseFields::CloudNoiseFields(std::int64_t seed)
    : lattices_(std::make_unique<Lattices>(
          mix32(std::uint32_t(seed) ^ mix32(std::uint32_t(std::uint64_t(seed) >> 32))))) {}
CloudNoiseFields::~CloudNoiseFields() = default;

namespace {

/// The shape field from its octaves (CloudNoiseFields::shape).
double combineShape(double perlin4, double perlin8, double perlin16, double billow4, double worley8,
                    double worley16, double worley32) {
    const double p = perlin4 + 0.5 * perlin8 + 0.25 * perlin16;
    const double perlin01 = saturate(0.5 + 0.5 * p / 1.75 * 1.6);
    // Perlin-Worley: the Perlin fBm remapped to start at the Worley billow.
    const double perlinWorley = remap(perlin01, 0.0, 1.0, billow4, 1.0);
    const double fbm = 0.625 * worley8 + 0.25 * worley16 + 0.125 * worley32;
    return saturate(remap(perlinWorley, fbm - 1.0, 1.0, 0.0, 1.0));
}

}  // namespace

double CloudNoiseFields::shape(const glm::dvec3& u) const {
    const Lattices& l = *lattices_;
    return combineShape(l.perlin4.noise(u * 4.0), l.perlin8.noise(u * 8.0), l.perlin16.noise(u * 16.0),
                        l.billow4.billow(u * 4.0), l.worley8.billow(u * 8.0), l.worley16.billow(u * 16.0),
                        l.worley32.billow(u * 32.0));
}

void CloudNoiseFields::shapeRow(int j, int k, int size, float* out) const {
    const Lattices& l = *lattices_;
    const double uy = (double(j) + 0.5) / double(size), uz = (double(k) + 0.5) / double(size);
    const std::size_t n = std::size_t(std::max(size, 0));
    std::vector<double> ux(n), x(n), scratch(n), billow4(n), worley8(n), worley16(n), worley32(n);
    for (int i = 0; i < size; ++i) ux[std::size_t(i)] = (double(i) + 0.5) / double(size);
    const std::pair<const WorleyLattice*, std::vector<double>*> worley[] = {
        {&l.billow4, &billow4}, {&l.worley8, &worley8}, {&l.worley16, &worley16}, {&l.worley32, &worley32}};
    for (const auto& [lattice, values] : worley) {
        const double scale = double(lattice->period);  // each octave is read at u x its period
        for (int i = 0; i < size; ++i) x[std::size_t(i)] = ux[std::size_t(i)] * scale;
        lattice->billowRow(x.data(), uy * scale, uz * scale, size, scratch.data(), values->data());
    }
    for (int i = 0; i < size; ++i) {
        const glm::dvec3 u(ux[std::size_t(i)], uy, uz);
        const std::size_t at = std::size_t(i);
        out[i] = float(combineShape(l.perlin4.noise(u * 4.0), l.perlin8.noise(u * 8.0), l.perlin16.noise(u * 16.0),
                                    billow4[at], worley8[at], worley16[at], worley32[at]));
    }
}

double CloudNoiseFields::detail(const glm::dvec3& u) const {
    const Lattices& l = *lattices_;
    return 0.625 * l.erosion4.billow(u * 4.0) + 0.25 * l.erosion8.billow(u * 8.0) +
           0.125 * l.erosion16.billow(u * 16.0);
}

}  // namespace detail

CloudNoise generateCloudNoise(std::int64_t seed, int threadCount) {
    CloudNoise noise;
    noise.seed = seed;
    constexpr int kShape = CloudNoise::kShapeSize;
    constexpr int kDetail = CloudNoise::kDetailSize;
    noise.shape.resize(std::size_t(kShape) * kShape * kShape);
    noise.detail.resize(std::size_t(kDetail) * kDetail * kDetail);
    const detail::CloudNoiseFields fields(seed);

    detail::WorkerPool pool(threadCount > 0 ? std::min(threadCount, 64) : machineThreads());
    auto shapeSlice = [&](int k, int) {
        for (int j = 0; j < kShape; ++j)
            fields.shapeRow(j, k, kShape, noise.shape.data() + std::size_t(k * kShape + j) * kShape);
    };
    pool.run(kShape, shapeSlice);
    equalise(noise.shape);

    auto detailSlice = [&](int k, int) {
        for (int j = 0; j < kDetail; ++j)
            for (int i = 0; i < kDetail; ++i)
                noise.detail[std::size_t((k * kDetail + j) * kDetail + i)] =
                    float(fields.detail((glm::dvec3(i, j, k) + 0.5) / double(kDetail)));
    };
    pool.run(kDetail, detailSlice);
    return noise;
}

std::shared_ptr<const CloudNoise> cloudNoise(std::int64_t seed) {
    // A small most-recently-used cache: an editor flipping between presets
    // (or seeds) regenerates nothing it saw lately.
    static std::mutex mutex;
    static std::vector<std::shared_ptr<const CloudNoise>> cache;
    constexpr std::size_t kCached = 4;
    std::lock_guard<std::mutex> lock(mutex);
    for (std::size_t i = 0; i < cache.size(); ++i) {
        if (cache[i]->seed == seed) {
            std::rotate(cache.begin(), cache.begin() + std::ptrdiff_t(i),
                        cache.begin() + std::ptrdiff_t(i) + 1);
            return cache.front();
        }
    }
    auto made = std::make_shared<const CloudNoise>(generateCloudNoise(seed));
    cache.insert(cache.begin(), made);
    if (cache.size() > kCached) cache.pop_back();
    return made;
}

std::uint64_t cloudNoiseFingerprint(const CloudNoise& noise) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    auto feed = [&h](const std::vector<float>& texels) {
        for (float v : texels) {
            std::uint32_t bits = 0;
            std::memcpy(&bits, &v, sizeof bits);
            for (int b = 0; b < 4; ++b) {
                h ^= (bits >> (8 * b)) & 0xffU;
                h *= 0x100000001b3ULL;
            }
        }
    };
    feed(noise.shape);
    feed(noise.detail);
    return h;
}

double sampleTileable(const std::vector<float>& texels, int size, const glm::dvec3& uvw) {
    if (size <= 0 || texels.size() < std::size_t(size) * size * size) return 0.0;
    int i0[3], i1[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        double x = uvw[a] - std::floor(uvw[a]);  // [0, 1)
        if (!std::isfinite(x)) x = 0.0;
        x = x * size - 0.5;
        const double cell = std::floor(x);
        f[a] = x - cell;
        i0[a] = wrap(int(cell), size);
        i1[a] = wrap(int(cell) + 1, size);
    }
    auto at = [&](int x, int y, int z) { return double(texels[std::size_t((z * size + y) * size + x)]); };
    const double c00 = at(i0[0], i0[1], i0[2]) + f[0] * (at(i1[0], i0[1], i0[2]) - at(i0[0], i0[1], i0[2]));
    const double c10 = at(i0[0], i1[1], i0[2]) + f[0] * (at(i1[0], i1[1], i0[2]) - at(i0[0], i1[1], i0[2]));
    const double c01 = at(i0[0], i0[1], i1[2]) + f[0] * (at(i1[0], i0[1], i1[2]) - at(i0[0], i0[1], i1[2]));
    const double c11 = at(i0[0], i1[1], i1[2]) + f[0] * (at(i1[0], i1[1], i1[2]) - at(i0[0], i1[1], i1[2]));
    const double c0 = c00 + f[1] * (c10 - c00);
    const double c1 = c01 + f[1] * (c11 - c01);
    return c0 + f[2] * (c1 - c0);
}

}  // namespace aerial
