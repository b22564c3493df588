// common/core/parallel.hpp — a loop on both cores, the same result as on one.
#pragma once
#include <exception>
#include <thread>

namespace ts {
// f(y) for y = 0 .. count - 1: the even y on the calling thread, the odd on
// another.  For loops whose steps depend on y alone and write apart (an
// image's rows), so the result is the one a single thread makes.  An
// exception from f reaches the caller once both halves have stopped.
template <class F>
void evenAndOdd(int count, F&& f) {
  std::exception_ptr oddFailed;
  std::thread odd([&] {
    try {
      for (int y = 1; y < count; y += 2) f(y);
    } catch (...) {
      oddFailed = std::current_exception();
    }
  });
  try {
    for (int y = 0; y < count; y += 2) f(y);
  } catch (...) {
    odd.join();
    throw;
  }
  odd.join();
  if (oddFailed) std::rethrow_exception(oddFailed);
}
}  // namespace ts
