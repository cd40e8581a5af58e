#include "plan_ras.hpp"

#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "voronav/core/error.hpp"
#include "voronav/render/figure.hpp"

namespace voronav::cli {

void add_ras_options(CLI::App* cmd, RasCliArgs& args) {
  cmd->add_option("--region-size", args.region_size,
                  "RAS: side of a square region [cells] (the paper's S_p)")
      ->check(CLI::Range(1, planning::kMaxRegionSize))
      ->capture_default_str();
  cmd->add_option("--density", args.density,
                  "RAS: number a region only if >= this many of its 8 neighbours are free "
                  "(0-8; 8 keeps a free ring around the path)")
      ->check(CLI::Range(0, 8))
      ->capture_default_str();
  cmd->add_option("--direction", args.direction,
                  "RAS: neighbour order, default (counter-clockwise from east), optimal "
                  "(toward the goal first, one order from the start->goal direction) or "
                  "optimal-per-region (re-sorted toward the goal at every region)")
      ->check(CLI::IsMember({"default", "optimal", "optimal-per-region"}))
      ->capture_default_str();
  cmd->add_flag("!--no-corner-cutting", args.corner_cutting,
                "RAS: diagonal steps need both flanking regions free (as A*); the paper allows "
                "passing a blocked corner");
}

planning::RasOptions to_ras_options(const RasCliArgs& args) {
  planning::RasOptions o;
  o.region_size = args.region_size;
  o.density = args.density;
  if (args.direction == "optimal") {
    o.direction = planning::RasDirection::kOptimal;
  } else if (args.direction == "optimal-per-region") {
    o.direction = planning::RasDirection::kOptimalPerRegion;
  } else if (args.direction == "default") {
    o.direction = planning::RasDirection::kDefault;
  } else {
    throw Error("--direction", 0,
                "expected default, optimal or optimal-per-region, got '" + args.direction + "'");
  }
  o.corner_rule = args.corner_cutting ? planning::RasCornerRule::kAllowCornerCutting
                                      : planning::RasCornerRule::kNoCornerCutting;
  planning::validate(o);
  return o;
}

void add_ras_json(nlohmann::json& out, const planning::RasPlanner& ras, const MapContext& ctx) {
  const planning::RasResult& r = ras.last_result();
  const planning::RasField& f = ras.field();
  const planning::RegionGrid& rg = ras.region_grid();
  const planning::RasOptions& o = ras.ras_options();
  out["ras_status"] = planning::to_string(r.status);
  out["region_size"] = o.region_size;
  out["density"] = o.density;
  out["direction"] = o.direction == planning::RasDirection::kOptimal ? "optimal"
                     : o.direction == planning::RasDirection::kOptimalPerRegion
                         ? "optimal-per-region"
                         : "default";
  out["region_grid"] = {rg.width(), rg.height()};
  out["regions"] = r.regions;
  out["steps"] = f.steps();
  nlohmann::json path = nlohmann::json::array();
  for (const std::int32_t k : r.path_ids) {
    const planning::RasRegion reg = f.region(k, rg);
    path.push_back({{"k", reg.k},
                    {"region", {reg.region.x, reg.region.y}},
                    {"p", {reg.p.x, reg.p.y}},
                    {"cell", ctx.cell_json(rg.center_cell(reg.region))},
                    {"N", reg.N},
                    {"d", reg.d},
                    {"step", reg.step}});
  }
  out["path_regions"] = path;
  nlohmann::json way = nlohmann::json::array();
  for (const Vec2 w : r.waypoints)
    way.push_back({w.x, w.y});
  out["waypoints"] = way;
}

void print_ras_text(const planning::RasPlanner& ras) {
  const planning::RasResult& r = ras.last_result();
  std::cout << "ras:      " << planning::to_string(r.status) << ", region grid "
            << ras.region_grid().width() << "x" << ras.region_grid().height() << " (size "
            << ras.ras_options().region_size << "), density " << ras.ras_options().density << "\n"
            << "regions:  " << r.regions << " numbered, " << r.path_regions.size()
            << " on the path\n";
}

void save_ras_picture(const PlanPicture& pic, const planning::RasPlanner& ras,
                      const std::filesystem::path& out) {
  const planning::RasField& f = ras.field();
  const planning::RegionGrid& rg = ras.region_grid();
  const planning::RasResult& r = ras.last_result();
  const GridGeometry& g = pic.map.geometry();
  const int rs = rg.region_size();
  const std::string title = "RAS: region size " + std::to_string(rs) + ", density " +
                            std::to_string(ras.ras_options().density) + ", " +
                            std::to_string(r.regions) + " regions numbered, " +
                            std::to_string(r.path_regions.size()) + " path regions";
  render::Figure fig(g, {.title = title, .crop = render::known_bounds(pic.map)});
  fig.occupancy(pic.map);
  if (rg.width() == 0) {
    fig.save(out);
    return;
  }
  // Region states, upsampled to cells: numbered regions by step (viridis), rejected ones orange.
  GridMap<float> step(g, std::numeric_limits<float>::quiet_NaN());
  BinaryGrid rejected(g, 0);
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const Cell c{x, y};
      const std::int32_t id = f.id_at(rg.region_of(c));
      if (id >= 0) step[c] = static_cast<float>(f.step(id));
      if (id == planning::RasField::kBelowDensity) rejected[c] = 1;
    }
  }
  fig.scalar(step, 0.0, std::max(1, f.steps() - 1), 0.45);
  fig.colorbar(0.0, std::max(1, f.steps() - 1), "numbering step");
  fig.binary(rejected, render::Color::hex(0xff7f0e, 0.55));
  // Region borders and ids when regions are large enough on screen (figure 2 style).
  const double region_px = fig.pixels_per_cell() * rs;
  const double res = g.resolution;
  if (region_px >= 8.0 && rs > 1) {
    const auto grey = render::Color::hex(0x606060, 0.35);
    for (int x = 0; x <= rg.width(); ++x) {
      const double cx = std::min(g.width, x * rs) * res;
      fig.segment(g.grid_to_world({cx / res, 0.0}), g.grid_to_world({cx / res, 1.0 * g.height}),
                  grey, 0.6);
    }
    for (int y = 0; y <= rg.height(); ++y) {
      const double cy = std::min(g.height, y * rs);
      fig.segment(g.grid_to_world({0.0, cy}), g.grid_to_world({1.0 * g.width, cy}), grey, 0.6);
    }
  }
  if (region_px >= 16.0 && f.size() <= 300) {  // ids only where they stay readable
    const double size = std::clamp(region_px * 0.32, 6.0, 13.0);
    for (std::int32_t k = 0; k < f.size(); ++k) {
      const Cell reg = f.region_of(k);
      fig.text(rg.center_world(reg), std::to_string(k), render::colors::kBlack, size);
    }
  }
  std::vector<std::pair<std::string, render::Color>> legend{
      {"numbered (colour = step)", render::viridis(0.5)},
      {"below density", render::Color::hex(0xff7f0e)}};
  if (r.ok()) {
    fig.polyline(r.waypoints, render::colors::kRed, 3.0);
    if (region_px >= 4.0)
      for (const Vec2 w : r.waypoints)
        fig.point(w, render::colors::kRed, 2.5);
    legend.emplace_back("path (region centres)", render::colors::kRed);
  }
  fig.marker(pic.start, render::colors::kGreen, 6, "start");
  fig.marker(pic.goal, render::colors::kRed, 6, "goal");
  fig.legend(std::move(legend));
  fig.save(out);
}

}  // namespace voronav::cli
