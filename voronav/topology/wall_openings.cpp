#include "voronav/topology/wall_openings.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/core/require.hpp"

namespace voronav::topology {
namespace {

struct P {
  double x = 0.0, y = 0.0;
};
P operator+(P a, P b) {
  return {a.x + b.x, a.y + b.y};
}
P operator-(P a, P b) {
  return {a.x - b.x, a.y - b.y};
}
P operator*(double s, P a) {
  return {s * a.x, s * a.y};
}
double dot(P a, P b) {
  return a.x * b.x + a.y * b.y;
}
P left_of(P u) {
  return {-u.y, u.x};
}
Cell cell_at(P p) {
  return {static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))};
}

// Directions of cell edges: 0 = +x, 1 = +y, 2 = -x, 3 = -y.
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

class Boundary {
 public:
  explicit Boundary(const BinaryGrid& blocked)
      : blocked_(blocked), w_(blocked.width()), h_(blocked.height()) {}

  bool is_blocked(int x, int y) const {
    const Cell c{x, y};
    return !blocked_.contains(c) || blocked_[c] != 0;
  }
  // The cells left and right of the edge leaving vertex (x, y) in direction d.
  void sides(int x, int y, int d, Cell* left, Cell* right) const {
    switch (d) {
      case 0:
        *left = {x, y}, *right = {x, y - 1};
        break;
      case 1:
        *left = {x - 1, y}, *right = {x, y};
        break;
      case 2:
        *left = {x - 1, y - 1}, *right = {x - 1, y};
        break;
      default:
        *left = {x, y - 1}, *right = {x - 1, y - 1};
        break;
    }
  }
  // Whether the edge leaving vertex (x, y) in direction d has free space on its left and an
  // obstacle on its right (a piece of the boundary, oriented).
  bool crack(int x, int y, int d) const {
    Cell l, r;
    sides(x, y, d, &l, &r);
    return !is_blocked(l.x, l.y) && is_blocked(r.x, r.y);
  }
  std::size_t index(int x, int y, int d) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(w_ + 1) +
            static_cast<std::size_t>(x)) *
               4 +
           static_cast<std::size_t>(d);
  }

  // Every closed chain of boundary vertices (free on the left), with the direction leaving each.
  template <typename F>
  void for_each_chain(F&& visit) const {
    std::vector<char> seen(static_cast<std::size_t>(w_ + 1) * static_cast<std::size_t>(h_ + 1) * 4,
                           0);
    std::vector<P> pts;
    std::vector<int> dirs;
    // Every boundary edge borders a free cell: start from the free cells' blocked neighbours.
    const int start_dx[4] = {0, 1, 1, 0}, start_dy[4] = {0, 0, 1, 1};  // the edge's first vertex
    const Cell nb[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};  // the blocked neighbour of each edge
    for (int fy = 0; fy < h_; ++fy)
      for (int fx = 0; fx < w_; ++fx) {
        if (blocked_[Cell{fx, fy}]) continue;
        for (int d = 0; d < 4; ++d) {
          if (!is_blocked(fx + nb[d].x, fy + nb[d].y)) continue;
          const int x = fx + start_dx[d], y = fy + start_dy[d];
          if (seen[index(x, y, d)]) continue;
          pts.clear();
          dirs.clear();
          int cx = x, cy = y, cd = d;
          while (!seen[index(cx, cy, cd)]) {
            seen[index(cx, cy, cd)] = 1;
            pts.push_back({static_cast<double>(cx), static_cast<double>(cy)});
            dirs.push_back(cd);
            cx += kDx[cd];
            cy += kDy[cd];
            // Next edge: turn left, straight on, turn right - the first that is a boundary edge.
            const int order[3] = {(cd + 1) % 4, cd, (cd + 3) % 4};
            int next = -1;
            for (const int nd : order)
              if (crack(cx, cy, nd)) {
                next = nd;
                break;
              }
            if (next < 0) break;  // cannot happen on a closed boundary
            cd = next;
          }
          visit(pts, dirs);
        }
      }
  }

 private:
  const BinaryGrid& blocked_;
  int w_, h_;
};

