// Saving and loading a built free space (docs/design.md section 6). The file is a
// header line naming the format and its version, the payload's size and CRC-32, then
// the payload: a Boost binary archive of saved::Space. Algebraic angles are stored by
// their functions (double enclosures of the exact coefficients, and those
// coefficients as bytes, decoded when first needed), their isolating intervals and
// root indices, so that every predicate on the loaded structure decides as on the
// built one.

#include <zlib.h>

#include <algorithm>
#include <boost/archive/binary_iarchive_impl.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/archive/impl/archive_serializer_map.ipp>
#include <boost/archive/impl/basic_binary_iarchive.ipp>
#include <boost/archive/impl/basic_binary_iprimitive.ipp>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <new>
#include <sstream>

#include "free_space_impl.h"
#include "freespace/input_error.h"
#include "freespace/io/input_file.h"
#include "freespace/io/output_file.h"
#include "saved_space.h"

namespace freespace {

namespace {

/// A part of a saved payload that cannot be what it claims to be; the text names it.
class DamagedPart : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Boost's binary input archive (same format), except that the length of a text or
/// a list is checked against the bytes left in the payload before any memory is set
/// aside for it (every item takes at least a byte): a checksum can be valid for
/// altered data, and a damaged length would have the loader allocate and fill up to
/// the whole memory of the machine.
class CheckedBinaryIArchive
    : public boost::archive::binary_iarchive_impl<CheckedBinaryIArchive, char, std::char_traits<char>> {
  using Base = boost::archive::binary_iarchive_impl<CheckedBinaryIArchive, char, std::char_traits<char>>;
  friend class boost::archive::detail::interface_iarchive<CheckedBinaryIArchive>;
  friend class boost::archive::basic_binary_iarchive<CheckedBinaryIArchive>;
  friend class boost::archive::basic_binary_iprimitive<CheckedBinaryIArchive, char, std::char_traits<char>>;
  friend class boost::archive::load_access;

 public:
  explicit CheckedBinaryIArchive(std::istream& payload) : Base(payload, 0), payload_(payload) { init(0); }

  using Base::load;
  void load(std::string& text) {
    std::size_t length = 0;
    load(length);
    if (length > bytesLeft()) throw DamagedPart("a text longer than the rest of the file");
    text.resize(length);
    if (length > 0) load_binary(text.data(), length);
  }

  // A flag is a byte of 0 or 1: any other value read into a bool is undefined
  // behaviour (found by fuzzing).
  void load(bool& flag) {
    static_assert(sizeof(bool) == 1, "a saved flag is one byte");
    unsigned char byte = 0;
    load_binary(&byte, 1);
    if (byte > 1) throw DamagedPart("a flag that is neither true nor false");
    flag = byte == 1;
  }

  template <class T>
  void load_override(T& value) {
    Base::load_override(value);
  }
  void load_override(boost::serialization::collection_size_type& count) {
    Base::load_override(count);
    if (count > bytesLeft()) throw DamagedPart("a list longer than the rest of the file");
  }

 private:
  std::size_t bytesLeft() const {
    return static_cast<std::size_t>(std::max<std::streamsize>(payload_.rdbuf()->in_avail(), 0));
  }

  std::istream& payload_;
};

/// The payload read in place, without a copy (a large space's payload is hundreds of
/// megabytes).
class PayloadBuffer : public std::streambuf {
 public:
  explicit PayloadBuffer(const std::string& payload) {
    char* begin = const_cast<char*>(payload.data());  // only read
    setg(begin, begin, begin + payload.size());
  }
};

}  // namespace

}  // namespace freespace

// Vectors of numbers are read as one block, as Boost's binary archive writes them.
BOOST_SERIALIZATION_USE_ARRAY_OPTIMIZATION(freespace::CheckedBinaryIArchive)

template class boost::archive::basic_binary_iprimitive<freespace::CheckedBinaryIArchive, char, std::char_traits<char>>;
template class boost::archive::basic_binary_iarchive<freespace::CheckedBinaryIArchive>;
template class boost::archive::binary_iarchive_impl<freespace::CheckedBinaryIArchive, char, std::char_traits<char>>;
template class boost::archive::detail::archive_serializer_map<freespace::CheckedBinaryIArchive>;

