#include "voronav/exploration/voronoi_tree.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <queue>
#include <string>

#include "voronav/core/cell_iterators.hpp"
#include "voronav/core/error.hpp"
#include "voronav/planning/astar.hpp"
#include "voronav/planning/grid_planner.hpp"

namespace voronav::exploration {
namespace {

bool cell_free(const BinaryGrid& g, Vec2 p) {
  const auto c = g.geometry().world_to_cell(p);
  return c && g.contains(*c) && g[*c] == 0;
}

double polyline_length(const std::vector<Vec2>& p) {
  double len = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i)
    len += distance(p[i - 1], p[i]);
  return len;
}

// A checked path from a to b: the straight segment when free, else A* (empty when neither).
std::vector<Vec2> checked_path(const BinaryGrid& g, planning::AStarPlanner& astar, Vec2 a, Vec2 b,
                               double max_detour_factor) {
  if (segment_free(g, a, b)) return {a, b};
  const GridGeometry& gg = g.geometry();
  const auto ca = gg.world_to_cell(a), cb = gg.world_to_cell(b);
  if (!ca || !cb) return {};
  // Only a path of length <= bound is kept, and every point p of such a path has
  // |p - a| + |p - b| <= bound, so |p - mid| <= bound / 2: A* runs on that square of the grid
  // only. (On the whole grid, an edge whose ends are not connected flooded the whole map: the
  // tree of tree-frontier on willow took most of the run time; issue 14.)
  const double bound = max_detour_factor * distance(a, b) + 2.0 * g.resolution();
  const auto cm = gg.world_to_cell((a + b) * 0.5);
  // (An unbounded detour, as the re-attachment of a third child asks, crops nothing.)
  const double half = std::ceil(0.5 * bound / g.resolution()) + 2.0;
  const int r = half < static_cast<double>(g.width() + g.height()) ? static_cast<int>(half)
                                                                   : g.width() + g.height();
  const Cell mid = cm ? *cm : *ca;
  const int x0 = std::max(0, mid.x - r), y0 = std::max(0, mid.y - r);
  const int x1 = std::min(g.width() - 1, mid.x + r), y1 = std::min(g.height() - 1, mid.y + r);
  GridGeometry cg = gg;
  cg.width = x1 - x0 + 1;
  cg.height = y1 - y0 + 1;
  cg.origin =
      Pose2{gg.origin.transform(Vec2{x0 * gg.resolution, y0 * gg.resolution}), gg.origin.yaw};
  BinaryGrid crop(cg, 1);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      crop[Cell{x - x0, y - y0}] = g[Cell{x, y}];
  const Cell from{ca->x - x0, ca->y - y0}, to{cb->x - x0, cb->y - y0};
  if (!crop.contains(from) || !crop.contains(to)) return {};
  const planning::PlanResult res = astar.plan(crop, from, to);
  if (!res.ok()) return {};
  std::vector<Vec2> path{a};
  for (std::size_t i = 1; i + 1 < res.path.size(); ++i)
    path.push_back(cg.cell_center(res.path[i]));
  path.push_back(b);
  if (polyline_length(path) > bound) return {};
  return path;
}

}  // namespace

void VoronoiTreeOptions::validate() const {
  if (!(max_detour_factor >= 1.0) || !std::isfinite(max_detour_factor))
    throw Error("VoronoiTreeOptions.max_detour_factor", 0, "expected a finite number >= 1");
  if (!(prune_leaf_shorter_than >= 0.0) || !std::isfinite(prune_leaf_shorter_than))
    throw Error("VoronoiTreeOptions.prune_leaf_shorter_than", 0, "expected a finite number >= 0");
}

BinaryGrid tree_grid(const OccupancyGrid& map, double radius) {
  return planning::make_planning_grid(binarize(map, {50, false}), radius);
}

bool segment_free(const BinaryGrid& traversable, Vec2 a, Vec2 b) {
  const GridGeometry& g = traversable.geometry();
  const auto ca = g.world_to_cell(a), cb = g.world_to_cell(b);
  if (!ca || !cb) return false;
  return for_each_line_cell(*ca, *cb,
                            [&](Cell c) { return traversable.contains(c) && traversable[c] == 0; });
}

std::vector<int> VoronoiTree::leaves_by_distance() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].is_leaf() && static_cast<int>(i) != root) out.push_back(static_cast<int>(i));
  std::stable_sort(out.begin(), out.end(), [&](int a, int b) {
    return nodes[static_cast<std::size_t>(a)].depth < nodes[static_cast<std::size_t>(b)].depth;
  });
  return out;
}

std::vector<int> VoronoiTree::node_route(int from, int to) const {
  const auto ancestors = [&](int n) {
    std::vector<int> chain;
    for (; n >= 0; n = nodes[static_cast<std::size_t>(n)].parent)
      chain.push_back(n);
    return chain;  // n, parent, ..., root
  };
  const std::vector<int> up = ancestors(from), down = ancestors(to);
  // Lowest common ancestor: walk both chains from the root end.
  std::size_t i = up.size(), j = down.size();
  while (i > 0 && j > 0 && up[i - 1] == down[j - 1]) {
    --i;
    --j;
  }
  std::vector<int> route(up.begin(), up.begin() + static_cast<std::ptrdiff_t>(i + 1));
  for (std::size_t k = j; k-- > 0;)
    route.push_back(down[k]);
  return route;
}

