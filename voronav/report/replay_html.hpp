// The replay page (issue 9): one self-contained index.html that shows a report::Recording in any
// browser without network access. The page template is voronav/report/viewer.html (plain
// HTML/CSS/JS, no libraries), embedded into the library at build time; the recording is inlined
// as JSON in a <script type="application/json"> element. The page draws the map and its layers on
// a canvas with toggles, animates the robots (play/pause, speed, time slider) and plots the metric
// series. Schema and page behaviour: docs/replay.md.
#pragma once

#include <string>
#include <string_view>

#include "voronav/report/recording.hpp"

namespace voronav::report {

/// The page template as embedded at build time (contains kRecordingPlaceholder once).
[[nodiscard]] std::string_view viewer_template();

/// The marker in the template that render_replay_html() replaces with the recording JSON.
inline constexpr std::string_view kRecordingPlaceholder = "\"__VORONAV_RECORDING_JSON__\"";

/// The complete page for a recording (validates it; throws voronav::Error on bad input).
[[nodiscard]] std::string render_replay_html(const Recording& recording);

/// Writes the page to `path`. When `path` is an existing directory or ends in '/', writes
/// `<path>/index.html` (creating the directory). Returns the file written.
std::string write_replay_html(const Recording& recording, const std::string& path);

}  // namespace voronav::report
