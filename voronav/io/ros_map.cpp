#include "voronav/io/ros_map.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <system_error>

#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"
#include "voronav/io/image.hpp"

namespace voronav::io {
namespace {

namespace fs = std::filesystem;

int line_of(const YAML::Node& n) {
  return n.Mark().line >= 0 ? n.Mark().line + 1 : 0;
}

YAML::Node require(const YAML::Node& root, const fs::path& file, const char* key) {
  const YAML::Node n = root[key];
  if (!n) throw Error(file.string(), line_of(root), std::string("missing key '") + key + "'");
  return n;
}

double number(const YAML::Node& n, const fs::path& file, const char* key) {
  if (!n.IsScalar())
    throw Error(file.string(), line_of(n), std::string(key) + ": expected a number");
  double v = 0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    throw Error(file.string(), line_of(n),
                std::string(key) + ": expected a number, got '" + n.Scalar() + "'");
  }
  if (!std::isfinite(v))
    throw Error(file.string(), line_of(n), std::string(key) + ": expected a finite number");
  return v;
}

RosMapMode parse_mode(const YAML::Node& n, const fs::path& file) {
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  if (s == "trinary") return RosMapMode::kTrinary;
  if (s == "scale") return RosMapMode::kScale;
  if (s == "raw") return RosMapMode::kRaw;
  throw Error(file.string(), line_of(n), "mode: expected trinary, scale or raw, got '" + s + "'");
}

}  // namespace

const char* to_string(RosMapMode mode) {
  switch (mode) {
    case RosMapMode::kTrinary:
      return "trinary";
    case RosMapMode::kScale:
      return "scale";
    case RosMapMode::kRaw:
      return "raw";
  }
  return "?";
}

OccupancyGrid image_to_occupancy(const GrayImage& image, const RosMapMetadata& m) {
  GridGeometry g{image.width, image.height, m.resolution, m.origin};
  OccupancyGrid grid(g, kUnknown);
  for (int j = 0; j < image.height; ++j) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(j) * static_cast<std::size_t>(image.width) +
                            static_cast<std::size_t>(x);
      const double shade = image.gray[i] / 255.0;
      const double occ = m.negate ? shade : 1.0 - shade;
      std::int8_t v = kUnknown;
      switch (m.mode) {
        case RosMapMode::kTrinary:
          v = m.occupied_thresh < occ ? kOccupied : (occ < m.free_thresh ? kFree : kUnknown);
          break;
        case RosMapMode::kScale:
          if (image.alpha[i] != 255)
            v = kUnknown;
          else if (m.occupied_thresh < occ)
            v = kOccupied;
          else if (occ < m.free_thresh)
            v = kFree;
          else
            v = static_cast<std::int8_t>(
                std::rint((occ - m.free_thresh) / (m.occupied_thresh - m.free_thresh) * 100.0));
          break;
        case RosMapMode::kRaw: {
          const int p = image.gray[i];
          v = p <= 100 ? static_cast<std::int8_t>(p) : kUnknown;
          break;
        }
      }
      grid[Cell{x, image.height - 1 - j}] = v;
    }
  }
  return grid;
}

