#pragma once

// What the files that build the named scenes share.

#include <cstdint>
#include <string>

#include "freespace/scenes/scene_generator.h"

namespace freespace::detail {

inline constexpr double kPi = 3.14159265358979323846;

/// A scene of the robot and the world (checked as a mesh named "<name>_world"), with
/// its problem: start, goal, and the planning volume around the world and the
/// robot's reach at the start and the goal.
Scene assembleScene(const std::string& name, Mesh robot, const TriangleSoup& world, const Pose2& start,
                    const Pose2& goal, bool solvable, const std::string& description);

/// The soup scenes (soup_scenes.cpp); makeSoupMazeScene builds the family.
Scene soupMazeScene(const std::string& name, unsigned rooms, std::uint64_t seed);
Scene soupPiecesScene();
Scene soupOpenSheetScene();
Scene soupCrackScene();

}  // namespace freespace::detail
