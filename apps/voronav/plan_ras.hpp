// The RAS part of `voronav plan` (seed 001): its options (--region-size, --density, --direction),
// the extra JSON fields (regions, path_regions, ...) and the picture of the numbered region space
// in the manner of the paper's figures 2, 12, 14 and 15. Kept apart from cmd_plan.cpp so that the
// generic command stays small.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_common.hpp"
#include "plan_picture.hpp"
#include "voronav/planning/ras.hpp"

namespace voronav::cli {

struct RasCliArgs {
  int region_size = 1;
  int density = 0;
  std::string direction = "default";
  bool corner_cutting = true;
};

/// Adds --region-size, --density, --direction and --no-corner-cutting to `cmd`.
void add_ras_options(CLI::App* cmd, RasCliArgs& args);
/// The RasOptions the arguments describe (validated; throws voronav::Error).
[[nodiscard]] planning::RasOptions to_ras_options(const RasCliArgs& args);
/// Adds the RAS fields of the last query of `ras` to a `plan --json` object.
void add_ras_json(nlohmann::json& out, const planning::RasPlanner& ras, const MapContext& ctx);
/// Text lines for the RAS fields (region grid, numbered regions, path regions, RAS status).
void print_ras_text(const planning::RasPlanner& ras);
/// Picture: map, numbered regions coloured by expansion step, regions rejected by the density
/// rule, region ids when they fit, the path through the region centres, start and goal.
void save_ras_picture(const PlanPicture& pic, const planning::RasPlanner& ras,
                      const std::filesystem::path& out);

}  // namespace voronav::cli
