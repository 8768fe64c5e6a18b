// Seeded perturbations of a scene, so that a figure from a chaotic system can be a distribution
// (a median over perturbed runs, with its range) instead of one run's accident. Seed 0 leaves the
// scene as built; any other seed tilts and scales gravity and scales every dynamic body's initial
// velocities, each by a relative amount drawn from [-kPerturbation, kPerturbation].
#pragma once

#include <cstdint>

#include "scene.h"

namespace pivot::scenes {

/// The relative size of a perturbation: about 1e-3, small beside any effect the report
/// measures, large beside a float's rounding.
constexpr float kPerturbation = 1.0e-3f;

/// What one seed changes. Every factor is 1 and the tilt 0 for seed 0.
struct Perturbation {
    float gravityScale = 1.0f;
    float gravityTilt = 0.0f;  ///< rad
    std::uint64_t velocitySeed = 0;

    static Perturbation of(std::uint32_t seed);
};

/// Gravity for the world `options` describes, perturbed by `seed`.
Vec2 perturbedGravity(Vec2 gravity, std::uint32_t seed);

/// Scales each of the scene's dynamic bodies' initial linear and angular velocities by its own
/// factor in [1 - kPerturbation, 1 + kPerturbation]. Nothing for seed 0.
void perturbVelocities(Scene& scene, std::uint32_t seed);

}  // namespace pivot::scenes
