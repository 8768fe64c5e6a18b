#include "perturbation.h"

#include <cmath>

namespace pivot::scenes {

namespace {

// SplitMix64: a few lines, good enough to spread seeds, and the same on every platform (the
// standard library's distributions are not).
std::uint64_t nextRandom(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A number in [-1, 1].
float symmetric(std::uint64_t& state) {
    return static_cast<float>(nextRandom(state) >> 40) / static_cast<float>(1u << 23) - 1.0f;
}

}  // namespace

Perturbation Perturbation::of(std::uint32_t seed) {
    Perturbation p;
    if (seed == 0) return p;
    std::uint64_t state = seed;
    p.gravityScale = 1.0f + kPerturbation * symmetric(state);
    p.gravityTilt = kPerturbation * symmetric(state);
    p.velocitySeed = nextRandom(state);
    return p;
}

Vec2 perturbedGravity(Vec2 gravity, std::uint32_t seed) {
    if (seed == 0) return gravity;
    const Perturbation p = Perturbation::of(seed);
    const float c = std::cos(p.gravityTilt), s = std::sin(p.gravityTilt);
    return p.gravityScale * Vec2{c * gravity.x - s * gravity.y, s * gravity.x + c * gravity.y};
}

void perturbVelocities(Scene& scene, std::uint32_t seed) {
    if (seed == 0) return;
    std::uint64_t state = Perturbation::of(seed).velocitySeed;
    World& world = *scene.world;
    for (BodyId body : scene.bodies) {
        const float scale = 1.0f + kPerturbation * symmetric(state);
        world.setBodyLinearVelocity(body, scale * world.bodyLinearVelocity(body));
        world.setBodyAngularVelocity(body, scale * world.bodyAngularVelocity(body));
    }
}

}  // namespace pivot::scenes
