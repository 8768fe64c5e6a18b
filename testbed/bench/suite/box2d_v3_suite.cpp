// Box2D v3's benchmark suite (benchmark app of v3.1: joint_grid, large_pyramid, many_pyramids,
// rain, smash, spinner, tumbler), rebuilt from its published bodies, shapes, joints and step
// counts. Two departures, the same in every engine: stacks are laid Builder::restGap() apart
// (v3 lays boxes touching; pivot2d's and Box2D 2.4.1's polygons have a skin that would start
// them overlapping), and rain's joints have no spring (v3 gives them a 5 Hz one; neither
// pivot2d's nor Box2D 2.4.1's revolute joint has a spring).
#include <array>
#include <cmath>
#include <memory>

#include "bench/suite/human.h"
#include "bench/suite/suite.h"
#include "scenes/parts.h"

namespace pivot::bench {

namespace {

// 100 x 100 circles jointed to their neighbours above and to the left, hanging from seven
// static ones in the middle of the top row; the circles never touch each other.
Script jointGrid(Builder& builder) {
    Material material;
    material.category = scenes::kGridCategory;
    material.mask = static_cast<std::uint16_t>(0xFFFF & ~scenes::kGridCategory);
    std::vector<int> bodies(100 * 100);
    scenes::layJointGrid(
        scenes::JointGridSpec{},
        [&](int index, Vec2 position, bool pinned) {
            BodySpec body;
            body.motion = pinned ? Motion::Static : Motion::Dynamic;
            body.position = position;
            bodies[static_cast<std::size_t>(index)] = builder.body(body);
            builder.circle(bodies[static_cast<std::size_t>(index)], {}, 0.4f, material);
        },
        [&](int a, int b, Vec2 anchor) {
            PinSpec pin;
            pin.bodyA = bodies[static_cast<std::size_t>(a)];
            pin.bodyB = bodies[static_cast<std::size_t>(b)];
            pin.pivot = anchor;
            builder.pin(pin);
        });
    return {};
}

// Boxes of half extent `h`, `base` on the bottom row, each row centred on the one below, the
// bottom row on y = floor with its first box's left side at x = left.
void pyramidOfBoxes(Builder& builder, int base, float h, float left, float floor) {
    const float pitch = 2.0f * h + builder.restGap();
    Material material;
    for (int row = 0; row < base; ++row) {
        const float y = floor + builder.restGap() + h + pitch * static_cast<float>(row);
        for (int i = 0; i < base - row; ++i) {
            BodySpec body;
            body.position = {
                left + h + 0.5f * pitch * static_cast<float>(row) + pitch * static_cast<float>(i),
                y};
            builder.box(builder.body(body), h, h, {}, 0.0f, material);
        }
    }
}

// 5,050 boxes, base 100, on a ground box.
Script largePyramid(Builder& builder) {
    BodySpec ground;
    ground.motion = Motion::Static;
    ground.position = {0.0f, -1.0f};
    builder.box(builder.body(ground), 100.0f, 1.0f, {}, 0.0f, Material{});
    pyramidOfBoxes(builder, 100, 0.5f, -50.0f, 0.0f);
    return {};
}

// 20 rows of 20 pyramids of base 10 (22,000 boxes), each row on a segment 11 m above the last.
Script manyPyramids(Builder& builder) {
    constexpr int kBase = 10, kRows = 20, kColumns = 20;
    constexpr float kExtent = 0.5f;
    const float rowHeight = 2.0f * kExtent * (kBase + 1.0f);
    const float groundWidth = 2.0f * kExtent * kColumns * (kBase + 1.0f);
    BodySpec groundSpec;
    groundSpec.motion = Motion::Static;
    const int ground = builder.body(groundSpec);
    for (int r = 0; r < kRows; ++r) {
        const float y = rowHeight * static_cast<float>(r);
        builder.segment(ground, {-groundWidth, y}, {groundWidth, y}, Material{});
    }
    const float baseWidth = 2.0f * kExtent * kBase;
    for (int r = 0; r < kRows; ++r) {
        for (int c = 0; c < kColumns; ++c) {
            const float centre = -0.5f * groundWidth +
                                 static_cast<float>(c) * (baseWidth + 2.0f * kExtent) + kExtent;
            pyramidOfBoxes(builder, kBase, kExtent, centre - 0.5f,
                           rowHeight * static_cast<float>(r));
        }
    }
    return {};
}

// A heavy box at 40 m/s into a sleeping wall of 9,600 small boxes, without gravity.
Script smash(Builder& builder) {
    builder.setGravity({0.0f, 0.0f});
    BodySpec ram;
    ram.position = {-20.0f, 0.0f};
    ram.velocity = {40.0f, 0.0f};
    Material heavy;
    heavy.density = 8.0f;
    builder.box(builder.body(ram), 4.0f, 4.0f, {}, 0.0f, heavy);
    constexpr int kColumns = 120, kRows = 80;
    const float pitch = 0.4f + builder.restGap();
    for (int i = 0; i < kColumns; ++i) {
        for (int j = 0; j < kRows; ++j) {
            BodySpec brick;
            brick.position = {static_cast<float>(i) * pitch + 30.0f,
                              (static_cast<float>(j) - 0.5f * kRows) * pitch};
            brick.awake = false;
            builder.box(builder.body(brick), 0.2f, 0.2f, {}, 0.0f, Material{});
        }
    }
    return {};
}

// A motor-driven blade turning in a ring of 360 chain segments, stirring 3,038 capsules, discs
// and squares. Each step reads the blade's angle, as v3's app does.
Script spinner(Builder& builder) {
    BodySpec groundSpec;
    groundSpec.motion = Motion::Static;
    const int ground = builder.body(groundSpec);
    constexpr int kPoints = 360;
    std::vector<Vec2> ring;
    for (int i = 0; i < kPoints; ++i) {  // clockwise, so the inside is solid
        const float angle = -2.0f * kPi * static_cast<float>(i) / kPoints;
        ring.push_back({40.0f * std::cos(angle), 40.0f * std::sin(angle) + 32.0f});
    }
    Material wall;
    wall.friction = 0.1f;
    builder.loop(ground, ring, wall);

    BodySpec bladeSpec;
    bladeSpec.position = {0.0f, 12.0f};
    bladeSpec.allowSleep = false;
    const int blade = builder.body(bladeSpec);
    Material slick;
    slick.friction = 0.0f;
    builder.roundedBox(blade, 0.4f, 20.0f, 0.2f, slick);
    PinSpec pin;
    pin.bodyA = ground;
    pin.bodyB = blade;
    pin.pivot = bladeSpec.position;
    pin.motor = true;
    pin.motorSpeed = 5.0f;
    pin.maxMotorTorque = 40000.0f;
    const int joint = builder.pin(pin);

    Material light;
    light.friction = 0.1f;
    light.restitution = 0.1f;
    light.density = 0.25f;
    float x = -24.0f, y = 2.0f;
    for (int i = 0; i < 3038; ++i) {
        BodySpec body;
        body.position = {x, y};
        const int id = builder.body(body);
        if (i % 3 == 0) {
            builder.capsule(id, {-0.25f, 0.0f}, {0.25f, 0.0f}, 0.25f, light);
        } else if (i % 3 == 1) {
            builder.circle(id, {}, 0.35f, light);
        } else {
            builder.box(id, 0.35f, 0.35f, {}, 0.0f, light);
        }
        x += 1.0f;
        if (x > 24.0f) {
            x = -24.0f;
            y += 1.0f;
        }
    }
    return [joint](Builder& b, int) { (void)b.pinAngle(joint); };
}

// A 20 m box of four heavy walls turned by a motor at 25 degrees a second, tumbling 2,025
// small boxes.
Script tumbler(Builder& builder) {
    BodySpec groundSpec;
    groundSpec.motion = Motion::Static;
    const int ground = builder.body(groundSpec);
    BodySpec drumSpec;
    drumSpec.position = {0.0f, 10.0f};
    const int drum = builder.body(drumSpec);
    Material walls;
    walls.density = 50.0f;
    builder.box(drum, 0.5f, 10.0f, {10.0f, 0.0f}, 0.0f, walls);
    builder.box(drum, 0.5f, 10.0f, {-10.0f, 0.0f}, 0.0f, walls);
    builder.box(drum, 10.0f, 0.5f, {0.0f, 10.0f}, 0.0f, walls);
    builder.box(drum, 10.0f, 0.5f, {0.0f, -10.0f}, 0.0f, walls);
    PinSpec pin;
    pin.bodyA = ground;
    pin.bodyB = drum;
    pin.pivot = drumSpec.position;
    pin.motor = true;
    pin.motorSpeed = kPi / 180.0f * 25.0f;
    pin.maxMotorTorque = 1e8f;
    builder.pin(pin);

    constexpr int kGrid = 45;
    float y = -0.2f * kGrid + 10.0f;
    for (int i = 0; i < kGrid; ++i) {
        float x = -0.2f * kGrid;
        for (int j = 0; j < kGrid; ++j) {
            BodySpec body;
            body.position = {x, y};
            builder.box(builder.body(body), 0.125f, 0.125f, {}, 0.0f, Material{});
            x += 0.4f;
        }
        y += 0.4f;
    }
    return {};
}

// Ragdolls raining onto five tiers of ground boxes: every 8 steps a column of five groups of
// five (one group a tier) appears, and once 40 columns are out, the oldest column is taken
// away as a new one comes, so 1,000 to 11,000 bodies are in the world.
class Rain {
public:
    static constexpr int kTiers = 5, kColumns = 40, kGroupSize = 5;
    static constexpr float kCell = 0.5f, kTierHeight = 45.0f;
    static constexpr int kCells = 500;

