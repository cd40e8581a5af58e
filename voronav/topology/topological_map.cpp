#include "voronav/topology/topological_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <string>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/core/require.hpp"
#include "voronav/voronoi/voronoi_graph.hpp"

namespace voronav::topology {

std::string_view diagram_method_name(DiagramMethod m) {
  return m == DiagramMethod::kCellularAutomaton ? "ca" : "edt";
}

DiagramMethod parse_diagram_method(std::string_view name, std::string_view what) {
  if (name == "edt") return DiagramMethod::kEdt;
  if (name == "ca") return DiagramMethod::kCellularAutomaton;
  throw Error(std::string(what), 0, "expected edt or ca, got '" + std::string(name) + "'");
}
namespace {

void check_options(const TopologyOptions& o) {
  require_finite_nonneg("TopologyOptions.min_rise", o.min_rise);
  require_finite_nonneg("TopologyOptions.rise_ratio", o.rise_ratio);
  require_finite_nonneg("TopologyOptions.max_door_width", o.max_door_width);
  require_finite_nonneg("TopologyOptions.min_region_area", o.min_region_area);
  require_finite_nonneg("TopologyOptions.max_rise_walk", o.max_rise_walk);
  require_finite_nonneg("TopologyOptions.passage_length", o.passage_length);
  require_finite_nonneg("TopologyOptions.min_wall_area", o.min_wall_area);
  require_finite_nonneg("TopologyOptions.passage_rise_ratio", o.passage_rise_ratio);
  require_finite_nonneg("TopologyOptions.room_test_elongation", o.room_test_elongation);
  require_finite_nonneg("TopologyOptions.regions_absorb_obstacles", o.regions_absorb_obstacles);
  require_finite_nonneg("TopologyOptions.furniture_line_area", o.furniture_line_area);
  check_wall_opening_options(o.wall_openings);
}

double sq(Cell a, Cell b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

// Critical points along the Voronoi graph (see the header): plateaus of local minima of the
// clearance along an edge whose clearance rises by `need` on both sides, the walk continuing
// across junctions into every other branch (any branch that rises counts), and passage ends.
class MinimaFinder {
 public:
  MinimaFinder(const voronoi::VoronoiGraph& graph, const GridMap<float>& clearance,
               const TopologyOptions& o, double res)
      : graph_(graph),
        clearance_(clearance),
        min_rise_(o.min_rise / res),
        rise_ratio_(o.rise_ratio),
        walk_(o.max_rise_walk / res),
        passage_(o.passage_length / res),
        passage_rise_(o.passage_rise_ratio),
        bulges_(o.passage_bulges),
        junctions_(o.passage_junctions),
        incident_(graph.nodes.size()) {
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
      incident_[static_cast<std::size_t>(graph.edges[e].a)].push_back({static_cast<int>(e), 1});
      incident_[static_cast<std::size_t>(graph.edges[e].b)].push_back({static_cast<int>(e), -1});
    }
  }

  // Critical points into *out; the passage ends at junctions (passage_junctions) also into
  // *junction_cuts.
  void run(std::vector<Cell>* out, std::vector<Cell>* junction_cuts) {
    junction_cuts_ = junction_cuts;
    for (std::size_t e = 0; e < graph_.edges.size(); ++e)
      edge(static_cast<int>(e), out);
  }

 private:
  double value(int e, std::size_t k) const {
    return static_cast<double>(clearance_[graph_.edges[static_cast<std::size_t>(e)].cells[k]]);
  }

  // Whether the clearance rises to `need` walking from cell k of edge e in direction step
  // before it drops below m, within `budget` cells; at an edge end the walk continues into the
  // node's other branches (when max_rise_walk > 0; else the walk stays on the edge).
  bool rises(int e, std::ptrdiff_t k, int step, double m, double need, double budget,
             int* visits) const {
    const auto& cells = graph_.edges[static_cast<std::size_t>(e)].cells;
    const auto n = static_cast<std::ptrdiff_t>(cells.size());
    for (; k >= 0 && k < n; k += step) {
      const double x = value(e, static_cast<std::size_t>(k));
      if (x < m) return false;
      if (x >= need) return true;
      budget -= 1.0;
      if (walk_ > 0.0 && budget <= 0.0) return false;
    }
    if (walk_ <= 0.0 || ++*visits > 64) return false;
    const auto& ed = graph_.edges[static_cast<std::size_t>(e)];
    const int node = step > 0 ? ed.b : ed.a;
    for (const auto& [e2, dir] : incident_[static_cast<std::size_t>(node)]) {
      if (e2 == e && dir == -step) continue;  // the end we arrived through
      const auto n2 =
          static_cast<std::ptrdiff_t>(graph_.edges[static_cast<std::size_t>(e2)].cells.size());
      if (rises(e2, dir > 0 ? 1 : n2 - 2, dir, m, need, budget, visits)) return true;
    }
    return false;
  }

  void edge(int e, std::vector<Cell>* out) const {
    const auto& ed = graph_.edges[static_cast<std::size_t>(e)];
    const std::size_t n = ed.cells.size();
    if (n < 3) return;
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i)
      v[i] = value(e, i);
    const double budget0 = walk_ > 0.0 ? walk_ : HUGE_VAL;
    if (passage_ > 0.0) {
      dead_end(e, v, ed.b, 1, budget0, out);
      dead_end(e, v, ed.a, -1, budget0, out);
    }
    std::size_t i = 1;
    while (i + 1 < n) {
      if (!(v[i] < v[i - 1])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < n - 1 && v[j + 1] == v[i])
        ++j;
      const double m = v[i];
      if (!(v[j + 1] > m)) {
        i = j + 1;
        continue;
      }
      const double need = m + std::max(min_rise_, rise_ratio_ * m);
      int visits = 0;
      const bool left = rises(e, static_cast<std::ptrdiff_t>(i) - 1, -1, m, need, budget0, &visits);
      visits = 0;
      const bool right = rises(e, static_cast<std::ptrdiff_t>(j) + 1, 1, m, need, budget0, &visits);
      bool wide_left = false, wide_right = false;
      if (passage_ > 0.0 && (left || right)) {
        const double need2 = std::max(need, m * (1.0 + passage_rise_));
        visits = 0;
        wide_left =
            left && rises(e, static_cast<std::ptrdiff_t>(i) - 1, -1, m, need2, budget0, &visits);
        visits = 0;
        wide_right =
            right && rises(e, static_cast<std::ptrdiff_t>(j) + 1, 1, m, need2, budget0, &visits);
      }
      if (junctions_ && passage_ > 0.0 && left != right && junction_cuts_ != nullptr) {
        // A passage (the run within one cell of the minimum, at least passage_length) whose
        // clearance rises at one end and whose other end runs into a junction of narrower
        // branches (passage_junctions) is cut at that other end.
        std::size_t bl = i, br = j;
        while (bl > 0 && v[bl - 1] >= m && v[bl - 1] <= m + 1.0)
          --bl;
        while (br + 1 < n && v[br + 1] >= m && v[br + 1] <= m + 1.0)
          ++br;
        const double need2 = std::max(need, m * (1.0 + passage_rise_));
        if (static_cast<double>(br - bl + 1) >= passage_) {
          if (left && ends_in_narrower(e, v, br, 1, m, need2))
            junction_cuts_->push_back(ed.cells[br]);
          if (right && ends_in_narrower(e, v, bl, -1, m, need2))
            junction_cuts_->push_back(ed.cells[bl]);
        }
      }
      if (wide_left || wide_right) {
        // A passage: the run of cells around the minimum whose clearance stays within one cell
        // of it. When it is at least passage_length long, the cuts go at its ends where the
        // clearance rises (a corridor opening into rooms), not in its middle.
        const double band = m + 1.0;
        std::size_t bl = i, br = j;
        while (bl > 0 && v[bl - 1] >= m && v[bl - 1] <= band)
          --bl;
        while (br + 1 < n && v[br + 1] >= m && v[br + 1] <= band)
          ++br;
        const auto len = static_cast<double>(br - bl + 1);
        // Where the classic rule fires (both sides rise) the passage rule replaces its middle
        // cut only when both ends open wide.
        if (left && right && !(wide_left && wide_right)) wide_left = wide_right = false;
        if (len >= passage_ && bulges_) {
          const double need2 = std::max(need, m * (1.0 + passage_rise_));
          if (wide_left)
            bl = static_cast<std::size_t>(
                past_bulges(v, static_cast<std::ptrdiff_t>(bl), -1, m, band, need2));
          if (wide_right)
            br = static_cast<std::size_t>(
                past_bulges(v, static_cast<std::ptrdiff_t>(br), 1, m, band, need2));
        }
        if (len >= passage_) {
          if (wide_left && bl > 0) out->push_back(ed.cells[bl]);
          if (wide_right && br + 1 < n) out->push_back(ed.cells[br]);
          if ((wide_left && bl > 0) || (wide_right && br + 1 < n)) {
            i = std::max(j, br) + 1;
            continue;
          }
        }
      }
      if (left && right) out->push_back(ed.cells[(i + j) / 2]);
      i = j + 1;
    }
  }

