#include "voronav/core/error.hpp"

namespace voronav {
namespace {
std::string format_message(const std::string& source, int line, const std::string& reason) {
  std::string out;
  if (!source.empty()) {
    out += source;
    if (line > 0) {
      out.push_back(':');
      out.append(std::to_string(line));
    }
    out.append(": ");
  }
  out.append(reason);
  return out;
}
}  // namespace

Error::Error(std::string source, int line, std::string reason)
    : std::runtime_error(format_message(source, line, reason)),
      source_(std::move(source)),
      line_(line),
      reason_(std::move(reason)) {}

}  // namespace voronav
