// World::debugDraw and debugDrawBody: the world described to the game's DebugDraw
// (pivot/debug_draw.h), and DebugDraw's default drawings of transforms and joints.
#include "pivot/debug_draw.h"

#include <array>

#include "model/body_edge.h"
#include "world/world_impl.h"

namespace pivot {

void DebugDraw::drawTransform(const Transform& xf, float axisLength) {
    drawSegment(xf.p, xf.p + axisLength * rotate(xf.q, Vec2{1.0f, 0.0f}), {0.9f, 0.2f, 0.2f});
    drawSegment(xf.p, xf.p + axisLength * rotate(xf.q, Vec2{0.0f, 1.0f}), {0.2f, 0.8f, 0.2f});
}

void DebugDraw::drawJoint(JointId, JointType, Vec2 anchorA, Vec2 anchorB, float, DebugColor color) {
    drawSegment(anchorA, anchorB, color);
    drawPoint(anchorA, 4.0f, color);
    drawPoint(anchorB, 4.0f, color);
}

namespace {

constexpr float kSeparatedJoint = 1e-3f;  // m: a joint drawn as come apart beyond this

DebugColor shapeColor(const Body& body, const Shape& shape) {
    if (shape.sensor) return debug_colors::kSensor;
    switch (body.type) {
        case BodyType::Static: return debug_colors::kStatic;
        case BodyType::Kinematic: return debug_colors::kKinematic;
        case BodyType::Dynamic: break;
    }
    return body.awake ? debug_colors::kDynamic : debug_colors::kSleeping;
}

void drawShape(DebugDraw& draw, const Shape& shape, const Transform& xf, DebugColor color) {
    const ConvexPolygon& p = shape.polygon;
    switch (shape.type) {
        case ShapeType::Circle:
            draw.drawSolidCircle(transformPoint(xf, shape.circle.center), shape.circle.radius,
                                 rotate(xf.q, Vec2{1.0f, 0.0f}), color);
            return;
        case ShapeType::Capsule:
            draw.drawSolidCapsule(transformPoint(xf, p.vertices[0]),
                                  transformPoint(xf, p.vertices[1]), p.radius, color);
            return;
        case ShapeType::Segment:
        case ShapeType::ChainSegment:
            draw.drawSegment(transformPoint(xf, p.vertices[0]), transformPoint(xf, p.vertices[1]),
                             color);
            return;
        case ShapeType::Polygon: {
            std::array<Vec2, kMaxPolygonVertices> world;
            for (int i = 0; i < p.count; ++i) world[i] = transformPoint(xf, p.vertices[i]);
            draw.drawSolidPolygon(world.data(), p.count, p.radius, color);
            return;
        }
    }
}

}  // namespace

void World::debugDraw(DebugDraw& draw, const DebugDrawOptions& options) const {
    const Impl& w = *impl_;
    const char* call = "World::debugDraw";
    requireFinite(call, "options.normalLength", options.normalLength);
    const WorldAccess::DrawScope drawing(w.access, call);
    if (options.shapes || options.aabbs) {
        w.bodies.forEach([&](std::int32_t, const Body& body) {
            for (std::int32_t s = body.shapeList; s != -1; s = w.shapes[s].next) {
                const Shape& shape = w.shapes[s];
                if (options.shapes) drawShape(draw, shape, body.xf, shapeColor(body, shape));
                if (options.aabbs) {
                    const AABB& box = shape.box;
                    const Vec2 corners[4] = {box.lower,
                                             {box.upper.x, box.lower.y},
                                             box.upper,
                                             {box.lower.x, box.upper.y}};
                    draw.drawPolygon(corners, 4, debug_colors::kAABB);
                }
            }
        });
    }
    if (options.joints) {
        w.joints.forEach([&](std::int32_t index, const Joint& joint) {
            const Vec2 a = transformPoint(w.bodies[joint.bodyA()].xf, joint.localAnchorA);
            const Vec2 b = transformPoint(w.bodies[joint.bodyB()].xf, joint.localAnchorB);
            const float separation = joint.separation(w.bodies);
            const DebugColor color = joint.letGo                    ? debug_colors::kLetGoJoint
                                     : separation > kSeparatedJoint ? debug_colors::kSeparatedJoint
                                                                    : debug_colors::kJoint;
            if (const auto* pulley = std::get_if<PulleyJoint>(&joint.data)) {
                // The rope: each anchor up to its ground anchor, and across.
                draw.drawSegment(pulley->groundAnchorA, a, color);
                draw.drawSegment(pulley->groundAnchorB, b, color);
                draw.drawSegment(pulley->groundAnchorA, pulley->groundAnchorB, color);
            }
            draw.drawJoint(w.jointId(index), joint.type(), a, b, separation, color);
        });
    }
    if (options.contactPoints || options.contactNormals) {
        w.contacts.forEach([&](std::int32_t, const Contact& c) {
            if (!c.touching || c.sensor) return;
            const ContactData data = w.contactManager.contactData(c);
            for (int i = 0; i < data.pointCount; ++i) {
                const Vec2 p = data.points[i].point;
                if (options.contactPoints) draw.drawPoint(p, 5.0f, debug_colors::kContactPoint);
                if (options.contactNormals) {
                    draw.drawSegment(p, p + options.normalLength * data.normal,
                                     debug_colors::kContactNormal);
                }
            }
        });
    }
    if (options.centersOfMass) {
        w.bodies.forEach([&](std::int32_t, const Body& body) {
            if (body.type == BodyType::Static) return;
            draw.drawTransform({body.center, body.xf.q}, 0.25f);
        });
    }
}

void World::debugDrawBody(BodyId id, const Transform& xf, DebugDraw& draw) const {
    const char* call = "World::debugDrawBody";
    const Impl& w = *impl_;
    const Body& body = w.bodies[w.bodyIndex(call, id)];
    // A pose between two steps (render interpolation) may be drawn beyond kMaxCoordinate, but
    // its rotation must be one: an interpolated one normalised.
    requireFinite(call, "xf.p", xf.p);
    requireRotation(call, "xf.q", xf.q);
    const WorldAccess::DrawScope drawing(w.access, call);
    for (std::int32_t s = body.shapeList; s != -1; s = w.shapes[s].next) {
        drawShape(draw, w.shapes[s], xf, shapeColor(body, w.shapes[s]));
    }
}

}  // namespace pivot