namespace freespace {

namespace {

const std::string kHeader = "freespace saved free space, format ";
constexpr int kFormatVersion = 7;

// Rationals as bytes: a sign byte (0 or 1), then the numerator's magnitude and the
// denominator, each as a 4-byte length (least significant byte first) and its bytes
// (most significant first): read back in linear time, unlike decimal text.

void appendMagnitude(std::string& out, mpz_srcptr value) {
  std::string digits((mpz_sizeinbase(value, 2) + 7) / 8, '\0');
  std::size_t count = 0;
  mpz_export(digits.data(), &count, 1, 1, 1, 0, value);
  digits.resize(count);
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((count >> (8 * i)) & 0xff));
  out += digits;
}

std::string bytesOf(const Rational& value) {
  const mpq_srcptr q = value.backend().data();
  std::string out(1, static_cast<char>(mpq_sgn(q) < 0 ? 1 : 0));
  appendMagnitude(out, mpq_numref(q));
  appendMagnitude(out, mpq_denref(q));
  return out;
}

/// Where the magnitude at `at` ends: its bytes must be there, without a leading zero
/// byte (one writing only). `digits` is set to their count.
std::size_t magnitudeEnd(const std::string& bytes, std::size_t at, std::size_t& digits) {
  if (at > bytes.size() || bytes.size() - at < 4) throw DamagedPart("a number");
  digits = 0;
  for (int i = 0; i < 4; ++i) digits |= std::size_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  at += 4;
  if (bytes.size() - at < digits || (digits > 0 && bytes[at] == '\0')) throw DamagedPart("a number");
  return at + digits;
}

/// Where the rational written by bytesOf at `at` ends, checked as far as that can be
/// done without arithmetic: a sign byte, no negative zero, a nonzero denominator.
std::size_t rationalEnd(const std::string& bytes, std::size_t at) {
  if (at >= bytes.size() || static_cast<unsigned char>(bytes[at]) > 1) throw DamagedPart("a number");
  const bool negative = bytes[at] == 1;
  std::size_t numeratorDigits = 0, denominatorDigits = 0;
  const std::size_t end = magnitudeEnd(bytes, magnitudeEnd(bytes, at + 1, numeratorDigits), denominatorDigits);
  if (denominatorDigits == 0 || (negative && numeratorDigits == 0)) throw DamagedPart("a number");
  return end;
}

boost::multiprecision::mpz_int magnitudeAt(const std::string& bytes, std::size_t& at) {
  std::size_t digits = 0;
  const std::size_t end = magnitudeEnd(bytes, at, digits);
  boost::multiprecision::mpz_int value;
  if (digits > 0) mpz_import(value.backend().data(), digits, 1, 1, 1, 0, bytes.data() + end - digits);
  at = end;
  return value;
}

/// The rational written by bytesOf at `at` (moved past it): canonical (lowest terms,
/// positive denominator, no negative zero), checked before GMP takes it (it must never
/// see a zero denominator or an unreduced fraction).
Rational rationalAt(const std::string& bytes, std::size_t& at) {
  using boost::multiprecision::mpz_int;
  const std::size_t end = rationalEnd(bytes, at);
  const bool negative = bytes[at] == 1;
  ++at;
  const mpz_int numerator = magnitudeAt(bytes, at), denominator = magnitudeAt(bytes, at);
  if (at != end || gcd(numerator, denominator) != 1) throw DamagedPart("a number");
  return Rational(negative ? mpz_int(-numerator) : numerator, denominator);
}

/// A text holding exactly one rational.
Rational rationalOf(const std::string& bytes) {
  std::size_t at = 0;
  const Rational value = rationalAt(bytes, at);
  if (at != bytes.size()) throw DamagedPart("a number");
  return value;
}

double finite(double value) {
  if (!std::isfinite(value)) throw DamagedPart("a coordinate");
  return value;
}

/// A loaded function's exact coefficients, decoded when a predicate first needs them
/// (their bytes were checked for form at loading; lowest terms and the stored
/// enclosures are checked here).
class SavedPolynomials final : public AngleFunction::ExactSource {
 public:
  SavedPolynomials(std::shared_ptr<const std::string> file, std::string bytes, std::uint32_t chart0Coefficients)
      : file_(std::move(file)), bytes_(std::move(bytes)), chart0Coefficients_(chart0Coefficients) {}

  RationalPolynomial polynomial(int chart, const Polynomial<Interval>& enclosure) const override {
    std::vector<Rational> coefficients;
    try {
      std::size_t at = 0;
      if (chart == 1) {
        for (std::uint32_t i = 0; i < chart0Coefficients_; ++i) at = rationalEnd(bytes_, at);
      }
      for (const Interval& stored : enclosure.coefficients()) {
        coefficients.push_back(rationalAt(bytes_, at));
        const Interval exact = enclosingInterval(coefficients.back());
        if (exact.lower() < stored.lower() || exact.upper() > stored.upper()) throw DamagedPart("");
      }
    } catch (const DamagedPart&) {
      throw InputError(*file_, "inconsistent saved free space at a function's exact coefficients");
    }
    return RationalPolynomial(std::move(coefficients));
  }

 private:
  std::shared_ptr<const std::string> file_;
  std::string bytes_;
  std::uint32_t chart0Coefficients_;
};

/// Algebraic angles to and from the table of a saved space (`file`: the one read, for
/// the messages of the functions' exact coefficients decoded later).
class AngleTable {
 public:
  explicit AngleTable(saved::Space& space, std::shared_ptr<const std::string> file = {})
      : space_(space), file_(std::move(file)) {}

  /// Decodes every loaded function's exact coefficients now (LoadCheck::Everything).
  void decodeEveryFunction() const {
    for (const auto& function : loaded_) {
      if (function) function->exact(0), function->exact(1);
    }
  }

  /// Each distinct angle once: a root by its function, chart and place among the
  /// function's roots (copies of it may hold enclosures refined differently), a
  /// rational angle by its chart and t.
  std::uint32_t add(const AlgebraicAngle& angle) {
    const bool byValue = angle.isRational() || angle.index() < 0;
    const auto [found, inserted] =
        indexOfAngle_.try_emplace(AngleKey{angle.isRational() ? nullptr : angle.function().get(), angle.chart(),
                                           angle.index(), byValue ? angle.root().lo : Rational(0)},
                                  static_cast<std::uint32_t>(space_.angles.size()));
    if (!inserted) return found->second;
    const IsolatingInterval root = angle.root();  // exact, so only for angles not seen yet
    saved::Angle stored;
    stored.chart = angle.chart();
    stored.index = angle.index();
    stored.lower = angle.lower();
    stored.upper = angle.upper();
    const bool doubleEnds = root.lo == Rational(angle.lower()) && root.hi == Rational(angle.upper());
    if (!doubleEnds || (angle.isRational() && angle.lower() != angle.upper())) {
      stored.lo = bytesOf(root.lo);
      stored.hi = bytesOf(root.hi);
    }
    if (angle.function()) stored.function = static_cast<std::int32_t>(functionIndex(*angle.function()));
    space_.angles.push_back(stored);
    return found->second;
  }

