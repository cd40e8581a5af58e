#include "voronav/topology/region_export.hpp"

#include <png.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <unordered_map>

#include "voronav/core/error.hpp"

namespace voronav::topology {
namespace {

std::string lower_ext(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};

}  // namespace

void write_label_image(const std::filesystem::path& path, const GridMap<std::int32_t>& region) {
  const std::string ext = lower_ext(path);
  if (ext != ".png" && ext != ".pgm")
    throw Error(path.string(), 0, "label image: expected a .png or .pgm file name");
  const int w = region.width(), h = region.height();
  std::vector<std::uint16_t> rows(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (int j = 0; j < h; ++j)
    for (int x = 0; x < w; ++x) {
      const std::int32_t r = region[Cell{x, h - 1 - j}];
      if (r >= 65535)
        throw Error(path.string(), 0, "label image: more than 65535 regions do not fit 16 bits");
      rows[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) +
           static_cast<std::size_t>(x)] = static_cast<std::uint16_t>(r < 0 ? 0 : r + 1);
    }
  // Big-endian samples for both formats.
  std::vector<unsigned char> bytes(rows.size() * 2);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    bytes[2 * i] = static_cast<unsigned char>(rows[i] >> 8);
    bytes[2 * i + 1] = static_cast<unsigned char>(rows[i] & 0xff);
  }
  if (ext == ".pgm") {
    std::ofstream f(path, std::ios::binary);
    f << "P5\n" << w << " " << h << "\n65535\n";
    f.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
    if (!f) throw Error(path.string(), 0, "label image: cannot write the file");
    return;
  }
  std::unique_ptr<std::FILE, FileCloser> fp(std::fopen(path.c_str(), "wb"));
  if (!fp) throw Error(path.string(), 0, "label image: cannot open the file for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw Error(path.string(), 0, "label image: libpng initialisation failed");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error(path.string(), 0, "label image: libpng failed to write the file");
  }
  png_init_io(png, fp.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 16,
               PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int j = 0; j < h; ++j)
    png_write_row(png,
                  bytes.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(w) * 2);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

std::vector<std::vector<std::uint16_t>> read_label_image(const std::filesystem::path& path) {
  const std::string ext = lower_ext(path);
  std::vector<std::vector<std::uint16_t>> out;
  if (ext == ".pgm") {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Error(path.string(), 0, "label image: cannot open the file");
    std::string magic;
    int w = 0, h = 0, maxval = 0;
    f >> magic >> w >> h >> maxval;
    f.get();
    if (magic != "P5" || w <= 0 || h <= 0 || maxval <= 0 || maxval > 65535)
      throw Error(path.string(), 1, "label image: expected a binary PGM (P5)");
    const int bps = maxval > 255 ? 2 : 1;
    std::vector<unsigned char> bytes(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                                     static_cast<std::size_t>(bps));
    f.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!f) throw Error(path.string(), 0, "label image: the pixel data is truncated");
    out.assign(static_cast<std::size_t>(h),
               std::vector<std::uint16_t>(static_cast<std::size_t>(w)));
    for (std::size_t i = 0; i < static_cast<std::size_t>(w) * static_cast<std::size_t>(h); ++i)
      out[i / static_cast<std::size_t>(w)][i % static_cast<std::size_t>(w)] =
          bps == 2 ? static_cast<std::uint16_t>((bytes[2 * i] << 8) | bytes[2 * i + 1]) : bytes[i];
    return out;
  }
  std::unique_ptr<std::FILE, FileCloser> fp(std::fopen(path.c_str(), "rb"));
  if (!fp) throw Error(path.string(), 0, "label image: cannot open the file");
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(path.string(), 0, "label image: libpng initialisation failed");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(path.string(), 0, "label image: not a readable PNG");
  }
  png_init_io(png, fp.get());
  png_read_info(png, info);
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  const int depth = png_get_bit_depth(png, info);
  if (png_get_color_type(png, info) != PNG_COLOR_TYPE_GRAY || (depth != 8 && depth != 16)) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw Error(path.string(), 0, "label image: expected an 8- or 16-bit grey PNG");
  }
  std::vector<unsigned char> row(static_cast<std::size_t>(w) * static_cast<std::size_t>(depth / 8));
  out.assign(h, std::vector<std::uint16_t>(w));
  for (png_uint_32 j = 0; j < h; ++j) {
    png_read_row(png, row.data(), nullptr);
    for (png_uint_32 x = 0; x < w; ++x)
      out[j][x] =
          depth == 16 ? static_cast<std::uint16_t>((row[2 * x] << 8) | row[2 * x + 1]) : row[x];
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return out;
}

