// Saving and loading a built free space (docs/design.md section 6). The file is a
// header line naming the format and its version, the payload (a Boost binary archive
// of saved::Space), then the payload's size and checksum (XXH3, 64 bits): written
// after it, so that the payload goes to the file as it is made. Algebraic angles are stored by
// their functions (double enclosures of the exact coefficients, and those
// coefficients as bytes, decoded when first needed), their isolating intervals and
// root indices, so that every predicate on the loaded structure decides as on the
// built one.

#include <xxhash.h>

#include <algorithm>
#include <array>
#include <boost/archive/binary_iarchive_impl.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/archive/impl/archive_serializer_map.ipp>
#include <boost/archive/impl/basic_binary_iarchive.ipp>
#include <boost/archive/impl/basic_binary_iprimitive.ipp>
#include <cmath>
#include <memory>
#include <new>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <unordered_map>

#include "every_core.h"
#include "free_space_impl.h"
#include "freespace/input_error.h"
#include "freespace/io/output_file.h"
#include "../io/mapped_input_file.h"
#include "saved_space.h"

namespace freespace {

namespace {

/// A part of a saved payload that cannot be what it claims to be; the text names it.
class DamagedPart : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Boost's binary input archive (same format), except that the length of a text or
/// a list of numbers is checked against the bytes left in the payload before any
/// memory is set aside for it (the bytes it claims must be there): a checksum can be
/// valid for altered data, and a damaged length would have the loader allocate and
/// fill up to the whole memory of the machine.
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
  /// A list of numbers (every list of a saved space), read as Boost's serialization
  /// of a vector reads it (its length, an item version in archives of library
  /// versions 4 and 5, then the numbers as one block), its bytes checked before the
  /// list is made.
  template <class T, std::enable_if_t<std::is_arithmetic_v<T> && !std::is_same_v<T, bool>, int> = 0>
  void load_override(std::vector<T>& list) {
    boost::serialization::collection_size_type count;
    Base::load_override(count);
    if (count > bytesLeft() / sizeof(T)) throw DamagedPart("a list longer than the rest of the file");
    if (BOOST_SERIALIZATION_VECTOR_VERSIONED(get_library_version())) {
      unsigned int itemVersion = 0;
      load(itemVersion);
    }
    list.resize(count);
    if (count > 0) load_binary(list.data(), count * sizeof(T));
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
  explicit PayloadBuffer(std::string_view payload) {
    char* begin = const_cast<char*>(payload.data());  // only read
    setg(begin, begin, begin + payload.size());
  }
};

}  // namespace

}  // namespace freespace

template class boost::archive::basic_binary_iprimitive<freespace::CheckedBinaryIArchive, char, std::char_traits<char>>;
template class boost::archive::basic_binary_iarchive<freespace::CheckedBinaryIArchive>;
template class boost::archive::binary_iarchive_impl<freespace::CheckedBinaryIArchive, char, std::char_traits<char>>;
template class boost::archive::detail::archive_serializer_map<freespace::CheckedBinaryIArchive>;

