// Grey-level images as map files hold them (PGM P2/P5 and PNG), read and written without any
// map semantics: the map loaders (ros_map, floorplan) turn pixels into occupancy. PNG goes
// through libpng; PGM is parsed by hand (a trivial format) with errors that name the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace voronav::io {

/// An 8-bit image, row 0 at the top (file order). `gray` is the mean of the colour channels, so
/// it equals what ROS map_server computes as the pixel's shade; `alpha` is 255 where opaque.
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> gray;   ///< width*height, row-major, top row first
  std::vector<std::uint8_t> alpha;  ///< same size; all 255 when the file has no alpha channel
  bool has_alpha = false;

  [[nodiscard]] std::uint8_t at(int x, int y) const {
    return gray[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)];
  }
};

/// Reads a PGM (P2 or P5; maxval up to 65535, scaled to 0..255) or a PNG (any colour type), by
/// the file's magic bytes. Throws voronav::Error naming the file and what is wrong.
[[nodiscard]] GrayImage read_image(const std::filesystem::path& path);
[[nodiscard]] GrayImage read_pgm(const std::filesystem::path& path);
[[nodiscard]] GrayImage read_png(const std::filesystem::path& path);

/// Writes a binary PGM (P5, maxval 255). Alpha is ignored.
void write_pgm(const std::filesystem::path& path, const GrayImage& image);
/// Writes a PNG: grey, or grey+alpha when image.has_alpha.
void write_png(const std::filesystem::path& path, const GrayImage& image);

}  // namespace voronav::io
