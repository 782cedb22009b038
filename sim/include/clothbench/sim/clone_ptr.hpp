#pragma once
/// A unique_ptr that copies its object through clone(): the Simulator, which owns its integrator and its
/// strain limiter this way, stays copyable.
#include <memory>
#include <utility>

namespace clothbench {

/// T has `std::unique_ptr<T> clone() const`.
template <class T>
class ClonePtr {
 public:
  ClonePtr() = default;
  explicit ClonePtr(std::unique_ptr<T> p) : p_(std::move(p)) {}
  ClonePtr(const ClonePtr& o) : p_(o.p_ ? o.p_->clone() : nullptr) {}
  ClonePtr& operator=(const ClonePtr& o) {
    if (this != &o) p_ = o.p_ ? o.p_->clone() : nullptr;
    return *this;
  }
  ClonePtr(ClonePtr&&) = default;
  ClonePtr& operator=(ClonePtr&&) = default;
  T* operator->() const { return p_.get(); }
  T& operator*() const { return *p_; }
  explicit operator bool() const { return p_ != nullptr; }

 private:
  std::unique_ptr<T> p_;
};

}  // namespace clothbench
