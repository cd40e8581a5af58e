#include "voronav/io/movingai.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string_view>

#include "voronav/core/error.hpp"
#include "voronav/core/read_file.hpp"

namespace voronav::io {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxSide = 1 << 16;

std::string strip(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == '\n' || s.back() == ' '))
    s.pop_back();
  return s;
}

int parse_int(const std::string& s, const fs::path& file, int line, const char* what) {
  int v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || s.empty())
    throw Error(file.string(), line, std::string(what) + ": expected an integer, got '" + s + "'");
  return v;
}

double parse_double(const std::string& s, const fs::path& file, int line, const char* what) {
  std::istringstream in(s);
  double v = 0;
  in >> v;
  if (!in || !in.eof() || !std::isfinite(v))
    throw Error(file.string(), line, std::string(what) + ": expected a number, got '" + s + "'");
  return v;
}

// Splits a .scen line: at tabs when it has one (map names may hold spaces), else at whitespace.
std::vector<std::string> split_columns(const std::string& line) {
  std::vector<std::string> cols;
  if (line.find('\t') != std::string::npos) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t tab = line.find('\t', start);
      cols.push_back(line.substr(start, tab - start));
      if (tab == std::string::npos) break;
      start = tab + 1;
    }
    for (auto& c : cols) {  // spaces around a tab-separated field
      while (!c.empty() && c.back() == ' ')
        c.pop_back();
      while (!c.empty() && c.front() == ' ')
        c.erase(c.begin());
    }
    return cols;
  }
  std::istringstream ls(line);
  for (std::string c; ls >> c;)
    cols.push_back(c);
  return cols;
}

}  // namespace

double last_digit_unit(const std::string& text, int min_digits) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t mant_begin = i;
  while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.'))
    ++i;
  const std::string mant = text.substr(mant_begin, i - mant_begin);
  int exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    const std::string e = text.substr(i + 1 + (i + 1 < text.size() && text[i + 1] == '+'));
    std::from_chars(e.data(), e.data() + e.size(), exponent);
  }
  const std::size_t dot = mant.find('.');
  const int int_len = static_cast<int>(dot == std::string::npos ? mant.size() : dot);
  int lead = 0, last = 0, digit = 0;
  bool nonzero = false;
  for (char c : mant) {
    if (c == '.') continue;
    const int power = int_len - 1 - digit++;
    if (c != '0' && !nonzero) {
      nonzero = true;
      lead = power;
    }
    last = power;
  }
  if (!nonzero) return 0.0;
  return std::pow(10.0, static_cast<double>(std::min(last, lead - (min_digits - 1)) + exponent));
}

bool matches_optimal(const MovingAiQuery& query, double found, double tolerance) {
  // 1e-9 relative slack: the unit itself is a rounded power of ten.
  const double allowed = std::max(tolerance, query.optimal_rounding) * (1.0 + 1e-9);
  return std::abs(found - query.optimal_length) <= allowed;
}

BinaryGrid MovingAiTerrain::traversable(bool water) const {
  BinaryGrid g(cells.width(), cells.height(), 1);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const char c = cells[i];
    g[i] = water ? (c == 'W' ? 0 : 1) : (c == '.' || c == 'G' || c == 'S' ? 0 : 1);
  }
  return g;
}

MovingAiTerrain scale_movingai_terrain(const MovingAiTerrain& terrain, int width, int height) {
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide)
    throw Error("scale_movingai_terrain", 0,
                "size " + std::to_string(width) + "x" + std::to_string(height) + " must be in 1.." +
                    std::to_string(kMaxSide));
  const int w = terrain.cells.width(), h = terrain.cells.height();
  MovingAiTerrain out{GridMap<char>(width, height, '@')};
  for (int fy = 0; fy < height; ++fy) {
    const int src_row = static_cast<int>(static_cast<long long>(fy) * h / height);
    for (int x = 0; x < width; ++x) {
      const int src_x = static_cast<int>(static_cast<long long>(x) * w / width);
      out.cells[movingai_to_cell(x, fy, height)] =
          terrain.cells[movingai_to_cell(src_x, src_row, h)];
    }
  }
  return out;
}

