#include "freespace/geometry/patch_box_index.h"

#include <algorithm>
#include <cmath>

namespace freespace {

namespace {

bool meet(const PatchBox& a, const PatchBox& b) {
  // Theta first: pieces of two patches that meet at all are mostly apart in it.
  for (int axis : {2, 0, 1}) {
    if (a.high[axis] < b.low[axis] || b.high[axis] < a.low[axis]) return false;
  }
  return true;
}

/// A uniform grid over the boxes' (x, y) square (PatchBoxIndex::Scales): for finding
/// the pairs of boxes that meet, each pair of boxes in one cell is tested, and a
/// meeting pair is reported only by the cell that holds the low corner of the two
/// boxes' common (x, y) part, so once; for queries, the cells a query covers. Cells
/// twice as wide as a typical box, so that a box covers a few cells and a cell holds
/// the boxes near it; wider when large boxes would cover too many.
class BoxGrid {
 public:
  BoxGrid(const std::vector<std::pair<PatchBox, std::uint32_t>>& boxes, const PatchBoxIndex::Scales& scales)
      : low_(scales.low), cellWidth_(std::max({2 * scales.typicalWidth, scales.side / kMaxCells, 1e-300})) {
    while (coveredCells(boxes) > kCellsPerBox * boxes.size()) cellWidth_ *= 2;
  }

  /// The column (of an x) or row (of a y) of the cells that holds the coordinate.
  std::uint64_t cellOf(double coordinate) const {
    const double cell = std::floor((coordinate - low_) / cellWidth_);
    return std::isnan(cell) ? 0 : static_cast<std::uint64_t>(std::clamp(cell, 0.0, kMaxCells));
  }
  /// The cell's one number.
  static std::uint64_t key(std::uint64_t column, std::uint64_t row) {
    return column * (static_cast<std::uint64_t>(kMaxCells) + 1) + row;
  }
  static std::uint64_t columnOf(std::uint64_t key) { return key / (static_cast<std::uint64_t>(kMaxCells) + 1); }
  static std::uint64_t rowOf(std::uint64_t key) { return key % (static_cast<std::uint64_t>(kMaxCells) + 1); }
  /// Calls `visit(key)` for each cell the box covers.
  template <class Visit>
  void forEachCell(const PatchBox& box, const Visit& visit) const {
    for (std::uint64_t column = cellOf(box.low[0]); column <= cellOf(box.high[0]); ++column) {
      for (std::uint64_t row = cellOf(box.low[1]); row <= cellOf(box.high[1]); ++row) visit(key(column, row));
    }
  }

 private:
  /// At most this many cells along an axis.
  static constexpr double kMaxCells = 1 << 20;
  /// At most this many cells per box on average.
  static constexpr std::size_t kCellsPerBox = 16;

  std::size_t coveredCells(const std::vector<std::pair<PatchBox, std::uint32_t>>& boxes) const {
    std::size_t cells = 0;
    for (const auto& entry : boxes) {
      cells += (cellOf(entry.first.high[0]) - cellOf(entry.first.low[0]) + 1) *
               (cellOf(entry.first.high[1]) - cellOf(entry.first.low[1]) + 1);
    }
    return cells;
  }

  double low_;
  double cellWidth_;
};

/// A cell a box covers; sorted by cell, then by the box's lowest angle.
struct CellEntry {
  std::uint64_t cell;
  double lowestAngle;
  std::uint32_t box;
  bool operator<(const CellEntry& other) const {
    return cell != other.cell ? cell < other.cell : lowestAngle < other.lowestAngle;
  }
};

bool lowerInAngle(const PatchBox& a, const PatchBox& b) { return a.low[2] < b.low[2]; }

PatchBoxIndex::Scales scalesOf(const std::vector<std::pair<PatchBox, std::uint32_t>>& boxes) {
  if (boxes.empty()) return {};
  double low = HUGE_VAL, high = -HUGE_VAL;
  std::vector<double> widths;
  for (const auto& [box, patch] : boxes) {
    low = std::min({low, box.low[0], box.low[1]});
    high = std::max({high, box.high[0], box.high[1]});
    widths.push_back(std::max(box.high[0] - box.low[0], box.high[1] - box.low[1]));
  }
  const auto middle = widths.begin() + static_cast<std::ptrdiff_t>(widths.size() / 2);
  std::nth_element(widths.begin(), middle, widths.end());
  return {low, high - low, *middle};
}

}  // namespace

/// The pieces' boxes on a uniform (x, y) grid (BoxGrid), for queries: each non-empty
/// cell lists the pieces that cover it, sorted by their lowest angle, so that a query
/// looks at the pieces of the cells it covers whose angles may reach its own.
struct PatchBoxIndex::Grid {
  BoxGrid cells;
  /// The non-empty cells' keys in order; cell k's pieces are entries[first[k]] to
  /// entries[first[k + 1]].
  std::vector<std::uint64_t> keys;
  std::vector<std::size_t> first;
  std::vector<std::pair<PatchBox, std::uint32_t>> entries;
  /// The columns and rows any piece covers.
  std::uint64_t lowColumn = 0, highColumn = 0, lowRow = 0, highRow = 0;

