// Runs the GA's children on worker threads (issue #16; not installed): item c goes to thread
// c mod T, thread 0 is the caller's. An exception thrown by any item (bad_alloc, an Error from an
// evaluation) is caught on its thread, every thread is joined, and the exception of the lowest
// item that threw is rethrown on the caller's thread, so it never reaches std::terminate and the
// caller sees the same exception for every thread count and timing.
#pragma once

#include <functional>

namespace voronav::coordination::internal {

/// Calls work(t, c) for c = t, t + T, t + 2T, ... < count on thread t = 0..T-1 (T = threads >= 1;
/// thread 0 is the calling thread). A thread stops at its first exception; after all threads are
/// joined, the exception of the lowest c is rethrown.
void run_strided(int count, int threads, const std::function<void(int thread, int item)>& work);

}  // namespace voronav::coordination::internal