  // A passage ending in a dead end (its edge ends at an end node): the run of cells from that
  // end whose clearance stays within one cell of the end's; when it is at least passage_length
  // long and the clearance beyond it rises to (1 + passage_rise_ratio) x, it is cut where it
  // opens (an open-fronted room, a dead-end corridor).
  void dead_end(int e, const std::vector<double>& v, int node, int end_dir, double budget0,
                std::vector<Cell>* out) const {
    if (graph_.nodes[static_cast<std::size_t>(node)].kind != voronoi::VoronoiNodeKind::kEnd) return;
    const auto n = static_cast<std::ptrdiff_t>(v.size());
    // Walk from the end inwards: k = last index, step -1 (end at b) or k = 0, step +1 (at a).
    const int step = -end_dir;
    std::ptrdiff_t k = end_dir > 0 ? n - 1 : 0;
    double lo = v[static_cast<std::size_t>(k)], hi = lo;
    std::ptrdiff_t last = k;
    for (std::ptrdiff_t q = k + step; q >= 0 && q < n; q += step) {
      const double x = v[static_cast<std::size_t>(q)];
      if (std::max(hi, x) - std::min(lo, x) > 1.0) break;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
      last = q;
    }
    if (last + step < 0 || last + step >= n) return;  // the whole edge: no opening on it
    if (static_cast<double>(std::abs(last - k) + 1) < passage_) return;
    const double m = lo;
    const double need =
        std::max(m + std::max(min_rise_, rise_ratio_ * m), m * (1.0 + passage_rise_));
    if (bulges_) last = past_bulges(v, last, step, m, lo + 1.0, need);
    int visits = 0;
    if (rises(e, last + step, step, m, need, budget0, &visits))
      out->push_back(
          graph_.edges[static_cast<std::size_t>(e)].cells[static_cast<std::size_t>(last)]);
  }

