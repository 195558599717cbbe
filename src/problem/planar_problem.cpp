#include "freespace/problem/planar_problem.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <boost/program_options/parsers.hpp>

#include "freespace/input_error.h"
#include "freespace/io/input_file.h"
#include "freespace/io/output_file.h"
#include "../io/mesh_text.h"

namespace freespace {

namespace {

namespace fs = std::filesystem;
using Section = std::map<std::string, std::string>;

/// The lines of each section, in file order.
using Sections = std::map<std::string, std::vector<ConfigEntry>>;

/// Parses the file as OMPL.app does (Boost.Program_options, every key accepted): a
/// line "key = value" under "[section]" comes back as "section.key".
Sections parseSections(std::istream& input, const std::string& cfgPath) {
  namespace po = boost::program_options;
  po::parsed_options parsed(nullptr);
  try {
    parsed = po::parse_config_file(input, po::options_description(), true);
  } catch (const po::invalid_config_file_syntax& error) {
    // Not error.what(): Boost 1.74 substitutes the line into its message template
    // until no placeholder is left, for ever when the line holds one.
    throw InputError(cfgPath, "a line is neither '[section]' nor 'key = value': '" +
                                  detail::printable(error.tokens()) + "'");
  } catch (const po::error_with_option_name& error) {
    throw InputError(cfgPath, "cannot be read as a configuration file at key '" +
                                  detail::printable(error.get_option_name()) + "'");
  } catch (const po::error& error) {
    throw InputError(cfgPath, std::string("cannot be read as a configuration file: ") + error.what());
  }
  Sections sections;
  for (const po::option& option : parsed.options) {
    // A control character (a NUL byte above all) would cut a file name and every
    // message that quotes it.
    const std::string value = option.value.empty() ? "" : option.value.front();
    const auto control = [](unsigned char c) { return c < 0x20 && c != '\t'; };
    if (std::any_of(option.string_key.begin(), option.string_key.end(), control) ||
        std::any_of(value.begin(), value.end(), control)) {
      std::string key = option.string_key;
      std::replace_if(key.begin(), key.end(), control, '?');
      throw InputError(cfgPath, "key '" + key + "': a control character (such as a NUL byte) in the line");
    }
    const std::size_t dot = option.string_key.find('.');
    const std::string section = dot == std::string::npos ? "" : option.string_key.substr(0, dot);
    const std::string key = dot == std::string::npos ? option.string_key : option.string_key.substr(dot + 1);
    sections[section].push_back({key, value});
  }
  return sections;
}

/// The section's keys with their values; a repeated key is an error or, when
/// `lastWins`, takes its last value.
Section keysOf(const std::vector<ConfigEntry>& entries, const std::string& cfgPath, const std::string& name,
               bool lastWins) {
  Section section;
  for (const ConfigEntry& entry : entries) {
    if (!section.emplace(entry.key, entry.value).second) {
      if (!lastWins) throw InputError(cfgPath, "[" + name + "] key '" + entry.key + "' is given more than once");
      section[entry.key] = entry.value;
    }
  }
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

  /// A whole number from 0 to 2^32 - 1.
  unsigned count(const std::string& key) {
    const double value = number(key);
    if (value < 0 || value > 4294967295.0 || std::floor(value) != value) {
      throw InputError(file_, "[" + name_ + "] " + key + " = '" + text(key) + "' is not a whole number from 0 to 4294967295");
    }
    return static_cast<unsigned>(value);
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

// Keys of [benchmark] that OMPL.app's benchmark reads and this project only keeps.
bool isKeptBenchmarkKey(const std::string& key) {
  return key == "output" || key == "save_paths" || key == "simplify";
}

void readBenchmarkSection(SectionReader& section, const std::vector<ConfigEntry>& entries, PlanarProblem& problem) {
  if (section.has("time_limit")) problem.timeLimit = section.number("time_limit");
  if (section.has("mem_limit")) problem.memLimit = section.number("mem_limit");
  if (section.has("run_count")) problem.runCount = section.count("run_count");
  for (const ConfigEntry& entry : entries) {
    if (isKeptBenchmarkKey(entry.key)) {
      section.text(entry.key);  // marks it used
      problem.benchmarkSettings.push_back(entry);
    }
  }
}

// OMPL.app's grouping of [planner] lines into planners (see PlannerEntry). Its
// "<planner>.problem.<key>" context lines are parameters like any other here.
std::vector<PlannerEntry> plannersOf(const std::vector<ConfigEntry>& entries) {
  std::vector<PlannerEntry> planners;
  for (const ConfigEntry& entry : entries) {
    const std::size_t dot = entry.key.find('.');
    if (dot == std::string::npos) {
      planners.push_back({entry.key, {}});
      continue;
    }
    const std::string type = entry.key.substr(0, dot);
    auto latest = std::find_if(planners.rbegin(), planners.rend(),
                               [&type](const PlannerEntry& planner) { return planner.type == type; });
    if (latest == planners.rend()) {
      planners.push_back({type, {}});
      latest = planners.rbegin();
    }
    latest->parameters.push_back({entry.key.substr(dot + 1), entry.value});
  }
  return planners;
}

std::string formatNumber(double value) {
  std::ostringstream stream;
  stream.precision(17);
  stream << value;
  return stream.str();
}

void writeProblemSection(std::ostream& out, const PlanarProblem& problem) {
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
}

void writeBenchmarkAndPlanners(std::ostream& out, const PlanarProblem& problem) {
  out << "\n[benchmark]\n"
      << "time_limit = " << formatNumber(problem.timeLimit) << "\n"
      << "mem_limit = " << formatNumber(problem.memLimit) << "\n"
      << "run_count = " << problem.runCount << "\n";
  for (const ConfigEntry& entry : problem.benchmarkSettings) out << entry.key << " = " << entry.value << "\n";
  if (problem.planners.empty()) return;
  out << "\n[planner]\n";
  for (const PlannerEntry& planner : problem.planners) {
    out << planner.type << " =\n";
    for (const ConfigEntry& parameter : planner.parameters) {
      out << planner.type << "." << parameter.key << " = " << parameter.value << "\n";
    }
  }
}

}  // namespace

PlanarProblem readProblem(const std::string& cfgPath, std::vector<std::string>* warnings) {
  std::ifstream input = openInputFile(cfgPath);
  Sections sections = parseSections(input, cfgPath);
  if (!sections.count("problem")) throw InputError(cfgPath, "missing section [problem]");

  PlanarProblem problem;
  SectionReader problemSection(cfgPath, "problem", keysOf(sections["problem"], cfgPath, "problem", false), warnings);
  readProblemSection(problemSection, problem);
  problemSection.warnUnused();

  const std::vector<ConfigEntry>& benchmark = sections["benchmark"];
  SectionReader benchmarkSection(cfgPath, "benchmark", keysOf(benchmark, cfgPath, "benchmark", true), warnings);
  readBenchmarkSection(benchmarkSection, benchmark, problem);
  benchmarkSection.warnUnused();

  problem.planners = plannersOf(sections["planner"]);
  for (const auto& [name, entries] : sections) {
    if (name.empty() && warnings) {
      for (const ConfigEntry& entry : entries) {
        warnings->push_back(cfgPath + ": key '" + entry.key + "' outside any section ignored");
      }
    } else if (name != "problem" && name != "benchmark" && name != "planner" && warnings) {
      warnings->push_back(cfgPath + ": unknown section [" + name + "] ignored");
    }
  }
  if (problem.name.empty()) problem.name = fs::path(cfgPath).stem().string();
  return problem;
}

void writeProblem(const PlanarProblem& problem, const std::string& cfgPath, bool overwrite) {
  writeFile(cfgPath, overwrite, [&problem](std::ostream& out) {
    writeProblemSection(out, problem);
    writeBenchmarkAndPlanners(out, problem);
  });
}

}  // namespace freespace
