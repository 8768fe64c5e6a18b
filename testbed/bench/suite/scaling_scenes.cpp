// many_chains, and how cost grows with the work: chains and pyramids of growing size. The chain
// is the testbed's (scenes::layChain), the pyramid the testbed's pyramid scene's layout
// (scenes::layPyramid) laid Builder::restGap() apart.
#include <string>

#include "bench/suite/suite.h"
#include "scenes/parts.h"

namespace pivot::bench {

namespace {

// A static box 1 m deep whose top face is at `top`, spanning [left, right].
void shelf(Builder& builder, float left, float right, float top) {
    BodySpec spec;
    spec.motion = Motion::Static;
    builder.box(builder.body(spec), 0.5f * (right - left), 0.5f,
                {0.5f * (left + right), top - 0.5f}, 0.0f, Material{});
}

// `count` chains of 30 links released horizontally at y = 25 from static roots, over a shelf.
Script chains(Builder& builder, int count) {
    shelf(builder, -10.0f, static_cast<float>(count) * scenes::kChainPitch + 10.0f, 0.0f);
    Material link;
    link.density = 20.0f;
    link.friction = 0.2f;
    const float y = 25.0f;
    for (int c = 0; c < count; ++c) {
        const float x0 = static_cast<float>(c) * scenes::kChainPitch;
        BodySpec rootSpec;
        rootSpec.motion = Motion::Static;
        rootSpec.position = {x0, y};
        int previous = builder.body(rootSpec);
        scenes::layChain(x0, y, [&](Vec2 centre, Vec2 anchor) {
            BodySpec spec;
            spec.position = centre;
            const int body = builder.body(spec);
            builder.box(body, 0.6f, 0.125f, {}, 0.0f, link);
            PinSpec pin;
            pin.bodyA = previous;
            pin.bodyB = body;
            pin.pivot = anchor;
            builder.pin(pin);
            previous = body;
        });
    }
    return {};
}

// A pyramid of unit boxes `rows` high on a shelf.
Script pyramid(Builder& builder, int rows) {
    shelf(builder, -1.0f, 12.0f, 0.0f);
    scenes::PyramidSpec spec;
    spec.rows = rows;
    spec.pitchX = spec.pitchY = 1.0f + builder.restGap();
    spec.floorGap = builder.restGap();
    spec.start = scenes::RowStart::FromLeft;
    scenes::layPyramid(spec, [&](Vec2 centre) {
        BodySpec body;
        body.position = centre;
        builder.box(builder.body(body), 0.5f, 0.5f, {}, 0.0f, Material{});
    });
    return {};
}

SuiteScene chainScene(const std::string& name, int count) {
    return {name,
            std::to_string(count) + (count == 1 ? " chain" : " chains") +
                " of 30 links, released horizontally",
            600, false, [count](Builder& builder) { return chains(builder, count); }};
}

}  // namespace

void addScalingScenes(std::vector<SuiteScene>& scenes) {
    scenes.push_back(chainScene("many_chains", 100));
    scenes.push_back(chainScene("chains_1", 1));
    scenes.push_back(chainScene("chains_10", 10));
    for (int rows : {10, 20, 40}) {
        scenes.push_back({"pyramid_" + std::to_string(rows),
                          "a pyramid " + std::to_string(rows) + " rows high", 500, false,
                          [rows](Builder& builder) { return pyramid(builder, rows); }});
    }
}

std::vector<SuiteScene> suiteScenes() {
    std::vector<SuiteScene> scenes;
    addBox2dV3Suite(scenes);
    addScalingScenes(scenes);
    return scenes;
}

}  // namespace pivot::bench
