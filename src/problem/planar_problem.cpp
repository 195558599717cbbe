#include "freespace/problem/planar_problem.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <boost/property_tree/ini_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include "freespace/input_error.h"
#include "freespace/io/mesh_reader.h"

namespace freespace {

namespace {

namespace fs = std::filesystem;
using Section = std::map<std::string, std::string>;

/// The keys of one INI section, taken literally ("start.x" is one key, not a path).
Section readSection(const boost::property_tree::ptree& tree, const std::string& name) {
  Section section;
  const auto found = tree.find(name);
  if (found == tree.not_found()) return section;
  for (const auto& [key, value] : found->second) section[key] = value.data();
  return section;
}

class SectionReader {
 public:
  SectionReader(const std::string& file, const std::string& name, Section keys,
                std::vector<std::string>* warnings)
      : file_(file), name_(name), keys_(std::move(keys)), warnings_(warnings) {}

  bool has(const std::string& key) const { return keys_.count(key) != 0; }

  std::string text(const std::string& key) {
    used_.insert(key);
    const auto found = keys_.find(key);
    if (found == keys_.end()) throw InputError(file_, "missing required key '" + key + "' in [" + name_ + "]");
    return found->second;
  }

  double number(const std::string& key) {
    const std::string value = text(key);
    std::istringstream stream(value);
    double result;
    stream >> result;
    if (stream.fail() || !(stream >> std::ws).eof() || !std::isfinite(result)) {
      throw InputError(file_, "[" + name_ + "] " + key + " = '" + value + "' is not a finite number");
    }
    return result;
  }

  Pose2 pose(const std::string& prefix) {
    return {number(prefix + ".x"), number(prefix + ".y"), number(prefix + ".theta")};
  }

  /// Warns about the keys nobody asked for.
  void warnUnused() const {
    if (!warnings_) return;
    for (const auto& [key, value] : keys_) {
      if (!used_.count(key)) warnings_->push_back(file_ + ": unknown key '" + key + "' in [" + name_ + "] ignored");
    }
  }