double ring_area(const Ring& ring) {
  double a = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& p = ring[i];
    const Vec2& q = ring[(i + 1) % ring.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return 0.5 * a;
}

std::vector<std::vector<Ring>> region_outlines(const GridMap<std::int32_t>& region, int regions) {
  const GridGeometry& geo = region.geometry();
  const int w = region.width(), h = region.height();
  auto id = [&](int x, int y) {
    return x < 0 || y < 0 || x >= w || y >= h ? -1 : region[Cell{x, y}];
  };
  // Directed boundary edges (region on the left) per region, keyed by start corner.
  struct Edge {
    int x0, y0, x1, y1;
  };
  std::vector<std::vector<Edge>> edges(static_cast<std::size_t>(std::max(regions, 0)));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int r = id(x, y);
      if (r < 0 || r >= regions) continue;
      auto& e = edges[static_cast<std::size_t>(r)];
      if (id(x, y - 1) != r) e.push_back({x, y, x + 1, y});
      if (id(x + 1, y) != r) e.push_back({x + 1, y, x + 1, y + 1});
      if (id(x, y + 1) != r) e.push_back({x + 1, y + 1, x, y + 1});
      if (id(x - 1, y) != r) e.push_back({x, y + 1, x, y});
    }
  auto key = [](int x, int y) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
           static_cast<std::uint32_t>(y);
  };
  std::vector<std::vector<Ring>> out(edges.size());
  for (std::size_t r = 0; r < edges.size(); ++r) {
    const auto& e = edges[r];
    std::unordered_multimap<std::uint64_t, std::size_t> from;
    from.reserve(e.size());
    for (std::size_t k = 0; k < e.size(); ++k)
      from.emplace(key(e[k].x0, e[k].y0), k);
    std::vector<std::uint8_t> used(e.size(), 0);
    for (std::size_t s = 0; s < e.size(); ++s) {
      if (used[s]) continue;
      std::vector<std::pair<int, int>> pts;
      std::size_t k = s;
      while (!used[k]) {
        used[k] = 1;
        pts.emplace_back(e[k].x0, e[k].y0);
        // Next edge from the end corner; at a corner shared diagonally, turn left (keeps the
        // two touching cells in separate rings consistently).
        const int dx = e[k].x1 - e[k].x0, dy = e[k].y1 - e[k].y0;
        std::size_t next = k;
        int best = 99;
        const auto range = from.equal_range(key(e[k].x1, e[k].y1));
        for (auto it = range.first; it != range.second; ++it) {
          if (used[it->second]) continue;
          const Edge& n = e[it->second];
          const int ndx = n.x1 - n.x0, ndy = n.y1 - n.y0;
          const int cross = dx * ndy - dy * ndx;  // > 0 left turn
          const int rank = cross > 0 ? 0 : (cross == 0 ? 1 : 2);
          if (rank < best) best = rank, next = it->second;
        }
        if (next == k) break;
        k = next;
      }
      // Drop collinear corners.
      Ring ring;
      const std::size_t n = pts.size();
      for (std::size_t i = 0; i < n; ++i) {
        const auto& a = pts[(i + n - 1) % n];
        const auto& b = pts[i];
        const auto& c = pts[(i + 1) % n];
        if ((b.first - a.first) * (c.second - b.second) -
                (b.second - a.second) * (c.first - b.first) ==
            0)
          continue;
        ring.push_back(
            geo.grid_to_world(Vec2{static_cast<double>(b.first), static_cast<double>(b.second)}));
      }
      if (ring.size() >= 3) out[r].push_back(std::move(ring));
    }
  }
  return out;
}

}  // namespace voronav::topology
