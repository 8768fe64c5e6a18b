// A pyramid of ten rows (55 boxes, laid as scenes::buildPyramid's) shot at: from 1 s on, every half
// second, a bullet (scenes::Volley) flies in from the left at 120 m/s, ten in all. Continuous
// collision keeps each shot from passing through the boxes it meets (BodyDef::bullet); the bench
// times the scene beside its Box2D 2.4.1 twin, continuous collision on in both. Walls 60 m high at
// either end of the ground (scenes::Volley::walls) keep what the shots knock about in the range.
#include "ground.h"
#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

void buildBullets(Scene& scene, const SceneOptions& options) {
    (void)options;  // no joints: the solver and bias do not matter
    createGround(*scene.world);
    const std::vector<BodyId> boxes = addPyramid(*scene.world, Volley::pyramid());
    scene.bodies.insert(scene.bodies.end(), boxes.begin(), boxes.end());
    addRange(*scene.world);
    scene.beforeStep = [](Scene& s, int step) {
        const Volley volley;
        const int shot = volley.shotAt(step);
        if (shot < 0) return;
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = {volley.x, volley.height(shot)};
        def.linearVelocity = {volley.speed, 0.0f};
        def.bullet = true;
        const BodyId bullet = s.world->createBody(def);
        ShapeDef shape;
        shape.density = volley.density;
        shape.friction = volley.friction;
        s.world->createShape(bullet, shape, Circle{{0.0f, 0.0f}, volley.radius});
        s.bodies.push_back(bullet);
    };
}

}  // namespace pivot::scenes
