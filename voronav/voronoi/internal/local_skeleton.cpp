#include "voronav/voronoi/internal/local_skeleton.hpp"

#include "voronav/voronoi/memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <new>
#include <utility>
#include <vector>

#include <sys/mman.h>

namespace voronav::voronoi::internal {

namespace {

// Under AddressSanitizer every block comes from calloc, which it checks (it does not watch
// mapped memory).
#if defined(__SANITIZE_ADDRESS__)
#define VORONAV_ZEROED_CALLOC_ONLY 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VORONAV_ZEROED_CALLOC_ONLY 1
#endif
#endif
#ifdef VORONAV_ZEROED_CALLOC_ONLY
constexpr bool kCallocOnly = true;
#else
constexpr bool kCallocOnly = false;
#endif
constexpr std::size_t kMapBytes = std::size_t{1} << 16;  // larger blocks are mapped

// Freed mapped blocks kept for reuse, oldest first (a fresh mapping costs a page fault per page
// touched, more than clearing a block that is already mapped): rebuilding a diagram of the same
// size then needs no new pages. Shared by all threads; never destroyed (static destruction
// order).
struct BlockCache {
  std::mutex mutex;
  std::vector<std::pair<void*, std::size_t>> blocks;
  std::size_t bytes = 0;
  std::size_t limit = kDefaultKeptBlockLimit;  // at most this much is kept
};
BlockCache& block_cache() {
  static auto* cache = new BlockCache;
  return *cache;
}

}  // namespace

void* zeroed_alloc(std::size_t n) {
  if (kCallocOnly || n < kMapBytes) {
    void* p = std::calloc(n, 1);
    if (!p) throw std::bad_alloc();
    return p;
  }
  {
    BlockCache& c = block_cache();
    const std::lock_guard<std::mutex> lock(c.mutex);
    for (auto it = c.blocks.begin(); it != c.blocks.end(); ++it)
      if (it->second == n) {
        void* p = it->first;
        c.bytes -= n;
        c.blocks.erase(it);
        std::memset(p, 0, n);
        return p;
      }
  }
  void* p = mmap(nullptr, n, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  return p;
}

namespace {

// Takes the oldest blocks out of the cache until `incoming` more bytes fit under its limit; the
// caller unmaps them outside the lock. Called with the lock held.
std::vector<std::pair<void*, std::size_t>> evict_for(BlockCache& c, std::size_t incoming) {
  std::vector<std::pair<void*, std::size_t>> evicted;
  std::size_t k = 0;
  while (k < c.blocks.size() && c.bytes + incoming > c.limit) {
    c.bytes -= c.blocks[k].second;
    evicted.push_back(c.blocks[k++]);
  }
  c.blocks.erase(c.blocks.begin(), c.blocks.begin() + static_cast<std::ptrdiff_t>(k));
  return evicted;
}

void unmap_all(const std::vector<std::pair<void*, std::size_t>>& blocks) {
  for (const auto& [q, m] : blocks)
    munmap(q, m);
}

}  // namespace

void zeroed_free(void* p, std::size_t n) {
  if (!p) return;
  if (kCallocOnly || n < kMapBytes) {
    std::free(p);
    return;
  }
  // The oldest blocks make room (they are of a diagram that is gone).
  std::vector<std::pair<void*, std::size_t>> evicted;
  bool keep = false;
  {
    BlockCache& c = block_cache();
    const std::lock_guard<std::mutex> lock(c.mutex);
    if (n <= c.limit) {
      evicted = evict_for(c, n);
      c.blocks.emplace_back(p, n);
      c.bytes += n;
      keep = true;
    }
  }
  if (!keep) munmap(p, n);
  unmap_all(evicted);
}

}  // namespace voronav::voronoi::internal

namespace voronav::voronoi {

void set_kept_block_limit(std::size_t bytes) {
  std::vector<std::pair<void*, std::size_t>> evicted;
  {
    internal::BlockCache& c = internal::block_cache();
    const std::lock_guard<std::mutex> lock(c.mutex);
    c.limit = bytes;
    evicted = internal::evict_for(c, 0);
  }
  internal::unmap_all(evicted);
}

std::size_t kept_block_limit() {
  internal::BlockCache& c = internal::block_cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  return c.limit;
}

bool kept_blocks_available() {
  return !internal::kCallocOnly;
}

std::size_t kept_block_bytes() {
  internal::BlockCache& c = internal::block_cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  return c.bytes;
}

}  // namespace voronav::voronoi

namespace voronav::voronoi::internal {

namespace {

// [lo, hi): the index range holding every set cell of `in` (empty: lo == hi). Scans 8 bytes at
// a time (the sets are sparse).
std::pair<std::size_t, std::size_t> set_range(const CellVector<std::uint8_t>& in,
                                              std::pair<std::size_t, std::size_t> span) {
  const std::size_t n = std::min(in.size(), span.second);
  auto word = [&](std::size_t i) {
    std::uint64_t v = 0;
    std::memcpy(&v, in.data() + i, 8);
    return v;
  };
  std::size_t lo = std::min(span.first, n);
  while (lo + 8 <= n && word(lo) == 0)
    lo += 8;
  while (lo < n && in[lo] == 0)
    ++lo;
  if (lo == n) return {0, 0};
  std::size_t hi = n;
  while (hi >= lo + 8 && word(hi - 8) == 0)
    hi -= 8;
  while (hi > lo && in[hi - 1] == 0)
    --hi;
  return {lo, hi};
}

}  // namespace

bool ParallelThinning::removable(const CellVector<std::uint8_t>& in, std::size_t c, int t) const {
  int nb[8];
  int deg = 0;
  for (int k = 0; k < 8; ++k) {
    const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + r_.offset(k));
    nb[k] = in[j] && removed_at(j) >= t ? 1 : 0;
    deg += nb[k];
  }
  if (deg < 2) return false;  // end points and isolated cells stay
  int n = 0;                  // Yokoi 8-connectivity number
  for (int k = 0; k < 8; k += 2) {
    const int a = 1 - nb[k], b = 1 - nb[k + 1], d = 1 - nb[(k + 2) % 8];
    n += a - a * b * d;
  }
  if (n != 1) return false;
  auto at = [&](int k) {
    return static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + r_.offset(k));
  };
  // The lowest key of a full 2x2 block goes (the result is one cell wide).
  for (int k = 0; k < 8; k += 2)
    if (nb[k] && nb[k + 1] && nb[(k + 2) % 8] && key_less(c, at(k)) && key_less(c, at(k + 1)) &&
        key_less(c, at((k + 2) % 8)))
      return true;
  // The corner of an L of three cells goes (its two arms touch diagonally: no 3-cell cycles).
  for (int k = 0; k < 8; k += 2)
    if (nb[k] && nb[(k + 2) % 8] && !nb[k + 1]) return true;
  // A border cell on the low side of the band goes (the ridge of the key field stays).
  for (int k = 0; k < 8; k += 2)
    if (nb[k] && !nb[(k + 4) % 8] && key_less(c, at(k))) return true;
  return false;
}

