// The construction over scenes of growing size: the tetrahedron in floor plans of
// 1, 2, 4, ... rooms (the scene generator's tetra_floorplan_N); with --mixed-rooms
// the 14-facet house robot in floor plans of 1, 2, 4, ... rooms up to MAX whose walls have
// three heights (0.375, 0.75, 1.25: below, between and above the robot's features);
// with --robots the robots of 4 to 108 facets in one such floor plan; then any
// scenes named on the command line (generator names, house_mixed_N or .cfg files). Prints per scene the
// time of each stage, the counts (patches, curves, vertices, sub-faces, shells, free
// cells), the peak memory and the share of predicates decided in double intervals;
// with --plot FILE.svg also draws the total time against the output size (vertices
// plus sub-faces); with --euler also prints the Euler characteristics of the shells of
// free cells (a check of the topology, not timed with the construction). With
// --repeat N each scene is built N times and the fastest build's times are printed
// (the least disturbed by other work on the machine).
//
// Usage: bench_construction [--rooms MAX] [--mixed-rooms MAX] [--robots ROOMS]
//                           [--repeat N] [--plot FILE.svg] [--euler] [SCENE ...]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmark_arguments.h"
#include "freespace/io/output_file.h"
#include "freespace/scenes/scene_generator.h"
#include "freespace/space/free_space.h"
#include "freespace/topology/shell_euler_characteristic.h"

using namespace freespace;

namespace {

struct Row {
  std::string name;
  std::size_t robotFacets, worldFacets, outputSize;
  double seconds;
};

/// The Euler characteristics of the shells of free cells (each should be even and at
/// most 2: closed orientable surfaces), as "value x count" pairs, and the time taken.
void printShellCharacteristics(const FreeSpace& space) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<long> chi = shellEulerCharacteristics(space.arrangement(), space.algebra());
  std::map<long, int> byCharacteristic;
  for (std::uint32_t shell = 0; shell < space.shellCount(); ++shell) {
    if (space.cellOfShell(shell)) byCharacteristic[chi[shell]]++;
  }
  std::cout << "  shells of free cells by Euler characteristic:";
  for (const auto& [value, count] : byCharacteristic) std::cout << " " << value << " x" << count;
  std::cout << " (" << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)"
            << std::endl;
}

/// The fastest of `repeats` builds: its total and stage times.
struct FastestBuild {
  double seconds = HUGE_VAL;
  std::vector<StageTime> stages;
};

/// Builds the free space `repeats` times (one at a time, so that the peak memory is
/// one build's) and keeps the last; `fastest` gets the fastest build's times.
std::unique_ptr<FreeSpace> buildRepeatedly(const Mesh& robot, const Mesh& world, unsigned repeats,
                                           FastestBuild& fastest) {
  std::unique_ptr<FreeSpace> space;
  for (unsigned run = 0; run < repeats; ++run) {
    space.reset();
    const auto start = std::chrono::steady_clock::now();
    space = std::make_unique<FreeSpace>(robot, world);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds < fastest.seconds) fastest = {seconds, space->stageTimes()};
  }
  return space;
}

Row measure(const std::string& name, const Mesh& robot, const Mesh& world, unsigned repeats, bool checkShells) {
  FastestBuild fastest;
  const std::unique_ptr<FreeSpace> built = buildRepeatedly(robot, world, repeats, fastest);
  const FreeSpace& space = *built;
  const double seconds = fastest.seconds;
  const Arrangement& arrangement = space.arrangement();
  std::size_t subFaces = 0;
  for (const PatchSubdivision& subdivision : arrangement.subdivisions) subFaces += subdivision.faceCount;
  std::cout << std::setw(20) << std::left << name << " robot " << robot.triangles().size() << ", world "
            << world.triangles().size() << " facets: " << std::setprecision(4) << seconds << " s (";
  if (repeats > 1) std::cout << "fastest of " << repeats << ": ";
  for (const StageTime& stage : fastest.stages) std::cout << stage.stage << " " << stage.seconds << ", ";
  std::cout << "); " << arrangement.patches.size() << " patches, " << arrangement.curves.size() << " curves, "
            << arrangement.vertices.size() << " vertices, " << subFaces << " sub-faces, " << space.shellCount()
            << " shells, " << space.cellCount() << " free cells; peak " << peakMemoryMegabytes()
            << " MB; double intervals " << 100 * space.statistics().doubleIntervalFraction() << "%" << std::endl;
  if (checkShells) printShellCharacteristics(space);
  return {name, robot.triangles().size(), world.triangles().size(), arrangement.vertices.size() + subFaces, seconds};
}

