#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "freespace/input_error.h"
#include "freespace/scenes/scene_generator.h"
#include "number_checks.h"

namespace freespace::cli {

namespace {

const std::string kSceneFamilies = "tetra_floorplan_<rooms>, soup_maze_<thousands of triangles>, house_mixed_<rooms>";

struct GenerateOptions {
  std::string out;
  std::vector<std::string> scenes;
  std::string format = "obj";
  std::uint64_t seed = 1;
  std::string nameSuffix;
  bool force = false;
};

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void runGenerate(const GenerateOptions& options) {
  const std::vector<std::string> names = options.scenes.empty() ? sceneNames() : options.scenes;
  for (const std::string& name : names) {
    if (!isSceneName(name)) {
      throw InputError("--scene",
                       "unknown scene '" + name + "'; valid scenes: " + joined(sceneNames()) + ", " + kSceneFamilies);
    }
  }
  for (const std::string& name : names) {
    Scene scene = makeScene(name, options.seed);
    if (!options.nameSuffix.empty()) scene = renamedScene(std::move(scene), scene.name + options.nameSuffix);
    const std::string cfg = writeScene(scene, options.out, options.format, options.force);
    std::cout << cfg << ": robot " << writtenSoup(scene.robot, scene.robotSoup).triangles.size() << " triangles, world "
              << writtenSoup(scene.world, scene.worldSoup).triangles.size() << " triangles, "
              << (scene.expectSolvable ? "solvable" : "no path") << "\n";
  }
}

}  // namespace

void addGenerateCommand(CLI::App& app) {
  auto options = std::make_shared<GenerateOptions>();
  CLI::App* command = app.add_subcommand(
      "generate", "Write test scenes: robot and world meshes and an OMPL.app problem (.cfg) for each");
  command->add_option("--out", options->out, "Folder to write into (created if needed)")->required()->check(nonEmpty());
  command->add_option("--scene", options->scenes,
                      "Scenes to write (default: all): " + joined(sceneNames()) + ", " + kSceneFamilies);
  command->add_option("--format", options->format, "Mesh format")
      ->capture_default_str()
      ->check(CLI::IsMember({"obj", "dae", "stl", "ply", "off", "vtk"}));
  command->add_option("--seed", options->seed, "Seed of the scenes with random parts")
      ->capture_default_str()
      ->check(wholeNumber());
  command->add_option("--name-suffix", options->nameSuffix,
                      "Appended to each scene's name and file names (e.g. _dae for a COLLADA copy)");
  command->add_flag("--force", options->force, "Overwrite existing files");
  command->callback([options] { runGenerate(*options); });
}

}  // namespace freespace::cli
