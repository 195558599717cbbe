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
  place(cosine, sine, Interval(x), Interval(y));
}

PlacedPair::PlacedPair(const Mesh& robot, const Mesh& world, const ExactPose& pose)
    : robot_(robot), world_(world), exactPose_(pose) {
  place(enclosingInterval(pose.cosine), enclosingInterval(pose.sine), enclosingInterval(pose.x), enclosingInterval(pose.y));
}

void PlacedPair::place(const Interval& cosine, const Interval& sine, const Interval& x, const Interval& y) {
  placedRobot_.reserve(robot_.vertices().size());
  for (const Point3& p : robot_.vertices()) {
    const Interval px(p.x()), py(p.y());
    placedRobot_.push_back({cosine * px - sine * py + x, sine * px + cosine * py + y, Interval(p.z())});
    robotBounds_.extend(boxOf(placedRobot_.back()));
  }
  exactRobot_.resize(robot_.vertices().size());
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
    if (!exactPose_) {
      Rational cosine, sine;
      angle_.cosSin(cosine, sine);
      exactPose_ = ExactPose{cosine, sine, Rational(x_), Rational(y_)};
    }
    const ExactPose& pose = *exactPose_;
    const Point3& p = robot_.vertices()[id & ~kRobotPoint];
    const Rational px(p.x()), py(p.y());
    cached = Vec3T<Rational>{pose.cosine * px - pose.sine * py + pose.x, pose.sine * px + pose.cosine * py + pose.y,
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
