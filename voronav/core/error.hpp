// voronav::Error: the one exception type for malformed input and misuse. It names the source
// (file or argument), the line where known, and what was expected, e.g.
// "maps/a.yaml:3: resolution: expected a positive number, got 'abc'".
#pragma once

#include <stdexcept>
#include <string>

namespace voronav {

class Error : public std::runtime_error {
 public:
  /// source: a file path or the name of an argument; line: 1-based, 0 when not applicable.
  Error(std::string source, int line, std::string reason);
  explicit Error(std::string reason) : Error("", 0, std::move(reason)) {}

  [[nodiscard]] const std::string& source() const { return source_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& reason() const { return reason_; }

 private:
  std::string source_;
  int line_;
  std::string reason_;
};

}  // namespace voronav
