// Parts that the benchmark, the tests and the testbed build into worlds: a shelf, a pyramid of
// boxes, a jointed grid of circles, chains. Each part's layout is written once here, as
// a template that hands out positions; the pivot2d builders below and their Box2D twins
// (scenes/box2d/parts.h) both take it, so the two engines get the same bodies in the same
// creation order.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::scenes {

// --- pyramid ---------------------------------------------------------------------------------

/// m: how far apart two boxes rest. Polygons collide with a kPolygonRadius skin in both engines
/// and contacts settle about kLinearSlop deep into it, so resting cores are this far apart.
constexpr float kRestGap = 2.0f * kPolygonRadius - kLinearSlop;

/// Where each row of a pyramid starts. Both centre a row over the one below, but they round
/// differently, and each scene keeps the one its recorded figures and hashes were made with.
enum class RowStart {
    Centred,   ///< every row centred on x = 0
    FromLeft,  ///< the bottom row's first box at x = left, each row half a pitch further in
};

/// Boxes 1 m square (density 1, friction 0.6), `rows` on the bottom row and one fewer on each
/// row above.
struct PyramidSpec {
    int rows = 20;
    float pitchX = 1.0f + kRestGap;  ///< m, centre to centre along a row
    float pitchY = 1.0f + kRestGap;  ///< m, row to row
    float floorGap = kRestGap;       ///< m, between the floor and the bottom row's boxes
    float floor = 0.0f;              ///< m, the top face the pyramid stands on
    RowStart start = RowStart::Centred;
    float left = 0.0f;  ///< m, RowStart::FromLeft only
};

/// Calls addBox(centre) for every box, bottom row first, each row from the left.
template <typename AddBox>
void layPyramid(const PyramidSpec& spec, AddBox&& addBox) {
    for (int row = 0; row < spec.rows; ++row) {
        const int count = spec.rows - row;
        const float first = spec.start == RowStart::Centred
                                ? -0.5f * spec.pitchX * static_cast<float>(count - 1)
                                : spec.left + 0.5f * static_cast<float>(row) * spec.pitchX;
        const float y = spec.floor + 0.5f + spec.floorGap + spec.pitchY * static_cast<float>(row);
        for (int i = 0; i < count; ++i) {
            addBox(Vec2{first + spec.pitchX * static_cast<float>(i), y});
        }
    }
}

/// A polygon's outline in its body's frame, for drawing; a rounded polygon's with each corner's
/// arc drawn as a few chords.
std::vector<Vec2> polygonOutline(const Polygon& polygon);
/// The outline of a polygon as DebugDraw::drawSolidPolygon describes it (vertices, rounding).
std::vector<Vec2> polygonOutline(const Vec2* vertices, int count, float radius);
/// A capsule as a rounded polygon of two vertices, for polygonOutline (drawing only: World
/// takes no two-vertex polygon).
Polygon capsuleAsPolygon(const Capsule& capsule);

/// The dynamic body under `point`, found as a pointer finds it (World::queryPoint), or a null
/// id when there is none; of several, the first the query reports.
BodyId dynamicBodyAt(const World& world, Vec2 point);

/// A static box 1 m deep whose top face is at `top`, spanning [left, right]; density 0.
BodyId addShelf(World& world, float left, float right, float top, float friction = 0.6f);

/// The pyramid's boxes, in creation order (the last is the top box).
std::vector<BodyId> addPyramid(World& world, const PyramidSpec& spec);

// --- joint grid ------------------------------------------------------------------------------

/// The grid's circles are in this category and do not collide with each other.
constexpr std::uint16_t kGridCategory = 0x0002;

/// The order a grid's bodies are created in. It is the order the solver meets them and their
/// joints in, so it changes the numbers.
enum class GridOrder {
    ColumnByColumn,  ///< as Box2D v3's joint_grid benchmark
    RowByRow,
};

/// A square grid of circles (radius 0.4 m, density 1) 1 m apart, each jointed to its neighbour
/// above and to its left, hanging from the middle of its top row, whose middle
/// 2 * pinnedHalfWidth + 1 bodies are static. The top left body is at the origin.
struct JointGridSpec {
    int size = 100;  ///< bodies along each side
    int pinnedHalfWidth = 3;
    GridOrder order = GridOrder::ColumnByColumn;
};

/// Calls body(index, position, pinned) for each body in creation order, then, for that body,
/// joint(indexA, indexB, anchor) to the body above it and to the body on its left. A body's
/// index is row * size + column whatever the order.
template <typename Body, typename Joint>
void layJointGrid(const JointGridSpec& spec, Body&& body, Joint&& joint) {
    const int n = spec.size;
    for (int outer = 0; outer < n; ++outer) {
        for (int inner = 0; inner < n; ++inner) {
            const bool byRow = spec.order == GridOrder::RowByRow;
            const int row = byRow ? outer : inner;
            const int column = byRow ? inner : outer;
            const float x = static_cast<float>(column);
            const float y = -static_cast<float>(row);
            const int index = row * n + column;
            body(index, Vec2{x, y}, row == 0 && std::abs(column - n / 2) <= spec.pinnedHalfWidth);
            if (row > 0) joint(index - n, index, Vec2{x, y + 0.5f});
            if (column > 0) joint(index - 1, index, Vec2{x - 0.5f, y});
        }
    }
}

