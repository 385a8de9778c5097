// cloud_noise_fields.hpp — private: the continuous, periodic noise fields the
// cloud textures are sampled from (cloud_noise.cpp), so a test can check the
// fields themselves: period 1 in every axis, continuous across the wrap.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>

namespace aerial::detail {

class CloudNoiseFields {
public:
    explicit CloudNoiseFields(std::int64_t seed);
    ~CloudNoiseFields();
    CloudNoiseFields(const CloudNoiseFields&) = delete;
    CloudNoiseFields& operator=(const CloudNoiseFields&) = delete;

    /// The shape field at u (period 1) before equalisation, in [0, 1].
    double shape(const glm::dvec3& u) const;
    /// shape() at the texel centres ((i + 0.5) / size, (j + 0.5) / size,
    /// (k + 0.5) / size) of row (j, k), i = 0 .. size - 1, bit for bit, into
    /// out[0 .. size): the Worley octaves a row at a time.
    void shapeRow(int j, int k, int size, float* out) const;
    /// The erosion field at u (period 1), in [0, 1].
    double detail(const glm::dvec3& u) const;

private:
    struct Lattices;
    std::unique_ptr<Lattices> lattices_;
};

}  // namespace aerial::detail
