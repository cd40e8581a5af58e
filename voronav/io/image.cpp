#include "voronav/io/image.hpp"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"

namespace voronav::io {
namespace {

constexpr int kMaxSide = 1 << 16;  // larger images are refused (a 65536^2 map is 4 GiB)
// At most 2^28 pixels (16384^2): the decoder holds 4 bytes a pixel while converting.
constexpr unsigned long long kMaxPixels = 1ULL << 28;

void check_size(const std::filesystem::path& path, long long w, long long h) {
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide)
    throw Error(path.string(), 0,
                "image size " + std::to_string(w) + "x" + std::to_string(h) + " is not in 1.." +
                    std::to_string(kMaxSide) + " per side");
  if (static_cast<unsigned long long>(w) * static_cast<unsigned long long>(h) > kMaxPixels)
    throw Error(path.string(), 0,
                "image size " + std::to_string(w) + "x" + std::to_string(h) +
                    " is over the limit of " + std::to_string(kMaxPixels) + " pixels");
}

std::string read_all(const std::filesystem::path& path) {
  return read_file_bounded(path, kMaxMapFileBytes, "image file");
}

/// Token reader for the PGM header (whitespace and '#' comments), tracking the line.
class PgmHeader {
 public:
  PgmHeader(const std::filesystem::path& path, const std::string& data) : path_(path), d_(data) {}

  long long number(const char* what) {
    skip();
    if (pos_ >= d_.size()) fail(std::string("truncated header: expected ") + what);
    if (!std::isdigit(static_cast<unsigned char>(d_[pos_])))
      fail(std::string("expected ") + what + ", got '" + d_.substr(pos_, 8) + "'");
    long long v = 0;
    while (pos_ < d_.size() && std::isdigit(static_cast<unsigned char>(d_[pos_]))) {
      v = v * 10 + (d_[pos_++] - '0');
      if (v > std::numeric_limits<int>::max()) fail(std::string(what) + " is too large");
    }
    return v;
  }
  std::size_t pos() const { return pos_; }
  void advance(std::size_t n) { pos_ += n; }
  [[noreturn]] void fail(const std::string& reason) const {
    throw Error(path_.string(), line_, "PGM: " + reason);
  }
  int line() const { return line_; }
  void skip() {
    while (pos_ < d_.size()) {
      const char c = d_[pos_];
      if (c == '#') {
        while (pos_ < d_.size() && d_[pos_] != '\n')
          ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        break;
      }
    }
  }

 private:
  const std::filesystem::path& path_;
  const std::string& d_;
  std::size_t pos_ = 2;
  int line_ = 1;
};

}  // namespace

GrayImage read_pgm(const std::filesystem::path& path) {
  const std::string d = read_all(path);
  if (d.size() < 2 || d[0] != 'P' || (d[1] != '2' && d[1] != '5'))
    throw Error(path.string(), 1, "PGM: expected the magic number P2 or P5");
  const bool ascii = d[1] == '2';
  PgmHeader h(path, d);
  const long long w = h.number("width"), ht = h.number("height"), maxval = h.number("maxval");
  check_size(path, w, ht);
  if (maxval < 1 || maxval > 65535)
    h.fail("maxval must be in 1..65535, got " + std::to_string(maxval));
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(ht);
  const std::size_t bytes_per = maxval > 255 ? 2 : 1;
  // The raster must be in the file before anything is allocated for it (P2: >= 1 byte a pixel).
  const std::size_t need = ascii ? n : n * bytes_per;
  if (d.size() - std::min(d.size(), h.pos()) < need)
    throw Error(path.string(), 0,
                "PGM: truncated raster: expected " + std::string(ascii ? "at least " : "") +
                    std::to_string(need) + " bytes for " + std::to_string(w) + "x" +
                    std::to_string(ht) + ", found " +
                    std::to_string(d.size() - std::min(d.size(), h.pos())));
  GrayImage img;
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(ht);
  img.gray.resize(n);
  img.alpha.assign(n, 255);
  auto scale = [&](long long v) {
    if (v > maxval)
      h.fail("pixel value " + std::to_string(v) + " exceeds maxval " + std::to_string(maxval));
    return static_cast<std::uint8_t>((v * 255 + maxval / 2) / maxval);
  };
  if (ascii) {
    for (std::size_t i = 0; i < n; ++i)
      img.gray[i] = scale(h.number("a pixel value"));
    return img;
  }
  // Exactly one whitespace character separates maxval from the raster.
  if (h.pos() >= d.size() || !std::isspace(static_cast<unsigned char>(d[h.pos()])))
    h.fail("expected whitespace after maxval");
  h.advance(1);
  if (d.size() - h.pos() < need)
    throw Error(path.string(), 0,
                "PGM: truncated raster: expected " + std::to_string(need) + " bytes for " +
                    std::to_string(w) + "x" + std::to_string(ht) + ", found " +
                    std::to_string(d.size() - h.pos()));
  const auto* p = reinterpret_cast<const unsigned char*>(d.data() + h.pos());
  for (std::size_t i = 0; i < n; ++i)
    img.gray[i] = bytes_per == 1 ? scale(p[i]) : scale(p[2 * i] * 256LL + p[2 * i + 1]);
  return img;
}