OccupancyGrid load_movingai_map(const fs::path& path) {
  const MovingAiTerrain t = load_movingai_terrain(path);
  OccupancyGrid grid(t.cells.width(), t.cells.height(), kFree);
  const BinaryGrid land = t.traversable(false);
  for (std::size_t i = 0; i < land.size(); ++i)
    grid[i] = land[i] == 0 ? kFree : kOccupied;
  return grid;
}

MovingAiTerrain load_movingai_terrain(const fs::path& path) {
  const std::string data = read_file_bounded(path, kMaxMapFileBytes, ".map file");
  std::istringstream in(data);
  std::string line;
  int n = 0;
  auto next = [&](const char* expected) {
    if (!std::getline(in, line))
      throw Error(path.string(), n + 1, std::string("truncated file: expected ") + expected);
    ++n;
    line = strip(line);
  };
  next("'type octile'");
  if (line.rfind("type", 0) != 0)
    throw Error(path.string(), n, "expected 'type octile', got '" + line + "'");
  int height = -1, width = -1;
  for (;;) {
    next("'height N', 'width N' and 'map'");
    if (line == "map") break;
    std::istringstream ls(line);
    std::string key, value;
    ls >> key >> value;
    if (key == "height")
      height = parse_int(value, path, n, "height");
    else if (key == "width")
      width = parse_int(value, path, n, "width");
    else
      throw Error(path.string(), n, "expected 'height', 'width' or 'map', got '" + line + "'");
  }
  if (height <= 0 || width <= 0 || height > kMaxSide || width > kMaxSide)
    throw Error(path.string(), n,
                "height and width must be given and in 1.." + std::to_string(kMaxSide));
  // The rows must be in the file before the grid is allocated.
  if (static_cast<std::size_t>(height) * static_cast<std::size_t>(width) > data.size())
    throw Error(
        path.string(), n,
        "truncated file: " + std::to_string(width) + "x" + std::to_string(height) +
            " map rows need " +
            std::to_string(static_cast<std::size_t>(height) * static_cast<std::size_t>(width)) +
            " characters, the file has " + std::to_string(data.size()) + " bytes");
  MovingAiTerrain terrain{GridMap<char>(width, height, '@')};
  for (int row = 0; row < height; ++row) {
    next(("map row " + std::to_string(row + 1) + " of " + std::to_string(height)).c_str());
    if (static_cast<int>(line.size()) != width)
      throw Error(path.string(), n,
                  "map row has " + std::to_string(line.size()) + " characters, expected width " +
                      std::to_string(width));
    for (int x = 0; x < width; ++x) {
      const char c = line[static_cast<std::size_t>(x)];
      if (std::string_view(".GS@OTW").find(c) == std::string_view::npos)
        throw Error(path.string(), n,
                    std::string("unknown map character '") + c + "' at column " +
                        std::to_string(x + 1) + " (expected . G S @ O T W)");
      terrain.cells[movingai_to_cell(x, row, height)] = c;
    }
  }
  while (std::getline(in, line)) {
    ++n;
    if (!strip(line).empty())
      throw Error(path.string(), n, "extra text after the " + std::to_string(height) + " map rows");
  }
  return terrain;
}

void save_movingai_map(const OccupancyGrid& grid, const fs::path& path) {
  std::ofstream out(path);
  if (!out) throw Error(path.string(), 0, "cannot write the .map file");
  out << "type octile\nheight " << grid.height() << "\nwidth " << grid.width() << "\nmap\n";
  for (int row = 0; row < grid.height(); ++row) {
    std::string s(static_cast<std::size_t>(grid.width()), '.');
    for (int x = 0; x < grid.width(); ++x)
      if (grid[movingai_to_cell(x, row, grid.height())] != kFree)
        s[static_cast<std::size_t>(x)] = '@';
    out << s << '\n';
  }
  if (!out) throw Error(path.string(), 0, "write failed");
}

