// FrameAhead: one worker thread that skins the next body frame and lets the collider prepare it.
#include "frame_ahead.hpp"

#include <utility>

#include "clothbench/sim/timer.hpp"

namespace clothbench::runner_detail {

FrameAhead::FrameAhead(const BodySource& source) : source_(source), worker_([this] { work(); }) {}

FrameAhead::~FrameAhead() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void FrameAhead::start(Collider& collider, double at) {
  wait();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    collider_ = &collider;
    t = at;
    busy_ = true;
  }
  changed_.notify_all();
}

void FrameAhead::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return !busy_; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void FrameAhead::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    // sleep until a frame is asked for (or the animation ends)
    changed_.wait(lock, [this] { return busy_ || quit_; });
    if (quit_) return;
    // skin and prepare it outside the lock; what throws goes to the waiter
    lock.unlock();
    try {
      Stopwatch skin;
      source_.frame_into(frame, t);
      skinning_ms = skin.ms();
      prepared = collider_->prepare_body(frame);
    } catch (...) {
      error_ = std::current_exception();
    }
    lock.lock();
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace clothbench::runner_detail
