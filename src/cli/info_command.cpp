#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "scene_input.h"

namespace freespace::cli {

namespace {

nlohmann::json boxJson(const Box3& box) {
  return {{"min", {box.min().x(), box.min().y(), box.min().z()}},
          {"max", {box.max().x(), box.max().y(), box.max().z()}}};
}

nlohmann::json meshJson(const std::string& file, const Mesh& mesh) {
  nlohmann::json components = nlohmann::json::array();
  for (const Box3& box : mesh.componentBounds()) {
    components.push_back({{"bounds", boxJson(box)}, {"z_range", {box.min().z(), box.max().z()}}});
  }
  return {{"file", file},
          {"vertices", mesh.vertices().size()},
          {"triangles", mesh.triangles().size()},
          {"components", mesh.componentCount()},
          {"volume", mesh.volume()},
          {"bounds", boxJson(mesh.bounds())},
          {"z_range", {mesh.bounds().min().z(), mesh.bounds().max().z()}},
          {"component_list", components}};
}

void printBox(const char* label, const Box3& box) {
  std::cout << label << "[" << box.min().x() << ", " << box.max().x() << "] x [" << box.min().y() << ", "
            << box.max().y() << "] x [" << box.min().z() << ", " << box.max().z() << "]\n";
}

void printMesh(const char* role, const nlohmann::json& info, const Mesh& mesh, const PreparationReport& preparation) {
  std::cout << role << ": " << info["file"].get<std::string>() << "\n"
            << "  vertices " << mesh.vertices().size() << ", triangles " << mesh.triangles().size() << ", components "
            << mesh.componentCount() << ", volume " << mesh.volume() << "\n"
            << "  z range [" << mesh.bounds().min().z() << ", " << mesh.bounds().max().z() << "]\n";
  printBox("  bounding box ", mesh.bounds());
  for (std::size_t i = 0; i < mesh.componentCount(); ++i) {
    std::cout << "  component " << i << ": ";
    printBox("", mesh.componentBounds()[i]);
  }
  const std::vector<std::string> changes = preparation.changes();
  if (changes.empty()) std::cout << "  read as it is (" << preparation.repair.describe().back() << ")\n";
  for (const std::string& change : changes) std::cout << "  repaired: " << change << "\n";
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  struct Options {
    SceneInput input;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand("info", "Mesh statistics: triangles, components, z ranges, bounding boxes");
  options->input.addOptions(*command);
  command->add_flag("--json", options->json, "print JSON");
  command->callback([options]() {
    const LoadedProblem loaded = options->input.load();
    nlohmann::json robot = meshJson(loaded.problem.robot, loaded.robot);
    nlohmann::json world = meshJson(loaded.problem.world, loaded.world);
    robot["repair"] = preparationJson(loaded.robotPreparation);
    world["repair"] = preparationJson(loaded.worldPreparation);
    if (options->json) {
      nlohmann::json all = {{"robot", robot}, {"world", world}};
      if (!loaded.cfgPath.empty()) {
        all["robot_centre"] = {loaded.robotCentre.x(), loaded.robotCentre.y(), loaded.robotCentre.z()};
      }
      std::cout << all.dump(2) << "\n";
      return;
    }
    printMesh("robot", robot, loaded.robot, loaded.robotPreparation);
    if (!loaded.cfgPath.empty()) {
      std::cout << "  re-centred: its vertex average (" << loaded.robotCentre.x() << ", " << loaded.robotCentre.y()
                << ") was moved to the origin\n";
    }
    printMesh("world", world, loaded.world, loaded.worldPreparation);
  });
}

}  // namespace freespace::cli