std::vector<MovingAiQuery> load_movingai_scen(const fs::path& path) {
  std::istringstream in(read_file_bounded(path, kMaxTextFileBytes, ".scen file"));
  std::string line;
  if (!std::getline(in, line)) throw Error(path.string(), 1, "empty file: expected 'version 1'");
  line = strip(line);
  {
    std::istringstream ls(line);
    std::string key, ver;
    ls >> key >> ver;
    if (key != "version" || (ver != "1" && ver != "1.0"))
      throw Error(path.string(), 1, "expected 'version 1', got '" + line + "'");
  }
  std::vector<MovingAiQuery> out;
  int n = 1;
  while (std::getline(in, line)) {
    ++n;
    line = strip(line);
    if (line.empty()) continue;
    const std::vector<std::string> cols = split_columns(line);
    if (cols.size() != 9)
      throw Error(path.string(), n,
                  "expected 9 tab-separated (or whitespace-separated) columns (bucket, map, width, "
                  "height, start x, start y, goal x, goal y, optimal length), got " +
                      std::to_string(cols.size()));
    MovingAiQuery q;
    q.line = n;
    q.bucket = parse_int(cols[0], path, n, "bucket");
    q.map = cols[1];
    q.map_width = parse_int(cols[2], path, n, "width");
    q.map_height = parse_int(cols[3], path, n, "height");
    q.start_x = parse_int(cols[4], path, n, "start x");
    q.start_y = parse_int(cols[5], path, n, "start y");
    q.goal_x = parse_int(cols[6], path, n, "goal x");
    q.goal_y = parse_int(cols[7], path, n, "goal y");
    q.optimal_length = parse_double(cols[8], path, n, "optimal length");
    q.optimal_rounding = last_digit_unit(cols[8]);
    if (q.optimal_length < 0) throw Error(path.string(), n, "optimal length must be >= 0");
    out.push_back(std::move(q));
  }
  return out;
}

void save_movingai_scen(const std::vector<MovingAiQuery>& queries, const fs::path& path) {
  std::ofstream out(path);
  if (!out) throw Error(path.string(), 0, "cannot write the .scen file");
  out << "version 1\n" << std::setprecision(17);
  for (const auto& q : queries)
    out << q.bucket << '\t' << q.map << '\t' << q.map_width << '\t' << q.map_height << '\t'
        << q.start_x << '\t' << q.start_y << '\t' << q.goal_x << '\t' << q.goal_y << '\t'
        << q.optimal_length << '\n';
  if (!out) throw Error(path.string(), 0, "write failed");
}

void check_scen_fits(const std::vector<MovingAiQuery>& queries, const OccupancyGrid& grid,
                     const fs::path& scen_path, bool allow_scaling) {
  for (const auto& q : queries) {
    const bool scaled = q.map_width != grid.width() || q.map_height != grid.height();
    if (scaled && allow_scaling) {
      if (q.map_width <= 0 || q.map_height <= 0 || q.map_width > kMaxSide ||
          q.map_height > kMaxSide)
        throw Error(scen_path.string(), q.line,
                    "map size columns must be in 1.." + std::to_string(kMaxSide));
      if (q.start_x < 0 || q.start_y < 0 || q.goal_x < 0 || q.goal_y < 0 ||
          q.start_x >= q.map_width || q.goal_x >= q.map_width || q.start_y >= q.map_height ||
          q.goal_y >= q.map_height)
        throw Error(scen_path.string(), q.line,
                    "start or goal lies outside the " + std::to_string(q.map_width) + "x" +
                        std::to_string(q.map_height) + " map of the size columns");
      continue;
    }
    if (scaled)
      throw Error(scen_path.string(), q.line,
                  "query is for a " + std::to_string(q.map_width) + "x" +
                      std::to_string(q.map_height) + " map, but the map is " +
                      std::to_string(grid.width()) + "x" + std::to_string(grid.height()));
    auto inside = [&](int x, int y) {
      return x >= 0 && y >= 0 && x < grid.width() && y < grid.height();
    };
    if (!inside(q.start_x, q.start_y) || !inside(q.goal_x, q.goal_y))
      throw Error(scen_path.string(), q.line, "start or goal lies outside the map");
  }
}

}  // namespace voronav::io
