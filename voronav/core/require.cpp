#include "voronav/core/require.hpp"

#include <cmath>

#include "voronav/core/error.hpp"

namespace voronav {

void require_finite_nonneg(const std::string& name, double v) {
  if (!(v >= 0.0) || !std::isfinite(v))
    throw Error(name, 0, "expected a finite number >= 0, got " + std::to_string(v));
}

void require_finite_positive(const std::string& name, double v) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw Error(name, 0, "expected a positive finite number, got " + std::to_string(v));
}

}  // namespace voronav