  // A passage's end, past its bulges: from cell `last` (the passage's last cell within its band
  // [m, band]) walking in direction `step` until the clearance drops below m or reaches `need`
  // (where the passage opens), the last cell back within the band. A bend or a short widening
  // that narrows again to the passage's width before anything opens is part of the passage, so
  // the cut goes at the narrowing where it really opens, not at the first bump (issue #15:
  // lab_intel, a corridor whose L bend came before its door).
  static std::ptrdiff_t past_bulges(const std::vector<double>& v, std::ptrdiff_t last, int step,
                                    double m, double band, double need) {
    const auto n = static_cast<std::ptrdiff_t>(v.size());
    std::ptrdiff_t end = last;
    for (std::ptrdiff_t q = last + step; q >= 0 && q < n; q += step) {
      const double x = v[static_cast<std::size_t>(q)];
      if (x < m || x >= need) break;
      if (x <= band) end = q;
    }
    // The cut needs a cell beyond it on the edge (the rise test starts there).
    if (end + step < 0 || end + step >= n) return last;
    return end;
  }

  // Whether the passage whose last band cell is `last` on edge e (walking in direction `step`)
  // runs into a junction of narrower passages: every cell from there to the edge's end stays
  // at least m and below the opening rise `need`, the end node is a junction, and every other
  // branch there narrows below the passage's band (its least clearance under m - 1 cell: a door,
  // a narrower corridor), so the passage does not go on through the junction.
  bool ends_in_narrower(int e, const std::vector<double>& v, std::size_t last, int step, double m,
                        double need) const {
    const auto n = static_cast<std::ptrdiff_t>(v.size());
    const auto k0 = static_cast<std::ptrdiff_t>(last);
    if (k0 + step < 0 || k0 + step >= n) return false;  // the cut needs a cell beyond it
    for (std::ptrdiff_t q = k0 + step; q >= 0 && q < n; q += step) {
      const double x = v[static_cast<std::size_t>(q)];
      if (x < m || x >= need) return false;
    }
    const auto& ed = graph_.edges[static_cast<std::size_t>(e)];
    const int node = step > 0 ? ed.b : ed.a;
    if (graph_.nodes[static_cast<std::size_t>(node)].kind != voronoi::VoronoiNodeKind::kJunction)
      return false;
    int others = 0;
    for (const auto& [e2, dir] : incident_[static_cast<std::size_t>(node)]) {
      if (e2 == e && dir == -step) continue;  // the passage's own end
      ++others;
      double least = HUGE_VAL;
      for (const Cell c : graph_.edges[static_cast<std::size_t>(e2)].cells)
        least = std::min(least, static_cast<double>(clearance_[c]));
      if (!(least < m - 1.0)) return false;
    }
    return others >= 2;
  }

  const voronoi::VoronoiGraph& graph_;
  const GridMap<float>& clearance_;
  double min_rise_, rise_ratio_, walk_, passage_, passage_rise_;
  bool bulges_, junctions_;
  std::vector<Cell>* junction_cuts_ = nullptr;
  std::vector<std::vector<std::pair<int, int>>> incident_;  // node -> (edge, +1 from a / -1 from b)
};

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int find(int x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  }
};

// Obstacle components (8-connected blocked cells) of at most max_cells cells, off the map's
// border, whose every neighbouring free cell lies in one and the same region, join that region
// (a table or a pillar inside a room: the room without a hole). A component next to two regions
// (a wall between rooms) or next to free cells of no region stays out. Returns how many joined.
std::size_t absorb_enclosed_obstacles(const BinaryGrid& blocked, double max_cells,
                                      GridMap<std::int32_t>* region) {
  const GridGeometry& geo = blocked.geometry();
  std::vector<char> seen(blocked.size(), 0);
  std::vector<Cell> comp, stack;
  std::size_t joined = 0;
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    if (!blocked[i] || seen[i]) continue;
    comp.clear();
    seen[i] = 1;
    stack.push_back(geo.cell_at(i));
    int owner = -1;
    bool enclosed = true;
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      comp.push_back(c);
      for (int k = 0; k < 8; ++k) {
        const Cell q = c + kNeighbours8[k];
        if (!geo.contains(q)) {
          enclosed = false;  // touches the map's border: not inside a room
          continue;
        }
        if (blocked[q]) {
          if (!seen[geo.index(q)]) {
            seen[geo.index(q)] = 1;
            stack.push_back(q);
          }
          continue;
        }
        const int r = (*region)[q];
        if (r < 0 || (owner >= 0 && r != owner)) enclosed = false;
        if (owner < 0) owner = r;
      }
    }
    if (!enclosed || owner < 0 || static_cast<double>(comp.size()) > max_cells) continue;
    for (const Cell c : comp)
      (*region)[c] = owner;
    ++joined;
  }
  return joined;
}

