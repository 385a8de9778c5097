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
    /// The erosion field at u (period 1), in [0, 1].
    double detail(const glm::dvec3& u) const;

private:
    struct Lattices;
    std::unique_ptr<Lattices> lattices_;
};

}  // namespace aerial::detail