struct JointGrid {
    std::vector<BodyId> bodies;   ///< by index (layJointGrid)
    std::vector<JointId> joints;  ///< in creation order
};

/// The grid, its joints made with RevoluteJointDef::atWorldAnchor (the world's default solver).
JointGrid addJointGrid(World& world, const JointGridSpec& spec);

// --- chains ----------------------------------------------------------------------------------

/// The testbed chain (Box2D's testbed chain): 30 links, boxes of 1.2 x 0.25 m (density 20,
/// friction 0.2) with joints 1 m apart, neighbours overlapping by 0.2 m, laid out horizontally
/// from its root at (x0, y). Calls link(centre, anchor) for each link from the root out, anchor
/// being the link's joint to the one before it (the first: to the root).
template <typename Link>
void layChain(float x0, float y, Link&& link) {
    for (int i = 0; i < 30; ++i) {
        link(Vec2{x0 + 0.5f + static_cast<float>(i), y}, Vec2{x0 + static_cast<float>(i), y});
    }
}

struct Chain {
    std::vector<BodyId> links;
    std::vector<JointId> joints;
};

/// The chain from `root`, each joint def made by jointAt(bodyA, bodyB, anchor).
template <typename JointAt>
Chain addChain(World& world, BodyId root, float x0, float y, JointAt&& jointAt) {
    ShapeDef shape;
    shape.density = 20.0f;
    shape.friction = 0.2f;
    const Polygon box = Polygon::box(0.6f, 0.125f);
    Chain chain;
    BodyId previous = root;
    layChain(x0, y, [&](Vec2 centre, Vec2 anchor) {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = centre;
        BodyId link = world.createBody(def);
        world.createShape(link, shape, box);
        chain.joints.push_back(world.createJoint(jointAt(previous, link, anchor)));
        chain.links.push_back(link);
        previous = link;
    });
    return chain;
}

/// m between the roots of neighbouring chains, so that they never meet.
constexpr float kChainPitch = 32.0f;

/// `count` chains released horizontally at y = 25, each from a static root body of its own,
/// kChainPitch apart, over one shelf; joints made with RevoluteJointDef::atWorldAnchor.
void addChains(World& world, int count);

// --- bullets -------------------------------------------------------------------------------

/// The shots of the `bullets` scene, in pivot2d and in its Box2D twin: 0.25 m balls of 20 kg/m^2
/// (friction 0.6), flagged as bullets, fired from the left at 120 m/s (2 m a step at 60 Hz, the
/// most a step may move a body, and further than a 1 m box plus the ball: without continuous
/// collision against dynamic bodies a shot would pass through boxes).
struct Volley {
    int firstStep = 60;  ///< 1 s at 60 Hz: the pyramid has settled
    int every = 30;      ///< steps between shots
    int shots = 10;
    float radius = 0.25f;
    float density = 20.0f;
    float friction = 0.6f;
    float speed = 120.0f;  ///< m/s, along +x
    float x = -25.0f;      ///< m, where a shot starts

    /// The shot fired before `step`, or -1.
    int shotAt(int step) const {
        if (step < firstStep || (step - firstStep) % every != 0) return -1;
        const int shot = (step - firstStep) / every;
        return shot < shots ? shot : -1;
    }
    /// m, the height of shot k: through the pyramid's eight lower rows in turn.
    float height(int shot) const { return 0.6f + 1.05f * static_cast<float>((shot * 3) % 8); }

    /// The pyramid shot at: ten rows of 1 m boxes, 1.05 m apart (small, so that the soak of
    /// every solver stays cheap under the sanitizers).
    static PyramidSpec pyramid() {
        PyramidSpec spec;
        spec.rows = 10;
        spec.pitchX = 1.05f;
        return spec;
    }

    /// The range's walls: static boxes 1 m thick and kWallHeight high, their inner faces at
    /// x = +-kWallX, standing on the ground.
    static constexpr float kWallX = 30.0f;
    static constexpr float kWallHeight = 60.0f;
};

/// Adds the walls of Volley's range to the world (a static body).
void addRange(World& world);

/// Switches continuous collision off in a scene whose subject is the joints of bodies landing on
/// thick ground at moderate speed: nothing there can tunnel, and the impact solve, which (as
/// Box2D 2.4.1's) ignores joints, would stretch a landing body's joints 5 to 20 times more than
/// the joint solvers being measured do (docs/contacts.md, "Continuous collision").
inline void keepContinuousOffForJoints(World& world) {
    world.setContinuousEnabled(false);
}

}  // namespace pivot::scenes
