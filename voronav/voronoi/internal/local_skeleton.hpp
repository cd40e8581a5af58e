// Thinning and spur pruning whose result is a function of the input alone (no scan order), so a
// change of the input can be propagated locally and still give exactly the full-build result.
//
// ParallelThinning is a cellular automaton on a padded raster: at step t only the cells of one
// of four subfields ((x mod 2, y mod 2), cycling) may be removed, all at once. Two cells of one
// subfield are never 8-adjacent, so removing simple cells of a subfield in parallel keeps the
// topology exactly as a sequential removal would. A cell c is removed at step t when it is alive,
// not an end (>= 2 alive neighbours), simple (Yokoi 8-connectivity number 1) and either
//  - it is the lowest key of a fully alive 2x2 block it belongs to (keeps the result one cell
//    wide), or
//  - it is the corner of an L of three cells (the two arms touch diagonally), or
//  - it has an alive 4-neighbour n with a higher key whose opposite 4-neighbour is not alive
//    (c is a border cell on the low side of the band: the ridge of the key field is kept).
// Keys are (squared clearance, cell index), a strict total order. The automaton stops after four
// quiet steps. Its whole run is stored as the removal step of every cell, so an update replays
// only the steps and cells whose 3x3 neighbourhood differs from the stored run.
//
// ParallelPruning removes, in one simultaneous round, every spur of its input: the path from an
// end cell to the first junction (>= 3 neighbours) when shorter than
// max(min_cells, ratio * clearance(junction)). Every spur is found on the unchanged input, so the
// order of the ends does not matter (two short spurs at one junction both go). An update redoes
// the spurs that pass within two cells of a changed cell: the stored ones found through the cells'
// owner, the new ones by walking out from the changed cells along cells of at most two
// neighbours to the ends, no farther than the longest possible spur.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "voronav/voronoi/internal/skeleton.hpp"