void ParallelThinning::build(const CellVector<std::uint8_t>& in,
                             const CellVector<std::int64_t>& key,
                             std::pair<std::size_t, std::size_t> span) {
  key_ = &key;
  const std::size_t n = in.size();
  cells_.reset(n);  // all kept, no record, not seen (zero pages: untouched cells cost nothing)
  epoch_ = 0;
  const auto [lo, hi] = set_range(in, span);  // sparse maps: only the range of the set is scanned
  std::vector<std::size_t> lists[4];
  for (std::size_t c = lo; c < hi; ++c)
    if (in[c]) lists[subfield(c)].push_back(c);
  int quiet = 0, last = -1;
  for (int t = 0;; ++t) {
    bool removed = false;
    auto& list = lists[t & 3];
    for (const std::size_t c : list) {
      if (removed_at(c) != kNever || !removable(in, c, t)) continue;
      set_removed(c, t);
      removed = true;
    }
    if (removed) {
      quiet = 0;
      last = t;
      std::erase_if(list, [&](std::size_t c) { return removed_at(c) != kNever; });
    } else if (++quiet >= 4) {
      break;
    }
  }
  steps_ = last + 1;
  out_ = CellVector<std::uint8_t>(n);
  for (std::size_t c = lo; c < hi; ++c)
    out_[c] = in[c] && removed_at(c) == kNever ? 1 : 0;
}

