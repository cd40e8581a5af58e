// Option checks shared by every module: each throws voronav::Error naming the option and the
// value when the value is not what the option expects (NaN and infinities are refused), so
// every module words the same mistake the same way.
#pragma once

#include <string>

namespace voronav {

/// Throws Error(name, 0, "expected a finite number >= 0, got v") unless 0 <= v < inf.
void require_finite_nonneg(const std::string& name, double v);
/// Throws Error(name, 0, "expected a positive finite number, got v") unless 0 < v < inf.
void require_finite_positive(const std::string& name, double v);

}  // namespace voronav