/// Total time against output size, both axes logarithmic.
void writePlot(const std::vector<Row>& rows, std::ostream& out) {
  const double width = 640, height = 420, margin = 60;
  double minX = 1e300, maxX = 0, minY = 1e300, maxY = 0;
  for (const Row& row : rows) {
    minX = std::min(minX, std::log10(static_cast<double>(std::max<std::size_t>(row.outputSize, 1))));
    maxX = std::max(maxX, std::log10(static_cast<double>(std::max<std::size_t>(row.outputSize, 1))));
    minY = std::min(minY, std::log10(row.seconds));
    maxY = std::max(maxY, std::log10(row.seconds));
  }
  minX = std::floor(minX), maxX = std::ceil(maxX) + (std::ceil(maxX) == std::floor(minX));
  minY = std::floor(minY), maxY = std::ceil(maxY) + (std::ceil(maxY) == std::floor(minY));
  const auto px = [&](double x) { return margin + (x - minX) / (maxX - minX) * (width - 2 * margin); };
  const auto py = [&](double y) { return height - margin - (y - minY) / (maxY - minY) * (height - 2 * margin); };
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (double x = minX; x <= maxX; ++x) {
    out << "<line x1=\"" << px(x) << "\" y1=\"" << py(minY) << "\" x2=\"" << px(x) << "\" y2=\"" << py(maxY)
        << "\" stroke=\"#ddd\"/><text x=\"" << px(x) << "\" y=\"" << height - margin + 18
        << "\" text-anchor=\"middle\">1e" << x << "</text>\n";
  }
  for (double y = minY; y <= maxY; ++y) {
    out << "<line x1=\"" << px(minX) << "\" y1=\"" << py(y) << "\" x2=\"" << px(maxX) << "\" y2=\"" << py(y)
        << "\" stroke=\"#ddd\"/><text x=\"" << margin - 8 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">1e" << y
        << " s</text>\n";
  }
  out << "<text x=\"" << width / 2 << "\" y=\"" << height - 12
      << "\" text-anchor=\"middle\">output size (vertices + sub-faces)</text>\n";
  for (const Row& row : rows) {
    const double x = px(std::log10(static_cast<double>(std::max<std::size_t>(row.outputSize, 1))));
    const double y = py(std::log10(row.seconds));
    out << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"4\" fill=\"#1f77b4\"/><text x=\"" << x + 6 << "\" y=\""
        << y - 6 << "\" font-size=\"10\">" << row.name << "</text>\n";
  }
  out << "</svg>\n";
}

/// The room counts 1, 2, 4, ... and the largest one last: twice `rooms`, at most
/// `largest` (and past it when `rooms` is `largest`, to end the loop).
unsigned doubledUpTo(unsigned rooms, unsigned largest) {
  return rooms < largest ? std::min(2 * rooms, largest) : 2 * rooms;
}

/// The house_mixed family's floor plan (seed 1).
Mesh mixedHeightFloorPlan(unsigned rooms) {
  return makeCheckedMesh(makeFloorPlan(mixedHeightLayout(rooms), 1).walls, "floor plan");
}

/// A scene named on the command line, read before the runs start.
struct NamedScene {
  std::string name;
  Mesh robot, world;
};

NamedScene namedScene(const std::string& name) {
  if (name.size() > 4 && name.substr(name.size() - 4) == ".cfg") {
    benchmarks::requireFiles({name});
    LoadedProblem problem = loadProblem(name);
    return {name.substr(name.find_last_of('/') + 1), std::move(problem.robot), std::move(problem.world)};
  }
  Scene scene = makeScene(name);
  return {scene.name, std::move(scene.robot), std::move(scene.world)};
}

constexpr const char* kUsage =
    "bench_construction [--rooms MAX] [--mixed-rooms MAX] [--robots ROOMS] [--repeat N] [--plot FILE.svg] [--euler] "
    "[SCENE ...]";

int run(int argc, char** argv) {
  unsigned maxRooms = 16, maxMixedRooms = 0, robotsRooms = 0, repeats = 1;
  std::string plot;
  bool checkShells = false;
  std::vector<NamedScene> extra;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--rooms" && i + 1 < argc) {
      maxRooms = benchmarks::wholeNumber(argument, argv[++i]);
    } else if (argument == "--mixed-rooms" && i + 1 < argc) {
      maxMixedRooms = benchmarks::wholeNumber(argument, argv[++i]);
    } else if (argument == "--robots" && i + 1 < argc) {
      robotsRooms = benchmarks::wholeNumber(argument, argv[++i]);
    } else if (argument == "--plot" && i + 1 < argc) {
      plot = argv[++i];
    } else if (argument == "--repeat" && i + 1 < argc) {
      repeats = benchmarks::wholeNumber(argument, argv[++i]);
      if (repeats == 0) throw std::invalid_argument("--repeat needs at least one build, not 0");
    } else if (argument == "--euler") {
      checkShells = true;
    } else {
      benchmarks::rejectOption(argument, kUsage);
      extra.push_back(namedScene(argument));
    }
  }
  std::vector<Row> rows;
  const auto measure = [&](const std::string& name, const Mesh& robot, const Mesh& world) {
    return ::measure(name, robot, world, repeats, checkShells);
  };
  for (unsigned rooms = 1; rooms <= maxRooms; rooms *= 2) {
    const Scene scene = makeScene("tetra_floorplan_" + std::to_string(rooms));
    rows.push_back(measure(scene.name, scene.robot, scene.world));
  }
  const Mesh house = makeHouseRobot();
  for (unsigned rooms = 1; rooms <= maxMixedRooms; rooms = doubledUpTo(rooms, maxMixedRooms)) {
    rows.push_back(measure("house_mixed_" + std::to_string(rooms), house, mixedHeightFloorPlan(rooms)));
  }
  if (robotsRooms > 0) {
    const Mesh world = mixedHeightFloorPlan(robotsRooms);
    const std::string suffix = "_mixed_" + std::to_string(robotsRooms);
    rows.push_back(measure("tetrahedron" + suffix, makeTetrahedronRobot(), world));
    rows.push_back(measure("house" + suffix, house, world));
    for (unsigned teeth = 1; teeth <= 4; ++teeth) {
      rows.push_back(measure("fishbone" + std::to_string(teeth) + suffix, makeFishboneRobot(teeth), world));
    }
  }
  for (const NamedScene& scene : extra) rows.push_back(measure(scene.name, scene.robot, scene.world));
  if (!plot.empty()) writeFile(plot, true, [&](std::ostream& out) { writePlot(rows, out); });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return benchmarks::reportingErrors("bench_construction", [&] { return run(argc, argv); });
}
