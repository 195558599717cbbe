// Loads a robot and an environment and asks whether a configuration is free.
// Usage: consumer ROBOT WORLD X Y THETA   (prints "free" or "collision")
#include <cstdlib>
#include <iostream>

#include <freespace/freespace.h>

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: consumer ROBOT WORLD X Y THETA\n";
    return 1;
  }
  try {
    const freespace::Mesh robot = freespace::loadMesh(argv[1]);
    const freespace::Mesh world = freespace::loadMesh(argv[2]);
    const freespace::ExactCollisionChecker checker(robot, world);
    const freespace::Pose2 pose{std::atof(argv[3]), std::atof(argv[4]), std::atof(argv[5])};
    std::cout << (checker.inCollision(pose) ? "collision" : "free") << "\n";
  } catch (const freespace::InputError& error) {
    std::cerr << error.what() << "\n";
    return 2;
  }
  return 0;
}
