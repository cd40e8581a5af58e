// Colours for pictures: RGBA in [0, 1], a palette of distinguishable colours for labels (obstacle
// components, regions, robots) and the viridis colour map for scalar fields (distance, density).
#pragma once

#include <cstdint>

namespace voronav::render {

struct Color {
  double r = 0, g = 0, b = 0, a = 1;
  [[nodiscard]] constexpr Color with_alpha(double alpha) const { return {r, g, b, alpha}; }
  [[nodiscard]] static constexpr Color hex(std::uint32_t rgb, double alpha = 1.0) {
    return {((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0, alpha};
  }
};

namespace colors {
inline constexpr Color kBlack{0, 0, 0};
inline constexpr Color kWhite{1, 1, 1};
inline constexpr Color kGrey = Color::hex(0x9e9e9e);
inline constexpr Color kUnknown = Color::hex(0xcdcdcd);  // map_server's 205
inline constexpr Color kRed = Color::hex(0xd62728);
inline constexpr Color kGreen = Color::hex(0x2ca02c);
inline constexpr Color kBlue = Color::hex(0x1f77b4);
inline constexpr Color kOrange = Color::hex(0xff7f0e);
inline constexpr Color kPurple = Color::hex(0x9467bd);
inline constexpr Color kCyan = Color::hex(0x17becf);
inline constexpr Color kTransparent{0, 0, 0, 0};
}  // namespace colors

/// A distinct colour for label `i` (cycles through a 20-colour qualitative palette).
[[nodiscard]] Color palette(int i);
/// Viridis colour map, t in [0, 1] (clamped).
[[nodiscard]] Color viridis(double t);

}  // namespace voronav::render
