#include "bench/query_bench.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>

#include "heap/counting_new.h"
#include "pivot/pivot.h"

namespace pivot::bench {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kShapes = 10000;
constexpr float kSide = 300.0f;  // the shapes are strewn over a 300 m square: 1 per 9 m^2

// One shape of the query world, drawn once and built in both engines.
struct ShapeSpec {
    int kind;  // 0 circle, 1 box, 2 pentagon
    float x, y, angle, size;
};

struct RaySpec {
    float x, y, dx, dy;
};

struct BoxSpec {
    float x, y, w, h;
};

struct Workload {
    std::vector<ShapeSpec> shapes;
    std::vector<RaySpec> rays;
    std::vector<BoxSpec> boxes;
};

Workload makeWorkload(int queries) {
    std::mt19937 random(2024);
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(random);
    };
    Workload w;
    for (int i = 0; i < kShapes; ++i) {
        w.shapes.push_back({i % 3, uniform(0.0f, kSide), uniform(0.0f, kSide), uniform(-3.0f, 3.0f),
                            uniform(0.3f, 1.2f)});
    }
    for (int i = 0; i < queries; ++i) {
        // Rays up to 40 m long in any direction: most hit something, some pass through gaps.
        const float angle = uniform(-kPi, kPi), reach = uniform(1.0f, 40.0f);
        w.rays.push_back({uniform(0.0f, kSide), uniform(0.0f, kSide), reach * std::cos(angle),
                          reach * std::sin(angle)});
        w.boxes.push_back(
            {uniform(0.0f, kSide), uniform(0.0f, kSide), uniform(0.5f, 8.0f), uniform(0.5f, 8.0f)});
    }
    return w;
}

Polygon pentagon(float size) {
    Polygon p;
    p.count = 5;
    for (int k = 0; k < 5; ++k) {
        const float a = 2.0f * kPi * k / 5.0f;
        p.vertices[k] = {size * std::cos(a), size * std::sin(a)};
    }
    return p;
}

std::unique_ptr<World> pivotWorld(const Workload& w) {
    auto world = std::make_unique<World>();
    for (const ShapeSpec& s : w.shapes) {
        BodyDef def;
        def.position = {s.x, s.y};
        def.angle = s.angle;
        const BodyId body = world->createBody(def);
        if (s.kind == 0) world->createShape(body, ShapeDef{}, Circle{{}, s.size});
        if (s.kind == 1) world->createShape(body, ShapeDef{}, Polygon::box(s.size, 0.5f * s.size));
        if (s.kind == 2) world->createShape(body, ShapeDef{}, pentagon(s.size));
    }
    world->step(1.0f / 60.0f);  // what a game queries: a world that has stepped
    return world;
}

std::unique_ptr<b2World> box2dWorld(const Workload& w) {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
    for (const ShapeSpec& s : w.shapes) {
        b2BodyDef def;
        def.position.Set(s.x, s.y);
        def.angle = s.angle;
        b2Body* body = world->CreateBody(&def);
        if (s.kind == 0) {
            b2CircleShape circle;
            circle.m_radius = s.size;
            body->CreateFixture(&circle, 1.0f);
        } else {
            b2PolygonShape polygon;
            if (s.kind == 1) {
                polygon.SetAsBox(s.size, 0.5f * s.size);
            } else {
                const Polygon p = pentagon(s.size);
                b2Vec2 vertices[5];
                for (int k = 0; k < 5; ++k) vertices[k].Set(p.vertices[k].x, p.vertices[k].y);
                polygon.Set(vertices, 5);
            }
            body->CreateFixture(&polygon, 1.0f);
        }
    }
    world->Step(1.0f / 60.0f, 8, 3);
    return world;
}

struct ClosestRay : b2RayCastCallback {
    bool hit = false;
    float ReportFixture(b2Fixture*, const b2Vec2&, const b2Vec2&, float fraction) override {
        hit = true;
        return fraction;
    }
};

struct CountBoxes : b2QueryCallback {
    long long found = 0;
    bool ReportFixture(b2Fixture*) override {
        ++found;
        return true;
    }
};

template <typename F>
double milliseconds(F&& f) {
    const Clock::time_point start = Clock::now();
    f();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::vector<QueryRow> runQueryBench(bool quick, int repeats) {
    const Workload w = makeWorkload(quick ? 1000 : 10000);
    const std::unique_ptr<World> pivot = pivotWorld(w);
    const std::unique_ptr<b2World> box2d = box2dWorld(w);

    QueryRow rays{"ray_casts"}, boxes{"aabb_queries"};
    std::vector<double> pivotRays, box2dRays, pivotBoxes, box2dBoxes;
    heap::Counter counter;
    long long pivotAllocations = 0;
    for (int r = 0; r < repeats + 1; ++r) {  // the first round warms up and is not counted
        long long pivotHits = 0, box2dHits = 0, pivotFound = 0, box2dFound = 0;
        counter.reset();
        const double pr = milliseconds([&] {
            for (const RaySpec& ray : w.rays) {
                pivotHits += pivot->castRayClosest({ray.x, ray.y}, {ray.dx, ray.dy}).has_value();
            }
        });
        const double pb = milliseconds([&] {
            for (const BoxSpec& b : w.boxes) {
                pivot->queryAABB(AABB{{b.x, b.y}, {b.x + b.w, b.y + b.h}}, QueryFilter{},
                                 [&](ShapeId) {
                                     ++pivotFound;
                                     return true;
                                 });
            }
        });
        const long long allocations = counter.allocations();
        const double br = milliseconds([&] {
            for (const RaySpec& ray : w.rays) {
                ClosestRay callback;
                box2d->RayCast(&callback, b2Vec2(ray.x, ray.y),
                               b2Vec2(ray.x + ray.dx, ray.y + ray.dy));
                box2dHits += callback.hit;
            }
        });
        const double bb = milliseconds([&] {
            CountBoxes callback;
            for (const BoxSpec& b : w.boxes) {
                b2AABB box;
                box.lowerBound.Set(b.x, b.y);
                box.upperBound.Set(b.x + b.w, b.y + b.h);
                box2d->QueryAABB(&callback, box);
            }
            box2dFound = callback.found;
        });
        if (r == 0) continue;
        pivotRays.push_back(pr);
        pivotBoxes.push_back(pb);
        box2dRays.push_back(br);
        box2dBoxes.push_back(bb);
        pivotAllocations += allocations;
        rays.pivotFound = pivotHits;
        rays.box2dFound = box2dHits;
        boxes.pivotFound = pivotFound;
        boxes.box2dFound = box2dFound;
    }
    rays.pivotMs = median(pivotRays);
    rays.box2dMs = median(box2dRays);
    boxes.pivotMs = median(pivotBoxes);
    boxes.box2dMs = median(box2dBoxes);
    rays.pivotAllocations = boxes.pivotAllocations = pivotAllocations;
    return {rays, boxes};
}

}  // namespace pivot::bench
