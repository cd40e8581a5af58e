#include "voronav/coordination/internal/strided_threads.hpp"

#include <exception>
#include <thread>
#include <vector>

namespace voronav::coordination::internal {

void run_strided(int count, int threads, const std::function<void(int thread, int item)>& work) {
  if (threads < 1) threads = 1;
  // One slot per thread: the item that threw first on it and its exception.
  std::vector<int> failed_item(static_cast<std::size_t>(threads), -1);
  std::vector<std::exception_ptr> failure(static_cast<std::size_t>(threads));
  auto body = [&](int t) {
    for (int c = t; c < count; c += threads) {
      try {
        work(t, c);
      } catch (...) {
        failed_item[static_cast<std::size_t>(t)] = c;
        failure[static_cast<std::size_t>(t)] = std::current_exception();
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  try {
    for (int t = 1; t < threads; ++t)
      pool.emplace_back(body, t);
  } catch (...) {  // a thread could not be started: the caller runs its items
    for (int t = static_cast<int>(pool.size()) + 1; t < threads; ++t)
      body(t);
  }
  body(0);
  for (auto& th : pool)
    th.join();
  int first = -1;
  for (int t = 0; t < threads; ++t) {
    const int c = failed_item[static_cast<std::size_t>(t)];
    if (c >= 0 && (first < 0 || c < failed_item[static_cast<std::size_t>(first)])) first = t;
  }
  if (first >= 0) std::rethrow_exception(failure[static_cast<std::size_t>(first)]);
}

}  // namespace voronav::coordination::internal
