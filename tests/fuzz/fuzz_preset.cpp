// fuzz_preset.cpp — libFuzzer target for the preset loader
// (aerial::parsePreset, the same code loadPreset runs on a file's bytes).
//
// For every input:
//   * parsing never crashes, never throws, never hangs and allocates within
//     the limits of aerial/limits.hpp (libFuzzer's -rss_limit_mb and
//     -timeout catch the rest);
//   * a failed load has at least one error, each naming the file;
//   * a preset that loads is valid (validatePreset finds nothing), saves to
//     JSON that loads back bit for bit (presetsIdentical), and evaluates at
//     a few times of day to finite values only (nothing non-finite reaches
//     the renderer).
// Any broken property aborts, which libFuzzer reports as a crash.
//
// Built two ways (tests/fuzz/CMakeLists.txt): with clang and
// -fsanitize=fuzzer as a real fuzzer (scripts/fuzz.sh), and in every normal
// build with replay_main.cpp, which runs the seed corpus through it as a
// CTest test.
#include <aerial/evaluate.hpp>
#include <aerial/finite.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/preset.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz_preset: property broken: %s\n", what);
        std::abort();
    }
}

using aerial::isFinite;

void checkState(const aerial::PresetState& s) {
    check(isFinite(s.sunLight.body.direction) && isFinite(s.sunLight.illuminance), "finite sun");
    check(isFinite(s.moonLight.body.direction) && isFinite(s.moonLight.illuminance), "finite moon");
    const aerial::Environment& e = s.environment;
    check(std::isfinite(e.fog.density) && std::isfinite(e.fog.falloff) && std::isfinite(e.fog.baseHeight),
          "finite fog");
    check(isFinite(e.atmosphere.rayleighScattering) && isFinite(e.atmosphere.mieScattering) &&
              isFinite(e.atmosphere.mieExtinction),
          "finite atmosphere");
    for (const aerial::FogVolume& v : s.volumes)
        check(isFinite(v.position) && isFinite(v.halfExtents) && std::isfinite(v.density) &&
                  isFinite(v.colour) && isFinite(v.gradientDirection) && v.density >= 0.0 &&
                  v.halfExtents.x > 0.0 && v.halfExtents.y > 0.0 && v.halfExtents.z > 0.0,
              "finite, positive volume");
    for (const aerial::Emitter& m : s.emitters)
        check(isFinite(m.position) && std::isfinite(m.intensity) && isFinite(m.colour) && m.intensity >= 0.0 &&
                  std::isfinite(m.intensityCd) && m.intensityCd >= 0.0 && std::isfinite(m.extinction) &&
                  m.extinction >= 0.0,
              "finite emitter");
    for (const aerial::CloudVolume& c : s.cloudVolumes)
        check(isFinite(c.position) && isFinite(c.halfExtents) && std::isfinite(c.coverage) &&
                  std::isfinite(c.edgeSoftness) && c.coverage >= 0.0 && c.coverage <= 1.0 &&
                  c.halfExtents.x >= 1.0 && c.halfExtents.y >= 1.0 && c.halfExtents.z >= 1.0,
              "finite cloud volume, coverage in [0, 1], extents >= 1 m");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    static const std::string file = std::string(AERIAL_SOURCE_DIR) + "/tests/data/bad_inputs/presets/fuzz.json";
    aerial::PresetLoadResult r = aerial::parsePreset(text, file);
    if (!r.ok()) {
        check(!r.errors.empty(), "a failed load reports an error");
        for (const aerial::PresetIssue& e : r.errors)
            check(e.file == file, "every error names the file");
        return 0;
    }
    check(r.errors.empty(), "a loaded preset has no errors");
    const aerial::Preset& preset = *r.preset;
    check(aerial::validatePreset(preset).empty(), "a loaded preset validates");

    const std::string saved = aerial::presetToJson(preset);
    aerial::PresetLoadResult again = aerial::parsePreset(saved, file);
    check(again.ok(), "the saved text loads");
    check(aerial::presetsIdentical(preset, *again.preset), "save + load gives the same preset");

    const aerial::CompiledPreset compiled(preset);
    check(compiled.issues().empty(), "a valid preset compiles without issues");
    aerial::PresetState state;
    for (double t : {0.0, 6.25, 12.0, 18.75, 23.99}) {
        compiled.evaluate(t, state);
        checkState(state);
    }
    // The fog of the last state along a few segments: finite, T in [0, 1].
    aerial::FogSceneDesc desc;
    desc.heightFog = state.environment.fog;
    desc.volumes = state.volumes;
    const aerial::FogScene scene(desc);
    for (const auto& [from, to] : {std::pair{glm::dvec3(0, 2, 0), glm::dvec3(0, 2, -500)},
                                   std::pair{glm::dvec3(-300, 5, 10), glm::dvec3(300, 1, -10)},
                                   std::pair{glm::dvec3(1, 1, 1), glm::dvec3(1, 1, 1)}}) {
        const aerial::FogQueryResult q = scene.query(from, to);
        check(isFinite(q.transmittance) && isFinite(q.inScatter) && q.transmittance.x >= 0.0 &&
                  q.transmittance.x <= 1.0 && q.globalOpticalDepth >= 0.0,
              "finite fog queries");
    }
    return 0;
}