  saved::AngleSet add(const AngleSet& set) {
    saved::AngleSet stored{set.fullCircle, {}};
    for (const AngleInterval& arc : set.arcs) {
      stored.arcs.push_back(add(arc.from));
      stored.arcs.push_back(add(arc.to));
      stored.arcs.push_back(arc.wraps ? 1 : 0);
    }
    return stored;
  }

  /// The angle at an index of the table, read once.
  AlgebraicAngle angle(std::uint32_t index) {
    if (read_.empty()) read_.resize(space_.angles.size());
    std::optional<AlgebraicAngle>& angle = read_.at(index);
    if (!angle) angle = readAngle(space_.angles[index]);
    return *angle;
  }

  AngleSet set(const saved::AngleSet& stored) {
    AngleSet set;
    set.fullCircle = stored.fullCircle;
    if (stored.arcs.size() % 3 != 0) throw DamagedPart("an angle set's arcs");
    for (std::size_t i = 0; i < stored.arcs.size(); i += 3) {
      set.arcs.push_back({angle(stored.arcs[i]), angle(stored.arcs[i + 1]), stored.arcs[i + 2] != 0});
    }
    return set;
  }

 private:
  std::size_t functionIndex(const AngleFunction& function) {
    const auto [found, inserted] = indexOf_.try_emplace(&function, space_.functions.size());
    if (inserted) {
      saved::Function stored;
      if (function.key()) stored.key.assign(function.key()->begin(), function.key()->end());
      stored.chart0Coefficients = static_cast<std::uint32_t>(function.exact(0).coefficients().size());
      for (int chart = 0; chart < 2; ++chart) {
        for (const Rational& c : function.exact(chart).coefficients()) {
          const Interval enclosure = enclosingInterval(c);
          stored.enclosures.insert(stored.enclosures.end(), {enclosure.lower(), enclosure.upper()});
          stored.exact += bytesOf(c);
        }
      }
      space_.functions.push_back(std::move(stored));
    }
    return found->second;
  }

  std::shared_ptr<const AngleFunction> function(std::size_t index) {
    if (loaded_.empty()) loaded_.resize(space_.functions.size());
    std::shared_ptr<const AngleFunction>& function = loaded_.at(index);
    if (!function) function = functionOf(space_.functions[index]);
    return function;
  }

  /// A stored function with its exact coefficients left undecoded (SavedPolynomials);
  /// their bytes are moved out of `stored`.
  std::shared_ptr<const AngleFunction> functionOf(saved::Function& stored) {
    const std::size_t coefficients = stored.enclosures.size() / 2;
    if (stored.enclosures.size() % 2 != 0 || stored.chart0Coefficients > coefficients) {
      throw DamagedPart("a function's coefficients");
    }
    std::array<std::vector<Interval>, 2> enclosures;
    for (std::size_t i = 0; i < coefficients; ++i) {
      const double lower = finite(stored.enclosures[2 * i]), upper = finite(stored.enclosures[2 * i + 1]);
      if (!(lower <= upper)) throw DamagedPart("a function's coefficients");
      enclosures[i < stored.chart0Coefficients ? 0 : 1].emplace_back(lower, upper);
    }
    std::size_t written = 0;
    for (std::size_t at = 0; at < stored.exact.size(); ++written) at = rationalEnd(stored.exact, at);
    if (written != coefficients) throw DamagedPart("a function's coefficients");
    std::optional<AngleFunction::RootKey> key;
    if (!stored.key.empty()) {
      if (stored.key.size() != 9) throw DamagedPart("a function's key");
      key.emplace();
      std::copy(stored.key.begin(), stored.key.end(), key->begin());
    }
    return std::make_shared<const AngleFunction>(
        std::array<Polynomial<Interval>, 2>{Polynomial<Interval>(std::move(enclosures[0])),
                                            Polynomial<Interval>(std::move(enclosures[1]))},
        key, std::make_unique<SavedPolynomials>(file_, std::move(stored.exact), stored.chart0Coefficients));
  }

  AlgebraicAngle readAngle(const saved::Angle& stored) {
    const bool doubles = stored.lo.empty() && stored.hi.empty();
    if ((stored.chart != 0 && stored.chart != 1) || stored.index < -1 || !(stored.lower <= stored.upper) ||
        (doubles && stored.function < 0 && (stored.lower != stored.upper || !(std::abs(stored.lower) <= 1)))) {
      throw DamagedPart("an angle");
    }
    if (doubles && stored.function < 0) return AlgebraicAngle::rational(stored.chart, stored.lower);
    if (doubles) {
      return AlgebraicAngle(function(static_cast<std::size_t>(stored.function)), stored.chart, stored.lower,
                            stored.upper, stored.index);
    }
    const IsolatingInterval root{rationalOf(stored.lo), rationalOf(stored.hi)};
    if (root.hi < root.lo) throw DamagedPart("an angle");
    if (stored.function < 0) {
      if (root.lo != root.hi) throw DamagedPart("a rational angle with an interval");
      return AlgebraicAngle::rational(stored.chart, root.lo);
    }
    return AlgebraicAngle(function(static_cast<std::size_t>(stored.function)), stored.chart, root, stored.index);
  }

