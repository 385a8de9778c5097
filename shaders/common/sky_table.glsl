// common/sky_table.glsl — the solver's hemisphere tables as textures and
// their lookup (DESIGN.md, "Sky"): per-pixel phase functions applied to the
// phase-less integrals I_R, I_M; used by the sky pass and by the scene's
// specular sky reflections.
//
// Each texel carries where it lies (aerial/sky.hpp, "Table coordinates"; the
// renderer's sky_textures.cpp): the alpha of the Mie texture is the row's
// elevation [rad], the alpha of the Rayleigh texture the texel's azimuth
// from the point opposite the light, phi - pi [rad, -pi..pi). A lookup takes
// the two rows around the view's elevation (the upper one's weight from the
// monotone cubic through the rows' elevations) and the two columns around
// the view's azimuth (the columns' azimuths blended between the two rows
// with that weight, the weight between the two columns the monotone cubic
// through their azimuths), then the hardware's bilinear filter at that
// continuous texel, as sampleSkyTable() does. Directions below the horizon use row 0.
// Requires common/frame.glsl and common/atmosphere.glsl.
#ifndef AERIAL_SKY_TABLE_GLSL
#define AERIAL_SKY_TABLE_GLSL

layout(binding = 0) uniform sampler2D uSunRayleigh;
layout(binding = 1) uniform sampler2D uSunMie;
layout(binding = 2) uniform sampler2D uMoonRayleigh;
layout(binding = 3) uniform sampler2D uMoonMie;
layout(binding = 6) uniform sampler2D uSunMultiple;   // I_ms, isotropic (no phase)
layout(binding = 7) uniform sampler2D uMoonMultiple;

/// Elevation [rad, >= 0] and world azimuth [rad] (from north (-Z) towards
/// east (+X); straight up gives 0) of direction v. `accurate` uses
/// preciseAtan2 (the sky pass: table lookups to ~5e-6); otherwise GLSL's atan
/// (~1e-4 relative on Mesa: enough for reflections, and cheaper).
vec2 skyAngles(vec3 v, bool accurate) {
    vec2 a = vec2(max(v.y, 0.0), v.x);
    vec2 b = vec2(length(v.xz), -v.z);
    if (accurate) return vec2(preciseAtan2(a.x, b.x), preciseAtan2(a.y, b.y));
    return vec2(a.x == 0.0 && b.x == 0.0 ? 0.0 : atan(a.x, b.x), a.y == 0.0 && b.y == 0.0 ? 0.0 : atan(a.y, b.y));
}

/// The Hermite cubic from 0 to 1 over x = 0..1 with slopes m0, m1 <= 2 at
/// its ends (monotone; monotoneCubic in core/src/sky/sky_table.cpp).
float skyTableMonotoneCubic(float x, float m0, float m1) {
    float x2 = x * x, x3 = x2 * x;
    return (x3 - 2.0 * x2 + x) * m0 + (3.0 * x2 - 2.0 * x3) + (x3 - x2) * m1;
}

/// The row at or below elevation el [rad] (clamped to the table) and the
/// weight of the row above it (the Mie texture's alpha; binary search over
/// the rows): the monotone cubic through the rows' (elevation, index), as
/// rowsAround and rowWeight in core/src/sky/sky_table.cpp.
vec2 skyTableRowAt(sampler2D mie, float el, int rows) {
    int lo = 0, hi = rows - 1;
    if (!(el > texelFetch(mie, ivec2(0, lo), 0).a)) return vec2(0.0);
    if (!(el < texelFetch(mie, ivec2(0, hi), 0).a)) return vec2(float(hi), 0.0);
    while (hi - lo > 1) {
        int mid = (lo + hi) >> 1;
        if (texelFetch(mie, ivec2(0, mid), 0).a <= el) lo = mid;
        else hi = mid;
    }
    float a = texelFetch(mie, ivec2(0, lo), 0).a, b = texelFetch(mie, ivec2(0, hi), 0).a;
    float span = b - a;
    if (!(span > 0.0)) return vec2(float(lo), 0.0);
    float t = clamp((el - a) / span, 0.0, 1.0);
    float m0 = lo >= 1 ? 2.0 * span / (b - texelFetch(mie, ivec2(0, lo - 1), 0).a) : 1.0;
    float m1 = hi + 1 < rows ? 2.0 * span / (texelFetch(mie, ivec2(0, hi + 1), 0).a - a) : 1.0;
    return vec2(float(lo), clamp(skyTableMonotoneCubic(t, m0, m1), 0.0, 1.0));
}

/// Column i's azimuth from the point opposite the light (the Rayleigh
/// texture's alpha) blended between rows j0 and j1 with weight t, for i =
/// -1..columns + 1 (wrapping by 2 pi).
float skyTableBlendedAzimuth(sampler2D rayleigh, int i, int j0, int j1, float t, int columns) {
    // Whole turns without % or / on a negative int (undefined in GLSL).
    int turns = i < 0 ? -((columns - 1 - i) / columns) : i / columns;
    int k = i - turns * columns;
    float a = mix(texelFetch(rayleigh, ivec2(k, j0), 0).a, texelFetch(rayleigh, ivec2(k, j1), 0).a, t);
    return a + 2.0 * kPi * float(turns);
}