    explicit Rain(Builder& builder) {
        BodySpec groundSpec;
        groundSpec.motion = Motion::Static;
        const int ground = builder.body(groundSpec);
        for (int t = 0; t < kTiers; ++t) {
            float x = -0.5f * kCells * kCell;
            for (int j = 0; j <= kCells; ++j) {
                builder.box(ground, 0.5f * kCell, 0.5f * kCell,
                            {x, kTierHeight * static_cast<float>(t)}, 0.0f, Material{});
                x += kCell;
            }
        }
    }

    void beforeStep(Builder& builder, int step) {
        if ((step & 7) != 0) return;
        if (filled_ < kColumns) {
            for (int t = 0; t < kTiers; ++t) spawnGroup(builder, t, filled_);
            ++filled_;
            return;
        }
        for (int t = 0; t < kTiers; ++t) {
            for (Human& human : group(t, next_)) removeHuman(builder, human);
            spawnGroup(builder, t, next_);
        }
        next_ = (next_ + 1) % kColumns;
    }

private:
    std::array<Human, kGroupSize>& group(int tier, int column) {
        return groups_[static_cast<std::size_t>(tier * kColumns + column)];
    }

    void spawnGroup(Builder& builder, int tier, int column) {
        const float span = kCells * kCell;
        Vec2 feet{-0.5f * span + span / kColumns * (static_cast<float>(column) + 0.5f),
                  40.0f + kTierHeight * static_cast<float>(tier)};
        for (int i = 0; i < kGroupSize; ++i) {
            group(tier, column)[static_cast<std::size_t>(i)] =
                spawnHuman(builder, feet, 0.05f, static_cast<std::int16_t>(-(i + 1)));
            feet.x += 0.5f;
        }
    }