  /// What identifies an angle of the table (see add).
  struct AngleKey {
    const AngleFunction* function;
    int chart;
    int index;
    Rational t;  // a rational angle's t, or the lower end of a root of unknown place
    bool operator<(const AngleKey& other) const {
      if (function != other.function) return std::less<>()(function, other.function);
      if (chart != other.chart) return chart < other.chart;
      if (index != other.index) return index < other.index;
      return t < other.t;
    }
  };

  saved::Space& space_;
  std::shared_ptr<const std::string> file_;
  std::map<const AngleFunction*, std::size_t> indexOf_;
  std::map<AngleKey, std::uint32_t> indexOfAngle_;
  std::vector<std::shared_ptr<const AngleFunction>> loaded_;
  std::vector<std::optional<AlgebraicAngle>> read_;
};

/// Frees a part of the decoded payload once it is read, so that the memory is used
/// again by what is built from the next parts (fresh pages cost the kernel's zeroing).
template <class T>
void release(std::vector<T>& part) {
  std::vector<T>().swap(part);
}

saved::Mesh savedMesh(const Mesh& mesh) {
  saved::Mesh stored;
  for (const Point3& p : mesh.vertices()) stored.vertices.insert(stored.vertices.end(), {p.x(), p.y(), p.z()});
  for (const TriangleIndices& t : mesh.triangles()) stored.triangles.insert(stored.triangles.end(), t.begin(), t.end());
  return stored;
}

Mesh meshOf(const saved::Mesh& stored, const std::string& path) {
  TriangleSoup soup;
  if (stored.vertices.size() % 3 != 0 || stored.triangles.size() % 3 != 0) throw DamagedPart("a mesh");
  for (std::size_t i = 0; i < stored.vertices.size(); i += 3) {
    soup.vertices.emplace_back(stored.vertices[i], stored.vertices[i + 1], stored.vertices[i + 2]);
  }
  for (std::size_t i = 0; i < stored.triangles.size(); i += 3) {
    soup.triangles.push_back({stored.triangles[i], stored.triangles[i + 1], stored.triangles[i + 2]});
  }
  try {
    Mesh mesh = Mesh::fromSoup(soup, path, nullptr, VertexWelding::asIndexed);
    if (mesh.vertices().size() * 3 != stored.vertices.size()) throw DamagedPart("a mesh's vertices");
    return mesh;
  } catch (const InputError& error) {
    throw DamagedPart("a mesh (" + error.problem() + ")");
  }
}

void pushPoint(std::vector<double>& out, const Point3& p) { out.insert(out.end(), {p.x(), p.y(), p.z()}); }
Point3 pointAt(const std::vector<double>& in, std::size_t i) {
  return {finite(in.at(3 * i)), finite(in.at(3 * i + 1)), finite(in.at(3 * i + 2))};
}

saved::Patch savedPatch(const PatchGeometry& patch, AngleTable& angles) {
  saved::Patch stored;
  const Contact& c = patch.patch.contact;
  stored.contact = {static_cast<std::int32_t>(c.kind), static_cast<std::int32_t>(c.robot),
                    static_cast<std::int32_t>(c.world), c.side};
  stored.range = angles.add(patch.patch.range);
  for (const SegmentEnd& end : patch.segment.ends) {
    stored.segment.insert(stored.segment.end(), {end.robotVertex ? 1u : 0u, end.vertex, end.edge[0], end.edge[1]});
  }
  stored.lineTags = {static_cast<std::int32_t>(patch.line.kind), patch.line.side};
  for (std::uint32_t v : patch.line.vertices) stored.lineTags.push_back(static_cast<std::int32_t>(v));
  for (const Point3& p : patch.line.points) pushPoint(stored.linePoints, p);
  for (const SpiralPoints& end : patch.ends) {
    stored.spiralRobotVertex.push_back(end.robotVertex ? 1 : 0);
    for (const Point3& p : end.points) pushPoint(stored.spiralPoints, p);
  }
  return stored;
}

PatchGeometry patchOf(const saved::Patch& stored, AngleTable& angles) {
  if (stored.contact.size() != 4 || stored.segment.size() != 8 || stored.lineTags.size() != 6 ||
      stored.linePoints.size() != 12 || stored.spiralRobotVertex.size() != 2 || stored.spiralPoints.size() != 18) {
    throw DamagedPart("a patch");
  }
  PatchGeometry patch;
  patch.patch.contact = {static_cast<ContactKind>(stored.contact[0]), static_cast<std::uint32_t>(stored.contact[1]),
                         static_cast<std::uint32_t>(stored.contact[2]), stored.contact[3]};
  patch.patch.range = angles.set(stored.range);
  for (int k = 0; k < 2; ++k) {
    patch.segment.ends[k] = {
        stored.segment[4 * k] != 0, stored.segment[4 * k + 1], {stored.segment[4 * k + 2], stored.segment[4 * k + 3]}};
  }
  patch.line.kind = static_cast<ContactKind>(stored.lineTags[0]);
  patch.line.side = stored.lineTags[1];
  for (int i = 0; i < 4; ++i) {
    patch.line.vertices[i] = static_cast<std::uint32_t>(stored.lineTags[2 + i]);
    patch.line.points[i] = pointAt(stored.linePoints, i);
  }
  cacheApproximateLine(patch.line);
  for (int k = 0; k < 2; ++k) {
    patch.ends[k].robotVertex = stored.spiralRobotVertex[k] != 0;
    for (int i = 0; i < 3; ++i) patch.ends[k].points[i] = pointAt(stored.spiralPoints, 3 * k + i);
  }
  return patch;
}

saved::Gluing savedGluing(const SubFaceGluing& gluing, AngleTable& angles) {
  saved::Gluing stored;
  for (const SubFaceGlue& glue : gluing.glues) {
    stored.glues.insert(stored.glues.end(), {glue.first.patch, glue.first.face, glue.second.patch, glue.second.face,
                                             static_cast<std::uint32_t>(glue.edge), angles.add(glue.at)});
  }
  for (const SubFaceId& face : gluing.unmatched)
    stored.unmatched.insert(stored.unmatched.end(), {face.patch, face.face});
  return stored;
}

SubFaceGluing gluingOf(const saved::Gluing& stored, AngleTable& angles) {
  if (stored.glues.size() % 6 != 0 || stored.unmatched.size() % 2 != 0) throw DamagedPart("a gluing");
  SubFaceGluing gluing;
  for (std::size_t i = 0; i < stored.glues.size(); i += 6) {
    if (stored.glues[i + 4] > static_cast<std::uint32_t>(GluedEdge::Horizontal)) throw DamagedPart("a glue");
    gluing.glues.push_back({{stored.glues[i], stored.glues[i + 1]},
                            {stored.glues[i + 2], stored.glues[i + 3]},
                            static_cast<GluedEdge>(stored.glues[i + 4]),
                            angles.angle(stored.glues[i + 5])});
  }
  for (std::size_t i = 0; i < stored.unmatched.size(); i += 2) {
    gluing.unmatched.push_back({stored.unmatched[i], stored.unmatched[i + 1]});
  }
  return gluing;
}

void appendRuns(std::vector<std::uint32_t>& out, const std::vector<CellGraph::NodeRun>& runs) {
  for (const CellGraph::NodeRun& run : runs) out.insert(out.end(), {run.interval, run.node});
}

saved::Graph savedGraph(const CellGraph::Parts& graph, AngleTable& angles) {
  saved::Graph stored;
  for (const AlgebraicAngle& angle : graph.criticalAngles) stored.criticalAngles.push_back(angles.add(angle));
  for (const CellGraphNode& node : graph.nodes) {
    stored.nodes.insert(stored.nodes.end(),
                        {node.cell, node.firstInterval, node.lastInterval, angles.add(node.sample)});
    stored.nodeGeometry.insert(stored.nodeGeometry.end(), {node.point[0], node.point[1]});
    stored.nodeGeometry.insert(stored.nodeGeometry.end(), node.box.begin(), node.box.end());
  }
  for (const CellGraphEdge& edge : graph.edges)
    stored.edges.insert(stored.edges.end(), {edge.from, edge.to, edge.angle});
  for (const auto& runs : graph.runsOfPiece) {
    stored.runCounts.push_back(static_cast<std::uint32_t>(runs.size()));
    appendRuns(stored.runs, runs);
  }
  appendRuns(stored.unboundedRuns, graph.unboundedRuns);
  return stored;
}

/// Pairs (interval, node) from `at` on (moved past them).
std::vector<CellGraph::NodeRun> runsAt(const std::vector<std::uint32_t>& stored, std::size_t& at, std::size_t count) {
  if (count > (stored.size() - at) / 2) throw DamagedPart("the graph's runs");
  std::vector<CellGraph::NodeRun> runs;
  for (std::size_t i = 0; i < count; ++i, at += 2) runs.push_back({stored[at], stored[at + 1]});
  return runs;
}

CellGraph::Parts graphOf(const saved::Graph& stored, AngleTable& angles) {
  CellGraph::Parts graph;
  for (std::uint32_t angle : stored.criticalAngles) graph.criticalAngles.push_back(angles.angle(angle));
  const std::size_t nodes = stored.nodes.size() / 4;
  if (stored.nodes.size() != 4 * nodes || stored.nodeGeometry.size() != 6 * nodes)
    throw DamagedPart("the graph's nodes");
  for (std::size_t i = 0; i < nodes; ++i) {
    CellGraphNode node;
    node.cell = stored.nodes[4 * i];
    node.firstInterval = stored.nodes[4 * i + 1];
    node.lastInterval = stored.nodes[4 * i + 2];
    node.sample = angles.angle(stored.nodes[4 * i + 3]);
    node.point = {finite(stored.nodeGeometry[6 * i]), finite(stored.nodeGeometry[6 * i + 1])};
    std::copy_n(stored.nodeGeometry.begin() + 6 * i + 2, 4, node.box.begin());
    graph.nodes.push_back(node);
  }
  if (stored.edges.size() % 3 != 0) throw DamagedPart("the graph's edges");
  for (std::size_t i = 0; i < stored.edges.size(); i += 3) {
    graph.edges.push_back({stored.edges[i], stored.edges[i + 1], stored.edges[i + 2]});
  }
  std::size_t at = 0;
  for (std::uint32_t count : stored.runCounts) graph.runsOfPiece.push_back(runsAt(stored.runs, at, count));
  if (at != stored.runs.size()) throw DamagedPart("the graph's runs");
  at = 0;
  graph.unboundedRuns = runsAt(stored.unboundedRuns, at, stored.unboundedRuns.size() / 2);
  if (at != stored.unboundedRuns.size()) throw DamagedPart("the graph's runs");
  return graph;
}

saved::Space savedSpace(const PerturbedMeshes& meshes, const Arrangement& arrangement,
                        const std::vector<ShellSide>& sides, const FreeCells& cells, const CellGraph& graph,
                        const std::vector<StageTime>& stageTimes) {
  saved::Space space;
  AngleTable angles(space);
  space.robot = savedMesh(meshes.robot);
  space.world = savedMesh(meshes.world);
  space.perturbed = meshes.record.enabled;
  space.seed = meshes.record.seed;
  space.relativeSize = meshes.record.relativeSize;
  space.absoluteSize = meshes.record.absoluteSize;
  space.scale = meshes.scale;
  for (const PatchGeometry& patch : arrangement.patches) space.patches.push_back(savedPatch(patch, angles));
  for (const PatchCurve& curve : arrangement.curves) {
    saved::Curve stored{curve.first, curve.second, angles.add(curve.angles), {}};
    for (const auto& ends : curve.ends) {
      for (const CurveEnd& end : ends) {
        stored.ends.insert(stored.ends.end(),
                           {end.endOnOtherLine[0][0], end.endOnOtherLine[0][1], end.endOnOtherLine[1][0],
                            end.endOnOtherLine[1][1], end.rangeEnd[0], end.rangeEnd[1]});
      }
    }
    space.curves.push_back(std::move(stored));
  }
  for (const PatchOverlap& overlap : arrangement.overlaps) {
    space.overlaps.push_back(
        {{overlap.patches[0], overlap.patches[1]},
         angles.add(overlap.angle),
         {overlap.reachesEnd[0][0], overlap.reachesEnd[0][1], overlap.reachesEnd[1][0], overlap.reachesEnd[1][1]}});
  }
  for (const PatchVertex& vertex : arrangement.vertices) {
    space.vertices.push_back(
        {{vertex.patches.begin(), vertex.patches.end()}, angles.add(vertex.angle), vertex.crossing});
  }
  for (const PatchSubdivision& subdivision : arrangement.subdivisions) {
    saved::Subdivision stored{{}, subdivision.faceCount};
    for (const PatchSlab& slab : subdivision.slabs) {
      stored.slabs.push_back(
          {angles.add(slab.from), angles.add(slab.to), angles.add(slab.sample), slab.curves, slab.faces});
    }
    space.subdivisions.push_back(std::move(stored));
  }
  for (const SubFaceGluing* gluing :
       {&arrangement.acrossCurves, &arrangement.aroundSpirals, &arrangement.acrossHorizontalEdges}) {
    space.gluings.push_back(savedGluing(*gluing, angles));
  }
  for (std::uint32_t shell = 0; shell < sides.size(); ++shell) {
    space.shellSides.push_back(static_cast<std::uint8_t>(sides[shell]));
    const std::optional<std::uint32_t> cell = cells.cellOfShell(shell);
    space.cellOfShell.push_back(cell ? static_cast<std::int32_t>(*cell) : -1);
  }
  space.cellCount = static_cast<std::uint32_t>(cells.count());
  for (const StageTime& stage : stageTimes) {
    space.stageNames.push_back(stage.stage);
    space.stageSeconds.push_back(stage.seconds);
  }
  space.graph = savedGraph(graph.parts(), angles);
  return space;
}

/// The header's integers are little-endian whatever the machine (the payload is a
/// Boost binary archive: files are for machines of one architecture).
void writeLittleEndian(std::ostream& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.put(static_cast<char>((value >> (8 * i)) & 0xff));
}

std::optional<std::uint64_t> readLittleEndian(std::istream& in, int bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) {
    const int byte = in.get();
    if (byte == std::char_traits<char>::eof()) return std::nullopt;
    value |= static_cast<std::uint64_t>(byte) << (8 * i);
  }
  return value;
}