/// The continuous column (0..columns) at the azimuth s = phi - pi [rad,
/// -pi..pi) from the point opposite the light, between rows j0 and j1 with
/// the upper row's weight t: uniform columns directly; warped ones (a light
/// just set, skyTableColumnsWarped) by binary search over the columns'
/// azimuths blended between the two rows, the weight between the two
/// columns found the monotone cubic through them (columnsAround in
/// core/src/sky/sky_table.cpp).
float skyTableColumnAt(sampler2D rayleigh, int j0, int j1, float t, float s, int columns, bool warped) {
    if (!warped) return (s + kPi) / (2.0 * kPi) * float(columns);
    int lo = 0, hi = columns;
    while (hi - lo > 1) {
        int mid = (lo + hi) >> 1;
        if (skyTableBlendedAzimuth(rayleigh, mid, j0, j1, t, columns) <= s) lo = mid;
        else hi = mid;
    }
    float a = skyTableBlendedAzimuth(rayleigh, lo, j0, j1, t, columns);
    float b = skyTableBlendedAzimuth(rayleigh, hi, j0, j1, t, columns);
    float span = b - a;
    if (!(span > 0.0)) return float(lo);
    float m0 = 2.0 * span / (b - skyTableBlendedAzimuth(rayleigh, lo - 1, j0, j1, t, columns));
    float m1 = 2.0 * span / (skyTableBlendedAzimuth(rayleigh, hi + 1, j0, j1, t, columns) - a);
    return float(lo) + clamp(skyTableMonotoneCubic(clamp((s - a) / span, 0.0, 1.0), m0, m1), 0.0, 1.0);
}

/// The azimuth from the point opposite the light [rad, -pi..pi) of a world azimuth.
float skyTableAntiLightAzimuth(float azimuth, float lightAzimuth) {
    float relative = azimuth - lightAzimuth;
    relative -= 2.0 * kPi * floor(relative / (2.0 * kPi));
    return relative - kPi;
}

/// The texture coordinate of a continuous column (wrapping) and row: texel
/// centres at (i + 0.5, j + 0.5), so the hardware's bilinear filter (GL_LINEAR,
/// GL_REPEAT along the azimuth) is sampleSkyTable()'s.
vec2 skyTableCoordinate(float column, float row, vec2 size) {
    if (!(column >= 0.0) || !(column < size.x)) column = 0.0;
    return (vec2(column, row) + 0.5) / size;
}

/// The texture coordinate of a direction with the given skyAngles in a table
/// solved for a light at world azimuth `lightAzimuth` [rad].
vec2 skyTableAt(sampler2D rayleigh, sampler2D mie, vec2 angles, float lightAzimuth, vec2 size, bool warped) {
    int columns = int(size.x), rows = int(size.y);
    vec2 row = skyTableRowAt(mie, angles.x, rows);
    int j0 = int(row.x), j1 = min(j0 + 1, rows - 1);
    float s = skyTableAntiLightAzimuth(angles.y, lightAzimuth);
    return skyTableCoordinate(skyTableColumnAt(rayleigh, j0, j1, row.y, s, columns, warped), row.x + row.y, size);
}

vec3 lightSky(sampler2D rayleigh, sampler2D mie, sampler2D multiple, vec3 v, vec2 angles, vec3 lightDirection,
              float lightAzimuth, vec2 size, bool warped, vec3 illuminance) {
    if (all(equal(illuminance, vec3(0.0)))) return vec3(0.0);
    vec2 at = skyTableAt(rayleigh, mie, angles, lightAzimuth, size, warped);
    float mu = dot(v, lightDirection);
    return illuminance * (rayleighPhase(mu) * texture(rayleigh, at).rgb +
                          miePhase(mu, frame.mieAnisotropy) * texture(mie, at).rgb + texture(multiple, at).rgb);
}

/// Sky radiance in direction v (unit) from both tables, without the discs;
/// `accurate` as in skyAngles.
vec3 skyRadiance(vec3 v, bool accurate) {
    vec2 angles = skyAngles(v, accurate);
    return lightSky(uSunRayleigh, uSunMie, uSunMultiple, v, angles, frame.sunDirection, frame.sunTableAzimuth,
                    vec2(frame.sunTableColumns, frame.sunTableRows), frame.sunTableWarped != 0.0,
                    frame.sunIlluminanceSpace) +
           lightSky(uMoonRayleigh, uMoonMie, uMoonMultiple, v, angles, frame.moonDirection, frame.moonTableAzimuth,
                    vec2(frame.moonTableColumns, frame.moonTableRows), frame.moonTableWarped != 0.0,
                    frame.moonIlluminanceSpace);
}

#endif
