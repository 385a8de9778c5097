// timeline.cpp — step, linear and periodic monotone cubic (Fritsch & Carlson
// 1980, "Monotone Piecewise Cubic Interpolation", SIAM J. Numer. Anal.
// 17(2)) interpolation of keys over the wrapping 24-hour day.
#include <aerial/timeline.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

constexpr double kDayHours = 24.0;

// Index of the last key at or before t, or -1 when t is before the first key
// (the wrapping segment from the last key).
int segmentBefore(const std::vector<double>& times, double t) {
    const auto it = std::upper_bound(times.begin(), times.end(), t);
    return int(it - times.begin()) - 1;
}

double component(const glm::dvec3& v, int c) { return v[c]; }

}  // namespace

double wrapHours(double timeHours) {
    if (!std::isfinite(timeHours)) return 0.0;
    double t = std::fmod(timeHours, kDayHours);
    if (t < 0.0) t += kDayHours;
    // fmod of a tiny negative number plus 24 can round to exactly 24.
    return t < kDayHours ? t : 0.0;
}

CompiledTrack compileTrack(const Track& track, int components) {
    CompiledTrack out;
    out.interpolation = track.interpolation;
    out.wrap = track.wrap;
    out.components = components == 1 || components == 2 ? components : 3;
    const std::size_t n = track.keys.size();
    out.times.reserve(n);
    out.values.reserve(n);
    bool anySmooth = false;
    for (const TrackKey& k : track.keys) {
        out.times.push_back(k.timeHours);
        glm::dvec3 v = k.value;
        for (int c = out.components; c < 3; ++c) v[c] = 0.0;
        out.values.push_back(v);
        const Interpolation mode = k.interpolation.value_or(track.interpolation);
        out.segments.push_back(mode);
        anySmooth = anySmooth || mode == Interpolation::Smooth;
    }
    if (!anySmooth || n < 2) return out;

    // Periodic Fritsch-Carlson: segment k runs from key k to key k+1, the
    // last one from key n-1 to key 0 of the next day. A held track (no wrap)
    // has no such segment: its end tangents are 0, so the curve meets the
    // held values smoothly.
    const bool wrap = track.wrap;
    const std::size_t segments = wrap ? n : n - 1;
    std::vector<double> h(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double next = k + 1 < n ? out.times[k + 1] : out.times[0] + kDayHours;
        h[k] = next - out.times[k];
    }
    out.tangents.assign(n, glm::dvec3(0.0));
    std::vector<double> secant(n), m(n);
    for (int c = 0; c < out.components; ++c) {
        for (std::size_t k = 0; k < segments; ++k) {
            const std::size_t next = (k + 1) % n;
            secant[k] = (component(out.values[next], c) - component(out.values[k], c)) / h[k];
        }
        // Steps 1-3: mean of the neighbouring secants, 0 at extrema and flats
        // (and at the ends of a held track, and at keys marked flat).
        for (std::size_t k = 0; k < n; ++k) {
            if ((!wrap && (k == 0 || k + 1 == n)) || track.keys[k].flat) {
                m[k] = 0.0;
                continue;
            }
            const double before = secant[(k + n - 1) % n];
            const double after = secant[k];
            m[k] = (before * after > 0.0) ? 0.5 * (before + after) : 0.0;
        }
        // Step 4: keep (alpha, beta) inside the circle of radius 3 on every
        // segment; scaling only shrinks tangents, so earlier segments stay
        // monotone.
        for (std::size_t k = 0; k < segments; ++k) {
            const std::size_t next = (k + 1) % n;
            if (secant[k] == 0.0) {
                m[k] = 0.0;
                m[next] = 0.0;
                continue;
            }
            const double alpha = m[k] / secant[k];
            const double beta = m[next] / secant[k];
            const double r2 = alpha * alpha + beta * beta;
            if (r2 > 9.0) {
                const double tau = 3.0 / std::sqrt(r2);
                m[k] = tau * alpha * secant[k];
                m[next] = tau * beta * secant[k];
            }
        }
        for (std::size_t k = 0; k < n; ++k) out.tangents[k][c] = m[k];
    }
    // Keys with their own slopes replace the automatic ones (computed above
    // as if no key had any, so the neighbours' stay as they were).
    out.tangentsIn = out.tangents;
    out.givenTangents.assign(n, false);
    for (std::size_t k = 0; k < n; ++k) {
        const std::optional<KeyTangents>& given = track.keys[k].tangents;
        if (!given) continue;
        out.givenTangents[k] = true;
        for (int c = 0; c < out.components; ++c) {
            out.tangentsIn[k][c] = given->in[c];
            out.tangents[k][c] = given->out[c];
        }
    }
    return out;
}

