// A count of the changes to what the island search and the island plans read: which bodies are
// awake and not static, the touching solid contacts and the joints and mouse joints between
// them, the joints' strategies and break limits. While the count stands still, last step's
// islands and plans are this step's, and the stepper keeps them instead of searching and
// colouring again (solver/stepper.h). A change that is not counted leaves stale islands, so
// everything that makes one goes through here: wakeUp (model/body.h), the contact manager's
// touch events and pre-solve answers, the world's calls that make, destroy or retype objects,
// and the stepper itself for the islands that fell asleep or let a joint go.
#pragma once

#include <cstdint>

namespace pivot {

class IslandRevision {
public:
    void bump() { ++count_; }
    std::uint64_t count() const { return count_; }

private:
    std::uint64_t count_ = 0;
};

}  // namespace pivot