/// The payload's CRC-32 (zlib's, several times faster than Boost's on the hundreds
/// of megabytes of a large space; the same checksum), in pieces that fit its length type.
std::uint32_t checksum(const std::string& payload) {
  constexpr std::size_t kPiece = std::size_t(1) << 30;
  uLong crc = crc32(0L, Z_NULL, 0);
  for (std::size_t at = 0; at < payload.size(); at += kPiece) {
    const std::size_t length = std::min(kPiece, payload.size() - at);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(payload.data() + at), static_cast<uInt>(length));
  }
  return static_cast<std::uint32_t>(crc);
}

/// The payload of a saved free space file, checked against its header.
std::string readPayload(const std::string& path) {
  std::ifstream in = openInputFile(path, std::ios::binary);
  std::string header;
  std::getline(in, header);
  if (header.rfind(kHeader, 0) != 0) throw InputError(path, "not a saved free space (no '" + kHeader + "' header)");
  const std::string version = header.substr(kHeader.size());
  if (version != std::to_string(kFormatVersion)) {
    throw InputError(
        path, "saved free space of format " + version + "; this build reads format " + std::to_string(kFormatVersion));
  }
  const std::optional<std::uint64_t> size = readLittleEndian(in, 8);
  const std::optional<std::uint64_t> crc = readLittleEndian(in, 4);
  if (!size || !crc) throw InputError(path, "damaged: truncated header");
  const std::streamoff start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  in.seekg(start);
  if (start < 0 || end < start || static_cast<std::uint64_t>(end - start) != *size) {
    throw InputError(path, "damaged: wrong length");
  }
  std::string payload(*size, '\0');
  in.read(payload.data(), static_cast<std::streamsize>(*size));
  if (!in) throw InputError(path, "damaged: wrong length");
  if (checksum(payload) != *crc) throw InputError(path, "damaged: checksum mismatch");
  return payload;
}