 private:
  std::string file_;
  std::string name_;
  Section keys_;
  std::vector<std::string>* warnings_;
  std::set<std::string> used_;
};

void readProblemSection(SectionReader& section, PlanarProblem& problem) {
  if (section.has("name")) problem.name = section.text("name");
  problem.robot = section.text("robot");
  problem.world = section.text("world");
  problem.start = section.pose("start");
  problem.goal = section.pose("goal");
  const char* volumeKeys[] = {"volume.min.x", "volume.min.y", "volume.max.x", "volume.max.y"};
  bool anyVolume = false;
  for (const char* key : volumeKeys) anyVolume = anyVolume || section.has(key);
  if (anyVolume) {
    const Eigen::Vector2d low(section.number("volume.min.x"), section.number("volume.min.y"));
    const Eigen::Vector2d high(section.number("volume.max.x"), section.number("volume.max.y"));
    problem.volume = Eigen::AlignedBox2d(low, high);
  }
  if (section.has("objective")) problem.objective = section.text("objective");
  if (section.has("objective.threshold")) problem.objectiveThreshold = section.number("objective.threshold");
}

void readBenchmarkSection(SectionReader& section, PlanarProblem& problem) {
  if (section.has("time_limit")) problem.timeLimit = section.number("time_limit");
  if (section.has("mem_limit")) problem.memLimit = section.number("mem_limit");
  if (section.has("run_count")) problem.runCount = static_cast<unsigned>(section.number("run_count"));
}

std::string formatNumber(double value) {
  std::ostringstream stream;
  stream.precision(17);
  stream << value;
  return stream.str();
}

}  // namespace

PlanarProblem readProblem(const std::string& cfgPath, std::vector<std::string>* warnings) {
  std::ifstream input(cfgPath);
  if (!input) throw InputError(cfgPath, "cannot open file");
  boost::property_tree::ptree tree;
  try {
    boost::property_tree::ini_parser::read_ini(input, tree);
  } catch (const boost::property_tree::ini_parser_error& error) {
    throw InputError(cfgPath, "line " + std::to_string(error.line()) + ": " + error.message());
  }
  if (tree.find("problem") == tree.not_found()) throw InputError(cfgPath, "missing section [problem]");

  PlanarProblem problem;
  SectionReader problemSection(cfgPath, "problem", readSection(tree, "problem"), warnings);
  readProblemSection(problemSection, problem);
  problemSection.warnUnused();

  SectionReader benchmarkSection(cfgPath, "benchmark", readSection(tree, "benchmark"), warnings);
  readBenchmarkSection(benchmarkSection, problem);
  benchmarkSection.warnUnused();

  const auto planners = tree.find("planner");
  if (planners != tree.not_found()) {
    for (const auto& [key, value] : planners->second) problem.planners.push_back(key);  // file order
  }
  for (const auto& [name, section] : tree) {
    if (name != "problem" && name != "benchmark" && name != "planner" && warnings) {
      warnings->push_back(cfgPath + ": unknown section [" + name + "] ignored");
    }
  }
  if (problem.name.empty()) problem.name = fs::path(cfgPath).stem().string();
  return problem;
}

void writeProblem(const PlanarProblem& problem, const std::string& cfgPath, bool overwrite) {
  if (!overwrite && fs::exists(cfgPath)) throw InputError(cfgPath, "already exists (not overwritten)");
  std::ofstream out(cfgPath);
  if (!out) throw InputError(cfgPath, "cannot write file");
  out << "[problem]\n"
      << "name = " << problem.name << "\n"
      << "robot = " << problem.robot << "\n"
      << "world = " << problem.world << "\n";
  const auto writePose = [&out](const char* prefix, const Pose2& pose) {
    out << prefix << ".x = " << formatNumber(pose.x) << "\n"
        << prefix << ".y = " << formatNumber(pose.y) << "\n"
        << prefix << ".theta = " << formatNumber(pose.theta) << "\n";
  };
  writePose("start", problem.start);
  writePose("goal", problem.goal);
  if (problem.volume) {
    out << "volume.min.x = " << formatNumber(problem.volume->min().x()) << "\n"
        << "volume.min.y = " << formatNumber(problem.volume->min().y()) << "\n"
        << "volume.max.x = " << formatNumber(problem.volume->max().x()) << "\n"
        << "volume.max.y = " << formatNumber(problem.volume->max().y()) << "\n";
  }
  if (!problem.objective.empty()) out << "objective = " << problem.objective << "\n";
  if (problem.objectiveThreshold) out << "objective.threshold = " << formatNumber(*problem.objectiveThreshold) << "\n";
  out << "\n[benchmark]\n"
      << "time_limit = " << formatNumber(problem.timeLimit) << "\n"
      << "mem_limit = " << formatNumber(problem.memLimit) << "\n"
      << "run_count = " << problem.runCount << "\n";
  if (!problem.planners.empty()) {
    out << "\n[planner]\n";
    for (const std::string& planner : problem.planners) out << planner << " =\n";
  }
  if (!out) throw InputError(cfgPath, "cannot write file");
}

LoadedProblem loadProblem(const std::string& cfgPath, std::vector<std::string>* warnings) {
  LoadedProblem loaded;
  loaded.cfgPath = cfgPath;
  loaded.problem = readProblem(cfgPath, warnings);
  const fs::path folder = fs::path(cfgPath).parent_path();
  const std::string robotPath = (folder / loaded.problem.robot).string();
  const std::string worldPath = (folder / loaded.problem.world).string();

  const Mesh robot = loadMesh(robotPath, warnings);
  Point3 sum = Point3::Zero();
  for (const Point3& vertex : robot.vertices()) sum += vertex;
  loaded.robotCentre = sum / static_cast<double>(robot.vertices().size());
  loaded.robotCentre.z() = 0;
  loaded.robot = robot.translated(-loaded.robotCentre, robotPath);
  loaded.world = loadMesh(worldPath, warnings);
  return loaded;
}

}  // namespace freespace