glm::dvec3 automaticTangent(const Track& track, std::size_t key, int components) {
    if (key >= track.keys.size()) return glm::dvec3(0.0);
    Track automatic = track;
    for (TrackKey& k : automatic.keys) k.tangents.reset();
    const CompiledTrack compiled = compileTrack(automatic, components);
    return key < compiled.tangents.size() ? compiled.tangents[key] : glm::dvec3(0.0);
}

glm::dvec3 evaluateTrack(const CompiledTrack& track, double timeHours) {
    const std::size_t n = track.times.size();
    if (n == 0) return glm::dvec3(0.0);
    if (n == 1) return track.values[0];
    const double t = wrapHours(timeHours);
    int k = segmentBefore(track.times, t);
    if (!track.wrap) {  // held: the first key's value before it, the last key's after it
        if (k < 0) return track.values.front();
        if (std::size_t(k) + 1 == n) return track.values.back();
    }
    double t0, t1;
    if (k < 0) {  // before the first key: the segment from yesterday's last key
        k = int(n) - 1;
        t0 = track.times[k] - kDayHours;
        t1 = track.times[0];
    } else if (std::size_t(k) + 1 == n) {  // after the last key: towards tomorrow's first
        t0 = track.times[k];
        t1 = track.times[0] + kDayHours;
    } else {
        t0 = track.times[k];
        t1 = track.times[k + 1];
    }
    const std::size_t next = (std::size_t(k) + 1) % n;
    const glm::dvec3& y0 = track.values[k];
    const glm::dvec3& y1 = track.values[next];
    // The segment's own interpolation (a key's override), else the track's.
    const Interpolation mode =
        std::size_t(k) < track.segments.size() ? track.segments[k] : track.interpolation;
    if (mode == Interpolation::Step) return y0;

    const double h = t1 - t0;
    const double s = std::clamp((t - t0) / h, 0.0, 1.0);
    if (mode == Interpolation::Linear || track.tangents.size() != n) {
        glm::dvec3 v = y0 + (y1 - y0) * s;
        return glm::clamp(v, glm::min(y0, y1), glm::max(y0, y1));
    }
    // Cubic Hermite basis on [0, 1] with tangents scaled by the segment length.
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    const double h10 = s3 - 2.0 * s2 + s;
    const double h01 = -2.0 * s3 + 3.0 * s2;
    const double h11 = s3 - s2;
    const bool given =
        track.givenTangents.size() == n && (track.givenTangents[k] || track.givenTangents[next]);
    const glm::dvec3& arriving = track.tangentsIn.size() == n ? track.tangentsIn[next] : track.tangents[next];
    const glm::dvec3 v = h00 * y0 + h10 * h * track.tangents[k] + h01 * y1 + h11 * h * arriving;
    // The artist's slopes may overshoot; automatic (monotone) segments stay
    // within [y0, y1], and the clamp only removes rounding.
    if (given) return v;
    return glm::clamp(v, glm::min(y0, y1), glm::max(y0, y1));
}

void setKey(Track& track, double timeHours, const glm::dvec3& value) {
    const double t = wrapHours(timeHours);
    const auto it = std::lower_bound(track.keys.begin(), track.keys.end(), t,
                                     [](const TrackKey& k, double time) { return k.timeHours < time; });
    if (it != track.keys.end() && it->timeHours == t)
        it->value = value;
    else
        track.keys.insert(it, TrackKey{t, value, false, {}, 0.0, {}, {}});
}

namespace {

/// An offset wrapped into [-12, 12) h.
double wrapOffset(double hours) { return wrapHours(hours + 12.0) - 12.0; }

}  // namespace

double anchoredKeyHours(const TrackKey& key, const Location& where) {
    if (!key.anchor) return key.timeHours;
    return wrapHours(sunEventHours(where, *key.anchor) + key.offsetHours);
}

void setKeyTime(TrackKey& key, double timeHours) {
    if (key.anchor) key.offsetHours = wrapOffset(key.offsetHours + (timeHours - key.timeHours));
    key.timeHours = timeHours;
}

void anchorKey(TrackKey& key, std::optional<SunEvent> event, const Location& where) {
    key.anchor = event;
    key.offsetHours = event ? wrapOffset(key.timeHours - sunEventHours(where, *event)) : 0.0;
}

glm::dvec3 evaluateTrack(const Track& track, double timeHours, int components) {
    return evaluateTrack(compileTrack(track, components), timeHours);
}

}  // namespace aerial
