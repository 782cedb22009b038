#pragma once
// The next body frame prepared on a second thread (body.prepare_ahead; bench/src only).
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "body_source.hpp"
#include "clothbench/sim/collider.hpp"

namespace clothbench::runner_detail {

// the next body frame, evaluated and handed to the collider's prepare_body on a second thread while the cloth steps
// through the current one (body.prepare_ahead): the body's motion is prescribed, so nothing of it waits on the cloth.
// One thread for the whole animation (an OpenGL context moving to a new thread every frame can cost more than the
// drawing)
class FrameAhead {
 public:
  explicit FrameAhead(const BodySource& source);
  FrameAhead(const FrameAhead&) = delete;
  FrameAhead& operator=(const FrameAhead&) = delete;
  ~FrameAhead();

  // the frame at `at`, its maps drawn by `collider`, under way on the worker
  void start(Collider& collider, double at);
  // until the frame under way is ready; rethrows what the worker threw
  void wait();

  BodyFrame frame;
  double t = -1;           // animation time of `frame`; < 0: none under way
  double skinning_ms = 0;  // its evaluation's time (on the worker)
  bool prepared = false;   // the collider prepared its update (else update_body does the work, in turn)

 private:
  void work();

  const BodySource& source_;
  Collider* collider_ = nullptr;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool busy_ = false, quit_ = false;
  std::exception_ptr error_;
  std::thread worker_;  // last: started once the members it reads exist
};

}  // namespace clothbench::runner_detail
