#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "free_space_input.h"

namespace freespace::cli {

namespace {

/// The graph in the input's units (the construction's are scaled by
/// FreeSpace::meshes().scale); angles in radians.
nlohmann::json graphJson(const FreeSpace& space) {
  const CellGraph& graph = space.cellGraph();
  const double scale = space.meshes().scale;
  const std::vector<AlgebraicAngle>& critical = graph.criticalAngles();
  // A node over every interval holds every angle: its ends are null.
  const auto ends = [&](const CellGraphNode& node) {
    if (critical.empty() || (node.firstInterval == 0 && node.lastInterval + 1 == graph.intervalCount())) {
      return std::pair(nlohmann::json(), nlohmann::json());
    }
    return std::pair(nlohmann::json(critical[node.firstInterval].radians()),
                     nlohmann::json(critical[(node.lastInterval + 1) % critical.size()].radians()));
  };
  nlohmann::json nodes = nlohmann::json::array(), edges = nlohmann::json::array();
  for (std::uint32_t index = 0; index < graph.nodes().size(); ++index) {
    const CellGraphNode& node = graph.nodes()[index];
    nlohmann::json box = nlohmann::json::array();
    for (double bound : node.box) {
      box.push_back(std::isfinite(bound) ? nlohmann::json(bound / scale) : nlohmann::json());
    }
    const auto [from, to] = ends(node);
    nodes.push_back({{"node", index},
                     {"cell", node.cell},
                     {"from", from},
                     {"to", to},
                     {"sample", node.sample.radians()},
                     {"point", {node.point[0] / scale, node.point[1] / scale}},
                     {"box", box}});
  }
  for (const CellGraphEdge& edge : graph.edges()) {
    edges.push_back({{"from", edge.from}, {"to", edge.to}, {"angle", critical[edge.angle].radians()}});
  }
  return {{"critical_angles", critical.size()}, {"nodes", nodes}, {"edges", edges}};
}

/// The problem's start and goal (with --cfg): their nodes, and the route of nodes the
/// graph joins them by (null when none: they lie in different cells, or one is
/// blocked).
nlohmann::json routeJson(const FreeSpace& space, const PlanarProblem& problem) {
  const std::optional<std::uint32_t> start = space.nodeOf(problem.start), goal = space.nodeOf(problem.goal);
  nlohmann::json answer = {{"start_node", start ? nlohmann::json(*start) : nlohmann::json()},
                           {"goal_node", goal ? nlohmann::json(*goal) : nlohmann::json()},
                           {"route", nlohmann::json()}};
  if (start && goal) {
    if (const auto route = space.cellGraph().route(*start, *goal)) answer["route"] = *route;
  }
  return answer;
}

void printRoute(const nlohmann::json& route) {
  const auto node = [](const nlohmann::json& value) {
    return value.is_null() ? std::string("blocked") : "node " + value.dump();
  };
  std::cout << "start: " << node(route["start_node"]) << ", goal: " << node(route["goal_node"]) << "; ";
  if (route["route"].is_null()) {
    std::cout << "no route (they lie in different cells, or one is blocked)\n";
    return;
  }
  std::cout << "route:";
  for (const nlohmann::json& step : route["route"]) std::cout << " " << step;
  std::cout << "\n";
}

}  // namespace

void addGraphCommand(CLI::App& app) {
  struct Options {
    FreeSpaceInput input;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "graph",
      "Print the free cell graph: faces of the slices over angle intervals (nodes) and where they meet; with --cfg, "
      "the route of nodes from the start to the goal");
  options->input.addOptions(*command);
  command->add_flag("--json", options->json, "print JSON");
  command->callback([options]() {
    LoadedProblem loaded;
    const std::unique_ptr<FreeSpace> space = options->input.build(loaded);
    nlohmann::json graph = graphJson(*space);
    if (!loaded.cfgPath.empty()) graph["problem"] = routeJson(*space, loaded.problem);
    if (options->json) {
      std::cout << graph.dump(2) << "\n";
      return;
    }
    std::cout << graph["nodes"].size() << " nodes, " << graph["edges"].size() << " edges, " << graph["critical_angles"]
              << " critical angles (angles in radians, from -pi/2 round to 3pi/2)\n";
    for (const nlohmann::json& node : graph["nodes"]) {
      std::cout << "node " << node["node"] << ": cell " << node["cell"] << ", ";
      if (node["from"].is_null()) {
        std::cout << "every theta";
      } else {
        std::cout << "theta from " << node["from"] << " to " << node["to"];
      }
      std::cout << ", a point " << node["point"][0] << " " << node["point"][1] << " at theta " << node["sample"]
                << "\n";
    }
    for (const nlohmann::json& edge : graph["edges"]) {
      std::cout << "edge " << edge["from"] << " - " << edge["to"] << " at theta " << edge["angle"] << "\n";
    }
    if (graph.contains("problem")) printRoute(graph["problem"]);
  });
}

}  // namespace freespace::cli
