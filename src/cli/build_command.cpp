#include <iostream>
#include <memory>

#include <chrono>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "free_space_input.h"
#include "freespace/input_error.h"
#include "freespace/io/output_file.h"
#include "number_checks.h"

namespace freespace::cli {

namespace {

nlohmann::json predicatesJson(const PredicateStatistics& statistics) {
  nlohmann::json all = nlohmann::json::object();
  for (int kind = 0; kind < static_cast<int>(PredicateKind::Count); ++kind) {
    const PredicateStatistics::KindCounts& counts = statistics.counts(static_cast<PredicateKind>(kind));
    nlohmann::json levels = nlohmann::json::object();
    for (int level = 0; level < kPrecisionLevelCount; ++level) levels[precisionLevelName(level)] = counts.decided[level];
    all[predicateKindName(static_cast<PredicateKind>(kind))] = {
        {"levels", levels}, {"identities", counts.identities}, {"escalated_seconds", counts.escalatedSeconds}};
  }
  return all;
}

/// Each free cell with a box holding it (none for the unbounded cell 0).
nlohmann::json cellsJson(const FreeSpace& space) {
  nlohmann::json cells = nlohmann::json::array();
  const std::vector<std::optional<PatchBox>>& boxes = space.cellBoxes();
  for (std::size_t cell = 0; cell < boxes.size(); ++cell) {
    nlohmann::json entry = {{"cell", cell}, {"bounded", boxes[cell].has_value()}};
    if (boxes[cell]) {
      entry["box"] = {{"min", {boxes[cell]->low[0], boxes[cell]->low[1], boxes[cell]->low[2]}},
                      {"max", {boxes[cell]->high[0], boxes[cell]->high[1], boxes[cell]->high[2]}}};
    }
    cells.push_back(entry);
  }
  return cells;
}

nlohmann::json statisticsJson(const FreeSpace& space) {
  const Arrangement& arrangement = space.arrangement();
  std::size_t subFaces = 0, edges = 0;
  for (const PatchSubdivision& subdivision : arrangement.subdivisions) subFaces += subdivision.faceCount;
  for (const SubFaceGluing* gluing :
       {&arrangement.acrossCurves, &arrangement.aroundSpirals, &arrangement.acrossHorizontalEdges}) {
    edges += gluing->glues.size();
  }
  nlohmann::json stages = nlohmann::json::object();
  double seconds = 0;
  for (const StageTime& stage : space.stageTimes()) {
    stages[stage.stage] = stage.seconds;
    seconds += stage.seconds;
  }
  const PerturbationRecord& perturbation = space.meshes().record;
  return {{"patches", arrangement.patches.size()},
          {"curves", arrangement.curves.size()},
          {"vertices", arrangement.vertices.size()},
          {"sub_faces", subFaces},
          {"edges", edges},
          {"shells", space.shellCount()},
          {"free_shells", space.freeShellCount()},
          {"cells", space.cellCount()},
          {"free_cells", space.cellCount()},
          {"seconds", seconds},
          {"stage_seconds", stages},
          {"peak_memory_mb", peakMemoryMegabytes()},
          {"perturbation",
           {{"enabled", perturbation.enabled},
            {"seed", perturbation.seed},
            {"relative_size", perturbation.relativeSize},
            {"absolute_size", perturbation.absoluteSize / space.meshes().scale}}},
          {"coordinate_scale", space.meshes().scale},
          {"cell_list", cellsJson(space)},
          {"predicates", predicatesJson(space.statistics())},
          {"double_interval_fraction", space.statistics().doubleIntervalFraction()}};
}

}  // namespace

void addBuildCommand(CLI::App& app) {
  struct Options {
    FreeSpaceInput input;
    std::string save;
    bool force = false;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("build", "Build the exact free space and print its statistics");
  options->input.addOptions(*command);
  command->add_flag("--json", options->json, "print JSON");
  command->add_option("--save", options->save, "save the built free space to this file (for locate, slice, export)")
      ->check(nonEmpty());
  command->add_flag("--force", options->force, "overwrite an existing --save file");
  command->callback([options]() {
    // Refuse before a long construction, not after it.
    if (!options->save.empty()) checkOutputPath(options->save, options->force);
    if (const std::optional<std::string> saved = options->input.savedSpaceFile()) {
      throw InputError(*saved, "build needs --cfg FILE or ROBOT WORLD, not a saved free space");
    }
    LoadedProblem loaded;
    const std::unique_ptr<FreeSpace> space = options->input.build(loaded);
    const auto graphStart = std::chrono::steady_clock::now();
    const CellGraph& graph = space->cellGraph();
    const double graphSeconds = secondsSince(graphStart);
    if (!options->save.empty()) space->save(options->save, options->force);
    nlohmann::json statistics = statisticsJson(*space);
    statistics["graph"] = {{"critical_angles", graph.criticalAngles().size()},
                           {"nodes", graph.nodes().size()},
                           {"edges", graph.edges().size()},
                           {"seconds", graphSeconds}};
    if (options->json) {
      std::cout << statistics.dump(2) << "\n";
      return;
    }
    std::cout << "patches " << statistics["patches"] << ", curves " << statistics["curves"] << ", vertices "
              << statistics["vertices"] << ", sub-faces " << statistics["sub_faces"] << ", edges "
              << statistics["edges"] << "\n"
              << "shells " << statistics["shells"] << " (" << statistics["free_shells"] << " bound free cells), free cells "
              << statistics["free_cells"] << " (cell 0 is the unbounded one)\n"
              << "seconds " << statistics["seconds"] << ":";
    for (const StageTime& stage : space->stageTimes()) std::cout << " " << stage.stage << " " << stage.seconds;
    std::cout << "\ncell graph: " << graph.nodes().size() << " nodes, " << graph.edges().size() << " edges over "
              << graph.intervalCount() << " angle intervals, " << graphSeconds << " s";
    std::cout << "\npeak memory " << statistics["peak_memory_mb"] << " MB; predicates decided in double intervals "
              << 100 * space->statistics().doubleIntervalFraction() << "%\n"
              << space->statistics().toText();
  });
}

}  // namespace freespace::cli