  explicit Grid(const std::vector<std::pair<PatchBox, std::uint32_t>>& pieces) : cells(pieces, scalesOf(pieces)) {
    std::vector<CellEntry> covered;
    for (std::uint32_t p = 0; p < pieces.size(); ++p) {
      cells.forEachCell(pieces[p].first, [&](std::uint64_t cell) {
        covered.push_back({cell, pieces[p].first.low[2], p});
      });
    }
    std::sort(covered.begin(), covered.end());
    lowColumn = lowRow = UINT64_MAX;
    for (const CellEntry& entry : covered) {
      if (keys.empty() || keys.back() != entry.cell) {
        keys.push_back(entry.cell);
        first.push_back(entries.size());
        const std::uint64_t column = BoxGrid::columnOf(entry.cell), row = BoxGrid::rowOf(entry.cell);
        lowColumn = std::min(lowColumn, column);
        highColumn = std::max(highColumn, column);
        lowRow = std::min(lowRow, row);
        highRow = std::max(highRow, row);
      }
      entries.push_back(pieces[entry.box]);
    }
    first.push_back(entries.size());
  }

  /// Calls `visit(patch)` for each piece that meets the query (a patch may come more
  /// than once), given the widest piece's angles.
  template <class Visit>
  void forEachMeeting(const PatchBox& query, double widestPiece, const Visit& visit) const {
    if (keys.empty()) return;
    const auto visitCell = [&](std::size_t k) {
      const auto begin = entries.begin() + static_cast<std::ptrdiff_t>(first[k]);
      const auto end = entries.begin() + static_cast<std::ptrdiff_t>(first[k + 1]);
      // Sorted by lowest angle, each at most widestPiece wide.
      const double from = query.low[2] - widestPiece;
      auto piece = std::partition_point(begin, end, [&](const auto& entry) { return entry.first.low[2] < from; });
      for (; piece != end && piece->first.low[2] <= query.high[2]; ++piece) {
        if (meet(piece->first, query)) visit(piece->second);
      }
    };
    const std::uint64_t fromColumn = std::max(lowColumn, cells.cellOf(query.low[0]));
    const std::uint64_t toColumn = std::min(highColumn, cells.cellOf(query.high[0]));
    const std::uint64_t fromRow = std::max(lowRow, cells.cellOf(query.low[1]));
    const std::uint64_t toRow = std::min(highRow, cells.cellOf(query.high[1]));
    if (fromColumn > toColumn || fromRow > toRow) return;
    // A query wider than the cells there are: each cell once.
    if ((toColumn - fromColumn + 1) * (toRow - fromRow + 1) > keys.size()) {
      for (std::size_t k = 0; k < keys.size(); ++k) visitCell(k);
      return;
    }
    for (std::uint64_t column = fromColumn; column <= toColumn; ++column) {
      for (std::uint64_t row = fromRow; row <= toRow; ++row) {
        const auto key = std::lower_bound(keys.begin(), keys.end(), BoxGrid::key(column, row));
        if (key != keys.end() && *key == BoxGrid::key(column, row)) {
          visitCell(static_cast<std::size_t>(key - keys.begin()));
        }
      }
    }
  }
};

PatchBoxIndex::PatchBoxIndex(const std::vector<PatchGeometry>& patches, const Cancellation& cancellation) {
  std::vector<std::pair<PatchBox, std::uint32_t>> pieceEntries;
  for (std::uint32_t i = 0; i < patches.size(); ++i) {
    cancellation.check();
    for (const PatchBox& box : patchBoxes(patches[i])) boxes_.emplace_back(box, i);
    firstPiece_.push_back(pieces_.size());
    std::vector<PatchBox> pieces = patchBoxes(patches[i], kPieceWidth);
    std::sort(pieces.begin(), pieces.end(), lowerInAngle);
    // With a margin over the rounding of the differences.
    for (const PatchBox& piece : pieces) {
      widestPiece_ = std::max(widestPiece_, piece.high[2] - piece.low[2] + 1e-9);
      pieceEntries.emplace_back(piece, i);
    }
    pieces_.insert(pieces_.end(), pieces.begin(), pieces.end());
  }
  firstPiece_.push_back(pieces_.size());
  scales_ = scalesOf(boxes_);
  grid_ = std::make_unique<Grid>(pieceEntries);
}

PatchBoxIndex::~PatchBoxIndex() = default;

std::vector<std::uint32_t> PatchBoxIndex::meeting(const PatchBox& query) const {
  std::vector<std::uint32_t> patches;
  grid_->forEachMeeting(query, widestPiece_, [&](std::uint32_t patch) { patches.push_back(patch); });
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  return patches;
}

std::vector<std::uint32_t> PatchBoxIndex::meetingAt(double theta, const std::array<double, 2>& low,
                                                    const std::array<double, 2>& high) const {
  constexpr double kAnglePad = 1e-9;
  const double reduced = std::remainder(theta, 2 * M_PI);
  PatchBox query{{low[0], low[1], 0}, {high[0], high[1], 0}};
  std::vector<std::uint32_t> patches;
  for (const double at : {reduced, reduced - 2 * M_PI, reduced + 2 * M_PI}) {
    if (at < -M_PI - kAnglePad || at > M_PI + kAnglePad) continue;
    query.low[2] = at - kAnglePad;
    query.high[2] = at + kAnglePad;
    const std::vector<std::uint32_t> found = meeting(query);
    patches.insert(patches.end(), found.begin(), found.end());
  }
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  return patches;
}

namespace {

/// A pair of patches as one number, the smaller in the high half (sorted faster).
std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) { return std::uint64_t{std::min(a, b)} << 32 | std::max(a, b); }

/// The pairs of boxes of different patches in one cell (its entries sorted by
/// lowest angle) that meet and that the cell reports (BoxGrid), as pair keys.
void addPairsInCell(const BoxGrid& grid, const std::vector<std::pair<PatchBox, std::uint32_t>>& boxes,
                    std::vector<CellEntry>::const_iterator cellStart, std::vector<CellEntry>::const_iterator cellEnd,
                    std::vector<std::uint64_t>& pairKeys) {
  for (auto i = cellStart; i != cellEnd; ++i) {
    const auto& [a, patchA] = boxes[i->box];
    // The boxes that follow up to a's highest angle are the only ones that can meet it.
    for (auto j = i + 1; j != cellEnd && j->lowestAngle <= a.high[2]; ++j) {
      const auto& [b, patchB] = boxes[j->box];
      if (patchA == patchB || !meet(a, b)) continue;
      const std::uint64_t corner =
          BoxGrid::key(grid.cellOf(std::max(a.low[0], b.low[0])), grid.cellOf(std::max(a.low[1], b.low[1])));
      if (corner == i->cell) pairKeys.push_back(pairKey(patchA, patchB));
    }
  }
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> PatchBoxIndex::meetingPairs(
    const Cancellation& cancellation) const {
  const BoxGrid grid(boxes_, scales_);
  std::vector<CellEntry> entries;
  for (std::uint32_t b = 0; b < boxes_.size(); ++b) {
    const PatchBox& box = boxes_[b].first;
    grid.forEachCell(box, [&](std::uint64_t cell) { entries.push_back({cell, box.low[2], b}); });
  }
  std::sort(entries.begin(), entries.end());
  std::vector<std::uint64_t> pairKeys;
  for (auto cellStart = entries.cbegin(); cellStart != entries.cend();) {
    cancellation.check();
    const auto cellEnd = std::find_if(cellStart, entries.cend(),
                                      [cell = cellStart->cell](const CellEntry& entry) { return entry.cell != cell; });
    addPairsInCell(grid, boxes_, cellStart, cellEnd, pairKeys);
    cellStart = cellEnd;
  }
  // Two arcs of one patch may both meet another patch.
  std::sort(pairKeys.begin(), pairKeys.end());
  pairKeys.erase(std::unique(pairKeys.begin(), pairKeys.end()), pairKeys.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const std::uint64_t key : pairKeys) {
    const auto first = static_cast<std::uint32_t>(key >> 32), second = static_cast<std::uint32_t>(key);
    if (piecesMeet(first, second)) pairs.emplace_back(first, second);
  }
  return pairs;
}

bool PatchBoxIndex::pieceMeets(std::uint32_t patch, const PatchBox& query) const {
  // The pieces are sorted by their lowest angle and at most widestPiece_ wide: those
  // that can meet the query start within that of its lowest angle.
  const auto end = pieces_.begin() + static_cast<std::ptrdiff_t>(firstPiece_[patch + 1]);
  PatchBox bound = query;
  bound.low[2] -= widestPiece_;
  for (auto piece = std::lower_bound(pieces_.begin() + static_cast<std::ptrdiff_t>(firstPiece_[patch]), end, bound,
                                     lowerInAngle);
       piece != end && piece->low[2] <= query.high[2]; ++piece) {
    if (meet(*piece, query)) return true;
  }
  return false;
}

bool PatchBoxIndex::piecesMeet(std::uint32_t first, std::uint32_t second) const {
  return std::any_of(pieces_.begin() + static_cast<std::ptrdiff_t>(firstPiece_[first]),
                     pieces_.begin() + static_cast<std::ptrdiff_t>(firstPiece_[first + 1]),
                     [&](const PatchBox& piece) { return pieceMeets(second, piece); });
}

}  // namespace freespace
