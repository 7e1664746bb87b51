#include "common/protocol/fiber.h"

#include <cxxabi.h>
#include <sys/mman.h>
#include <ucontext.h>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

namespace labkit::remote {

namespace {

// A judge's deepest stack (CGAL's exact arithmetic included) is well under this; the 64 KB
// below it are kept unmapped, so that an overflow stops the process (the harness's crash
// handler, on its own signal stack, names the case) instead of writing over another
// fiber's stack.
constexpr std::size_t kStackBytes = std::size_t(1) << 20;
constexpr std::size_t kGuardBytes = std::size_t(64) << 10;

// Stacks are kept for the next fibers: a batch starts a thousand of them.
std::vector<char*>& free_stacks() {
  static std::vector<char*> stacks;
  return stacks;
}

char* take_stack() {
  if (!free_stacks().empty()) {
    char* stack = free_stacks().back();
    free_stacks().pop_back();
    return stack;
  }
  void* p = mmap(nullptr, kGuardBytes + kStackBytes, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  mprotect(p, kGuardBytes, PROT_NONE);
  return static_cast<char*>(p) + kGuardBytes;
}

void give_back(char* stack) {
  constexpr std::size_t kKept = 64;
  if (free_stacks().size() < kKept)
    free_stacks().push_back(stack);
  else
    munmap(stack - kGuardBytes, kGuardBytes + kStackBytes);
}

// The exceptions being handled, which the C++ runtime keeps per thread (libsupc++'s
// __cxa_eh_globals: the chain of caught exceptions, and the count of uncaught ones). A
// fiber that waits inside a catch block must find its own chain when it resumes, as a
// thread would, so each switch trades them.
struct HandledExceptions {
  void* caught = nullptr;
  unsigned int uncaught = 0;
};
HandledExceptions& handled_now() { return *reinterpret_cast<HandledExceptions*>(abi::__cxa_get_globals()); }

}  // namespace

struct Fiber::State {
  std::function<void()> body;
  char* stack = nullptr;
  ucontext_t context{};
  ucontext_t caller{};
  HandledExceptions handled;
  std::exception_ptr thrown;
  bool started = false, done = false;
};

namespace {
Fiber::State* running = nullptr;  // the fiber whose body runs now, if any

void start_running() {
  Fiber::State& s = *running;
  try {
    s.body();
  } catch (...) {
    s.thrown = std::current_exception();
  }
  s.done = true;
  // Returning would end the thread: back to resume() for good.
  swapcontext(&s.context, &s.caller);
}
}  // namespace

Fiber::Fiber(std::function<void()> body) : state_(std::make_unique<State>()) { state_->body = std::move(body); }

Fiber::~Fiber() {
  // A fiber left waiting (its batch failed) is dropped with its stack: its frames never run again.
  if (state_->stack) give_back(state_->stack);
}

bool Fiber::resume() {
  State& s = *state_;
  if (s.done) return true;
  if (running) throw std::logic_error("kit error: a fiber resumed from inside another");
  if (!s.started) {
    s.stack = take_stack();
    getcontext(&s.context);
    s.context.uc_stack.ss_sp = s.stack;
    s.context.uc_stack.ss_size = kStackBytes;
    s.context.uc_link = nullptr;
    makecontext(&s.context, start_running, 0);
    s.started = true;
  }
  const HandledExceptions mine = handled_now();
  handled_now() = s.handled;
  running = &s;
  swapcontext(&s.caller, &s.context);
  running = nullptr;
  s.handled = handled_now();
  handled_now() = mine;
  if (s.done) {
    give_back(s.stack);
    s.stack = nullptr;
    if (s.thrown) std::rethrow_exception(std::exchange(s.thrown, nullptr));
  }
  return s.done;
}

void Fiber::wait() {
  if (!running) throw std::logic_error("kit error: Fiber::wait outside a fiber");
  State& s = *running;
  swapcontext(&s.context, &s.caller);
}

bool Fiber::inside() { return running != nullptr; }

}  // namespace labkit::remote