namespace voronav::voronoi::internal {

/// Zeroed memory of n bytes: a large block is mapped straight from the system (fresh zero pages,
/// of which only those touched later cost a page fault); a small one comes from calloc. (calloc
/// alone does not guarantee this: once the allocator has raised its mapping threshold after a
/// free, a large block comes from the heap and is cleared page by page.)
void* zeroed_alloc(std::size_t n);
void zeroed_free(void* p, std::size_t n);

/// An allocator of zeroed memory (zeroed_alloc) whose value-initialisation writes nothing: a
/// CellVector<T> v(n) holds n zeros and touches none of its pages until they are written, so an
/// array over the whole grid costs what its used part costs. Only for trivial types whose zero
/// bytes are the value-initialised value, and only grown from empty (a vector that shrinks and
/// grows again would keep the old values in the regrown part).
template <class T>
struct ZeroAllocator {
  static_assert(std::is_trivially_copyable_v<T>);
  using value_type = T;
  ZeroAllocator() = default;
  template <class U>
  explicit ZeroAllocator(const ZeroAllocator<U>& /*other*/) {}
  T* allocate(std::size_t n) { return static_cast<T*>(zeroed_alloc(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) { zeroed_free(p, n * sizeof(T)); }
  template <class U>
  void construct(U* /*p*/) noexcept {}  // already zero
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
  friend bool operator==(const ZeroAllocator& /*a*/, const ZeroAllocator& /*b*/) { return true; }
};
template <class T>
using CellVector = std::vector<T, ZeroAllocator<T>>;

/// A per-cell array of a trivial type, all bytes zero at the start (zeroed_alloc): the cells a
/// run never touches cost no time (a std::vector would write every cell). Copies copy the
/// contents.
template <class T>
class ZeroedArray {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  ZeroedArray() = default;
  ZeroedArray(const ZeroedArray& o) { copy_from(o); }
  ZeroedArray& operator=(const ZeroedArray& o) {
    if (this != &o) copy_from(o);
    return *this;
  }
  ZeroedArray(ZeroedArray&&) noexcept = default;
  ZeroedArray& operator=(ZeroedArray&&) noexcept = default;
  /// n cells, all zero (the old contents are dropped).
  void reset(std::size_t n) {
    data_.reset();
    size_ = 0;
    if (n == 0) return;
    data_ = std::unique_ptr<T[], Free>(static_cast<T*>(zeroed_alloc(n * sizeof(T))),
                                       Free{n * sizeof(T)});
    size_ = n;
  }
  [[nodiscard]] std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  struct Free {
    std::size_t bytes = 0;
    void operator()(T* p) const { zeroed_free(p, bytes); }
  };
  void copy_from(const ZeroedArray& o) {
    reset(o.size_);
    if (size_ > 0) std::memcpy(data_.get(), o.data_.get(), size_ * sizeof(T));
  }
  std::unique_ptr<T[], Free> data_;
  std::size_t size_ = 0;
};

/// An index range holding every cell.
inline constexpr std::pair<std::size_t, std::size_t> kAllCells{0, ~std::size_t{0}};

/// A cell whose value changed, with its value before the change.
struct Delta {
  std::size_t cell = 0;
  std::uint8_t old_value = 0;
};

class ParallelThinning {
 public:
  explicit ParallelThinning(const PaddedRaster& r) : r_(r) {}

  /// Full run on `in` (1 = cell of the input set); key: per padded cell (squared clearance).
  /// span: an index range [first, second) known to hold every cell of the set (only it is
  /// scanned).
  void build(const CellVector<std::uint8_t>& in, const CellVector<std::int64_t>& key,
             std::pair<std::size_t, std::size_t> span = kAllCells);
  /// `in` has already changed at in_changes (with their old values); key_changes lists the cells
  /// whose key changed. Returns the output cells that changed (with their old values).
  /// fixed_point (optional): a superset F of `in` in which no cell is removable (the output of
  /// a thinning with the same keys, of which `in` is a pruned subset). A cell can then only be
  /// removed when a cell of F in its 3x3 neighbourhood is dead (not in `in`, or removed
  /// before), so the changes farther than 2 cells from every such cell, in the stored run and
  /// in the new one, cannot change any decision: they are not replayed (the re-thinning after a
  /// pruning round then costs what the pruning changed, not what the first thinning changed).
  std::vector<Delta> update(const CellVector<std::uint8_t>& in,
                            const std::vector<Delta>& in_changes,
                            const CellVector<std::int64_t>& key,
                            const std::vector<std::size_t>& key_changes, std::size_t* work,
                            const CellVector<std::uint8_t>* fixed_point = nullptr);
  [[nodiscard]] const CellVector<std::uint8_t>& out() const { return out_; }
  /// Of the last update with a fixed point: the changes and key changes that started dormant,
  /// and those of them that a removal nearby woke up (replayed after all).
  [[nodiscard]] std::size_t last_dormant() const { return last_dormant_; }
  [[nodiscard]] std::size_t last_woken() const { return last_woken_; }
  /// Steps of the stored run (>= 1 + its last removal step).
  [[nodiscard]] int steps() const { return steps_; }

 private:
  static constexpr std::int32_t kNever = 0x7fffffff;
  [[nodiscard]] bool removable(const CellVector<std::uint8_t>& in, std::size_t c, int t) const;
  // Removal step of cell c (kNever: kept), stored as kNever - step so that 0 means kept.
  [[nodiscard]] std::int32_t removed_at(std::size_t c) const { return kNever - cells_[c].removed; }
  void set_removed(std::size_t c, std::int32_t t) { cells_[c].removed = kNever - t; }
  [[nodiscard]] bool key_less(std::size_t a, std::size_t b) const {
    const std::int64_t ka = (*key_)[a], kb = (*key_)[b];
    return ka != kb ? ka < kb : a < b;
  }
  [[nodiscard]] int subfield(std::size_t c) const {
    const auto w = static_cast<std::size_t>(r_.width);
    return static_cast<int>((c % w) & 1U) | static_cast<int>(((c / w) & 1U) << 1U);
  }

  PaddedRaster r_;
  const CellVector<std::int64_t>* key_ = nullptr;  // set for the duration of build/update
  CellVector<std::uint8_t> out_;
  int steps_ = 0;  // >= 1 + the last step that removed a cell
  std::size_t last_dormant_ = 0, last_woken_ = 0;
  // Per cell, side by side so that a replay, which visits scattered cells, reads one cache line
  // per cell instead of three: the step of the stored run that removed it (kNever - step; 0 =
  // kept), its record in the current update (index + 1; 0 = none) and the scratch mark of the
  // current step (epoch; 0 = never). All zero at the start: the array is allocated zeroed.
  // rec also holds two flags of update(): a dormant change and a dormant key change.
  struct CellState {
    std::int32_t removed;
    std::uint32_t rec;
    std::uint32_t seen;
  };
  static constexpr std::uint32_t kRecIndex = 0x3fffffffU;
  static constexpr std::uint32_t kDormantChange = 0x80000000U;
  static constexpr std::uint32_t kDormantKey = 0x40000000U;
  ZeroedArray<CellState> cells_;
  // Scratch for update().
  struct Rec {
    std::size_t cell;
    std::uint8_t old_in, new_in;
    std::int32_t old_removed_at, new_removed_at;
    std::int32_t x, y;  // coordinates (no division in the step loop)
    bool active;        // listed in active_
  };
  std::vector<Rec> recs_, perm_;
  std::vector<std::uint32_t> active_;
  std::vector<std::uint8_t> relevant_;
  std::vector<std::size_t> cand_;
  // The candidates of each subfield at its latest step t0, reusable four steps later while no
  // removal step changed, no record's difference flips (valid_until) and no key-changed cell
  // died (perm_size).
  struct SubfieldCache {
    int t0 = -1;
    int valid_until = 0;
    std::size_t perm_size = 0;
    bool any_diff = false;
    std::vector<std::size_t> cand;
  };
  SubfieldCache cache_[4];
  std::uint32_t epoch_ = 0;
};

class ParallelPruning {
 public:
  /// min_cells, ratio: spur threshold max(min_cells, ratio * sqrt(d2(junction))) [cells].
  ParallelPruning(const PaddedRaster& r, double min_cells, double ratio)
      : r_(r), min_cells_(min_cells), ratio_(ratio) {}

  /// d2: squared clearance per padded cell; max_len: an upper bound on every spur threshold
  /// (walks stop there).
  void build(const CellVector<std::uint8_t>& in, const CellVector<std::int64_t>& d2, double max_len,
             std::pair<std::size_t, std::size_t> span = kAllCells);
  std::vector<Delta> update(const CellVector<std::uint8_t>& in,
                            const std::vector<Delta>& in_changes,
                            const CellVector<std::int64_t>& d2,
                            const std::vector<std::size_t>& key_changes, double max_len,
                            std::size_t* work);
  [[nodiscard]] const CellVector<std::uint8_t>& out() const { return out_; }

 private:
  // Walks from end e; true (and the cells to remove in path) when the spur is pruned.
  bool walk(const CellVector<std::uint8_t>& in, std::size_t e, double max_len,
            std::vector<std::size_t>& path) const;

  PaddedRaster r_;
  const CellVector<std::int64_t>* d2_ = nullptr;  // set for the duration of build/update
  double min_cells_ = 0.0;
  double ratio_ = 0.0;
  CellVector<std::uint8_t> out_;
  // Per cell, side by side (one cache line per look, not two): the end of the pruned spur
  // through it (index + 1; 0 = none) and the scratch mark of update() (queued in the current
  // epoch; 0 = never). All zero at the start: the array is allocated zeroed.
  struct Slot {
    std::uint32_t owner;
    std::uint32_t seen;
  };
  ZeroedArray<Slot> slots_;
  [[nodiscard]] std::int64_t owner(std::size_t c) const {
    return static_cast<std::int64_t>(slots_[c].owner) - 1;
  }
  void set_owner(std::size_t c, std::size_t end) {
    slots_[c].owner = static_cast<std::uint32_t>(end) + 1;
  }
  std::unordered_map<std::size_t, std::vector<std::size_t>> spurs_;  // end -> removed path
  std::vector<std::size_t> dirty_, touched_, candidates_, path_;     // scratch of update()
  std::vector<std::pair<std::size_t, int>> queue_;
  std::uint32_t epoch_ = 0;
};

}  // namespace voronav::voronoi::internal