// Ramer-Douglas-Peucker on the corner indices c[lo..hi] of a chain of points: appends the split
// indices to keep (unordered; an explicit stack, so long jagged chains cannot overflow the stack).
void split(const std::vector<P>& pts, const std::vector<std::size_t>& c, std::size_t lo0,
           std::size_t hi0, double tol, std::vector<std::size_t>* keep) {
  std::vector<std::pair<std::size_t, std::size_t>> todo{{lo0, hi0}};
  while (!todo.empty()) {
    const auto [lo, hi] = todo.back();
    todo.pop_back();
    if (hi <= lo + 1) continue;
    const P a = pts[c[lo]], b = pts[c[hi]];
    const P ab = b - a;
    const double len = std::sqrt(dot(ab, ab));
    double worst = -1.0;
    std::size_t at = lo;
    for (std::size_t k = lo + 1; k < hi; ++k) {
      const P ap = pts[c[k]] - a;
      const double d =
          len > 0.0 ? std::abs(ab.x * ap.y - ab.y * ap.x) / len : std::sqrt(dot(ap, ap));
      if (d > worst) worst = d, at = k;
    }
    if (worst <= tol) continue;
    keep->push_back(at);
    todo.push_back({lo, at});
    todo.push_back({at, hi});
  }
}

// Least-squares line through pts[i0..i1] (wrapping), oriented from the first to the last point.
WallSegment fit(const std::vector<P>& pts, std::size_t i0, std::size_t i1) {
  const std::size_t n = pts.size();
  const std::size_t count = (i1 + n - i0) % n + 1;
  P m{};
  for (std::size_t k = 0; k < count; ++k)
    m = m + pts[(i0 + k) % n];
  m = (1.0 / static_cast<double>(count)) * m;
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const P d = pts[(i0 + k) % n] - m;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
  }
  const double th = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  P u{std::cos(th), std::sin(th)};
  const P first = pts[i0], last = pts[i1 % n];
  if (dot(last - first, u) < 0.0) u = -1.0 * u;
  const P a = m + dot(first - m, u) * u, b = m + dot(last - m, u) * u;
  return {a.x, a.y, b.x, b.y};
}

struct Face {
  P a, b, u, n;  // ends, unit direction, unit normal towards the free side
  double len = 0.0;
};

struct Gap {
  P p, q, u, n;  // the gap's ends on the face line (p after the first face, q before the second)
  double along = 0.0;
  bool used = false;
};

}  // namespace

void check_wall_opening_options(const WallOpeningOptions& o) {
  require_finite_nonneg("WallOpeningOptions.min_width", o.min_width);
  require_finite_nonneg("WallOpeningOptions.max_width", o.max_width);
  require_finite_nonneg("WallOpeningOptions.min_wall_length", o.min_wall_length);
  require_finite_nonneg("WallOpeningOptions.max_offset", o.max_offset);
  require_finite_nonneg("WallOpeningOptions.fit_tolerance", o.fit_tolerance);
  require_finite_nonneg("WallOpeningOptions.max_wall_thickness", o.max_wall_thickness);
  if (!(o.max_angle_deg >= 0.0 && o.max_angle_deg < 90.0))
    throw Error("WallOpeningOptions.max_angle_deg", 0,
                "expected an angle in [0, 90) degrees, got " + std::to_string(o.max_angle_deg));
  if (o.max_width > 0.0 && o.max_width < o.min_width)
    throw Error("WallOpeningOptions.max_width", 0,
                "expected 0 (off) or at least min_width " + std::to_string(o.min_width) + ", got " +
                    std::to_string(o.max_width));
}

double WallSegment::length() const {
  return std::hypot(bx - ax, by - ay);
}

