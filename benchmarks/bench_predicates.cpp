// Nanoseconds per predicate at each precision level of the robust-number layer:
// the FFF sign (three patch lines concurrent?) at a rational angle evaluated in double
// intervals, MPFI at each precision of the ladder, and exact rationals; the same
// through the adaptive engine; and root isolation and comparison of algebraic angles.
// Target: a double-interval FFF sign under 100 ns.
#include <benchmark/benchmark.h>

#include <random>

#include "freespace/numbers/adaptive_sign.h"
#include "freespace/numbers/algebraic_angle.h"
#include "freespace/numbers/angle_polynomial.h"

using namespace freespace;

namespace {

/// Random patch lines with coordinates of a few units, as a scene would give.
std::vector<PatchLine<double>> randomLines(std::size_t count) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-4, 4);
  std::vector<PatchLine<double>> lines(count);
  for (PatchLine<double>& line : lines) {
    for (double* field : {&line.a1x, &line.a1y, &line.a2x, &line.a2y, &line.k1, &line.k2, &line.k3}) {
      *field = value(random);
    }
  }
  return lines;
}

/// The FFF determinant's sign at a rational angle (chart 0, t = 0.3), written once
/// for all number types.
struct ThreePatchSign {
  const PatchLine<double> *l1, *l2, *l3;
  template <class T>
  T operator()(NumberType<T>) const {
    T cosine, sine;
    HalfAngle{0, 0.3}.cosSin(cosine, sine);
    return threePatchDeterminant(convertLine<T>(*l1), convertLine<T>(*l2), convertLine<T>(*l3), cosine, sine);
  }
};

const std::vector<PatchLine<double>>& lines() {
  static const std::vector<PatchLine<double>> instance = randomLines(3 * 1024);
  return instance;
}

ThreePatchSign predicateNumber(std::size_t i) {
  const std::size_t j = 3 * (i % 1024);
  return {&lines()[j], &lines()[j + 1], &lines()[j + 2]};
}

template <class T>
void ThreePatchAtLevel(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    const T value = T(predicateNumber(i++)(NumberType<T>{}));
    benchmark::DoNotOptimize(value);
  }
}

void ThreePatchDoubleInterval(benchmark::State& state) {
  RoundingScope rounding;
  std::size_t i = 0;
  for (auto _ : state) {
    const Interval value = predicateNumber(i++)(NumberType<Interval>{});
    benchmark::DoNotOptimize(certainSign(value));
  }
}

/// The same with the angle's cosine and sine intervals known (computed once per
/// angle, as a sweep does) and the lines' interval coefficients too (computed once
/// per patch): the determinant alone.
void ThreePatchDoubleIntervalAtKnownAngle(benchmark::State& state) {
  RoundingScope rounding;
  Interval cosine, sine;
  HalfAngle{0, 0.3}.cosSin(cosine, sine);
  std::vector<PatchLine<Interval>> intervalLines;
  for (const PatchLine<double>& line : lines()) intervalLines.push_back(convertLine<Interval>(line));
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t j = 3 * (i++ % 1024);
    benchmark::DoNotOptimize(
        certainSign(threePatchDeterminant(intervalLines[j], intervalLines[j + 1], intervalLines[j + 2], cosine, sine)));
  }
}

/// The angle's conversion alone: cosine and sine intervals from t.
void HalfAngleToDoubleIntervals(benchmark::State& state) {
  RoundingScope rounding;
  double t = 0.3;
  for (auto _ : state) {
    Interval cosine, sine;
    HalfAngle{0, t}.cosSin(cosine, sine);
    benchmark::DoNotOptimize(cosine);
    benchmark::DoNotOptimize(sine);
    t = t * 0.5 + 0.1;
  }
}

void ThreePatchThroughEngine(benchmark::State& state) {
  PredicateStatistics statistics;
  AdaptiveSignEngine engine(statistics);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(engine.sign(PredicateKind::ThreePatch, predicateNumber(i++)));
  state.counters["double_fraction"] = statistics.doubleIntervalFraction();
}

std::shared_ptr<const AngleFunction> efFunction(const PatchLine<double>& line) {
  return std::make_shared<AngleFunction>([line](auto type, int chart) {
    using T = typename decltype(type)::type;
    return tangentPolynomial(edgeFacetForm(T(line.k1), T(line.k2), T(line.k3)), chart);
  });
}

std::shared_ptr<const AngleFunction> fffFunction(std::size_t i) {
  const ThreePatchSign p = predicateNumber(i);
  return std::make_shared<AngleFunction>([p](auto type, int chart) {
    using T = typename decltype(type)::type;
    return threePatchPolynomial(convertLine<T>(*p.l1), convertLine<T>(*p.l2), convertLine<T>(*p.l3), chart);
  });
}

void EdgeFacetRoots(benchmark::State& state) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(algebra.roots(efFunction(lines()[i++ % lines().size()]), PredicateKind::EdgeFacet));
  state.counters["double_fraction"] = statistics.doubleIntervalFraction();
}

void ThreePatchRoots(benchmark::State& state) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(algebra.roots(fffFunction(i++), PredicateKind::ThreePatch));
  state.counters["double_fraction"] = statistics.doubleIntervalFraction();
}

void CompareEdgeFacetRoots(benchmark::State& state) {
  PredicateStatistics statistics;
  AngleAlgebra algebra(statistics);
  std::vector<AlgebraicAngle> angles;
  for (const PatchLine<double>& line : lines()) {
    for (const AlgebraicAngle& angle : algebra.roots(efFunction(line), PredicateKind::EdgeFacet)) angles.push_back(angle);
  }
  PredicateStatistics comparisons;
  AngleAlgebra counted(comparisons);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(counted.compare(angles[i % angles.size()], angles[(i * 7 + 3) % angles.size()]));
    ++i;
  }
  state.counters["double_fraction"] = comparisons.doubleIntervalFraction();
}

}  // namespace

BENCHMARK(ThreePatchDoubleInterval);
BENCHMARK(ThreePatchDoubleIntervalAtKnownAngle);
BENCHMARK(HalfAngleToDoubleIntervals);
BENCHMARK_TEMPLATE(ThreePatchAtLevel, MultiprecisionInterval<kMultiprecisionDigits[0]>);
BENCHMARK_TEMPLATE(ThreePatchAtLevel, MultiprecisionInterval<kMultiprecisionDigits[1]>);
BENCHMARK_TEMPLATE(ThreePatchAtLevel, MultiprecisionInterval<kMultiprecisionDigits[2]>);
BENCHMARK_TEMPLATE(ThreePatchAtLevel, MultiprecisionInterval<kMultiprecisionDigits[3]>);
BENCHMARK_TEMPLATE(ThreePatchAtLevel, Rational);
BENCHMARK(ThreePatchThroughEngine);
BENCHMARK(EdgeFacetRoots);
BENCHMARK(ThreePatchRoots);
BENCHMARK(CompareEdgeFacetRoots);
BENCHMARK_MAIN();
