// Built in place of box2d_v3_engine.cpp when CMake was not given Box2D v3's source tree.
#include "bench/engines/engine.h"

namespace pivot::bench {

std::vector<EngineKind> box2dV3Engines() {
    return {};
}

}  // namespace pivot::bench