std::vector<WallSegment> wall_segments(const BinaryGrid& blocked, double fit_tolerance_cells,
                                       double min_length_cells) {
  std::vector<WallSegment> out;
  Boundary(blocked).for_each_chain([&](const std::vector<P>& pts, const std::vector<int>& dirs) {
    const std::size_t n = pts.size();
    std::vector<std::size_t> corners;
    for (std::size_t k = 0; k < n; ++k)
      if (dirs[k] != dirs[(k + n - 1) % n]) corners.push_back(k);
    if (corners.size() < 2) return;
    // Split the closed chain at its first corner and the corner farthest from it, then each half.
    std::size_t far = 1;
    for (std::size_t k = 1; k < corners.size(); ++k) {
      const P d = pts[corners[k]] - pts[corners[0]], e = pts[corners[far]] - pts[corners[0]];
      if (dot(d, d) > dot(e, e)) far = k;
    }
    std::vector<std::size_t> c = corners;
    c.push_back(corners[0]);  // closes the chain: c.back() is the first corner again
    std::vector<std::size_t> keep{0};
    split(pts, c, 0, far, fit_tolerance_cells, &keep);
    keep.push_back(far);
    split(pts, c, far, c.size() - 1, fit_tolerance_cells, &keep);
    keep.push_back(c.size() - 1);
    std::sort(keep.begin(), keep.end());
    for (std::size_t k = 0; k + 1 < keep.size(); ++k) {
      const WallSegment s = fit(pts, c[keep[k]], c[keep[k + 1]]);
      if (s.length() >= min_length_cells) out.push_back(s);
    }
  });
  return out;
}