namespace freespace {

namespace {

const std::string kHeader = "freespace saved free space, format ";
constexpr int kFormatVersion = 9;

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
std::size_t magnitudeEnd(std::string_view bytes, std::size_t at, std::size_t& digits) {
  if (at > bytes.size() || bytes.size() - at < 4) throw DamagedPart("a number");
  digits = 0;
  for (int i = 0; i < 4; ++i) digits |= std::size_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  at += 4;
  if (bytes.size() - at < digits || (digits > 0 && bytes[at] == '\0')) throw DamagedPart("a number");
  return at + digits;
}

/// Where the rational written by bytesOf at `at` ends, checked as far as that can be
/// done without arithmetic: a sign byte, no negative zero, a nonzero denominator.
std::size_t rationalEnd(std::string_view bytes, std::size_t at) {
  if (at >= bytes.size() || static_cast<unsigned char>(bytes[at]) > 1) throw DamagedPart("a number");
  const bool negative = bytes[at] == 1;
  std::size_t numeratorDigits = 0, denominatorDigits = 0;
  const std::size_t end = magnitudeEnd(bytes, magnitudeEnd(bytes, at + 1, numeratorDigits), denominatorDigits);
  if (denominatorDigits == 0 || (negative && numeratorDigits == 0)) throw DamagedPart("a number");
  return end;
}

boost::multiprecision::mpz_int magnitudeAt(std::string_view bytes, std::size_t& at) {
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
Rational rationalAt(std::string_view bytes, std::size_t& at) {
  using boost::multiprecision::mpz_int;
  const std::size_t end = rationalEnd(bytes, at);
  const bool negative = bytes[at] == 1;
  ++at;
  const mpz_int numerator = magnitudeAt(bytes, at), denominator = magnitudeAt(bytes, at);
  if (at != end || gcd(numerator, denominator) != 1) throw DamagedPart("a number");
  return Rational(negative ? mpz_int(-numerator) : numerator, denominator);
}

double finite(double value) {
  if (!std::isfinite(value)) throw DamagedPart("a coordinate");
  return value;
}

/// A loaded function's exact coefficients, decoded when a predicate first needs them
/// from its bytes in the loaded space's `exact` (their form was checked at loading;
/// lowest terms and the stored enclosures are checked here).
class SavedPolynomials final : public AngleFunction::ExactSource {
 public:
  SavedPolynomials(std::shared_ptr<const std::string> file, std::shared_ptr<const std::string> exact, std::size_t begin,
                   std::size_t end, std::uint32_t chart0Coefficients)
      : file_(std::move(file)),
        exact_(std::move(exact)),
        begin_(begin),
        end_(end),
        chart0Coefficients_(chart0Coefficients) {}

  RationalPolynomial polynomial(int chart, const Polynomial<Interval>& enclosure) const override {
    const std::string_view bytes = std::string_view(*exact_).substr(begin_, end_ - begin_);
    std::vector<Rational> coefficients;
    try {
      std::size_t at = 0;
      if (chart == 1) {
        for (std::uint32_t i = 0; i < chart0Coefficients_; ++i) at = rationalEnd(bytes, at);
      }
      for (const Interval& stored : enclosure.coefficients()) {
        coefficients.push_back(rationalAt(bytes, at));
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
  std::shared_ptr<const std::string> exact_;
  std::size_t begin_, end_;
  std::uint32_t chart0Coefficients_;
};

/// The sum of `counts`, or `limit + 1` once it passes `limit` (a damaged count must
/// not wrap the sum around to a size that fits).
std::uint64_t sumUpTo(const std::vector<std::uint32_t>& counts, std::uint64_t limit) {
  std::uint64_t sum = 0;
  for (std::uint32_t count : counts) {
    sum += count;
    if (sum > limit) return limit + 1;
  }
  return sum;
}

/// Frees a part of the decoded payload once it is read, so that the memory is used
/// again by what is built from the next parts (fresh pages cost the kernel's zeroing).
template <class T>
void release(T& part) {
  part = T();
}

/// Algebraic angles to and from the table of a saved space (`file`: the one read, for
/// the messages of the functions' exact coefficients decoded later).
class AngleTable {
 public:
  explicit AngleTable(saved::Space& space, std::shared_ptr<const std::string> file = {})
      : space_(space), file_(std::move(file)) {}

  /// Each distinct angle once: a root by its function, chart and place among the
  /// function's roots (copies of it may hold enclosures refined differently), a
  /// rational angle by its chart and t.
  std::uint32_t add(const AlgebraicAngle& angle) {
    saved::Angles& angles = space_.angles;
    const bool byValue = angle.isRational() || angle.index() < 0;
    const auto [found, inserted] =
        indexOfAngle_.try_emplace(AngleKey{angle.isRational() ? nullptr : angle.function().get(), angle.chart(),
                                           angle.index(), byValue ? angle.root().lo : Rational(0)},
                                  static_cast<std::uint32_t>(angles.functions.size()));
    if (!inserted) return found->second;
    angles.functions.push_back(angle.function() ? static_cast<std::int32_t>(functionIndex(*angle.function())) : -1);
    angles.charts.push_back(static_cast<std::uint8_t>(angle.chart()));
    angles.indices.push_back(angle.index());
    angles.enclosures.insert(angles.enclosures.end(), {angle.lower(), angle.upper()});
    const IsolatingInterval root = angle.root();  // exact, so only for angles not seen yet
    const bool doubleEnds = root.lo == Rational(angle.lower()) && root.hi == Rational(angle.upper());
    if (!doubleEnds || (angle.isRational() && angle.lower() != angle.upper())) {
      angles.exactAngles.push_back(found->second);
      angles.exactIntervals += bytesOf(root.lo) + bytesOf(root.hi);
    }
    return found->second;
  }

  void add(const AngleSet& set, saved::AngleSets& sets) {
    sets.fullCircle.push_back(set.fullCircle ? 1 : 0);
    sets.arcCounts.push_back(static_cast<std::uint32_t>(set.arcs.size()));
    for (const AngleInterval& arc : set.arcs)
      sets.arcs.insert(sets.arcs.end(), {add(arc.from), add(arc.to), arc.wraps});
  }

  /// Writes the coefficients of the functions of the angles added: most were never
  /// needed exactly by the construction, and making them is most of a save, so they
  /// are made and written into bytes on every core, a batch at a time.
  void writeFunctionCoefficients() {
    constexpr std::size_t kBatch = 4096;
    std::vector<saved::Functions> batch(kBatch);
    for (std::size_t first = 0; first < functionsToWrite_.size(); first += kBatch) {
      const std::size_t count = std::min(kBatch, functionsToWrite_.size() - first);
      onEveryCore(
          count, [] { return true; },
          [&](std::size_t k) {
            const AngleFunction& function = *functionsToWrite_[first + k];
            writeCoefficients({function.exactOnce(0), function.exactOnce(1)}, batch[k]);
          });
      saved::Functions& functions = space_.functions;
      for (std::size_t k = 0; k < count; ++k) {
        const saved::Functions& written = batch[k];
        functions.coefficientCounts.insert(functions.coefficientCounts.end(), written.coefficientCounts.begin(),
                                           written.coefficientCounts.end());
        functions.enclosures.insert(functions.enclosures.end(), written.enclosures.begin(), written.enclosures.end());
        functions.exact += written.exact;
        functions.exactEnds.push_back(functions.exact.size());
        release(batch[k]);
      }
    }
    release(functionsToWrite_);
  }

  /// Reads every angle of the loaded table in the table's order (the structures then
  /// look them up at random), and frees the stored ones; the functions' exact
  /// coefficients are kept, undecoded, for the functions to decode when needed.
  void readEveryAngle() {
    const saved::Angles& stored = space_.angles;
    const std::size_t count = stored.functions.size();
    if (stored.charts.size() != count || stored.indices.size() != count || stored.enclosures.size() != 2 * count) {
      throw DamagedPart("the angles");
    }
    prepareFunctions();
    read_.reserve(count);
    std::size_t exact = 0, at = 0;  // the next angle with an exact interval, and where that interval starts
    for (std::size_t i = 0; i < count; ++i) {
      std::optional<IsolatingInterval> root;
      if (exact < stored.exactAngles.size() && stored.exactAngles[exact] == i) {
        root = IsolatingInterval{rationalAt(stored.exactIntervals, at), rationalAt(stored.exactIntervals, at)};
        ++exact;
      }
      read_.push_back(readAngle(i, root));
    }
    if (exact != stored.exactAngles.size() || at != stored.exactIntervals.size()) {
      throw DamagedPart("an angle's exact interval");
    }
    release(space_.angles);
    release(space_.functions);
    release(firstCoefficient_);
    release(firstKey_);
  }

  /// The angle at an index of the table (after readEveryAngle).
  const AlgebraicAngle& angle(std::uint32_t index) const {
    if (index >= read_.size()) throw DamagedPart("an angle's index");
    return read_[index];
  }

  /// Decodes every loaded function's exact coefficients now (LoadCheck::Everything).
  void decodeEveryFunction() const {
    for (const auto& function : loaded_) {
      if (function) function->exact(0), function->exact(1);
    }
  }

 private:
  std::size_t functionIndex(const AngleFunction& function) {
    saved::Functions& functions = space_.functions;
    const auto [found, inserted] = indexOf_.try_emplace(&function, functions.keyed.size());
    if (inserted) {
      functions.keyed.push_back(function.key() ? 1 : 0);
      if (function.key()) functions.keys.insert(functions.keys.end(), function.key()->begin(), function.key()->end());
      functionsToWrite_.push_back(&function);
    }
    return found->second;
  }

  /// One function's coefficient counts, enclosures and exact bytes into `out`.
  static void writeCoefficients(const std::array<RationalPolynomial, 2>& charts, saved::Functions& out) {
    for (const RationalPolynomial& chart : charts) {
      out.coefficientCounts.push_back(static_cast<std::uint32_t>(chart.coefficients().size()));
      for (const Rational& c : chart.coefficients()) {
        const Interval enclosure = enclosingInterval(c);
        out.enclosures.insert(out.enclosures.end(), {enclosure.lower(), enclosure.upper()});
        out.exact += bytesOf(c);
      }
    }
  }

  /// Checks that the stored functions' lists fit together, and notes where each
  /// function's coefficients and key begin; their exact bytes move to exact_.
  void prepareFunctions() {
    saved::Functions& stored = space_.functions;
    const std::size_t count = stored.keyed.size();
    if (stored.coefficientCounts.size() != 2 * count || stored.exactEnds.size() != count) {
      throw DamagedPart("the functions");
    }
    firstCoefficient_.reserve(count + 1);
    firstKey_.reserve(count + 1);
    std::uint64_t coefficients = 0, keys = 0, exactEnd = 0;
    for (std::size_t i = 0; i < count; ++i) {
      firstCoefficient_.push_back(coefficients);
      firstKey_.push_back(keys);
      coefficients += std::uint64_t(stored.coefficientCounts[2 * i]) + stored.coefficientCounts[2 * i + 1];
      if (coefficients > stored.enclosures.size()) throw DamagedPart("the functions");  // before it could wrap
      if (stored.keyed[i] > 1) throw DamagedPart("a function's key");
      keys += stored.keyed[i] * AngleFunction::RootKey().size();
      if (stored.exactEnds[i] < exactEnd) throw DamagedPart("a function's coefficients");
      exactEnd = stored.exactEnds[i];
    }
    if (2 * coefficients != stored.enclosures.size() || keys != stored.keys.size() || exactEnd != stored.exact.size()) {
      throw DamagedPart("the functions");
    }
    exact_ = std::make_shared<const std::string>(std::move(stored.exact));
    loaded_.resize(count);
  }

  std::shared_ptr<const AngleFunction> function(std::int32_t index) {
    if (index < 0 || static_cast<std::size_t>(index) >= loaded_.size()) throw DamagedPart("an angle's function");
    std::shared_ptr<const AngleFunction>& function = loaded_[index];
    if (!function) function = functionOf(static_cast<std::size_t>(index));
    return function;
  }

  /// A stored function with its exact coefficients left undecoded (SavedPolynomials).
  std::shared_ptr<const AngleFunction> functionOf(std::size_t index) {
    const saved::Functions& stored = space_.functions;
    const std::uint32_t chart0 = stored.coefficientCounts[2 * index];
    std::array<std::vector<Interval>, 2> enclosures;
    const std::size_t first = firstCoefficient_[index];
    for (std::size_t i = first; i < first + chart0 + stored.coefficientCounts[2 * index + 1]; ++i) {
      const double lower = finite(stored.enclosures[2 * i]), upper = finite(stored.enclosures[2 * i + 1]);
      if (!(lower <= upper)) throw DamagedPart("a function's coefficients");
      enclosures[i - first < chart0 ? 0 : 1].emplace_back(lower, upper);
    }
    const std::size_t begin = index == 0 ? 0 : stored.exactEnds[index - 1], end = stored.exactEnds[index];
    const std::string_view bytes = std::string_view(*exact_).substr(begin, end - begin);
    std::size_t written = 0;
    for (std::size_t at = 0; at < bytes.size(); ++written) at = rationalEnd(bytes, at);
    if (written != enclosures[0].size() + enclosures[1].size()) throw DamagedPart("a function's coefficients");
    std::optional<AngleFunction::RootKey> key;
    if (stored.keyed[index] != 0) {
      key.emplace();
      std::copy_n(stored.keys.begin() + firstKey_[index], key->size(), key->begin());
    }
    return std::make_shared<const AngleFunction>(
        std::array<Polynomial<Interval>, 2>{Polynomial<Interval>(std::move(enclosures[0])),
                                            Polynomial<Interval>(std::move(enclosures[1]))},
        key, std::make_unique<SavedPolynomials>(file_, exact_, begin, end, chart0));
  }

  /// The table's angle at `index`, with its exact isolating interval if it has one.
  AlgebraicAngle readAngle(std::size_t index, const std::optional<IsolatingInterval>& exact) {
    const saved::Angles& stored = space_.angles;
    const std::int32_t function = stored.functions[index], rootIndex = stored.indices[index];
    const int chart = stored.charts[index];
    const double lower = stored.enclosures[2 * index], upper = stored.enclosures[2 * index + 1];
    // Every angle's enclosures lie in its chart's t in [-1, 1] (where roots are isolated),
    // ordered: NaN, infinite or larger ends would reach GMP, which raises SIGFPE on them.
    if (chart > 1 || !(-1 <= lower && lower <= upper && upper <= 1) ||
        (exact && !(-1 <= exact->lo && exact->lo <= exact->hi && exact->hi <= 1))) {
      throw DamagedPart("an angle");
    }
    if (function < 0) {  // a rational angle: one value of t
      if (!exact && lower != upper) throw DamagedPart("an angle");
      if (!exact) return AlgebraicAngle::rational(chart, lower);
      if (exact->lo != exact->hi) throw DamagedPart("a rational angle with an interval");
      return AlgebraicAngle::rational(chart, exact->lo);
    }
    std::shared_ptr<const AngleFunction> of = this->function(function);
    // A root's place among the chart's roots, fewer than its coefficients (or unknown).
    if (rootIndex < -1 || rootIndex >= static_cast<std::int64_t>(of->approximate(chart).coefficients().size())) {
      throw DamagedPart("an angle");
    }
    if (!exact) return AlgebraicAngle(std::move(of), chart, lower, upper, rootIndex);
    return AlgebraicAngle(std::move(of), chart, *exact, rootIndex);
  }

  /// What identifies an angle of the table (see add).
  struct AngleKey {
    const AngleFunction* function;
    int chart;
    int index;
    Rational t;  // a rational angle's t, or the lower end of a root of unknown place
    bool operator==(const AngleKey& other) const {
      return function == other.function && chart == other.chart && index == other.index && t == other.t;
    }
  };
  struct HashOfAngleKey {
    std::size_t operator()(const AngleKey& key) const {
      std::size_t hash = std::hash<const void*>()(key.function);
      for (const std::size_t part : {std::hash<int>()(key.chart), std::hash<int>()(key.index),
                                     std::hash<double>()(mpq_get_d(key.t.backend().data()))}) {
        hash ^= part + 0x9e3779b97f4a7c15 + (hash << 6) + (hash >> 2);
      }
      return hash;
    }
  };

  saved::Space& space_;
  std::shared_ptr<const std::string> file_;
  std::unordered_map<const AngleFunction*, std::size_t> indexOf_;
  std::unordered_map<AngleKey, std::uint32_t, HashOfAngleKey> indexOfAngle_;
  std::vector<const AngleFunction*> functionsToWrite_;
  std::vector<std::uint64_t> firstCoefficient_, firstKey_;
  std::shared_ptr<const std::string> exact_;
  std::vector<std::shared_ptr<const AngleFunction>> loaded_;
  std::vector<AlgebraicAngle> read_;
};

/// The sets of a saved::AngleSets, one after another.
class AngleSetReader {
 public:
  AngleSetReader(const saved::AngleSets& sets, const AngleTable& angles) : sets_(sets), angles_(angles) {
    const std::uint64_t arcs = sumUpTo(sets.arcCounts, sets.arcs.size() / 3);
    if (sets.fullCircle.size() != sets.arcCounts.size() || 3 * arcs != sets.arcs.size()) {
      throw DamagedPart("an angle set's arcs");
    }
  }

  std::size_t count() const { return sets_.arcCounts.size(); }

  AngleSet next() {
    AngleSet set;
    if (sets_.fullCircle.at(set_) > 1) throw DamagedPart("an angle set");
    set.fullCircle = sets_.fullCircle[set_] != 0;
    set.arcs.reserve(sets_.arcCounts[set_]);
    for (std::uint32_t i = 0; i < sets_.arcCounts[set_]; ++i, arc_ += 3) {
      set.arcs.push_back(
          {angles_.angle(sets_.arcs[arc_]), angles_.angle(sets_.arcs[arc_ + 1]), sets_.arcs[arc_ + 2] != 0});
    }
    ++set_;
    return set;
  }

 private:
  const saved::AngleSets& sets_;
  const AngleTable& angles_;
  std::size_t set_ = 0, arc_ = 0;
};

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
  return {finite(in[3 * i]), finite(in[3 * i + 1]), finite(in[3 * i + 2])};
}

void addPatch(const PatchGeometry& patch, AngleTable& angles, saved::Patches& patches) {
  const Contact& c = patch.patch.contact;
  patches.contacts.insert(patches.contacts.end(),
                          {static_cast<std::int32_t>(c.kind), static_cast<std::int32_t>(c.robot),
                           static_cast<std::int32_t>(c.world), c.side});
  angles.add(patch.patch.range, patches.ranges);
  for (const SegmentEnd& end : patch.segment.ends) {
    patches.segments.insert(patches.segments.end(), {end.robotVertex ? 1u : 0u, end.vertex, end.edge[0], end.edge[1]});
  }
  patches.lineTags.insert(patches.lineTags.end(), {static_cast<std::int32_t>(patch.line.kind), patch.line.side});
  for (std::uint32_t v : patch.line.vertices) patches.lineTags.push_back(static_cast<std::int32_t>(v));
  for (const Point3& p : patch.line.points) pushPoint(patches.linePoints, p);
  for (const SpiralPoints& end : patch.ends) {
    patches.spiralRobotVertices.push_back(end.robotVertex ? 1 : 0);
    for (const Point3& p : end.points) pushPoint(patches.spiralPoints, p);
  }
}

/// The stored patches; their lists are checked to hold `count` patches each first.
std::vector<PatchGeometry> patchesOf(const saved::Patches& stored, const AngleTable& angles) {
  const std::size_t count = stored.contacts.size() / 4;
  AngleSetReader ranges(stored.ranges, angles);
  if (stored.contacts.size() != 4 * count || ranges.count() != count || stored.segments.size() != 8 * count ||
      stored.lineTags.size() != 6 * count || stored.linePoints.size() != 12 * count ||
      stored.spiralRobotVertices.size() != 2 * count || stored.spiralPoints.size() != 18 * count) {
    throw DamagedPart("the patches");
  }
  std::vector<PatchGeometry> patches(count);
  for (std::size_t i = 0; i < count; ++i) {
    PatchGeometry& patch = patches[i];
    const std::int32_t* contact = &stored.contacts[4 * i];
    patch.patch.contact = {static_cast<ContactKind>(contact[0]), static_cast<std::uint32_t>(contact[1]),
                           static_cast<std::uint32_t>(contact[2]), contact[3]};
    patch.patch.range = ranges.next();
    const std::uint32_t* segment = &stored.segments[8 * i];
    for (int k = 0; k < 2; ++k) {
      patch.segment.ends[k] = {segment[4 * k] != 0, segment[4 * k + 1], {segment[4 * k + 2], segment[4 * k + 3]}};
    }
    const std::int32_t* tags = &stored.lineTags[6 * i];
    patch.line.kind = static_cast<ContactKind>(tags[0]);
    patch.line.side = tags[1];
    for (int j = 0; j < 4; ++j) {
      patch.line.vertices[j] = static_cast<std::uint32_t>(tags[2 + j]);
      patch.line.points[j] = pointAt(stored.linePoints, 4 * i + j);
    }
    cacheApproximateLine(patch.line);
    for (int k = 0; k < 2; ++k) {
      patch.ends[k].robotVertex = stored.spiralRobotVertices[2 * i + k] != 0;
      for (int j = 0; j < 3; ++j) patch.ends[k].points[j] = pointAt(stored.spiralPoints, 6 * i + 3 * k + j);
    }
  }
  return patches;
}

void addCurve(const PatchCurve& curve, AngleTable& angles, saved::Curves& curves) {
  curves.patches.insert(curves.patches.end(), {curve.first, curve.second});
  angles.add(curve.angles, curves.angles);
  for (const auto& ends : curve.ends) {
    for (const CurveEnd& end : ends) {
      curves.ends.insert(curves.ends.end(),
                         {end.endOnOtherLine[0][0], end.endOnOtherLine[0][1], end.endOnOtherLine[1][0],
                          end.endOnOtherLine[1][1], end.rangeEnd[0], end.rangeEnd[1]});
    }
  }
}

std::vector<PatchCurve> curvesOf(const saved::Curves& stored, const AngleTable& angles) {
  const std::size_t count = stored.patches.size() / 2;
  AngleSetReader arcs(stored.angles, angles);
  const std::size_t arcCount = stored.angles.arcs.size() / 3;  // as AngleSetReader checked
  if (stored.patches.size() != 2 * count || arcs.count() != count || stored.ends.size() != 12 * arcCount) {
    throw DamagedPart("the curves");
  }
  std::vector<PatchCurve> curves;
  curves.reserve(count);
  const std::uint8_t* flags = stored.ends.data();
  for (std::size_t i = 0; i < count; ++i) {
    PatchCurve curve{stored.patches[2 * i], stored.patches[2 * i + 1], arcs.next(), {}};
    curve.ends.resize(curve.angles.arcs.size());
    for (auto& ends : curve.ends) {
      for (CurveEnd& end : ends) {
        end.endOnOtherLine = {{{flags[0] != 0, flags[1] != 0}, {flags[2] != 0, flags[3] != 0}}};
        end.rangeEnd = {flags[4] != 0, flags[5] != 0};
        flags += 6;
      }
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

std::vector<PatchOverlap> overlapsOf(const saved::Overlaps& stored, const AngleTable& angles) {
  const std::size_t count = stored.angles.size();
  if (stored.patches.size() != 2 * count || stored.reachesEnd.size() != 4 * count) throw DamagedPart("the overlaps");
  std::vector<PatchOverlap> overlaps;
  overlaps.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* reaches = &stored.reachesEnd[4 * i];
    overlaps.push_back({{stored.patches[2 * i], stored.patches[2 * i + 1]},
                        angles.angle(stored.angles[i]),
                        {{{reaches[0] != 0, reaches[1] != 0}, {reaches[2] != 0, reaches[3] != 0}}}});
  }
  return overlaps;
}

std::vector<PatchVertex> verticesOf(const saved::Vertices& stored, const AngleTable& angles) {
  const std::size_t count = stored.angles.size();
  if (stored.patches.size() != 3 * count || stored.crossings.size() != count) throw DamagedPart("the vertices");
  std::vector<PatchVertex> vertices;
  vertices.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    // The place of the patch that crosses the other two's curve, if one does.
    if (stored.crossings[i] < -1 || stored.crossings[i] > 2) throw DamagedPart("a vertex");
    vertices.push_back({{stored.patches[3 * i], stored.patches[3 * i + 1], stored.patches[3 * i + 2]},
                        angles.angle(stored.angles[i]),
                        stored.crossings[i]});
  }
  return vertices;
}

void addSubdivision(const PatchSubdivision& subdivision, AngleTable& angles, saved::Subdivisions& subdivisions) {
  subdivisions.faceCounts.push_back(subdivision.faceCount);
  subdivisions.slabCounts.push_back(static_cast<std::uint32_t>(subdivision.slabs.size()));
  for (const PatchSlab& slab : subdivision.slabs) {
    subdivisions.slabAngles.insert(subdivisions.slabAngles.end(),
                                   {angles.add(slab.from), angles.add(slab.to), angles.add(slab.sample)});
    subdivisions.curveCounts.push_back(static_cast<std::uint32_t>(slab.curves.size()));
    subdivisions.curves.insert(subdivisions.curves.end(), slab.curves.begin(), slab.curves.end());
    subdivisions.faces.insert(subdivisions.faces.end(), slab.faces.begin(), slab.faces.end());
  }
}

std::vector<PatchSubdivision> subdivisionsOf(const saved::Subdivisions& stored, const AngleTable& angles) {
  const std::size_t patches = stored.faceCounts.size();
  const std::uint64_t slabs = sumUpTo(stored.slabCounts, stored.curveCounts.size());
  const std::uint64_t curves = sumUpTo(stored.curveCounts, stored.curves.size());
  if (stored.slabCounts.size() != patches || stored.curveCounts.size() != slabs ||
      stored.slabAngles.size() != 3 * slabs || stored.curves.size() != curves ||
      stored.faces.size() != curves + slabs) {
    throw DamagedPart("the subdivisions");
  }
  std::vector<PatchSubdivision> subdivisions(patches);
  std::size_t slab = 0;
  auto curve = stored.curves.begin(), face = stored.faces.begin();
  for (std::size_t patch = 0; patch < patches; ++patch) {
    PatchSubdivision& subdivision = subdivisions[patch];
    subdivision.faceCount = stored.faceCounts[patch];
    subdivision.slabs.reserve(stored.slabCounts[patch]);
    for (std::uint32_t i = 0; i < stored.slabCounts[patch]; ++i, ++slab) {
      const std::uint32_t* ends = &stored.slabAngles[3 * slab];
      const std::uint32_t crossing = stored.curveCounts[slab];
      subdivision.slabs.push_back({angles.angle(ends[0]),
                                   angles.angle(ends[1]),
                                   angles.angle(ends[2]),
                                   {curve, curve + crossing},
                                   {face, face + crossing + 1}});
      curve += crossing;
      face += crossing + 1;
    }
  }
  return subdivisions;
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

SubFaceGluing gluingOf(const saved::Gluing& stored, const AngleTable& angles) {
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

CellGraph::Parts graphOf(const saved::Graph& stored, const AngleTable& angles) {
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
    // A node of the unbounded cell may have an unbounded box, never an undefined one.
    for (int k = 0; k < 4; ++k) {
      node.box[k] = stored.nodeGeometry[6 * i + 2 + k];
      if (std::isnan(node.box[k])) throw DamagedPart("a node's box");
    }
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
  for (const PatchGeometry& patch : arrangement.patches) addPatch(patch, angles, space.patches);
  for (const PatchCurve& curve : arrangement.curves) addCurve(curve, angles, space.curves);
  for (const PatchOverlap& overlap : arrangement.overlaps) {
    space.overlaps.patches.insert(space.overlaps.patches.end(), overlap.patches.begin(), overlap.patches.end());
    space.overlaps.angles.push_back(angles.add(overlap.angle));
    space.overlaps.reachesEnd.insert(
        space.overlaps.reachesEnd.end(),
        {overlap.reachesEnd[0][0], overlap.reachesEnd[0][1], overlap.reachesEnd[1][0], overlap.reachesEnd[1][1]});
  }
  for (const PatchVertex& vertex : arrangement.vertices) {
    space.vertices.patches.insert(space.vertices.patches.end(), vertex.patches.begin(), vertex.patches.end());
    space.vertices.angles.push_back(angles.add(vertex.angle));
    space.vertices.crossings.push_back(vertex.crossing);
  }
  for (const PatchSubdivision& subdivision : arrangement.subdivisions) {
    addSubdivision(subdivision, angles, space.subdivisions);
  }
  space.acrossCurves = savedGluing(arrangement.acrossCurves, angles);
  space.aroundSpirals = savedGluing(arrangement.aroundSpirals, angles);
  space.acrossHorizontalEdges = savedGluing(arrangement.acrossHorizontalEdges, angles);
  for (std::uint32_t shell = 0; shell < sides.size(); ++shell) {
    space.shellSides.push_back(static_cast<std::uint8_t>(sides[shell]));
    const std::optional<std::uint32_t> cell = cells.cellOfShell(shell);
    space.cellOfShell.push_back(cell ? static_cast<std::int32_t>(*cell) : -1);
  }
  space.cellCount = static_cast<std::uint32_t>(cells.count());
  for (const StageTime& stage : stageTimes) {
    space.stageNames += stage.stage + '\n';
    space.stageSeconds.push_back(stage.seconds);
  }
  space.graph = savedGraph(graph.parts(), angles);
  angles.writeFunctionCoefficients();
  return space;
}

/// The header's integers are little-endian whatever the machine (the payload is a
/// Boost binary archive: files are for machines of one architecture).
void writeLittleEndian(std::ostream& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.put(static_cast<char>((value >> (8 * i)) & 0xff));
}

std::uint64_t readLittleEndian(const char* bytes, int count) {
  std::uint64_t value = 0;
  for (int i = 0; i < count; ++i) value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[i])) << (8 * i);
  return value;
}

/// The payload's checksum: XXH3's 64 bits (a CRC-32 took a sixth of the load of
/// house_mixed_160; XXH3 reads memory about as fast as it comes).
std::uint64_t checksum(std::string_view payload) { return XXH3_64bits(payload.data(), payload.size()); }

/// The payload of a saved free space file (read in place), checked against its
/// header and its trailer.
std::string_view checkedPayload(const MappedInputFile& file, const std::string& path) {
  const std::string_view bytes(file.data(), file.size());
  const std::size_t lineEnd = bytes.find('\n');
  if (bytes.rfind(kHeader, 0) != 0 || lineEnd == std::string_view::npos) {
    throw InputError(path, "not a saved free space (no '" + kHeader + "' header)");
  }
  const std::string_view version = bytes.substr(kHeader.size(), lineEnd - kHeader.size());
  if (version != std::to_string(kFormatVersion)) {
    throw InputError(path, "saved free space of format " + std::string(version) + "; this build reads format " +
                               std::to_string(kFormatVersion));
  }
  constexpr std::size_t kTrailer = 16;
  if (bytes.size() - (lineEnd + 1) < kTrailer) throw InputError(path, "damaged: wrong length");
  const char* trailer = bytes.data() + bytes.size() - kTrailer;
  const std::string_view payload = bytes.substr(lineEnd + 1, bytes.size() - kTrailer - (lineEnd + 1));
  if (payload.size() != readLittleEndian(trailer, 8)) throw InputError(path, "damaged: wrong length");
  if (checksum(payload) != readLittleEndian(trailer + 8, 8)) throw InputError(path, "damaged: checksum mismatch");
  return payload;
}

/// An output buffer that passes what is written to `out` a block at a time, counting
/// and hashing it on the way (XXH3, 64 bits). A failed write of `out` is left in
/// `out`'s state for its writer to find; nothing more is written to it then.
class HashingBuffer : public std::streambuf {
 public:
  explicit HashingBuffer(std::ostream& out) : out_(out), state_(XXH3_createState(), XXH3_freeState) {
    if (!state_ || XXH3_64bits_reset(state_.get()) != XXH_OK) throw std::bad_alloc();
    setp(block_.data(), block_.data() + block_.size());
  }

  std::uint64_t size() const { return size_ + static_cast<std::uint64_t>(pptr() - pbase()); }
  /// The hash of everything written so far (the block held is passed on first).
  std::uint64_t hash() {
    pass();
    return XXH3_64bits_digest(state_.get());
  }

 protected:
  int_type overflow(int_type c) override {
    pass();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    pass();
    return 0;
  }

 private:
  void pass() {
    const std::size_t held = static_cast<std::size_t>(pptr() - pbase());
    XXH3_64bits_update(state_.get(), pbase(), held);
    if (out_) out_.write(pbase(), static_cast<std::streamsize>(held));  // else no use writing on
    size_ += held;
    setp(block_.data(), block_.data() + block_.size());
  }

  std::ostream& out_;
  std::unique_ptr<XXH3_state_t, XXH_errorcode (*)(XXH3_state_t*)> state_;
  std::array<char, 1 << 20> block_;
  std::uint64_t size_ = 0;
};

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
  writeFile(path, overwrite, [&](std::ostream& out) {
    out << kHeader << kFormatVersion << '\n';
    const auto buffer = std::make_unique<HashingBuffer>(out);
    {
      std::ostream payload(buffer.get());
      boost::archive::binary_oarchive archive(payload);
      archive << space;
    }
    const std::uint64_t size = buffer->size(), sum = buffer->hash();
    writeLittleEndian(out, size, 8);
    writeLittleEndian(out, sum, 8);
  });
}

std::unique_ptr<FreeSpace> FreeSpace::load(const std::string& path, LoadCheck check) {
  saved::Space space;
  try {
    const MappedInputFile file(path);  // unmapped once decoded
    PayloadBuffer buffer(checkedPayload(file, path));
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
    angles.readEveryAngle();
    impl->meshes.robot = meshOf(space.robot, path);
    impl->meshes.world = meshOf(space.world, path);
    impl->meshes.record = {space.perturbed, space.seed, space.relativeSize, space.absoluteSize};
    int exponent = 0;
    if (std::frexp(space.scale, &exponent) != 0.5) throw DamagedPart("the coordinates' scale (not a power of two)");
    impl->meshes.scale = space.scale;
    Arrangement& arrangement = impl->arrangement;
    arrangement.patches = patchesOf(space.patches, angles);
    release(space.patches);
    arrangement.boxIndex = std::make_shared<const PatchBoxIndex>(arrangement.patches);
    arrangement.curves = curvesOf(space.curves, angles);
    release(space.curves);
    arrangement.overlaps = overlapsOf(space.overlaps, angles);
    arrangement.vertices = verticesOf(space.vertices, angles);
    arrangement.subdivisions = subdivisionsOf(space.subdivisions, angles);
    release(space.subdivisions);
    arrangement.acrossCurves = gluingOf(space.acrossCurves, angles);
    arrangement.aroundSpirals = gluingOf(space.aroundSpirals, angles);
    arrangement.acrossHorizontalEdges = gluingOf(space.acrossHorizontalEdges, angles);
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
    std::istringstream stageNames(space.stageNames);
    for (std::string name; std::getline(stageNames, name);) {
      if (impl->stageTimes.size() == space.stageSeconds.size()) throw DamagedPart("the stages' times");
      const double seconds = space.stageSeconds[impl->stageTimes.size()];
      if (!std::isfinite(seconds)) throw DamagedPart("the stages' times");
      impl->stageTimes.push_back({name, seconds});
    }
    if (impl->stageTimes.size() != space.stageSeconds.size()) throw DamagedPart("the stages' times");
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