std::vector<Delta> ParallelThinning::update(const CellVector<std::uint8_t>& in,
                                            const std::vector<Delta>& in_changes,
                                            const CellVector<std::int64_t>& key,
                                            const std::vector<std::size_t>& key_changes,
                                            std::size_t* work,
                                            const CellVector<std::uint8_t>* fixed_point) {
  key_ = &key;
  const auto w = static_cast<std::ptrdiff_t>(r_.width);
  const auto h = static_cast<std::ptrdiff_t>(r_.height);
  const auto uw = static_cast<std::size_t>(r_.width);
  std::vector<Rec>& recs = recs_;
  recs.clear();
  // Records whose old and new alive intervals may still differ at the current step or later
  // (indices into recs); a record leaves when both runs agree from then on and comes back when
  // its removal step changes.
  std::vector<std::uint32_t>& active = active_;
  active.clear();
  // The records mirror the new state of their cells (new_in, new_removed_at), so the scan of
  // the records at every step reads no per-cell array.
  auto touch = [&](std::size_t c, std::uint8_t old_in) -> Rec& {
    CellState& cc = cells_[c];
    if (cc.rec & kRecIndex) return recs[(cc.rec & kRecIndex) - 1];
    cc.rec = (cc.rec & ~kRecIndex) | (static_cast<std::uint32_t>(recs.size()) + 1);
    recs.push_back({c, old_in, in[c], removed_at(c), removed_at(c),
                    static_cast<std::int32_t>(c % uw), static_cast<std::int32_t>(c / uw), false});
    return recs.back();
  };
  int last_change = -1;  // the step of the latest change of the replay's inputs (-1: before)
  int step = -1;
  std::vector<Rec>& perm = perm_;
  perm.clear();
  auto activate = [&](std::size_t c) {
    Rec& rec = recs[(cells_[c].rec & kRecIndex) - 1];
    if (!rec.active) {
      rec.active = true;
      active.push_back((cells_[c].rec & kRecIndex) - 1);
    }
  };
  // The cells within 2 of c (clamped to the raster).
  auto around2 = [&](std::size_t c, auto&& f) {
    const auto x = static_cast<std::ptrdiff_t>(c % uw), y = static_cast<std::ptrdiff_t>(c / uw);
    const std::ptrdiff_t x0 = std::max<std::ptrdiff_t>(0, x - 2), x1 = std::min(w - 1, x + 2);
    for (std::ptrdiff_t yy = std::max<std::ptrdiff_t>(0, y - 2); yy <= std::min(h - 1, y + 2); ++yy)
      for (std::ptrdiff_t xx = x0; xx <= x1; ++xx)
        if (f(static_cast<std::size_t>(yy * w + xx))) return true;
    return false;
  };
  // Dormant changes (see fixed_point in the header) wake up when the replay removes a cell
  // within 2 of them: from the next step on the cells between may see a dead cell of the
  // fixed point.
  std::size_t dormant = 0;
  last_woken_ = 0;
  auto wake_around = [&](std::size_t c) {
    around2(c, [&](std::size_t y) {
      std::uint32_t& r = cells_[y].rec;
      if (r & kDormantChange) {
        r &= ~kDormantChange;
        --dormant;
        ++last_woken_;
        touch(y, in[y] ? 0 : 1);
        activate(y);
        last_change = step;
      }
      if (r & kDormantKey) {
        r &= ~kDormantKey;
        --dormant;
        ++last_woken_;
        if (in[y])
          perm.push_back({y, 1, 1, 0, 0, static_cast<std::int32_t>(y % uw),
                          static_cast<std::int32_t>(y / uw), false});
        last_change = step;
      }
      return false;
    });
  };
  auto set_removed_at = [&](std::size_t c, std::int32_t t) {
    last_change = step;
    Rec& rec = touch(c, in[c]);
    rec.new_removed_at = t;
    set_removed(c, t);
    activate(c);
    if (dormant > 0 && t != kNever) wake_around(c);
  };
  // With a fixed point F of the input: a change or key change matters only within 2 of a cell
  // of F that is dead at some step, in the stored run (removed there) or the new one (not in
  // the input, or removed by the replay); the others start dormant. Decided before any removal
  // step is reset.
  std::vector<std::uint8_t>& relevant = relevant_;
  relevant.clear();
  if (fixed_point) {
    const CellVector<std::uint8_t>& f = *fixed_point;
    auto hot = [&](std::size_t c) {
      return around2(c, [&](std::size_t y) { return (f[y] && !in[y]) || cells_[y].removed != 0; });
    };
    for (const Delta& d : in_changes)
      relevant.push_back(hot(d.cell) ? 1 : 0);
    for (const std::size_t k : key_changes)
      relevant.push_back(!in[k] || hot(k) ? 1 : 0);
  }
  for (std::size_t i = 0; i < in_changes.size(); ++i) {
    const Delta& d = in_changes[i];
    if (!relevant.empty() && !relevant[i]) {
      if (!(cells_[d.cell].rec & kDormantChange)) ++dormant;
      cells_[d.cell].rec |= kDormantChange;
      continue;
    }
    touch(d.cell, d.old_value);
    set_removed_at(d.cell, kNever);  // decided again below
  }
  // Cells of the set whose key changed: dirty at every step while they are alive (the key of a
  // dead cell is never read again, so it leaves the list).
  for (std::size_t i = 0; i < key_changes.size(); ++i) {
    const std::size_t k = key_changes[i];
    if (!in[k]) continue;
    if (!relevant.empty() && !relevant[in_changes.size() + i]) {
      if (!(cells_[k].rec & kDormantKey)) ++dormant;
      cells_[k].rec |= kDormantKey;
      continue;
    }
    perm.push_back({k, 1, 1, 0, 0, static_cast<std::int32_t>(k % uw),
                    static_cast<std::int32_t>(k / uw), false});
  }

  std::vector<std::size_t>& cand = cand_;
  const int old_steps = steps_;
  int quiet = 0, last = -1;
  for (auto& sc : cache_)
    sc.t0 = -1;
  for (int t = 0;; ++t) {
    step = t;
    const int sf = t & 3;
    std::erase_if(perm, [&](const Rec& p) { return removed_at(p.cell) < t; });
    // The candidates of this subfield are those of four steps ago when nothing changed since:
    // no removal step was set again, no record crossed the end of its differing interval and
    // no key-changed cell died (late steps, where the run is quiet, reuse the list).
    SubfieldCache& sc = cache_[static_cast<std::size_t>(sf)];
    bool any_diff = false;
    if (sc.t0 == t - 4 && last_change < sc.t0 && t < sc.valid_until &&
        perm.size() == sc.perm_size) {
      any_diff = sc.any_diff;
      cand.assign(sc.cand.begin(), sc.cand.end());
      sc.t0 = t;
    } else {
      if (++epoch_ == 0) {
        for (std::size_t c = 0; c < cells_.size(); ++c)
          cells_[c].seen = 0;
        epoch_ = 1;
      }
      cand.clear();
      // The cells of the current subfield in the 3x3 neighbourhood of c (at x, y).
      auto add_around = [&](std::size_t c, std::int32_t cx, std::int32_t cy) {
        const std::ptrdiff_t fx = (cx & 1) == (sf & 1) ? 0 : -1;
        const std::ptrdiff_t fy = (cy & 1) == ((sf >> 1) & 1) ? 0 : -1;
        for (std::ptrdiff_t dy = fy; dy <= 1; dy += 2)
          for (std::ptrdiff_t dx = fx; dx <= 1; dx += 2) {
            const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + dy * w + dx);
            if (!in[j] || cells_[j].seen == epoch_) continue;
            cells_[j].seen = epoch_;
            cand.push_back(j);
          }
      };
      // A record's cell is alive up to step oa in the stored run and na in the new one (-1:
      // never alive); the two differ at the steps t with min < t <= max.
      std::size_t kept = 0;
      int valid_until = kNever;  // the first later step at which a record's difference flips
      for (const std::uint32_t k : active) {
        Rec& rec = recs[k];
        const std::int32_t oa = rec.old_in ? rec.old_removed_at : -1;
        const std::int32_t na = rec.new_in ? rec.new_removed_at : -1;
        const std::int32_t lo = std::min(oa, na), hi = std::max(oa, na);
        if (lo == hi || hi < t) {  // equal from here on (until the removal step changes again)
          rec.active = false;
          continue;
        }
        active[kept++] = k;
        if (lo >= t) {
          valid_until = std::min(valid_until, lo + 1);
          continue;
        }
        if (hi < kNever) valid_until = std::min(valid_until, hi + 1);
        any_diff = true;
        add_around(rec.cell, rec.x, rec.y);
      }
      active.resize(kept);
      if (any_diff || !perm.empty()) {
        for (const Rec& p : perm)
          add_around(p.cell, p.x, p.y);
        sc.t0 = t;
        sc.valid_until = valid_until;
        sc.perm_size = perm.size();
        sc.any_diff = any_diff;
        sc.cand.assign(cand.begin(), cand.end());
      }
    }
    if (!any_diff && perm.empty()) break;  // the same state as the stored run from here on
    bool removed = false;
    for (const std::size_t c : cand) {
      const std::int32_t at = removed_at(c);
      if (at < t) continue;
      if (work) ++*work;
      if (removable(in, c, t)) {
        removed = true;
        if (at != t) set_removed_at(c, t);
      } else if (at == t) {
        set_removed_at(c, kNever);
      }
    }
    if (removed) {
      quiet = 0;
      last = t;
    } else {
      ++quiet;
    }
    // Past the stored run's last removal, four quiet steps of the changed cells end it.
    if (quiet >= 4 && t - 3 >= old_steps) break;
  }
  steps_ = std::max(old_steps, last + 1);
  last_dormant_ = dormant + last_woken_;
  std::vector<Delta> out;
  if (dormant > 0) {
    // Still dormant: kept in both runs; the output follows the input there.
    for (const Delta& d : in_changes) {
      std::uint32_t& r = cells_[d.cell].rec;
      if (!(r & kDormantChange)) continue;
      r &= ~kDormantChange;
      out_[d.cell] = in[d.cell];
      out.push_back({d.cell, d.old_value});
    }
    for (const std::size_t k : key_changes)
      cells_[k].rec &= ~kDormantKey;
  }
  for (const Rec& rec : recs) {
    cells_[rec.cell].rec = 0;
    const std::uint8_t was = rec.old_in && rec.old_removed_at == kNever ? 1 : 0;
    const std::uint8_t now = in[rec.cell] && removed_at(rec.cell) == kNever ? 1 : 0;
    if (was == now) continue;
    out_[rec.cell] = now;
    out.push_back({rec.cell, was});
  }
  return out;
}