std::vector<WallOpening> find_wall_openings(const BinaryGrid& blocked,
                                            const WallOpeningOptions& o) {
  check_wall_opening_options(o);
  std::vector<WallOpening> out;
  if (o.max_width <= 0.0 || blocked.size() == 0) return out;
  const double res = blocked.geometry().resolution;
  const double min_w = o.min_width / res, max_w = o.max_width / res;
  const double max_off = o.max_offset / res, thick = o.max_wall_thickness / res;
  const double cos_max = std::cos(o.max_angle_deg * std::numbers::pi / 180.0);
  auto free_at = [&](P p) {
    const Cell c = cell_at(p);
    return blocked.contains(c) && blocked[c] == 0;
  };

  std::vector<Face> faces;
  for (const WallSegment& s :
       wall_segments(blocked, o.fit_tolerance / res, std::max(1.0, o.min_wall_length / res))) {
    Face f;
    f.a = {s.ax, s.ay};
    f.b = {s.bx, s.by};
    f.len = s.length();
    f.u = (1.0 / f.len) * (f.b - f.a);
    f.n = left_of(f.u);
    faces.push_back(f);
  }

  // 2. Gaps: each face's nearest collinear successor across free space.
  std::vector<Gap> gaps;
  std::vector<char> gap_after(faces.size(), 0);
  for (const Face& f1 : faces) {
    const Face* best = nullptr;
    double best_along = HUGE_VAL;
    for (const Face& f2 : faces) {
      if (&f1 == &f2 || dot(f1.u, f2.u) < cos_max) continue;
      const P g = f2.a - f1.b;
      const double along = dot(g, f1.u);
      if (along < min_w || along > max_w || along >= best_along) continue;
      if (std::abs(dot(g, f1.n)) > max_off || std::abs(dot(f1.b - f2.a, f2.n)) > max_off) continue;
      best = &f2;
      best_along = along;
    }
    if (best == nullptr) continue;
    // Free on both sides of the face line all along the gap: a gap in the wall, not a niche face
    // or a pillar standing in the line.
    bool open = true;
    for (double t = 0.5; t < best_along - 0.25 && open; t += 0.5)
      open = free_at(f1.b + t * f1.u + 0.5 * f1.n) && free_at(f1.b + t * f1.u - 0.5 * f1.n);
    if (!open) continue;
    gaps.push_back({f1.b, best->a, f1.u, f1.n, best_along, false});
    gap_after[static_cast<std::size_t>(&f1 - faces.data())] = 1;
  }

  // 3. Pair the gaps of a wall's two faces; close each opening from jamb to jamb.
  auto jamb = [&](P e, P step, Cell* c) {
    for (int k = 0; k <= 8; ++k) {
      const Cell q = cell_at(e + (0.5 * k) * step);
      if (!blocked.contains(q)) return false;
      if (blocked[q]) {
        *c = q;
        return true;
      }
    }
    return false;
  };
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    if (gaps[i].used) continue;
    Gap& g = gaps[i];
    g.used = true;
    P e1 = g.p - 0.5 * g.n, e2 = g.q - 0.5 * g.n;  // half a cell behind the face
    bool both = false;
    for (std::size_t j = i + 1; j < gaps.size(); ++j) {
      Gap& h = gaps[j];
      if (h.used || dot(g.u, h.u) > -cos_max) continue;
      const double depth = -dot(h.p - g.p, g.n);  // how far behind g's face h's face lies
      if (depth <= 0.0 || depth > thick + max_off) continue;
      // h runs the other way: h.q faces g.p, h.p faces g.q. Overlap along g of at least half.
      const double s0 = dot(h.q - g.p, g.u), s1 = dot(h.p - g.p, g.u);
      const double overlap = std::min(g.along, s1) - std::max(0.0, s0);
      if (overlap < 0.5 * std::min(g.along, h.along)) continue;
      h.used = true;
      e1 = 0.5 * (g.p + h.q);
      e2 = 0.5 * (g.q + h.p);
      both = true;
      break;
    }
    WallOpening op;
    if (!jamb(e1, -1.0 * g.u, &op.jambs[0]) || !jamb(e2, g.u, &op.jambs[1])) continue;
    for_each_line_cell(op.jambs[0], op.jambs[1], [&](Cell c) {
      if (blocked.contains(c) && !blocked[c]) op.line.push_back(c);
    });
    if (op.line.empty()) continue;
    op.width_cells = g.along;
    op.both_faces = both;
    out.push_back(std::move(op));
  }

  // 4. Wall ends pointing at a wall: a wall whose two faces end together in free space (a stub),
  // continued along its line, meets an obstacle within min_width..max_width: the opening between
  // the stub's end and that obstacle is closed on the wall's middle line.
  if (o.wall_ends)
    for (std::size_t i = 0; i < faces.size(); ++i) {
      if (gap_after[i]) continue;
      const Face& f1 = faces[i];
      const Face* other = nullptr;
      for (const Face& f3 : faces) {
        if (dot(f1.u, f3.u) > -cos_max) continue;
        const double depth = -dot(f3.a - f1.b, f1.n);
        if (depth <= 0.0 || depth > thick + max_off) continue;
        if (std::abs(dot(f3.a - f1.b, f1.u)) > max_off + 1.0) continue;
        other = &f3;
        break;
      }
      if (other == nullptr) continue;
      const P e = 0.5 * (f1.b + other->a);
      WallOpening op;
      if (!jamb(e, -1.0 * f1.u, &op.jambs[0])) continue;
      // The ray starts where the stub's cells end (its fitted end may lie inside its last cell).
      double start = -1.0, hit = -1.0;
      for (double t = 0.0; t <= max_w + 2.5; t += 0.5) {
        const Cell q = cell_at(e + t * f1.u);
        if (!blocked.contains(q)) break;
        if (start < 0.0) {
          if (!blocked[q]) start = t;
          if (start < 0.0 && t >= 2.0) break;
          continue;
        }
        if (blocked[q]) {
          op.jambs[1] = q;
          hit = t - start;
          break;
        }
      }
      if (start < 0.0 || hit < min_w || hit > max_w) continue;
      for_each_line_cell(op.jambs[0], op.jambs[1], [&](Cell c) {
        if (blocked.contains(c) && !blocked[c]) op.line.push_back(c);
      });
      if (op.line.empty()) continue;
      op.width_cells = hit;
      op.both_faces = true;
      op.wall_end = true;
      out.push_back(std::move(op));
    }
  return out;
}

}  // namespace voronav::topology