    std::array<std::array<Human, kGroupSize>, kTiers * kColumns> groups_{};
    int filled_ = 0;  // columns spawned so far
    int next_ = 0;    // once all are out, the column replaced next
};

Script rain(Builder& builder) {
    auto state = std::make_shared<Rain>(builder);
    return [state](Builder& b, int step) { state->beforeStep(b, step); };
}

}  // namespace

void addBox2dV3Suite(std::vector<SuiteScene>& scenes) {
    scenes.push_back({"joint_grid",
                      "100 x 100 circles jointed to their neighbours above and to the left", 500,
                      false, jointGrid});
    scenes.push_back(
        {"large_pyramid", "a pyramid of 5,050 boxes, base 100", 500, false, largePyramid});
    scenes.push_back({"many_pyramids", "20 x 20 pyramids of base 10 (22,000 boxes) on 20 segments",
                      200, false, manyPyramids});
    scenes.push_back({"rain",
                      "ragdolls (11 capsule bones, limits, joint friction) raining onto ground "
                      "tiers, up to 1,000 at a time; sleeping on",
                      1000, true, rain});
    scenes.push_back({"smash",
                      "a heavy box at 40 m/s into a sleeping wall of 9,600 boxes, no gravity; "
                      "sleeping on",
                      300, true, smash});
    scenes.push_back({"spinner",
                      "a motor-driven blade in a chain ring stirring 3,038 capsules, discs and "
                      "squares; sleeping on",
                      1400, true, spinner});
    scenes.push_back({"tumbler", "a motor-turned box tumbling 2,025 small boxes; sleeping on", 750,
                      true, tumbler});
}

}  // namespace pivot::bench