bool ParallelPruning::walk(const CellVector<std::uint8_t>& in, std::size_t e, double max_len,
                           std::vector<std::size_t>& path) const {
  path.assign(1, e);
  std::size_t prev = e, cur = e;
  double length = 0.0;
  while (cur == e || skeleton_degree(in.data(), r_, cur) < 3) {
    if (length >= max_len) return false;  // longer than any threshold: kept
    // Next cell: a neighbour not yet on the path, straight neighbours first.
    std::size_t next = cur;
    double step = 0.0;
    for (int pass = 0; pass < 2 && next == cur; ++pass)
      for (int k = pass; k < 8; k += 2) {
        const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cur) + r_.offset(k));
        if (!in[j] || j == prev) continue;
        const auto back = std::min<std::ptrdiff_t>(3, static_cast<std::ptrdiff_t>(path.size()));
        if (std::find(path.end() - back, path.end(), j) != path.end()) continue;
        next = j;
        step = pass == 0 ? 1.0 : std::sqrt(2.0);
        break;
      }
    if (next == cur) return false;  // the other end of an isolated branch: never pruned
    length += step;
    prev = cur;
    cur = next;
    path.push_back(cur);
  }
  const double threshold =
      std::max(min_cells_, ratio_ * std::sqrt(static_cast<double>((*d2_)[cur])));
  if (length >= threshold) return false;
  path.pop_back();  // the junction stays
  return true;
}