GrayImage read_png(const std::filesystem::path& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  const std::string file = read_all(path);
  if (!png_image_begin_read_from_memory(&png, file.data(), file.size()))
    throw Error(path.string(), 0, std::string("PNG: ") + png.message);
  if (static_cast<long long>(png.width) > kMaxSide ||
      static_cast<long long>(png.height) > kMaxSide) {
    png_image_free(&png);
    check_size(path, png.width, png.height);
  }
  // Deflate expands at most ~1032:1 and a 1-bit pixel is 1/8 byte, so a file this small cannot
  // hold the image its header declares: refuse it before allocating the RGBA buffer.
  const auto pixels = static_cast<unsigned long long>(png.width) * png.height;
  if (pixels > kMaxPixels || pixels / 8 > 1100ULL * file.size() + 4096) {
    png_image_free(&png);
    throw Error(
        path.string(), 0,
        "PNG: " + std::to_string(png.width) + "x" + std::to_string(png.height) +
            (pixels > kMaxPixels ? " is over the limit of " + std::to_string(kMaxPixels) + " pixels"
                                 : " pixels cannot be stored in a file of " +
                                       std::to_string(file.size()) + " bytes"));
  }
  png.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> rgba(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, rgba.data(), 0, nullptr)) {
    const std::string msg = png.message;
    png_image_free(&png);
    throw Error(path.string(), 0, "PNG: " + msg);
  }
  GrayImage img;
  img.width = static_cast<int>(png.width);
  img.height = static_cast<int>(png.height);
  const std::size_t n = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  img.gray.resize(n);
  img.alpha.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned sum = rgba[4 * i] + rgba[4 * i + 1] + rgba[4 * i + 2];
    img.gray[i] = static_cast<std::uint8_t>((sum + 1) / 3);
    img.alpha[i] = rgba[4 * i + 3];
    if (img.alpha[i] != 255) img.has_alpha = true;
  }
  return img;
}

GrayImage read_image(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), 0, "cannot open the image file");
  char magic[8] = {};
  in.read(magic, 8);
  if (in.gcount() >= 2 && magic[0] == 'P' && (magic[1] == '2' || magic[1] == '5'))
    return read_pgm(path);
  if (in.gcount() == 8 && std::memcmp(magic, "\x89PNG\r\n\x1a\n", 8) == 0) return read_png(path);
  throw Error(path.string(), 0, "unsupported image: expected a PGM (P2/P5) or PNG file");
}

void write_pgm(const std::filesystem::path& path, const GrayImage& image) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path.string(), 0, "cannot write the image file");
  out << "P5\n# CREATOR: voronav\n" << image.width << ' ' << image.height << "\n255\n";
  out.write(reinterpret_cast<const char*>(image.gray.data()),
            static_cast<std::streamsize>(image.gray.size()));
  if (!out) throw Error(path.string(), 0, "write failed");
}

void write_png(const std::filesystem::path& path, const GrayImage& image) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  std::vector<std::uint8_t> buf;
  const void* src = image.gray.data();
  if (image.has_alpha) {
    png.format = PNG_FORMAT_GA;
    buf.resize(image.gray.size() * 2);
    for (std::size_t i = 0; i < image.gray.size(); ++i) {
      buf[2 * i] = image.gray[i];
      buf[2 * i + 1] = image.alpha.empty() ? 255 : image.alpha[i];
    }
    src = buf.data();
  } else {
    png.format = PNG_FORMAT_GRAY;
  }
  if (!png_image_write_to_file(&png, path.c_str(), 0, src, 0, nullptr))
    throw Error(path.string(), 0, std::string("PNG write failed: ") + png.message);
}

}  // namespace voronav::io
