// The browser replay: one self-contained HTML file (inline script and data, no network) that
// replays recorded runs on canvases, one per position solver side by side, with play, pause
// and a scrub bar, and the joint-separation plot of every run under them.
#pragma once

#include <string>
#include <vector>

#include "replay/recording.h"

namespace pivot::replay {

std::string renderReplayHtml(const std::vector<Recording>& recordings);

/// Records the named scenes (600 steps, every 2nd step a frame) and writes the page to `path`.
/// Returns an empty string, or what went wrong.
std::string writeReplayFile(const std::string& path, const std::vector<std::string>& sceneNames);

}  // namespace pivot::replay
