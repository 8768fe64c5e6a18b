#include "parts.h"

#include <cmath>

namespace pivot::scenes {

BodyId dynamicBodyAt(const World& world, Vec2 point) {
    BodyId found;
    world.queryPoint(point, QueryFilter{}, [&](ShapeId shape) {
        const BodyId body = world.shapeBody(shape);
        if (world.bodyType(body) != BodyType::Dynamic) return true;
        found = body;
        return false;
    });
    return found;
}

BodyId addShelf(World& world, float left, float right, float top, float friction) {
    BodyId shelf = world.createBody(BodyDef{});
    ShapeDef def;
    def.density = 0.0f;
    def.friction = friction;
    world.createShape(
        shelf, def,
        Polygon::box(0.5f * (right - left), 0.5f, {0.5f * (left + right), top - 0.5f}, 0.0f));
    return shelf;
}

std::vector<BodyId> addPyramid(World& world, const PyramidSpec& spec) {
    ShapeDef shape;
    shape.density = 1.0f;
    shape.friction = 0.6f;
    const Polygon box = Polygon::box(0.5f, 0.5f);
    std::vector<BodyId> boxes;
    layPyramid(spec, [&](Vec2 centre) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = centre;
        BodyId body = world.createBody(def);
        world.createShape(body, shape, box);
        boxes.push_back(body);
    });
    return boxes;
}

JointGrid addJointGrid(World& world, const JointGridSpec& spec) {
    JointGrid grid;
    grid.bodies.resize(static_cast<std::size_t>(spec.size) * static_cast<std::size_t>(spec.size));
    ShapeDef shape;
    shape.filter = {kGridCategory, static_cast<std::uint16_t>(0xFFFF & ~kGridCategory), 0};
    const Circle circle{{0.0f, 0.0f}, 0.4f};
    layJointGrid(
        spec,
        [&](int index, Vec2 position, bool pinned) {
            BodyDef def;
            def.type = pinned ? BodyType::Static : BodyType::Dynamic;
            def.position = position;
            BodyId body = world.createBody(def);
            shape.density = pinned ? 0.0f : 1.0f;
            world.createShape(body, shape, circle);
            grid.bodies[index] = body;
        },
        [&](int a, int b, Vec2 anchor) {
            grid.joints.push_back(world.createJoint(
                RevoluteJointDef::atWorldAnchor(grid.bodies[a], grid.bodies[b], anchor)));
        });
    return grid;
}

void addChains(World& world, int count) {
    addShelf(world, -10.0f, static_cast<float>(count) * kChainPitch + 10.0f, 0.0f);
    const float y = 25.0f;
    for (int c = 0; c < count; ++c) {
        const float x0 = static_cast<float>(c) * kChainPitch;
        BodyId root = world.createBody(BodyDef{});
        world.setBodyTransform(root, {x0, y}, 0.0f);
        addChain(world, root, x0, y, RevoluteJointDef::atWorldAnchor);
    }
}

void addRange(World& world) {
    const BodyId walls = world.createBody(BodyDef{});
    ShapeDef wall;
    wall.density = 0.0f;
    const float half = 0.5f * Volley::kWallHeight;
    for (float side : {-1.0f, 1.0f}) {
        world.createShape(walls, wall,
                          Polygon::box(0.5f, half, {side * (Volley::kWallX + 0.5f), half}, 0.0f));
    }
}

Polygon capsuleAsPolygon(const Capsule& capsule) {
    Polygon polygon;
    polygon.count = 2;
    polygon.vertices[0] = capsule.center1;
    polygon.vertices[1] = capsule.center2;
    polygon.radius = capsule.radius;
    return polygon;
}

std::vector<Vec2> polygonOutline(const Vec2* vertices, int count, float radius) {
    Polygon polygon;
    polygon.count = count;
    polygon.radius = radius;
    for (int i = 0; i < count; ++i) polygon.vertices[static_cast<std::size_t>(i)] = vertices[i];
    return polygonOutline(polygon);
}

std::vector<Vec2> polygonOutline(const Polygon& polygon) {
    const int n = polygon.count;
    if (polygon.radius == 0.0f) return {polygon.vertices.begin(), polygon.vertices.begin() + n};
    constexpr int kChords = 6;
    std::vector<Vec2> points;
    for (int i = 0; i < n; ++i) {
        const Vec2 v = polygon.vertices[i];
        const Vec2 before = v - polygon.vertices[(i + n - 1) % n];
        const Vec2 after = polygon.vertices[(i + 1) % n] - v;
        // The outward normals of the edges meeting at v (counter-clockwise: on the right).
        const float from = std::atan2(-before.x, before.y);
        float to = std::atan2(-after.x, after.y);
        if (to < from) to += 2.0f * kPi;
        for (int k = 0; k <= kChords; ++k) {
            const float angle = from + (to - from) * static_cast<float>(k) / kChords;
            points.push_back(v + polygon.radius * Vec2{std::cos(angle), std::sin(angle)});
        }
    }
    return points;
}

}  // namespace pivot::scenes