void ParallelPruning::build(const CellVector<std::uint8_t>& in, const CellVector<std::int64_t>& d2,
                            double max_len, std::pair<std::size_t, std::size_t> span) {
  d2_ = &d2;
  const std::size_t n = in.size();
  slots_.reset(n);  // no owner, not seen
  epoch_ = 0;
  spurs_.clear();
  std::vector<std::size_t> path;
  const auto [lo, hi] = set_range(in, span);
  for (std::size_t c = lo; c < hi; ++c) {
    if (!in[c] || skeleton_degree(in.data(), r_, c) != 1 || !walk(in, c, max_len, path)) continue;
    for (const std::size_t p : path)
      set_owner(p, c);
    spurs_.emplace(c, path);
  }
  out_ = CellVector<std::uint8_t>(n);
  for (std::size_t c = lo; c < hi; ++c)
    out_[c] = in[c] && owner(c) < 0 ? 1 : 0;
}

std::vector<Delta> ParallelPruning::update(const CellVector<std::uint8_t>& in,
                                           const std::vector<Delta>& in_changes,
                                           const CellVector<std::int64_t>& d2,
                                           const std::vector<std::size_t>& key_changes,
                                           double max_len, std::size_t* work) {
  d2_ = &d2;
  std::vector<std::size_t>& dirty = dirty_;  // scratch vectors keep their capacity
  dirty.clear();
  for (const Delta& d : in_changes)
    dirty.push_back(d.cell);
  for (const std::size_t k : key_changes)  // the clearance matters at junctions only
    if (in[k] && skeleton_degree(in.data(), r_, k) >= 3) dirty.push_back(k);
  if (dirty.empty()) return {};
  const auto w = static_cast<std::ptrdiff_t>(r_.width);
  const auto h = static_cast<std::ptrdiff_t>(r_.height);
  // The cells within 2 of a dirty cell (a spur's decision reads its path, its junction and
  // their 3x3 neighbourhoods; the junction touches the path).
  auto around = [&](std::size_t c, auto&& f) {
    const auto x = static_cast<std::ptrdiff_t>(c) % w, y = static_cast<std::ptrdiff_t>(c) / w;
    const std::ptrdiff_t x0 = std::max<std::ptrdiff_t>(0, x - 2), x1 = std::min(w - 1, x + 2);
    for (std::ptrdiff_t yy = std::max<std::ptrdiff_t>(0, y - 2); yy <= std::min(h - 1, y + 2); ++yy)
      for (std::ptrdiff_t xx = x0; xx <= x1; ++xx)
        f(static_cast<std::size_t>(yy * w + xx));
  };
  if (++epoch_ == 0) {
    for (std::size_t c = 0; c < slots_.size(); ++c)
      slots_[c].seen = 0;
    epoch_ = 1;
  }
  std::vector<std::size_t>&touched = touched_, &candidates = candidates_;
  std::vector<std::pair<std::size_t, int>>& queue = queue_;
  touched.clear();
  candidates.clear();
  queue.clear();
  // Undoes the stored spur through c, if any (its end is walked again below).
  auto undo = [&](std::size_t c) {
    if (owner(c) < 0) return;
    const auto e = static_cast<std::size_t>(owner(c));
    const auto it = spurs_.find(e);
    for (const std::size_t p : it->second) {
      slots_[p].owner = 0;
      touched.push_back(p);
    }
    spurs_.erase(it);
    candidates.push_back(e);
  };
  // 1. Undo the stored spurs that pass near a dirty cell, and 2. collect the set cells near the
  // dirty ones (one pass over the 5x5 neighbourhoods): the ends whose spur may pass near a dirty
  // cell now are found by walking out from them through cells of at most two neighbours, no
  // farther than the longest spur. Stored spurs lie on cells of the old input: a cell near a
  // dirty one that is not in the input now was not in it before either, unless it changed
  // itself (those are undone first), so only the cells of the input are looked at (the per-cell
  // slots are read for the few skeleton cells of each window, not for all 25 cells).
  for (const Delta& d : in_changes)
    if (d.old_value) undo(d.cell);
  for (const std::size_t d : dirty)
    around(d, [&](std::size_t c) {
      if (!in[c]) return;
      Slot& s = slots_[c];
      if (s.seen == epoch_) return;  // the neighbourhoods of nearby dirty cells overlap
      s.seen = epoch_;
      undo(c);
      queue.emplace_back(c, 0);
    });
  const int max_depth = static_cast<int>(std::ceil(max_len)) + 3;
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const auto [c, depth] = queue[q];
    if (work) ++*work;
    const int deg = skeleton_degree(in.data(), r_, c);
    if (deg == 1) candidates.push_back(c);
    if ((deg >= 3 && depth > 0) || depth >= max_depth) continue;
    for (int k = 0; k < 8; ++k) {
      const auto j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + r_.offset(k));
      if (!in[j] || slots_[j].seen == epoch_) continue;
      slots_[j].seen = epoch_;
      queue.emplace_back(j, depth + 1);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<std::size_t>& path = path_;
  for (const std::size_t e : candidates) {
    if (!in[e] || owner(e) >= 0 || skeleton_degree(in.data(), r_, e) != 1) continue;
    if (!walk(in, e, max_len, path)) continue;
    for (const std::size_t p : path) {
      set_owner(p, e);
      touched.push_back(p);
    }
    spurs_.emplace(e, path);
  }
  for (const Delta& d : in_changes)
    touched.push_back(d.cell);
  // A cell listed twice is equal to out_ the second time (no sort needed).
  std::vector<Delta> out;
  for (const std::size_t c : touched) {
    const std::uint8_t now = in[c] && owner(c) < 0 ? 1 : 0;
    if (now == out_[c]) continue;
    out.push_back({c, out_[c]});
    out_[c] = now;
  }
  return out;
}

}  // namespace voronav::voronoi::internal
