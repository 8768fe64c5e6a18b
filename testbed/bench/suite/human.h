// The ragdoll of Box2D v3's `rain` benchmark (its "human"): eleven capsule bones (hip, torso,
// head, two legs of two bones with a foot on the shin, two arms of two bones) pinned by revolute
// joints with limits and friction (a motor at speed 0 with a small torque), 1.9 m tall at scale
// 1. The dimensions, limits and frictions are Box2D v3.1's published ones.
#pragma once

#include <array>

#include "bench/suite/builder.h"

namespace pivot::bench {

struct Human {
    static constexpr int kBones = 11;
    std::array<int, kBones> bodies{};  ///< builder handles, hip first
    bool spawned = false;
};

/// Builds a human standing on `feet` (the point under its hip). Its shapes are in `group`
/// (a negative filter group: bones of one human never touch) and category 2, touching the
/// ground (category 1) and other humans; its feet touch only the ground. Joint friction:
/// `frictionTorque` N m at the hip, scaled per joint as v3 scales it.
Human spawnHuman(Builder& builder, Vec2 feet, float frictionTorque, std::int16_t group);

/// Destroys the human's bodies (and with them its joints).
void removeHuman(Builder& builder, Human& human);

}  // namespace pivot::bench
