// The kept-block pool behind the GVD's large per-cell arrays (internal::zeroed_alloc).
//
// A full GVD build maps its large arrays fresh from the system; when a diagram is destroyed its
// blocks are kept (up to a limit) so that the next build of the same size reuses mapped pages
// instead of paying a page fault per page. The pool is process-wide. Its limit (default 128 MiB)
// is an option: 0 turns keeping off, which suits a process that builds one big diagram and then
// needs the memory for something else. Builds under AddressSanitizer never use the pool.
#pragma once

#include <cstddef>

namespace voronav::voronoi {

inline constexpr std::size_t kDefaultKeptBlockLimit = std::size_t{128} << 20;

/// Sets the most bytes of freed blocks the pool keeps; lowering it releases the oldest blocks
/// at once.
void set_kept_block_limit(std::size_t bytes);
/// The current limit in bytes.
std::size_t kept_block_limit();
/// Bytes currently kept in the pool (0 under AddressSanitizer, which never uses it).
std::size_t kept_block_bytes();
/// False in builds under AddressSanitizer, whose large arrays come from calloc (checked by it).
bool kept_blocks_available();

}  // namespace voronav::voronoi
