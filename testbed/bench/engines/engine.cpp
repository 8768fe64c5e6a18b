#include "bench/engines/engine.h"

namespace pivot::bench {

std::vector<EngineKind> allEngines() {
    std::vector<EngineKind> kinds = pivotEngines();
    kinds.push_back(box2dEngine());
    for (EngineKind& kind : box2dV3Engines()) kinds.push_back(std::move(kind));
    return kinds;
}

}  // namespace pivot::bench