/// Indices that must be in range for the structure to be used safely.
void checkConsistency(const Arrangement& arrangement, const std::vector<ShellSide>& sides,
                      const std::vector<std::optional<std::uint32_t>>& cellOfShell, std::size_t cellCount) {
  const std::size_t patches = arrangement.patches.size();
  if (arrangement.subdivisions.size() != patches) throw DamagedPart("subdivisions");
  for (const PatchCurve& curve : arrangement.curves) {
    if (curve.first >= patches || curve.second >= patches) throw DamagedPart("a curve's patches");
  }
  for (const PatchOverlap& overlap : arrangement.overlaps) {
    for (std::uint32_t patch : overlap.patches) {
      if (patch >= patches) throw DamagedPart("an overlap's patches");
    }
  }
  for (const PatchVertex& vertex : arrangement.vertices) {
    for (std::uint32_t patch : vertex.patches) {
      if (patch >= patches) throw DamagedPart("a vertex's patches");
    }
  }
  for (std::uint32_t patch = 0; patch < patches; ++patch) {
    const PatchSubdivision& subdivision = arrangement.subdivisions[patch];
    // Every sub-face lies in a slab: a larger count would have the shells set aside
    // memory for sub-faces that are not there (found by fuzzing).
    std::size_t slabFaces = 0;
    for (const PatchSlab& slab : subdivision.slabs) slabFaces += slab.faces.size();
    if (subdivision.faceCount > slabFaces) throw DamagedPart("a subdivision's face count");
    for (const PatchSlab& slab : subdivision.slabs) {
      if (slab.faces.size() != slab.curves.size() + 1) throw DamagedPart("a slab's faces");
      for (std::uint32_t curve : slab.curves) {
        if (curve >= arrangement.curves.size()) throw DamagedPart("a slab's curves");
        const PatchCurve& c = arrangement.curves[curve];
        if (c.first != patch && c.second != patch) throw DamagedPart("a slab's curve of other patches");
      }
      for (std::uint32_t face : slab.faces) {
        if (face >= subdivision.faceCount) throw DamagedPart("a slab's faces");
      }
    }
  }
  const auto checkFace = [&](SubFaceId face) {
    if (face.patch >= patches || face.face >= arrangement.subdivisions[face.patch].faceCount) {
      throw DamagedPart("a glued sub-face");
    }
  };
  for (const SubFaceGluing* gluing :
       {&arrangement.acrossCurves, &arrangement.aroundSpirals, &arrangement.acrossHorizontalEdges}) {
    for (const SubFaceGlue& glue : gluing->glues) checkFace(glue.first), checkFace(glue.second);
    for (const SubFaceId& face : gluing->unmatched) checkFace(face);
  }
  if (sides.size() != cellOfShell.size()) throw DamagedPart("shells");
  for (std::size_t shell = 0; shell < sides.size(); ++shell) {
    const auto& cell = cellOfShell[shell];
    if (cell.has_value() != (sides[shell] == ShellSide::Free) || (cell && *cell >= cellCount)) {
      throw DamagedPart("a shell's cell");
    }
  }
}

}  // namespace