RosMap read_ros_map(const fs::path& yaml_path) {
  YAML::Node root;
  try {
    root = YAML::Load(read_file_bounded(yaml_path, kMaxTextFileBytes, "map YAML file"));
  } catch (const YAML::Exception& e) {
    throw Error(yaml_path.string(), e.mark.line + 1, "malformed YAML: " + e.msg);
  }
  if (!root.IsMap()) throw Error(yaml_path.string(), 1, "expected a YAML mapping of map keys");
  RosMapMetadata m;
  const YAML::Node image = require(root, yaml_path, "image");
  if (!image.IsScalar() || image.Scalar().empty())
    throw Error(yaml_path.string(), line_of(image), "image: expected a file name");
  m.image = image.Scalar();
  m.resolution = number(require(root, yaml_path, "resolution"), yaml_path, "resolution");
  if (!(m.resolution > 0) || !std::isfinite(m.resolution))
    throw Error(yaml_path.string(), line_of(root["resolution"]),
                "resolution: expected a positive number [m/cell]");
  const YAML::Node origin = require(root, yaml_path, "origin");
  if (!origin.IsSequence() || origin.size() != 3)
    throw Error(yaml_path.string(), line_of(origin), "origin: expected [x, y, yaw]");
  m.origin = {{number(origin[0], yaml_path, "origin x"), number(origin[1], yaml_path, "origin y")},
              number(origin[2], yaml_path, "origin yaw")};
  if (const YAML::Node n = root["negate"]) {
    const double v = number(n, yaml_path, "negate");
    if (v != 0 && v != 1) throw Error(yaml_path.string(), line_of(n), "negate: expected 0 or 1");
    m.negate = v != 0;
  }
  m.occupied_thresh =
      number(require(root, yaml_path, "occupied_thresh"), yaml_path, "occupied_thresh");
  m.free_thresh = number(require(root, yaml_path, "free_thresh"), yaml_path, "free_thresh");
  if (!(m.free_thresh >= 0 && m.free_thresh <= m.occupied_thresh && m.occupied_thresh <= 1))
    throw Error(yaml_path.string(), line_of(root["free_thresh"]),
                "thresholds: expected 0 <= free_thresh <= occupied_thresh <= 1");
  if (const YAML::Node n = root["mode"]) m.mode = parse_mode(n, yaml_path);
  if (m.mode == RosMapMode::kScale && m.free_thresh == m.occupied_thresh)
    throw Error(yaml_path.string(), line_of(root["free_thresh"]),
                "mode scale needs free_thresh < occupied_thresh");
  const fs::path image_path = m.image.is_absolute() ? m.image : yaml_path.parent_path() / m.image;
  std::error_code exists_ec;  // no throw for names the file system refuses (too long, ...)
  if (!fs::exists(image_path, exists_ec))
    throw Error(
        yaml_path.string(), line_of(image),
        "image '" + m.image.string() + "' not found (looked for " + image_path.string() + ")");
  return {image_to_occupancy(read_image(image_path), m), m};
}

fs::path save_ros_map(const OccupancyGrid& grid, const fs::path& yaml_path,
                      const SaveRosMapOptions& o) {
  if (grid.empty()) throw Error(yaml_path.string(), 0, "cannot save an empty map");
  if (!(o.free_thresh >= 0 && o.free_thresh <= o.occupied_thresh && o.occupied_thresh <= 1))
    throw Error(yaml_path.string(), 0, "expected 0 <= free_thresh <= occupied_thresh <= 1");
  const std::string name = o.image_name.empty() ? yaml_path.stem().string() + ".pgm" : o.image_name;
  const fs::path image_path = yaml_path.parent_path() / name;
  GrayImage img;
  img.width = grid.width();
  img.height = grid.height();
  img.gray.resize(grid.size());
  img.alpha.assign(grid.size(), 255);
  const int free_i = static_cast<int>(std::rint(o.free_thresh * 100.0));
  const int occ_i = static_cast<int>(std::rint(o.occupied_thresh * 100.0));
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const int v = grid[Cell{x, y}];
      const std::size_t i =
          static_cast<std::size_t>(grid.height() - 1 - y) * static_cast<std::size_t>(grid.width()) +
          static_cast<std::size_t>(x);
      std::uint8_t p = 205;
      switch (o.mode) {
        case RosMapMode::kTrinary:
          if (v >= 0 && v <= free_i)
            p = 254;
          else if (v >= occ_i && v <= 100)
            p = 0;
          break;
        case RosMapMode::kScale:
          if (v < 0 || v > 100) {
            img.alpha[i] = 0;
            img.has_alpha = true;
          } else {
            p = static_cast<std::uint8_t>(std::rint((100.0 - v) / 100.0 * 255.0));
          }
          break;
        case RosMapMode::kRaw:
          p = v < 0 ? 255 : static_cast<std::uint8_t>(v);
          break;
      }
      img.gray[i] = p;
    }
  }
  const std::string ext = image_path.extension().string();
  if (ext == ".png")
    write_png(image_path, img);
  else if (ext == ".pgm") {
    if (img.has_alpha)
      throw Error(image_path.string(), 0,
                  "mode scale with unknown cells needs a .png image (alpha)");
    write_pgm(image_path, img);
  } else {
    throw Error(image_path.string(), 0, "image name must end in .pgm or .png");
  }
  std::ofstream out(yaml_path);
  if (!out) throw Error(yaml_path.string(), 0, "cannot write the map YAML file");
  out.precision(17);
  const Pose2& org = grid.geometry().origin;
  out << "image: " << name << "\nmode: " << to_string(o.mode)
      << "\nresolution: " << grid.resolution() << "\norigin: [" << org.position.x << ", "
      << org.position.y << ", " << org.yaw << "]\nnegate: 0\noccupied_thresh: " << o.occupied_thresh
      << "\nfree_thresh: " << o.free_thresh << "\n";
  if (!out) throw Error(yaml_path.string(), 0, "write failed");
  return image_path;
}

}  // namespace voronav::io
