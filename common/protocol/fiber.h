// A judge that can wait for its answer in the middle of a call and go on where it stopped.
//
// The harness judges a thousand random cases at a time, and each case's call must cross
// to the answerer's process. One round trip per call would cost more than the judging,
// so each case's judge runs as a fiber (a function with a stack of its own, on the one
// thread): when it calls the code under test, the call is recorded and the fiber waits;
// once every fiber waits or is done, the recorded calls go to the answerer at once, and
// each waiting fiber resumes inside its call, now with its answer (answerer.h). Nothing
// runs twice: a judge reads like the plain sequence of calls it is.
//
//   judge_items (common/harness/check.cpp)       case k's fiber
//   fiber.resume()  -------------------------->  judge: lab02::answerer::segment_plane(...)
//                                                  Answerer::ask: not known yet, record it
//                   <--------------------------    Fiber::wait()
//   remote::flush(): every recorded call sent,
//   the answers kept
//   fiber.resume()  -------------------------->    ask returns the answer; the judge goes on
//                   <--------------------------  judge returns: resume() says it is done
#pragma once

#include <exception>
#include <functional>
#include <memory>

namespace labkit::remote {

class Fiber {
 public:
  explicit Fiber(std::function<void()> body);
  ~Fiber();
  Fiber(const Fiber&) = delete;
  Fiber& operator=(const Fiber&) = delete;

  // Runs the body until it waits or returns: true once it has returned. What the body
  // throws is thrown again here, in the caller's stack.
  bool resume();

  // Inside a fiber: back to the resume() that ran it, until it is resumed again.
  static void wait();
  static bool inside();

  struct State;  // its stack and saved registers (fiber.cpp)

 private:
  std::unique_ptr<State> state_;
};

}  // namespace labkit::remote
