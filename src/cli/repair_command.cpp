#include <iostream>
#include <memory>

#include "commands.h"
#include "freespace/io/mesh_reader.h"
#include "freespace/io/mesh_writer.h"
#include "number_checks.h"
#include "preparation_options.h"

namespace freespace::cli {

namespace {

struct RepairOptions {
  std::string input;
  std::string output;
  PreparationOptions preparation;
  bool json = false;
  bool force = false;
};

void runRepair(const RepairOptions& options) {
  std::vector<std::string> warnings;
  PreparationReport report;
  const Mesh mesh = loadMesh(options.input, &warnings, options.preparation.settings(), &report);
  for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
  writeMesh(mesh, options.output, options.force);
  if (options.json) {
    nlohmann::json json = preparationJson(report);
    json["input"] = options.input;
    json["output"] = options.output;
    json["triangles"] = mesh.triangles().size();
    json["components"] = mesh.componentCount();
    json["volume"] = mesh.volume();
    std::cout << json.dump(2) << "\n";
    return;
  }
  std::cout << options.output << ": " << mesh.triangles().size() << " triangles in " << mesh.componentCount()
            << " closed components, volume " << mesh.volume() << "\n";
  for (const std::string& change : report.changes()) std::cout << "  " << change << "\n";
}

}  // namespace

void addRepairCommand(CLI::App& app) {
  auto options = std::make_shared<RepairOptions>();
  CLI::App* command = app.add_subcommand(
      "repair", "Repair a mesh and write the solid it shows (closed components; the changes are reported)");
  command->add_option("input", options->input, "mesh file to repair")->required();
  command->add_option("output", options->output, "mesh file to write (the format follows the extension)")
      ->required()
      ->check(nonEmpty());
  options->preparation.addOptions(*command, "--tolerance");
  command->add_flag("--json", options->json, "print what was changed as JSON");
  command->add_flag("--force", options->force, "overwrite an existing output file");
  command->callback([options] { runRepair(*options); });
}

}  // namespace freespace::cli
