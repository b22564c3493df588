// common/core/kept.hpp — values made once per process for their inputs: a
// map a figure's passes ask for again and again, a driver's answer.  A few
// are kept (the oldest dropped first); the values are shared, never changed.
// Safe from several threads (a window measures on its own): two that ask for
// the same missing value at once may both make it, the same value.
#pragma once
#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace ts {
template <class Key, class Value>
class Kept {
 public:
  explicit Kept(size_t most) : most_(most) {}
  // The value kept for `key`, else make() kept and returned.  Keys are
  // compared with ==, so any key that has it will do (a matrix, a string).
  template <class Make>
  Value get(const Key& key, Make&& make) {
    {
      std::lock_guard<std::mutex> hold(mutex_);
      for (const auto& [k, v] : made_)
        if (k == key) return v;
    }
    Value v = make();  // outside the lock: the others may go on asking
    std::lock_guard<std::mutex> hold(mutex_);
    if (made_.size() >= most_) made_.erase(made_.begin());
    made_.emplace_back(key, v);
    return v;
  }

 private:
  size_t most_;
  std::mutex mutex_;
  std::vector<std::pair<Key, Value>> made_;
};
}  // namespace ts
