#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "configuration_query.h"

namespace freespace::cli {

namespace {

std::string kindName(ContactKind kind) {
  switch (kind) {
    case ContactKind::VertexFacet:
      return "vertex-facet";
    case ContactKind::FacetVertex:
      return "facet-vertex";
    default:
      return "edge-edge";
  }
}

/// The witness in words: which features touch, as vertex numbers of the two meshes.
std::string witnessText(const Clearance& clearance) {
  const auto& v = clearance.contactVertices;
  const auto list = [](std::initializer_list<std::uint32_t> vertices) {
    std::string text;
    for (std::uint32_t vertex : vertices) text += (text.empty() ? "" : " ") + std::to_string(vertex);
    return text;
  };
  switch (clearance.contact->kind) {
    case ContactKind::VertexFacet:
      return "robot vertex " + list({v[0]}) + " on environment triangle " + list({v[1], v[2], v[3]});
    case ContactKind::FacetVertex:
      return "environment vertex " + list({v[0]}) + " on robot triangle " + list({v[1], v[2], v[3]});
    default:
      return "robot edge " + list({v[0], v[1]}) + " on environment edge " + list({v[2], v[3]});
  }
}

nlohmann::json clearanceJson(const Pose2& pose, const Clearance& clearance) {
  // JSON has no infinity: an unbounded clearance is null.
  nlohmann::json answer = {{"x", pose.x},
                           {"y", pose.y},
                           {"theta", pose.theta},
                           {"free", clearance.location.free},
                           {"clearance", 0.5 * clearance.lower + 0.5 * clearance.upper},
                           {"clearance_lower", clearance.lower},
                           {"clearance_upper", clearance.upper}};
  if (clearance.location.free) answer["cell"] = clearance.location.cell;
  if (clearance.contact) {
    answer["contact"] = {{"kind", kindName(clearance.contact->kind)},
                         {"vertices", clearance.contactVertices},
                         {"direction", clearance.direction},
                         {"nearest", clearance.nearest}};
  }
  return answer;
}

void printClearance(const Pose2& pose, const Clearance& clearance) {
  std::cout << pose.x << " " << pose.y << " " << pose.theta << ": "
            << (clearance.location.free ? "free, cell " + std::to_string(clearance.location.cell)
                                        : std::string("blocked"))
            << ", clearance " << 0.5 * clearance.lower + 0.5 * clearance.upper << " (certified in [" << clearance.lower
            << ", " << clearance.upper << "])";
  if (clearance.contact) {
    std::cout << ", " << witnessText(clearance) << ", reached along (" << clearance.direction[0] << ", "
              << clearance.direction[1] << ") at (" << clearance.nearest[0] << ", " << clearance.nearest[1] << ")";
  }
  std::cout << "\n";
}

}  // namespace

void addClearanceCommand(CLI::App& app) {
  addConfigurationQuery(app, "clearance",
                        "Clearance of configurations: how far the robot can slide horizontally before touching "
                        "(negative: how far it must slide to get free), certified, with the contact that limits it",
                        [](const FreeSpace& space, const Pose2& pose, bool json) {
                          const Clearance clearance = space.clearance(pose);
                          if (json) {
                            std::cout << clearanceJson(pose, clearance).dump() << "\n";
                          } else {
                            printClearance(pose, clearance);
                          }
                        });
}

}  // namespace freespace::cli
