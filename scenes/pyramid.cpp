// A pyramid of 1 m boxes (density 1, friction 0.6), 20 rows high, on the ground: 210 boxes
// that must stand still. The rows start at their resting spacing (kRestGap); neighbours in a
// row start 5 cm apart.
#include "ground.h"
#include "parts.h"
#include "scene.h"

namespace pivot::scenes {

void buildPyramid(Scene& scene, const SceneOptions& options) {
    scene.restFromStep = stepAt(options, 1.0f);
    createGround(*scene.world);
    PyramidSpec pyramid;
    pyramid.rows = 20;
    pyramid.pitchX = 1.05f;
    const std::vector<BodyId> boxes = addPyramid(*scene.world, pyramid);
    scene.bodies.insert(scene.bodies.end(), boxes.begin(), boxes.end());
}

}  // namespace pivot::scenes
