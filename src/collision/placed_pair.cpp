#include "placed_pair.h"

namespace freespace::detail {

namespace {

Box3 boxOf(const Vec3T<Interval>& p) {
  return Box3(Point3(p.x.lower(), p.y.lower(), p.z.lower()), Point3(p.x.upper(), p.y.upper(), p.z.upper()));
}

}  // namespace

PlacedPair::PlacedPair(const Mesh& robot, const Mesh& world, const HalfAngle& angle, double x, double y)
    : robot_(robot), world_(world), angle_(angle), x_(x), y_(y) {
  Interval cosine, sine;
  angle_.cosSin(cosine, sine);
  const Interval placedX(x_), placedY(y_);
  placedRobot_.reserve(robot.vertices().size());
  for (const Point3& p : robot.vertices()) {
    const Interval px(p.x()), py(p.y());
    placedRobot_.push_back({cosine * px - sine * py + placedX, sine * px + cosine * py + placedY, Interval(p.z())});
    robotBounds_.extend(boxOf(placedRobot_.back()));
  }
  exactRobot_.resize(robot.vertices().size());
}

Vec3T<Interval> PlacedPair::approximate(PointId id) const {
  if (id & kRobotPoint) return placedRobot_[id & ~kRobotPoint];
  const Point3& p = world_.vertices()[id];
  return {Interval(p.x()), Interval(p.y()), Interval(p.z())};
}

const Vec3T<Rational>& PlacedPair::exact(PointId id) {
  if (!(id & kRobotPoint)) {
    if (exactWorld_.empty()) exactWorld_.resize(world_.vertices().size());
    std::optional<Vec3T<Rational>>& cached = exactWorld_[id];
    if (!cached) {
      const Point3& p = world_.vertices()[id];
      cached = Vec3T<Rational>{Rational(p.x()), Rational(p.y()), Rational(p.z())};
    }
    return *cached;
  }
  std::optional<Vec3T<Rational>>& cached = exactRobot_[id & ~kRobotPoint];
  if (!cached) {
    if (!exactCosSin_) {
      Rational cosine, sine;
      angle_.cosSin(cosine, sine);
      exactCosSin_ = Vec3T<Rational>{cosine, sine, Rational(0)};
    }
    const Rational& cosine = exactCosSin_->x;
    const Rational& sine = exactCosSin_->y;
    const Point3& p = robot_.vertices()[id & ~kRobotPoint];
    const Rational px(p.x()), py(p.y());
    cached = Vec3T<Rational>{cosine * px - sine * py + Rational(x_), sine * px + cosine * py + Rational(y_),
                             Rational(p.z())};
  }
  return *cached;
}

Box3 PlacedPair::bounds(PointId id) const { return boxOf(approximate(id)); }

Box3 PlacedPair::robotTriangleBounds(std::uint32_t triangle) const {
  Box3 box;
  for (std::uint32_t vertex : robot_.triangles()[triangle]) box.extend(boxOf(placedRobot_[vertex]));
  return box;
}

}  // namespace freespace::detail
