// The text of voronav/report/viewer.html, generated into the build tree by
// cmake/VoronavEmbed.cmake (so the page stays an editable, lintable file in the repo).
#pragma once

#include <string_view>

namespace voronav::report::internal {
[[nodiscard]] std::string_view viewer_html();
}  // namespace voronav::report::internal
