// default_preset.cpp — defaultPreset: the built-in preset the editor opens
// on (aerial/preset.hpp).
#include <aerial/preset.hpp>

#include <utility>
#include <vector>

namespace aerial {

Preset defaultPreset() {
    Preset p;
    p.name = "Default";
    p.description =
        "Earth's atmosphere at 45 deg N in June; a light haze, a morning ground fog that burns off "
        "by noon and a lamp lit at night.";
    Environment& env = p.environment;
    // A full moon on the default day (172): night reads as moonlit.
    env.location.moonPhaseOffsetDays = 20.0;
    env.fog.density = 0.0004;
    env.fog.falloff = 0.02;
    env.fog.baseHeight = 0.0;

    FogVolume ground;
    ground.id = "ground_fog";
    ground.name = "Ground fog";
    ground.shape = FogVolumeShape::Ellipsoid;
    ground.position = {0.0, 0.0, -60.0};
    ground.halfExtents = {80.0, 12.0, 60.0};
    ground.density = 0.03;
    ground.falloff = 0.15;
    p.volumes.push_back(ground);

    Emitter lamp;
    lamp.id = "lamp";
    lamp.name = "Lamp";
    lamp.position = {6.0, 4.0, -20.0};
    lamp.intensityCd = 0.0;   // keyed: a 1 500 cd sodium lamp at night
    lamp.attenuation = 10.0;  // a glowing core ~0.3 m across
    lamp.temperatureK = 2100.0;
    p.emitters.push_back(lamp);

    auto track = [](TrackTarget target, Interpolation interp, std::vector<TrackKey> keys) {
        Track t;
        t.target = std::move(target);
        t.interpolation = interp;
        t.keys = std::move(keys);
        return t;
    };
    p.tracks.push_back(track(TrackTarget::global("fog.density_per_m"), Interpolation::Smooth,
                             {{0.0, glm::dvec3(0.0006, 0, 0)},
                              {6.0, glm::dvec3(0.0012, 0, 0)},
                              {14.0, glm::dvec3(0.0002, 0, 0)},
                              {20.0, glm::dvec3(0.0004, 0, 0)}}));
    p.tracks.push_back(track(TrackTarget::volume("ground_fog", "density_per_m"), Interpolation::Smooth,
                             {{4.0, glm::dvec3(0.0)},
                              {6.5, glm::dvec3(0.035, 0, 0)},
                              {9.0, glm::dvec3(0.01, 0, 0)},
                              {12.0, glm::dvec3(0.0)}}));
    p.tracks.push_back(track(TrackTarget::emitter("lamp", "intensity_cd"), Interpolation::Linear,
                             {{5.5, glm::dvec3(1500.0, 0, 0)},
                              {6.5, glm::dvec3(0.0)},
                              {19.5, glm::dvec3(0.0)},
                              {20.5, glm::dvec3(1500.0, 0, 0)}}));
    return p;
}

}  // namespace aerial