void FreeSpace::save(const std::string& path, bool overwrite) const {
  const saved::Space space =
      savedSpace(impl_->meshes, impl_->arrangement, impl_->sides, *impl_->cells, cellGraph(), impl_->stageTimes);
  std::ostringstream payloadStream;
  {
    boost::archive::binary_oarchive archive(payloadStream);
    archive << space;
  }
  const std::string payload = payloadStream.str();
  const std::uint64_t size = payload.size();
  const std::uint32_t crc = checksum(payload);
  writeFile(path, overwrite, [&](std::ostream& out) {
    out << kHeader << kFormatVersion << '\n';
    writeLittleEndian(out, size, 8);
    writeLittleEndian(out, crc, 4);
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
  });
}

std::unique_ptr<FreeSpace> FreeSpace::load(const std::string& path, LoadCheck check) {
  saved::Space space;
  try {
    const std::string payload = readPayload(path);  // freed once decoded
    PayloadBuffer buffer(payload);
    std::istream payloadStream(&buffer);
    CheckedBinaryIArchive archive(payloadStream);
    archive >> space;
  } catch (const InputError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const DamagedPart& part) {
    throw InputError(path, std::string("damaged: ") + part.what());
  } catch (const std::exception&) {
    // The archive's and the standard library's own texts would mean nothing to a user.
    throw InputError(path, "damaged: the payload ends early or does not decode");
  }
  auto impl = std::make_unique<Impl>();
  try {
    AngleTable angles(space, std::make_shared<const std::string>(path));
    impl->meshes.robot = meshOf(space.robot, path);
    impl->meshes.world = meshOf(space.world, path);
    impl->meshes.record = {space.perturbed, space.seed, space.relativeSize, space.absoluteSize};
    int exponent = 0;
    if (std::frexp(space.scale, &exponent) != 0.5) throw DamagedPart("the coordinates' scale (not a power of two)");
    impl->meshes.scale = space.scale;
    Arrangement& arrangement = impl->arrangement;
    for (const saved::Patch& patch : space.patches) arrangement.patches.push_back(patchOf(patch, angles));
    release(space.patches);
    arrangement.boxIndex = std::make_shared<const PatchBoxIndex>(arrangement.patches);
    for (const saved::Curve& stored : space.curves) {
      PatchCurve curve{stored.first, stored.second, angles.set(stored.angles), {}};
      if (stored.ends.size() != 12 * curve.angles.arcs.size()) throw DamagedPart("a curve's ends");
      for (std::size_t arc = 0; arc < curve.angles.arcs.size(); ++arc) {
        std::array<CurveEnd, 2> ends{};
        for (int e = 0; e < 2; ++e) {
          const std::uint8_t* flags = &stored.ends[12 * arc + 6 * e];
          ends[e].endOnOtherLine = {{{flags[0] != 0, flags[1] != 0}, {flags[2] != 0, flags[3] != 0}}};
          ends[e].rangeEnd = {flags[4] != 0, flags[5] != 0};
        }
        curve.ends.push_back(ends);
      }
      arrangement.curves.push_back(std::move(curve));
    }
    release(space.curves);
    for (const saved::Overlap& stored : space.overlaps) {
      if (stored.patches.size() != 2 || stored.reachesEnd.size() != 4) throw DamagedPart("an overlap");
      arrangement.overlaps.push_back({{stored.patches[0], stored.patches[1]},
                                      angles.angle(stored.angle),
                                      {{{stored.reachesEnd[0] != 0, stored.reachesEnd[1] != 0},
                                        {stored.reachesEnd[2] != 0, stored.reachesEnd[3] != 0}}}});
    }
    for (const saved::Vertex& stored : space.vertices) {
      if (stored.patches.size() != 3) throw DamagedPart("a vertex");
      arrangement.vertices.push_back(
          {{stored.patches[0], stored.patches[1], stored.patches[2]}, angles.angle(stored.angle), stored.crossing});
    }
    for (const saved::Subdivision& stored : space.subdivisions) {
      PatchSubdivision subdivision;
      subdivision.faceCount = stored.faceCount;
      for (const saved::Slab& slab : stored.slabs) {
        subdivision.slabs.push_back(
            {angles.angle(slab.from), angles.angle(slab.to), angles.angle(slab.sample), slab.curves, slab.faces});
      }
      arrangement.subdivisions.push_back(std::move(subdivision));
    }
    release(space.subdivisions);
    if (space.gluings.size() != 3) throw DamagedPart("gluings");
    arrangement.acrossCurves = gluingOf(space.gluings[0], angles);
    arrangement.aroundSpirals = gluingOf(space.gluings[1], angles);
    arrangement.acrossHorizontalEdges = gluingOf(space.gluings[2], angles);
    std::vector<std::optional<std::uint32_t>> cellOfShell;
    for (std::size_t shell = 0; shell < space.shellSides.size(); ++shell) {
      if (space.shellSides[shell] > static_cast<std::uint8_t>(ShellSide::Open)) throw DamagedPart("a shell");
      impl->sides.push_back(static_cast<ShellSide>(space.shellSides[shell]));
      const std::int32_t cell = space.cellOfShell.at(shell);
      cellOfShell.push_back(cell < 0 ? std::nullopt : std::optional<std::uint32_t>(static_cast<std::uint32_t>(cell)));
    }
    checkConsistency(arrangement, impl->sides, cellOfShell, space.cellCount);
    arrangement.shells = Shells(arrangement.subdivisions, {&arrangement.acrossCurves, &arrangement.aroundSpirals,
                                                           &arrangement.acrossHorizontalEdges});
    if (arrangement.shells.count() != impl->sides.size()) throw DamagedPart("the shells' count");
    impl->cells = std::make_unique<FreeCells>(std::move(cellOfShell), space.cellCount);
    for (std::size_t i = 0; i < space.stageNames.size() && i < space.stageSeconds.size(); ++i) {
      impl->stageTimes.push_back({space.stageNames[i], space.stageSeconds[i]});
    }
    impl->finish();
    try {
      impl->graph =
          std::make_unique<CellGraph>(arrangement, graphOf(space.graph, angles), space.cellCount, impl->algebra);
    } catch (const std::invalid_argument& part) {
      throw DamagedPart(part.what());
    }
    if (check == LoadCheck::Everything) angles.decodeEveryFunction();
  } catch (const InputError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const DamagedPart& part) {
    throw InputError(path, std::string("inconsistent saved free space at ") + part.what());
  } catch (const std::exception&) {
    throw InputError(path, "inconsistent saved free space: its parts do not fit together");
  }
  return std::unique_ptr<FreeSpace>(new FreeSpace(std::move(impl)));
}

}  // namespace freespace
