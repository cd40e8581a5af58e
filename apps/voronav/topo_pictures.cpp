#include "topo_pictures.hpp"

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli_common.hpp"
#include "voronav/core/error.hpp"
#include "voronav/io/map_loader.hpp"
#include "voronav/render/figure.hpp"
#include "voronav/topology/edge_route.hpp"
#include "voronav/topology/segmentation.hpp"
#include "voronav/topology/topological_map.hpp"
#include "voronav/voronoi/labeled_voronoi.hpp"

namespace voronav::cli {

void save_stages(const OccupancyGrid& grid, const BinaryGrid& blocked,
                 const topology::TopologicalMap& m, bool border_blocked,
                 const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  make_output_dir(dir, "--out");
  const render::CellBox crop = render::known_bounds(grid, 2);
  auto figure = [&](const std::string& title) {
    render::FigureOptions o;
    o.crop = crop;
    o.title = title;
    return render::Figure(grid.geometry(), o);
  };
  const render::Color wall = render::colors::kBlack;
  {
    auto f = figure("(a) binary map");
    f.binary(blocked, wall, render::colors::kWhite);
    f.legend({{"free", render::colors::kWhite}, {"blocked", wall}});
    f.save(dir / "a_binary.png");
  }
  {
    // Edge cells coloured by their edge code (5..12 the eight shapes, 3..4 noise).
    auto f = figure("(b) edge cells, coloured by edge code (5-12 shapes, 3-4 noise)");
    f.binary(blocked, render::colors::kGrey.with_alpha(0.35), render::colors::kWhite);
    const GridMap<std::uint8_t> codes = voronoi::edge_codes(blocked, border_blocked);
    GridMap<std::int32_t> lab(grid.geometry(), -1);
    for (std::size_t i = 0; i < codes.size(); ++i)
      if (codes[i] >= 3) lab[i] = codes[i];
    f.labels(lab, 1.0);
    f.save(dir / "b_edges.png");
  }
  {
    auto f = figure("(c) Voronoi diagram over the clearance");
    double hi = 1.0;
    for (const float v : m.clearance.values())
      if (std::isfinite(v)) hi = std::max(hi, static_cast<double>(v));
    f.scalar(m.clearance, 0.0, hi, 0.6);
    f.colorbar(0.0, hi * grid.resolution(), "clearance [m]");
    f.binary(blocked, wall);
    f.binary(m.diagram, render::colors::kRed);
    f.legend({{"obstacle", wall}, {"Voronoi diagram", render::colors::kRed}});
    f.save(dir / "c_voronoi.png");
  }
  auto draw_lines = [&](render::Figure& f, bool only_separating) {
    for (const auto& cp : m.critical_points) {
      if (only_separating && !cp.separates) continue;
      f.segment(grid.geometry().cell_center(cp.basis[0]), grid.geometry().cell_center(cp.basis[1]),
                cp.separates ? render::colors::kBlue : render::colors::kGrey, 2.0);
      f.marker(cp.cell, render::colors::kOrange, 3.5);
    }
  };
  {
    auto f = figure("(d) critical points and critical lines");
    f.binary(blocked, wall, render::colors::kWhite);
    f.binary(m.diagram, render::colors::kRed.with_alpha(0.6));
    draw_lines(f, false);
    f.legend({{"Voronoi diagram", render::colors::kRed},
              {"critical point", render::colors::kOrange},
              {"critical line (separates regions)", render::colors::kBlue},
              {"critical line (rejected)", render::colors::kGrey}});
    f.save(dir / "d_critical.png");
  }
  {
    auto f = figure("(e) topological regions");
    f.binary(blocked, wall, render::colors::kWhite);
    f.labels(m.region, 0.75);
    draw_lines(f, true);
    f.legend({{"region (one colour each)", render::palette(3)},
              {"critical line", render::colors::kBlue}});
    f.save(dir / "e_regions.png");
  }
  {
    auto f = figure("(f) topological graph");
    f.binary(blocked, wall, render::colors::kWhite);
    f.labels(m.region, 0.25);
    for (const auto& e : m.edges) {
      // Drawn along the Voronoi diagram (topology::edge_route), not as straight segments that
      // would cut through walls in non-convex regions.
      const std::vector<Cell> route = topology::edge_route(m, e);
      for (std::size_t k = 1; k < route.size(); ++k)
        f.segment(grid.geometry().cell_center(route[k - 1]), grid.geometry().cell_center(route[k]),
                  render::colors::kBlue, 2.0);
      f.marker(e.midpoint, render::colors::kBlue, 2.5);
    }
    for (const auto& r : m.regions)
      f.marker(r.centre, render::colors::kRed, 4.0);
    f.legend({{"region node", render::colors::kRed},
              {"edge (along the Voronoi diagram) and its crossing", render::colors::kBlue}});
    f.save(dir / "f_graph.png");
  }
}

}  // namespace voronav::cli
