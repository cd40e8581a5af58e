#include "voronav/voronoi/voronoi_graph.hpp"

#include <cmath>
#include <limits>

#include "voronav/core/error.hpp"

namespace voronav::voronoi {
namespace {

int degree(const BinaryGrid& d, Cell c) {
  int n = 0;
  for (const Cell o : kNeighbours8) {
    const Cell q = c + o;
    n += d.contains(q) && d[q] != 0;
  }
  return n;
}

double step_length(Cell a, Cell b) {
  return (a.x != b.x && a.y != b.y) ? std::sqrt(2.0) : 1.0;
}

}  // namespace

VoronoiGraph build_voronoi_graph(const BinaryGrid& diagram, const GridMap<float>& clearance) {
  if (diagram.width() != clearance.width() || diagram.height() != clearance.height())
    throw Error("build_voronoi_graph", 0, "the diagram and the clearance differ in size");
  const GridGeometry& g = diagram.geometry();
  const double res = g.resolution;
  VoronoiGraph out{{}, {}, GridMap<std::int32_t>(g, -1)};
  auto clear_m = [&](Cell c) {
    const float v = clearance[c];
    return std::isfinite(v) ? static_cast<double>(v) * res
                            : std::numeric_limits<double>::infinity();
  };
  // 1. Node cells (degree != 2), clustered 8-connected into nodes.
  std::vector<Cell> stack;
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    if (!diagram[i] || out.node_of[i] >= 0) continue;
    const Cell c = g.cell_at(i);
    if (degree(diagram, c) == 2) continue;
    const int id = static_cast<int>(out.nodes.size());
    VoronoiNode node;
    out.node_of[c] = id;
    stack.push_back(c);
    while (!stack.empty()) {
      const Cell p = stack.back();
      stack.pop_back();
      node.cluster.push_back(p);
      for (const Cell o : kNeighbours8) {
        const Cell q = p + o;
        if (!diagram.contains(q) || !diagram[q] || out.node_of[q] >= 0) continue;
        if (degree(diagram, q) == 2) continue;
        out.node_of[q] = id;
        stack.push_back(q);
      }
    }
    double cx = 0.0, cy = 0.0;
    int max_degree = 0;
    for (const Cell p : node.cluster) {
      cx += p.x;
      cy += p.y;
      max_degree = std::max(max_degree, degree(diagram, p));
    }
    cx /= static_cast<double>(node.cluster.size());
    cy /= static_cast<double>(node.cluster.size());
    node.cell = node.cluster.front();
    double best = HUGE_VAL;
    for (const Cell p : node.cluster) {
      const double d = (p.x - cx) * (p.x - cx) + (p.y - cy) * (p.y - cy);
      if (d < best) {
        best = d;
        node.cell = p;
      }
    }
    node.kind = max_degree <= 1 && node.cluster.size() == 1 ? VoronoiNodeKind::kEnd
                                                            : VoronoiNodeKind::kJunction;
    node.clearance_m = clear_m(node.cell);
    out.nodes.push_back(std::move(node));
  }
  // 2. Edges: walk from every node cell along degree-2 cells to the next node.
  GridMap<std::uint8_t> visited(g, 0);
  auto walk = [&](Cell start, Cell first, int from) {
    VoronoiEdge e;
    e.a = from;
    e.cells = {start, first};
    Cell prev = start, cur = first;
    while (out.node_of[cur] < 0) {
      visited[cur] = 1;
      Cell next = cur;
      for (int pass = 0; pass < 2 && next == cur; ++pass)
        for (int k = pass == 0 ? 0 : 4; k < (pass == 0 ? 4 : 8); ++k) {
          const Cell q = cur + kNeighbours8[k];
          if (!diagram.contains(q) || !diagram[q] || q == prev) continue;
          if (out.node_of[q] < 0 && visited[q]) continue;
          if (q == start && e.cells.size() < 3) continue;
          next = q;
          break;
        }
      if (next == cur) break;  // cannot happen on a thinned diagram; stop safely
      prev = cur;
      cur = next;
      e.cells.push_back(cur);
    }
    e.b = out.node_of[cur] >= 0 ? out.node_of[cur] : from;
    e.min_clearance_m = HUGE_VAL;
    for (std::size_t k = 0; k < e.cells.size(); ++k) {
      if (k > 0) e.length_m += step_length(e.cells[k - 1], e.cells[k]) * res;
      e.min_clearance_m = std::min(e.min_clearance_m, clear_m(e.cells[k]));
    }
    out.nodes[static_cast<std::size_t>(e.a)].degree++;
    out.nodes[static_cast<std::size_t>(e.b)].degree++;
    out.edges.push_back(std::move(e));
  };
  for (int id = 0; id < static_cast<int>(out.nodes.size()); ++id) {
    const std::vector<Cell> cluster = out.nodes[static_cast<std::size_t>(id)].cluster;
    for (const Cell m : cluster)
      for (const Cell o : kNeighbours8) {
        const Cell q = m + o;
        if (!diagram.contains(q) || !diagram[q]) continue;
        const int other = out.node_of[q];
        if (other == id) continue;
        if (other >= 0) {
          // Two clusters touching directly: one edge per touching cell pair, listed once.
          if (other < id) continue;
          walk(m, q, id);
          continue;
        }
        if (visited[q]) continue;
        walk(m, q, id);
      }
  }
  // 3. Closed loops without any node: one node on the loop and a self-loop edge.
  for (std::size_t i = 0; i < diagram.size(); ++i) {
    if (!diagram[i] || out.node_of[i] >= 0 || visited[i]) continue;
    const Cell c = g.cell_at(i);
    const int id = static_cast<int>(out.nodes.size());
    out.nodes.push_back({c, {c}, VoronoiNodeKind::kLoop, clear_m(c), 0});
    out.node_of[c] = id;
    for (const Cell o : kNeighbours8) {
      const Cell q = c + o;
      if (diagram.contains(q) && diagram[q] && !visited[q]) {
        walk(c, q, id);
        break;
      }
    }
  }
  for (VoronoiNode& n : out.nodes)
    if (n.degree == 0) n.kind = VoronoiNodeKind::kIsolated;
  return out;
}

VoronoiGraph build_voronoi_graph(const GeneralizedVoronoi& gvd) {
  return build_voronoi_graph(gvd.diagram, gvd.clearance);
}

}  // namespace voronav::voronoi