TopologicalMap build_from(const voronoi::GeneralizedVoronoi& g, const BinaryGrid& diagram,
                          const TopologyOptions& o) {
  const GridGeometry& geo = g.geometry;
  const double res = geo.resolution;
  TopologicalMap out{geo, g.blocked, diagram, g.clearance, {}, GridMap<std::int32_t>(geo, -1),
                     {},  {},        0,       0,           0};
  if (geo.empty()) return out;

  // 1. Critical points along the Voronoi graph's edges.
  const voronoi::VoronoiGraph graph = voronoi::build_voronoi_graph(diagram, g.clearance);
  std::vector<Cell> minima, junction_cuts;
  MinimaFinder(graph, g.clearance, o, res).run(&minima, &junction_cuts);
  const std::size_t n_narrowings = minima.size();
  minima.insert(minima.end(), junction_cuts.begin(), junction_cuts.end());
  // Obstacle components under min_wall_area are free-standing furniture: a narrowing between
  // furniture and anything else is not a door (the basis points of a door lie on walls).
  std::vector<std::size_t> component_cells;
  if (o.min_wall_area > 0.0 || o.furniture_line_area > 0.0)
    for (std::size_t i = 0; i < g.obstacle_label.size(); ++i) {
      const std::int32_t l = g.obstacle_label[i];
      if (l < 0) continue;
      if (static_cast<std::size_t>(l) >= component_cells.size())
        component_cells.resize(static_cast<std::size_t>(l) + 1, 0);
      ++component_cells[static_cast<std::size_t>(l)];
    }
  const double min_wall_cells = o.min_wall_area / (res * res);
  auto piece_under = [&](Cell s, double cells) {
    if (!geo.contains(s)) return false;  // outside: the border wall
    const std::int32_t l = g.obstacle_label[s];
    return l >= 0 && static_cast<double>(component_cells[static_cast<std::size_t>(l)]) < cells;
  };
  auto on_furniture = [&](Cell s) {
    return o.min_wall_area > 0.0 && piece_under(s, min_wall_cells);
  };
  const double furniture_line_cells = o.furniture_line_area / (res * res);
  auto furniture_line = [&](Cell s1, Cell s2) {
    return o.furniture_line_area > 0.0 &&
           (piece_under(s1, furniture_line_cells) || piece_under(s2, furniture_line_cells));
  };
  BinaryGrid cut(geo, 0);
  // Openings in wall lines (wall_openings.hpp) and narrowings can find the same opening; two
  // lines within half a wall's thickness + 2 cells of each other would leave a sliver between
  // them, so the later one is dropped. With wall_openings_first the wall lines come first (a
  // narrowing next to a wall-line opening is dropped), else the narrowings.
  const bool walls = o.wall_openings.max_width > 0.0;
  const int reach = static_cast<int>(std::ceil(0.5 * o.wall_openings.max_wall_thickness / res)) + 2;
  BinaryGrid wall_cut(geo, 0);
  // The lines that can hide a wall-line opening (the earlier openings and the narrowings' lines)
  // all but the narrowings' lines ending on furniture (furniture_line_area: a line from a door's
  // jamb to a chair beside it does not close the door) and the passage ends at junctions (they
  // close the passage's mouth, not a door beside it); furniture_cut: the former, for the count.
  BinaryGrid hiding_cut(geo, 0), furniture_cut(geo, 0);
  auto near_cut = [&](const std::vector<Cell>& line, const BinaryGrid& grid) {
    for (const Cell c : line)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const Cell q = c + Cell{dx, dy};
          if (geo.contains(q) && grid[q] != 0) return true;
        }
    return false;
  };
  std::vector<WallOpening> openings;
  if (walls) openings = find_wall_openings(g.blocked, o.wall_openings);
  auto add_openings = [&] {
    for (WallOpening& op : openings) {
      if (near_cut(op.line, hiding_cut)) continue;
      if (near_cut(op.line, furniture_cut)) ++out.openings_past_furniture;
      CriticalPoint cp;
      cp.basis = op.jambs;
      cp.clearance_m = 0.5 * op.width_cells * res;
      cp.line = std::move(op.line);
      cp.cell = cp.midpoint = cp.line[cp.line.size() / 2];
      cp.wall_gap = true;
      for (const Cell c : cp.line)
        cut[c] = wall_cut[c] = hiding_cut[c] = 1;
      out.critical_points.push_back(std::move(cp));
    }
  };
  if (walls && o.wall_openings_first) add_openings();
  for (std::size_t mi = 0; mi < minima.size(); ++mi) {
    const Cell p = minima[mi];
    const double clear = static_cast<double>(g.clearance[p]);
    if (!std::isfinite(clear)) continue;
    if (o.max_door_width > 0.0 && 2.0 * clear * res > o.max_door_width) continue;
    const Cell s1 = g.nearest_site[p];
    if (s1 == voronoi::kNoSiteCell) continue;
    // The other basis point: the neighbourhood site farthest from the first.
    Cell s2 = s1;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell q = p + Cell{dx, dy};
        if (!geo.contains(q)) continue;
        const Cell t = g.blocked[q] ? q : g.nearest_site[q];
        if (t == voronoi::kNoSiteCell) continue;
        if (sq(t, s1) > sq(s2, s1)) s2 = t;
      }
    if (o.basis_across && sq(s1, s2) < 2.25 * clear * clear) {
      // Both sites on one wall (at a corner or a mouth): the line would not cross the
      // narrowing. The second basis point is the obstacle across it, where the ray from s1
      // through the critical point meets one within 1.5 x the clearance (a narrowing's other
      // side lies about the clearance away; farther, the point is no narrowing across).
      const double dx = p.x - s1.x, dy = p.y - s1.y;
      const double len = std::hypot(dx, dy);
      if (len > 0.0)
        for (double t = 1.0; t <= 1.5 * clear; t += 0.5) {
          const Cell q{static_cast<int>(std::lround(p.x + t * dx / len)),
                       static_cast<int>(std::lround(p.y + t * dy / len))};
          if (!geo.contains(q)) break;
          if (g.blocked[q]) {
            s2 = q;
            ++out.basis_across;
            break;
          }
        }
    }
    if (sq(s1, s2) < 4.0) continue;  // not two separate obstacles
    if (on_furniture(s1) || on_furniture(s2)) continue;
    CriticalPoint cp;
    cp.cell = p;
    cp.basis = {s1, s2};
    cp.passage_junction = mi >= n_narrowings;
    cp.clearance_m = clear * res;
    const double mx = 0.5 * (s1.x + s2.x), my = 0.5 * (s1.y + s2.y);
    double best = HUGE_VAL;
    for_each_line_cell(s1, s2, [&](Cell c) {
      if (!geo.contains(c) || g.blocked[c]) return;
      cp.line.push_back(c);
      const double d = (c.x - mx) * (c.x - mx) + (c.y - my) * (c.y - my);
      if (d < best) {
        best = d;
        cp.midpoint = c;
      }
    });
    if (cp.line.empty()) continue;
    if (walls && o.wall_openings_first && near_cut(cp.line, wall_cut)) continue;
    // A line on furniture, or a passage's end at a junction (it closes the passage's mouth,
    // not a door beside the junction), hides no wall-line opening.
    const bool furniture = furniture_line(s1, s2);
    const bool hides = !furniture && !cp.passage_junction;
    for (const Cell c : cp.line) {
      cut[c] = 1;
      if (hides) hiding_cut[c] = 1;
      if (furniture) furniture_cut[c] = 1;
    }
    out.critical_points.push_back(std::move(cp));
  }
  if (walls && !o.wall_openings_first) add_openings();

  // 2. Regions: 4-connected components of the free cells minus the critical lines.
  GridMap<std::int32_t> comp(geo, -1);
  int ncomp = 0;
  std::vector<Cell> stack;
  for (std::size_t i = 0; i < comp.size(); ++i) {
    if (g.blocked[i] || cut[i] || comp[i] >= 0) continue;
    comp[i] = ncomp;
    stack.push_back(geo.cell_at(i));
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      for (int k = 0; k < 4; ++k) {
        const Cell q = c + kNeighbours8[k];
        if (!geo.contains(q) || g.blocked[q] || cut[q] || comp[q] >= 0) continue;
        comp[q] = ncomp;
        stack.push_back(q);
      }
    }
    ++ncomp;
  }
  // Sides of every critical line (the two most frequent components next to its cells).
  std::vector<std::pair<int, int>> sides(out.critical_points.size(), {-1, -1});
  std::map<std::pair<int, int>, double> shared;  // component pair -> shared line length
  for (std::size_t k = 0; k < out.critical_points.size(); ++k) {
    std::map<int, int> count;
    for (const Cell c : out.critical_points[k].line)
      for (int d = 0; d < 4; ++d) {
        const Cell q = c + kNeighbours8[d];
        if (geo.contains(q) && comp[q] >= 0) count[comp[q]]++;
      }
    if (count.size() < 2) continue;
    std::vector<std::pair<int, int>> byc(count.begin(), count.end());
    std::sort(byc.begin(), byc.end(), [](auto a, auto b) {
      return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    sides[k] = {std::min(byc[0].first, byc[1].first), std::max(byc[0].first, byc[1].first)};
    shared[sides[k]] += static_cast<double>(out.critical_points[k].line.size());
  }
  // 3. Merge rule: the smallest region under min_region_area goes into the neighbour sharing the
  // most critical-line cells with it; repeat.
  std::vector<double> area(static_cast<std::size_t>(ncomp), 0.0);
  for (std::size_t i = 0; i < comp.size(); ++i)
    if (comp[i] >= 0) area[static_cast<std::size_t>(comp[i])] += res * res;
  UnionFind uf(ncomp);
  const double min_area = o.min_region_area;
  // 2b. Room test of the critical lines (validate_sides): a line stays only when one of the two
  // regions it separates is wider than the line, i.e. holds a cell whose clearance reaches the
  // rise of a passage end; two regions no wider than the line between them are pieces of one
  // passage (a corridor cut at a small widening) and are joined. Repeated until no line fails.
  if (o.validate_sides) {
    std::vector<double> widest(static_cast<std::size_t>(ncomp), 0.0);
    for (std::size_t i = 0; i < comp.size(); ++i)
      if (comp[i] >= 0) {
        auto& w = widest[static_cast<std::size_t>(comp[i])];
        w = std::max(w, static_cast<double>(g.clearance[i]));
      }
    // Elongation of a region: its area over the square around its widest inscribed disc,
    // (2 x widest clearance)^2; about 1-2 for a room, length / width for a corridor piece.
    auto elongation = [&](std::size_t r) {
      const double w = 2.0 * widest[r] * res;
      return w > 0.0 ? area[r] / (w * w) : 0.0;
    };
    bool changed = true;
    while (changed) {
      changed = false;
      for (std::size_t k = 0; k < out.critical_points.size(); ++k) {
        if (sides[k].first < 0) continue;
        // A passage's end at a junction of narrower passages separates two passages of
        // different widths by construction: the room test does not apply.
        if (out.critical_points[k].passage_junction) continue;
        const int a = uf.find(sides[k].first), b = uf.find(sides[k].second);
        if (a == b) continue;
        const double m = out.critical_points[k].clearance_m / res;
        const double need = std::max(m + o.min_rise / res,
                                     m * (1.0 + std::max(o.rise_ratio, o.passage_rise_ratio)));
        const auto au = static_cast<std::size_t>(a), bu = static_cast<std::size_t>(b);
        if (widest[au] >= need || widest[bu] >= need) continue;
        // Only pieces of a passage are joined: one side must be elongated (a corridor piece);
        // two room-shaped sides behind a wide opening stay apart.
        if (std::max(elongation(au), elongation(bu)) < o.room_test_elongation) continue;
        const std::size_t keep = area[au] >= area[bu] ? au : bu;
        const std::size_t gone = keep == au ? bu : au;
        uf.parent[gone] = static_cast<int>(keep);
        area[keep] += area[gone];
        widest[keep] = std::max(widest[keep], widest[gone]);
        changed = true;
      }
    }
  }
  while (true) {
    // Current adjacency between merged regions.
    std::map<std::pair<int, int>, double> adj;
    for (const auto& [pair, w] : shared) {
      const int a = uf.find(pair.first), b = uf.find(pair.second);
      if (a != b) adj[{std::min(a, b), std::max(a, b)}] += w;
    }
    int smallest = -1;
    for (int r = 0; r < ncomp; ++r) {
      if (uf.find(r) != r || area[static_cast<std::size_t>(r)] >= min_area) continue;
      bool has_neighbour = false;
      for (const auto& [pair, w] : adj)
        has_neighbour |= pair.first == r || pair.second == r;
      if (!has_neighbour) continue;
      if (smallest < 0 ||
          area[static_cast<std::size_t>(r)] < area[static_cast<std::size_t>(smallest)])
        smallest = r;
    }
    if (smallest < 0) break;
    int target = -1;
    double best_w = -1.0;
    for (const auto& [pair, w] : adj) {
      if (pair.first != smallest && pair.second != smallest) continue;
      const int other = pair.first == smallest ? pair.second : pair.first;
      if (w > best_w || (w == best_w && other < target)) {
        best_w = w;
        target = other;
      }
    }
    uf.parent[static_cast<std::size_t>(smallest)] = target;
    area[static_cast<std::size_t>(target)] += area[static_cast<std::size_t>(smallest)];
  }
  // 4. Compact region ids in row-major order of first appearance.
  std::vector<int> id_of(static_cast<std::size_t>(ncomp), -1);
  int nregions = 0;
  for (std::size_t i = 0; i < comp.size(); ++i) {
    if (comp[i] < 0) continue;
    const int root = uf.find(comp[i]);
    if (id_of[static_cast<std::size_t>(root)] < 0)
      id_of[static_cast<std::size_t>(root)] = nregions++;
    out.region[i] = id_of[static_cast<std::size_t>(root)];
  }
  // Critical-line cells join the smallest adjacent region (passes until all are placed).
  bool pending = true;
  while (pending) {
    pending = false;
    bool progress = false;
    for (std::size_t i = 0; i < comp.size(); ++i) {
      if (!cut[i] || out.region[i] >= 0) continue;
      const Cell c = geo.cell_at(i);
      int best = -1;
      for (int d = 0; d < 4; ++d) {
        const Cell q = c + kNeighbours8[d];
        if (!geo.contains(q) || out.region[q] < 0 || (cut[q] && out.region[q] < 0)) continue;
        if (best < 0 || out.region[q] < best) best = out.region[q];
      }
      if (best >= 0) {
        out.region[i] = best;
        progress = true;
      } else {
        pending = true;
      }
    }
    if (!progress) break;  // line cells enclosed by other line cells only: left out
  }
  // 4b. Regions still under min_region_area (specks between crossing lines, pockets cut off by
  // line cells) merge into the neighbour sharing the longest border (4-neighbour cell pairs),
  // smallest first; a region with no neighbour under the area is dropped (its cells get no
  // region: an isolated free speck is not a room).
  {
    std::vector<double> rarea(static_cast<std::size_t>(nregions), 0.0);
    std::map<std::pair<int, int>, double> border;
    for (int y = 0; y < geo.height; ++y)
      for (int x = 0; x < geo.width; ++x) {
        const int r = out.region[Cell{x, y}];
        if (r < 0) continue;
        rarea[static_cast<std::size_t>(r)] += res * res;
        for (const Cell q : {Cell{x + 1, y}, Cell{x, y + 1}}) {
          if (!geo.contains(q)) continue;
          const int t = out.region[q];
          if (t >= 0 && t != r) border[{std::min(r, t), std::max(r, t)}] += 1.0;
        }
      }
    UnionFind ufr(nregions);
    std::vector<char> dropped(static_cast<std::size_t>(nregions), 0);
    while (true) {
      int smallest = -1;
      for (int r = 0; r < nregions; ++r) {
        const auto ru = static_cast<std::size_t>(r);
        if (ufr.find(r) != r || dropped[ru] || rarea[ru] >= min_area) continue;
        if (smallest < 0 || rarea[ru] < rarea[static_cast<std::size_t>(smallest)]) smallest = r;
      }
      if (smallest < 0) break;
      std::map<int, double> weight;
      for (const auto& [pair, w] : border) {
        const int a = ufr.find(pair.first), b = ufr.find(pair.second);
        if (a == b) continue;
        if (a == smallest) weight[b] += w;
        if (b == smallest) weight[a] += w;
      }
      int target = -1;
      double best_w = -1.0;
      for (const auto& [t, w] : weight)
        if (w > best_w) best_w = w, target = t;
      if (target < 0) {
        dropped[static_cast<std::size_t>(smallest)] = 1;
        continue;
      }
      ufr.parent[static_cast<std::size_t>(smallest)] = target;
      rarea[static_cast<std::size_t>(target)] += rarea[static_cast<std::size_t>(smallest)];
    }
    std::vector<int> rid(static_cast<std::size_t>(nregions), -1);
    int n2 = 0;
    for (std::size_t i = 0; i < comp.size(); ++i) {
      const int r = out.region[i];
      if (r < 0) continue;
      const int root = ufr.find(r);
      if (dropped[static_cast<std::size_t>(root)]) {
        out.region[i] = -1;
        continue;
      }
      if (rid[static_cast<std::size_t>(root)] < 0) rid[static_cast<std::size_t>(root)] = n2++;
      out.region[i] = rid[static_cast<std::size_t>(root)];
    }
    nregions = n2;
  }
  // 4c. Obstacles enclosed by one region (furniture, pillars) join it (regions_absorb_obstacles).
  std::size_t absorbed_components = 0;
  if (o.regions_absorb_obstacles > 0.0)
    absorbed_components =
        absorb_enclosed_obstacles(g.blocked, o.regions_absorb_obstacles / (res * res), &out.region);
  out.absorbed_obstacles = absorbed_components;
  // 5. Region statistics and centres (the centre: a free cell).
  out.regions.resize(static_cast<std::size_t>(nregions));
  std::vector<double> sx(static_cast<std::size_t>(nregions), 0.0), sy(sx);
  for (std::size_t i = 0; i < comp.size(); ++i) {
    const int r = out.region[i];
    if (r < 0) continue;
    const Cell c = geo.cell_at(i);
    auto& reg = out.regions[static_cast<std::size_t>(r)];
    reg.id = r;
    reg.cells++;
    if (g.blocked[i]) reg.absorbed_cells++;
    sx[static_cast<std::size_t>(r)] += c.x;
    sy[static_cast<std::size_t>(r)] += c.y;
  }
  std::vector<double> best(static_cast<std::size_t>(nregions), HUGE_VAL);
  for (std::size_t i = 0; i < comp.size(); ++i) {
    const int r = out.region[i];
    if (r < 0 || g.blocked[i]) continue;
    const auto ru = static_cast<std::size_t>(r);
    const Cell c = geo.cell_at(i);
    const double n = static_cast<double>(out.regions[ru].cells);
    const double d =
        (c.x - sx[ru] / n) * (c.x - sx[ru] / n) + (c.y - sy[ru] / n) * (c.y - sy[ru] / n);
    if (d < best[ru]) {
      best[ru] = d;
      out.regions[ru].centre = c;
    }
  }
  for (auto& reg : out.regions) {
    reg.area_m2 = static_cast<double>(reg.cells) * res * res;
    reg.centre_world = geo.cell_center(reg.centre);
  }
  // 6. Graph edges: one per separating critical line (its two sides: the two most frequent final
  // regions next to its cells), then one per pair of regions that touch without a separating
  // line (so that every region is connected where its free space is), crossing at the border
  // cell nearest the middle of their common border.
  std::set<std::pair<int, int>> linked;
  auto add_edge = [&](int a, int b, int cp, Cell mid) {
    const Vec2 m = geo.cell_center(mid);
    TopoEdge e;
    e.a = std::min(a, b);
    e.b = std::max(a, b);
    e.critical_point = cp;
    e.midpoint = mid;
    e.length_m = distance(out.regions[static_cast<std::size_t>(e.a)].centre_world, m) +
                 distance(m, out.regions[static_cast<std::size_t>(e.b)].centre_world);
    out.edges.push_back(e);
    linked.insert({e.a, e.b});
  };
  for (std::size_t k = 0; k < out.critical_points.size(); ++k) {
    CriticalPoint& cp = out.critical_points[k];
    std::map<int, int> count;
    for (const Cell c : cp.line)
      for (int d = 0; d < 4; ++d) {
        const Cell q = c + kNeighbours8[d];
        if (geo.contains(q) && out.region[q] >= 0 && !cut[q]) count[out.region[q]]++;
      }
    std::vector<std::pair<int, int>> byc(count.begin(), count.end());
    std::sort(byc.begin(), byc.end(), [](auto a, auto b) {
      return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    cp.separates = byc.size() >= 2;
    if (!cp.separates) continue;
    add_edge(byc[0].first, byc[1].first, static_cast<int>(k), cp.midpoint);
  }
  std::map<std::pair<int, int>, std::vector<Cell>> touching;
  for (int y = 0; y < geo.height; ++y)
    for (int x = 0; x < geo.width; ++x) {
      const int r = out.region[Cell{x, y}];
      if (r < 0) continue;
      for (const Cell q : {Cell{x + 1, y}, Cell{x, y + 1}}) {
        if (!geo.contains(q)) continue;
        const int t = out.region[q];
        if (t < 0 || t == r) continue;
        const std::pair<int, int> key{std::min(r, t), std::max(r, t)};
        if (!linked.contains(key)) touching[key].push_back(Cell{x, y});
      }
    }
  for (const auto& [key, cells] : touching) {
    double mx = 0.0, my = 0.0;
    for (const Cell c : cells)
      mx += c.x, my += c.y;
    mx /= static_cast<double>(cells.size());
    my /= static_cast<double>(cells.size());
    Cell mid = cells[0];
    double best_d = HUGE_VAL;
    for (const Cell c : cells) {
      const double d = (c.x - mx) * (c.x - mx) + (c.y - my) * (c.y - my);
      if (d < best_d) best_d = d, mid = c;
    }
    add_edge(key.first, key.second, -1, mid);
  }
  return out;
}

}  // namespace

TopologicalMap build_topological_map(const BinaryGrid& blocked, const BinaryGrid& diagram,
                                     const TopologyOptions& options) {
  check_options(options);
  if (blocked.width() != diagram.width() || blocked.height() != diagram.height())
    throw Error("build_topological_map", 0, "the map and the diagram differ in size");
  const voronoi::GeneralizedVoronoi g = voronoi::build_gvd(blocked, options.gvd);
  return build_from(g, diagram, options);
}

TopologicalMap build_topological_map(const BinaryGrid& blocked, const TopologyOptions& options) {
  check_options(options);
  voronoi::GeneralizedVoronoi g = voronoi::build_gvd(blocked, options.gvd);
  if (options.method == DiagramMethod::kEdt) {
    const BinaryGrid diagram = g.diagram;
    return build_from(g, diagram, options);
  }
  voronoi::CaVoronoiOptions ca = options.ca;
  ca.border_is_blocked = options.gvd.border_is_blocked;
  const voronoi::LabeledVoronoi lv = voronoi::build_labeled_voronoi(blocked, ca);
  // The CA diagram gets the same spur pruning as the EDT one.
  BinaryGrid diagram = lv.diagram;
  voronoi::prune_diagram(diagram, g.clearance, options.gvd);
  return build_from(g, diagram, options);
}

TopoPlan plan_on_graph(const TopologicalMap& map, Cell start, Cell goal) {
  TopoPlan plan;
  const int rs = map.region_of(start), rg = map.region_of(goal);
  if (rs < 0) {
    plan.status = TopoPlanStatus::kStartBlocked;
    return plan;
  }
  if (rg < 0) {
    plan.status = TopoPlanStatus::kGoalBlocked;
    return plan;
  }
  const GridGeometry& geo = map.geometry;
  auto pos = [&](Cell c) { return geo.cell_center(c); };
  const Vec2 goal_w = pos(goal);
  // States: 0 = at the start; 1 + 2k + side = having crossed edge k into its a (0) or b (1) region.
  const std::size_t ne = map.edges.size();
  const std::size_t n = 1 + 2 * ne;
  auto region_of_state = [&](std::size_t s) {
    if (s == 0) return rs;
    const TopoEdge& e = map.edges[(s - 1) / 2];
    return (s - 1) % 2 == 0 ? e.a : e.b;
  };
  auto point_of_state = [&](std::size_t s) {
    if (s == 0) return pos(start);
    return pos(map.edges[(s - 1) / 2].midpoint);
  };
  // Incident edges per region.
  std::vector<std::vector<std::size_t>> incident(map.regions.size());
  for (std::size_t k = 0; k < ne; ++k) {
    incident[static_cast<std::size_t>(map.edges[k].a)].push_back(k);
    incident[static_cast<std::size_t>(map.edges[k].b)].push_back(k);
  }
  std::vector<double> gcost(n, HUGE_VAL);
  std::vector<std::size_t> parent(n, n);
  std::vector<char> closed(n, 0);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  gcost[0] = 0.0;
  open.push({distance(pos(start), goal_w), 0});
  std::size_t reached = n;
  double best_total = HUGE_VAL;
  while (!open.empty()) {
    const auto [f, s] = open.top();
    open.pop();
    if (closed[s]) continue;
    if (f >= best_total) break;
    closed[s] = 1;
    ++plan.expanded;
    const int r = region_of_state(s);
    const Vec2 p = point_of_state(s);
    if (r == rg) {
      const double total = gcost[s] + distance(p, goal_w);
      if (total < best_total) {
        best_total = total;
        reached = s;
      }
      continue;  // the goal is in this region: no need to leave it
    }
    for (const std::size_t k : incident[static_cast<std::size_t>(r)]) {
      const TopoEdge& e = map.edges[k];
      const std::size_t t = 1 + 2 * k + (e.a == r ? 1 : 0);
      if (closed[t]) continue;
      const double g2 = gcost[s] + distance(p, point_of_state(t));
      if (g2 < gcost[t]) {
        gcost[t] = g2;
        parent[t] = s;
        open.push({g2 + distance(point_of_state(t), goal_w), t});
      }
    }
  }
  if (reached == n) {
    plan.status = TopoPlanStatus::kUnreachable;
    return plan;
  }
  std::vector<std::size_t> chain;
  for (std::size_t s = reached; s != n; s = parent[s])
    chain.push_back(s);
  std::reverse(chain.begin(), chain.end());
  plan.status = TopoPlanStatus::kOk;
  plan.regions.push_back(rs);
  plan.waypoints.push_back(start);
  for (std::size_t k = 1; k < chain.size(); ++k) {
    const std::size_t s = chain[k];
    const int e = static_cast<int>((s - 1) / 2);
    plan.edges.push_back(e);
    plan.regions.push_back(region_of_state(s));
    plan.waypoints.push_back(map.edges[static_cast<std::size_t>(e)].midpoint);
    plan.graph_cost_m += map.edges[static_cast<std::size_t>(e)].length_m;
  }
  plan.waypoints.push_back(goal);
  for (std::size_t k = 1; k < plan.waypoints.size(); ++k)
    plan.waypoint_length_m += distance(pos(plan.waypoints[k - 1]), pos(plan.waypoints[k]));
  return plan;
}

}  // namespace voronav::topology