std::vector<Vec2> VoronoiTree::waypoints(int from, int to) const {
  const std::vector<int> route = node_route(from, to);
  std::vector<Vec2> out{nodes[static_cast<std::size_t>(route.front())].position};
  for (std::size_t k = 1; k < route.size(); ++k) {
    const TreeNode& a = nodes[static_cast<std::size_t>(route[k - 1])];
    const TreeNode& b = nodes[static_cast<std::size_t>(route[k])];
    if (b.parent == route[k - 1]) {  // down: the child's path
      out.insert(out.end(), b.path.begin() + 1, b.path.end());
    } else {  // up: this node's path reversed
      out.insert(out.end(), a.path.rbegin() + 1, a.path.rend());
    }
  }
  return out;
}

VoronoiTree build_voronoi_tree(const PointVoronoi& voronoi, const BinaryGrid& traversable,
                               Vec2 start, const VoronoiTreeOptions& options) {
  options.validate();
  if (!start.is_finite()) throw Error("build_voronoi_tree", 0, "start must be finite");
  VoronoiTree tree;
  const std::size_t nv = voronoi.vertices.size();
  std::vector<char> kept(nv, 0);
  for (std::size_t i = 0; i < nv; ++i)
    kept[i] = cell_free(traversable, voronoi.vertices[i]);

  planning::AStarPlanner astar;
  struct Arc {
    std::size_t to;
    double cost;
    std::vector<Vec2> path;
  };
  std::vector<std::vector<Arc>> adj(nv);
  for (const auto& [a, b] : voronoi.edges) {
    if (!kept[a] || !kept[b]) continue;
    std::vector<Vec2> p = checked_path(traversable, astar, voronoi.vertices[a], voronoi.vertices[b],
                                       options.max_detour_factor);
    if (p.empty()) continue;
    const double cost = polyline_length(p);
    std::vector<Vec2> rev(p.rbegin(), p.rend());
    adj[a].push_back({b, cost, std::move(p)});
    adj[b].push_back({a, cost, std::move(rev)});
  }

  // Connected parts of the clipped graph (kept vertices joined by checked paths).
  std::vector<std::size_t> part(nv, nv), part_size;
  for (std::size_t s = 0; s < nv; ++s) {
    if (!kept[s] || part[s] != nv) continue;
    const std::size_t id = part_size.size();
    part_size.push_back(0);
    std::vector<std::size_t> stack{s};
    part[s] = id;
    while (!stack.empty()) {
      const std::size_t u = stack.back();
      stack.pop_back();
      ++part_size[id];
      for (const Arc& arc : adj[u])
        if (part[arc.to] == nv) {
          part[arc.to] = id;
          stack.push_back(arc.to);
        }
    }
  }
  const std::size_t largest =
      part_size.empty() ? 0 : *std::max_element(part_size.begin(), part_size.end());

  // Root: the kept vertex nearest the start (within the largest part: an isolated vertex near
  // the start, cut off by known obstacles, gives a tree without leaves).
  std::size_t root = nv;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nv; ++i) {
    if (!kept[i]) continue;
    if (options.root_in_largest_component && part_size[part[i]] != largest) continue;
    const double d = distance(voronoi.vertices[i], start);
    if (d < best) {
      best = d;
      root = i;
    }
  }
  if (root == nv) return tree;

  // Shortest-path tree (Dijkstra) over the clipped graph.
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> via(nv, nv);
  std::vector<const std::vector<Vec2>*> via_path(nv, nullptr);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[root] = 0.0;
  open.push({0.0, root});
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    for (const Arc& arc : adj[u]) {
      if (d + arc.cost < dist[arc.to]) {
        dist[arc.to] = d + arc.cost;
        via[arc.to] = u;
        via_path[arc.to] = &arc.path;
        open.push({dist[arc.to], arc.to});
      }
    }
  }

  // Tree nodes for the reached vertices.
  std::vector<int> node_of(nv, -1);
  for (std::size_t i = 0; i < nv; ++i) {
    if (!std::isfinite(dist[i])) continue;
    node_of[i] = static_cast<int>(tree.nodes.size());
    TreeNode n;
    n.position = voronoi.vertices[i];
    tree.nodes.push_back(std::move(n));
  }
  tree.root = node_of[root];
  std::vector<std::vector<int>> children(tree.nodes.size());
  for (std::size_t i = 0; i < nv; ++i) {
    if (node_of[i] < 0 || i == root) continue;
    TreeNode& n = tree.nodes[static_cast<std::size_t>(node_of[i])];
    n.parent = node_of[via[i]];
    n.path = *via_path[i];
    children[static_cast<std::size_t>(n.parent)].push_back(node_of[i]);
  }

  // At most two children per node (left = nearer); extra children go to the nearest kept child.
  std::deque<int> queue{tree.root};
  while (!queue.empty()) {
    const int u = queue.front();
    queue.pop_front();
    TreeNode& nu = tree.nodes[static_cast<std::size_t>(u)];
    auto& ch = children[static_cast<std::size_t>(u)];
    std::stable_sort(ch.begin(), ch.end(), [&](int a, int b) {
      return distance(tree.nodes[static_cast<std::size_t>(a)].position, nu.position) <
             distance(tree.nodes[static_cast<std::size_t>(b)].position, nu.position);
    });
    for (std::size_t k = 2; k < ch.size(); ++k) {
      const int c = ch[k];
      TreeNode& nc = tree.nodes[static_cast<std::size_t>(c)];
      const int k0 = ch[0], k1 = ch[1];
      const auto& p0 = tree.nodes[static_cast<std::size_t>(k0)].position;
      const auto& p1 = tree.nodes[static_cast<std::size_t>(k1)].position;
      const int to = distance(p0, nc.position) <= distance(p1, nc.position) ? k0 : k1;
      const TreeNode& nt = tree.nodes[static_cast<std::size_t>(to)];
      std::vector<Vec2> p = checked_path(traversable, astar, nt.position, nc.position,
                                         std::numeric_limits<double>::max() / 4);
      if (p.empty()) {  // via the old parent: reversed path to `to`, then the path to c
        p.assign(nt.path.rbegin(), nt.path.rend());
        p.insert(p.end(), nc.path.begin() + 1, nc.path.end());
      }
      nc.parent = to;
      nc.path = std::move(p);
      children[static_cast<std::size_t>(to)].push_back(c);
    }
    if (ch.size() > 2) ch.resize(2);
    nu.left = ch.empty() ? -1 : ch[0];
    nu.right = ch.size() > 1 ? ch[1] : -1;
    for (int c : ch)
      queue.push_back(c);
  }

  // Weights (eq. 11) and depths, in breadth-first order from the root.
  const auto compute_depths = [&] {
    std::deque<int> q{tree.root};
    while (!q.empty()) {
      const int u = q.front();
      q.pop_front();
      TreeNode& n = tree.nodes[static_cast<std::size_t>(u)];
      if (n.parent >= 0) {
        const TreeNode& p = tree.nodes[static_cast<std::size_t>(n.parent)];
        n.weight = distance(p.position, n.position);
        n.depth = p.depth + n.weight;
      }
      for (int c : {n.left, n.right})
        if (c >= 0) q.push_back(c);
    }
  };
  compute_depths();

  if (options.prune_leaf_shorter_than > 0.0) {
    std::vector<char> removed(tree.nodes.size(), 0);
    bool changed = true;
    while (changed) {
      changed = false;
      for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        TreeNode& n = tree.nodes[i];
        if (removed[i] || static_cast<int>(i) == tree.root || !n.is_leaf()) continue;
        if (n.weight >= options.prune_leaf_shorter_than) continue;
        TreeNode& p = tree.nodes[static_cast<std::size_t>(n.parent)];
        if (p.left == static_cast<int>(i)) {
          p.left = p.right;  // the remaining child becomes the left (nearer) one
          p.right = -1;
        } else {
          p.right = -1;
        }
        removed[i] = 1;
        changed = true;
      }
    }
    // Compact the indices.
    std::vector<int> remap(tree.nodes.size(), -1);
    std::vector<TreeNode> kept_nodes;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
      if (removed[i]) continue;
      remap[i] = static_cast<int>(kept_nodes.size());
      kept_nodes.push_back(std::move(tree.nodes[i]));
    }
    const auto re = [&](int v) { return v < 0 ? -1 : remap[static_cast<std::size_t>(v)]; };
    for (TreeNode& n : kept_nodes) {
      n.parent = re(n.parent);
      n.left = re(n.left);
      n.right = re(n.right);
    }
    tree.root = re(tree.root);
    tree.nodes = std::move(kept_nodes);
  }
  return tree;
}

std::vector<std::vector<int>> dispatch_leaves(const VoronoiTree& tree, int robots) {
  return dispatch_leaves(tree.leaves_by_distance(), robots);
}

std::vector<std::vector<int>> dispatch_leaves(const std::vector<int>& leaves, int robots) {
  if (robots < 1)
    throw Error("dispatch_leaves", 0, "expected at least one robot, got " + std::to_string(robots));
  std::vector<std::vector<int>> out(static_cast<std::size_t>(robots));
  if (leaves.empty()) return out;
  const std::size_t n = out.size(), l = leaves.size();
  if (n >= l) {
    for (std::size_t i = 0; i < n; ++i)
      out[i].push_back(leaves[i % l]);
  } else {
    for (std::size_t k = 0; k < l; ++k)
      out[k % n].push_back(leaves[k]);
  }
  return out;
}

}  // namespace voronav::exploration
