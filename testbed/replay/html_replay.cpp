// Placeholder: implementation pending.
#include "replay/html_replay.h"

namespace pivot::replay {

std::string writeReplayFile(const std::string&, const std::vector<std::string>&) {
    return "the browser replay is not implemented yet";
}

}  // namespace pivot::replay
