#include "common/protocol/answerer.h"
#include "common/protocol/fiber.h"
#include "common/protocol/report.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_set>

namespace labkit::remote {

namespace {

using Clock = std::chrono::steady_clock;

// An answer may hold this many bytes for each byte of its request, and this many at least;
// beyond that, whatever is left of a batch's allowance. Most answers are small next to
// their request (lab 06's BSP trees hold at most 11 bytes per byte of it), but a correct
// answer need not be: an octree over a few balls that overlap splits to its max_depth
// (8 children a level), and three balls, capacity 1, depth 5 make 67 KB from 0.3 KB.
// The allowance takes such an answer whole while a batch's answers stay under 64 MB, and
// with the floor keeps a batch of 1,024 calls under 128 MB: no answer, and no batch, can
// run the judge's process out of memory.
constexpr std::size_t kAnswerPerRequestByte = 32;
constexpr std::size_t kSmallestLimit = std::size_t(64) << 10;
constexpr std::size_t kBatchAllowance = std::size_t(64) << 20;
constexpr std::size_t kGreetingLimit = 64;
// Replies to served calls that the answerer has not read yet: a legitimate caller reads
// each before it makes the next call, so this much means it does not read them at all.
constexpr std::size_t kUnreadReplies = std::size_t(16) << 20;
// Polls without waiting before one that sleeps (see exchange()).
constexpr int kSpins = 200;
constexpr const char* kHello = "labkit-answerer 1";
// Start-ups in a row that die before answering anything: then the program is broken
// as a whole (a crash in a static initialiser, say), and no call is tried again.
constexpr int kFailedStarts = 3;

std::vector<std::string> command_from_environment() {
  const char* v = std::getenv(report::variable::answerer);
  if (!v || !*v)
    throw std::runtime_error(
        "LABKIT_ANSWERER is not set: this test program runs the lab's code in a process of its own and needs its "
        "path (./labkit check and ctest set it; see common/protocol/answerer.h)");
  if (v[0] != '[') return {v};
  std::vector<std::string> argv;
  try {
    argv = nlohmann::json::parse(v).get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("LABKIT_ANSWERER is not a JSON array of strings: ") + e.what());
  }
  if (argv.empty()) throw std::runtime_error("LABKIT_ANSWERER is an empty command line");
  return argv;
}

// Reads whole frames out of a byte stream as it arrives.
class Frames {
 public:
  void add(const char* data, std::size_t n) {
    buffer_.erase(0, at_);  // what was read already, once per chunk received
    at_ = 0;
    buffer_.append(data, n);
  }
  // True and the frame's payload when one is complete. A frame longer than `largest`
  // throws as soon as its length is read, before its bytes are waited for or kept.
  bool next(std::string& payload, std::size_t largest) {
    if (buffer_.size() - at_ < sizeof(std::uint64_t)) return false;
    std::uint64_t n;
    std::memcpy(&n, buffer_.data() + at_, sizeof n);
    if (n > largest)
      throw std::runtime_error("its answer declares " + std::to_string(n) +
                               " bytes, more than any answer to this call can hold (at most " +
                               std::to_string(largest) + ")");
    if (buffer_.size() - at_ - sizeof n < n) return false;
    payload.assign(buffer_, at_ + sizeof n, n);
    at_ += sizeof n + n;
    return true;
  }

 private:
  std::string buffer_;
  std::size_t at_ = 0;
};

std::string signal_words(int s) {
  switch (s) {
    case SIGSEGV: return "segmentation fault: a read or write through a bad pointer or past an array's end";
    case SIGFPE: return "floating-point exception: an integer division by zero";
    case SIGABRT: return "aborted: a failed assert(), or an exception nobody caught";
    case SIGBUS: return "bus error: a misaligned or unmapped memory access";
    case SIGILL: return "illegal instruction";
    case SIGKILL: return "killed (SIGKILL): out of memory, or a limit was reached";
    case SIGXCPU: return "killed: the CPU-time limit was reached";
    case SIGXFSZ: return "killed: it wrote a file beyond the size limit";
  }
  return std::string("killed by signal ") + std::to_string(s) + " (" + strsignal(s) + ")";
}

// The batch, shared by every call of the process.
struct Batch {
  bool gathering = false;   // between begin_batch() and end_batch()
  int default_answers = 0;  // DefaultAnswers scopes open
  int examples = 0;         // RecordingExample scopes open
  std::vector<std::string> pending;
  std::unordered_map<std::string, Response> answers;
};
Batch batch;
bool started = false;  // an answerer exists

}  // namespace

Answerer& Answerer::instance() {
  started = true;
  static Answerer answerer(command_from_environment());
  return answerer;
}

Answerer::Answerer(std::vector<std::string> argv) : argv_(std::move(argv)) {
  // Writing to an answerer that just died must not kill the judge.
  std::signal(SIGPIPE, SIG_IGN);
  // What the answerer's confinement leaves behind when it is killed (bubblewrap's own
  // children) comes back to this process to be reaped at once. Left to the machine's
  // init, such zombies pile up under the answerer's uid until its process cap refuses
  // every new start.
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  if (const char* v = std::getenv(report::variable::call_seconds); v && *v) {
    const double s = std::strtod(v, nullptr);
    if (s > 0) call_limit_ = std::chrono::milliseconds(long(s * 1000));
  }
}

Answerer::~Answerer() { stop(true); }

bool Answerer::start() {
  int requests[2], answers[2], output[2];
  if (pipe2(requests, O_CLOEXEC) != 0) return false;
  if (pipe2(answers, O_CLOEXEC) != 0) {
    close(requests[0]), close(requests[1]);
    return false;
  }
  if (pipe2(output, O_CLOEXEC) != 0) {
    close(requests[0]), close(requests[1]), close(answers[0]), close(answers[1]);
    return false;
  }
  std::vector<char*> args;
  for (std::string& a : argv_) args.push_back(a.data());
  args.push_back(nullptr);
  char path[] = "PATH=/usr/bin:/bin";
  char* environment[] = {path, nullptr};  // nothing of the judge's: no seed, no settings
  const pid_t judge = getpid();

  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);  // its own group: a time-out ends everything it started
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != judge) _exit(127);
    const int null = open("/dev/null", O_RDONLY);
    dup2(null, 0);
    dup2(output[1], 1);  // its prints: to the judge, never into the protocol
    dup2(output[1], 2);
    // Out of the way first (the pipes may already sit on 3 or 4), then in place; dup2
    // leaves the copies open across exec.
    const int in = fcntl(requests[0], F_DUPFD_CLOEXEC, 10), out = fcntl(answers[1], F_DUPFD_CLOEXEC, 10);
    if (in < 0 || out < 0 || dup2(in, 3) != 3 || dup2(out, 4) != 4) _exit(127);
    // Nothing else the judge's process holds, or inherited from whoever started it,
    // reaches the code under test: its standard streams and the two pipes only.
    if (syscall(SYS_close_range, 5u, ~0u, 0u) != 0)
      for (int fd = 5; fd < 65536; ++fd) close(fd);
    execvpe(args[0], args.data(), environment);
    const std::string why =
        std::string("labkit: cannot run the code under test (") + argv_[0] + "): " + strerror(errno) + "\n";
    if (write(2, why.data(), why.size()) < 0) {}
    _exit(127);
  }
  close(requests[0]);
  close(answers[1]);
  close(output[1]);
  if (pid < 0) {
    close(requests[1]), close(answers[0]), close(output[0]);
    return false;
  }
  pid_ = pid;
  to_ = requests[1];
  from_ = answers[0];
  output_ = output[0];
  output_tail_.clear();
  fcntl(to_, F_SETFL, O_NONBLOCK);
  fcntl(from_, F_SETFL, O_NONBLOCK);
  fcntl(output_, F_SETFL, O_NONBLOCK);
  greeted_ = false;
  return true;
}

void Answerer::drain_output() {
  constexpr std::size_t kTail = 600;
  char buffer[1 << 14];
  while (output_ >= 0) {
    const ssize_t n = read(output_, buffer, sizeof buffer);
    if (n == 0) {  // it closed its output: nothing more will come
      close(output_);
      output_ = -1;
    }
    if (n <= 0) break;
    if (write(2, buffer, std::size_t(n)) < 0) {}
    output_tail_.append(buffer, std::size_t(n));
    if (output_tail_.size() > 2 * kTail) output_tail_.erase(0, output_tail_.size() - kTail);
  }
}

void Answerer::stop(bool kill_it) {
  if (to_ >= 0) close(to_);
  if (from_ >= 0) close(from_);
  if (output_ >= 0) close(output_);
  to_ = from_ = output_ = -1;
  if (pid_ > 0) {
    if (kill_it) {
      kill(-pid_, SIGKILL);
      kill(pid_, SIGKILL);
    }
    int status = 0;
    waitpid(pid_, &status, 0);
  }
  pid_ = -1;
  while (waitpid(-1, nullptr, WNOHANG) > 0) {}  // the orphans of its confinement
}

// After the answer stream ended: how the process ended, in words.
std::string Answerer::ended_how() {
  if (to_ >= 0) close(to_);
  if (from_ >= 0) close(from_);
  to_ = from_ = -1;
  drain_output();
  std::string how = "it stopped answering";
  // How it ended, read without reaping it: until it is reaped its pid stays its own, so
  // killing its group below can never reach a process that took the pid over.
  siginfo_t info{};
  if (pid_ > 0 && waitid(P_PID, id_t(pid_), &info, WEXITED | WNOWAIT) == 0) {
    const int code = info.si_status;
    if (info.si_code == CLD_KILLED || info.si_code == CLD_DUMPED) how = signal_words(code);
    // A confinement wrapper reports its child's signal N as exit status 128 + N.
    else if (code > 128 && code < 128 + 65)
      how = signal_words(code - 128);
    else if (code == 127)
      how = "its program could not be started (" + argv_[0] + ": the reason is in the output above)";
    else
      how = "the process exited with status " + std::to_string(code) +
            " in the middle of a call (exit(), quick_exit() or _exit() in the code?)";
  }
  stop(true);
  return how;
}

namespace {

// What goes to the answerer: the requests not answered yet, framed, and the replies to
// its served calls, which go out between two requests, never inside one.
class Outbox {
 public:
  Outbox(const std::vector<std::string>& requests, std::size_t from) {
    std::size_t size = 0;
    for (std::size_t i = from; i < requests.size(); ++i) size += sizeof(std::uint64_t) + requests[i].size();
    requests_.reserve(size);
    for (std::size_t i = from; i < requests.size(); ++i) append_frame(requests_, requests[i]);
  }
  bool pending() const { return written_ < requests_.size() || replied_ < replies_.size(); }
  std::size_t unsent_replies() const { return replies_.size(); }
  void reply(const std::string& reply) { append_frame(replies_, reply); }

  // Writes what the pipe takes: the rest of the request being sent, else a reply.
  void send(int fd) {
    if (written_ == frame_end_ && replied_ < replies_.size()) {
      const ssize_t n = write(fd, replies_.data() + replied_, replies_.size() - replied_);
      if (n > 0) replied_ += std::size_t(n);
      if (replied_ == replies_.size()) replies_.clear(), replied_ = 0;
      return;
    }
    if (written_ == frame_end_) {
      std::uint64_t n = 0;
      std::memcpy(&n, requests_.data() + written_, sizeof n);
      frame_end_ = written_ + sizeof n + std::size_t(n);
    }
    const ssize_t n = write(fd, requests_.data() + written_, frame_end_ - written_);
    if (n > 0) written_ += std::size_t(n);
  }

 private:
  static void append_frame(std::string& to, const std::string& payload) {
    const std::uint64_t n = payload.size();
    to.append(reinterpret_cast<const char*>(&n), sizeof n).append(payload);
  }
  std::string requests_, replies_;
  std::size_t written_ = 0, frame_end_ = 0;  // requests_[written_, frame_end_): the request being sent
  std::size_t replied_ = 0;
};

// Waits for one of `fds` to be ready, for at most `wait_ms`. A few quick looks first: the
// answerer often replies within microseconds (a served call's round trip), and waking
// from sleep costs far more on a VM. Each look yields the processor, so that on a busy
// machine the answerer runs instead.
int wait_ready(pollfd (&fds)[3], long long wait_ms) {
  int ready = 0;
  for (int spin = 0; spin < kSpins && ready == 0; ++spin)
    if ((ready = poll(fds, 3, 0)) == 0) sched_yield();
  if (ready == 0) ready = poll(fds, 3, int(std::min<long long>(wait_ms, 1000)));
  return ready;
}

}  // namespace

std::pair<Response::Kind, std::string> Answerer::serve(const std::vector<std::string>& requests, std::size_t& received,
                                                       std::vector<Response>& out, int& failed_starts) {
  Outbox outbox(requests, received);
  Frames frames;
  std::size_t answered_bytes = 0;  // the answers this batch holds so far (a restart keeps them)
  for (std::size_t i = 0; i < received; ++i) answered_bytes += out[i].bytes.size();
  const auto largest = [&] {
    if (!greeted_) return kGreetingLimit;
    const std::size_t left = answered_bytes < kBatchAllowance ? kBatchAllowance - answered_bytes : 0;
    return std::max(largest_answer(requests[received].size()), left);
  };
  auto deadline = Clock::now() + call_limit_ + (greeted_ ? std::chrono::milliseconds(0) : std::chrono::seconds(10));
  // Each whole frame that arrived: the greeting, a given function's call (counted in this
  // call's ledger, and answered if served; the call's time limit goes on running), or an
  // answer. Throws std::runtime_error for anything else.
  const auto take_frames = [&] {
    std::string payload;
    while (received < requests.size() && frames.next(payload, largest())) {
      if (!greeted_) {
        if (payload != kHello) throw std::runtime_error("it did not greet as an answerer does");
        greeted_ = true;
        failed_starts = 0;
      } else if (!payload.empty() && (payload[0] == char(Status::given) || payload[0] == char(Status::counted))) {
        std::string reply;
        if (given::take_frame(static_cast<unsigned char>(payload[0]), payload.substr(1), out[received].served, reply)) {
          if (outbox.unsent_replies() > kUnreadReplies)
            throw std::runtime_error("it made given calls without reading their results");
          outbox.reply(reply);
        }
        continue;
      } else {
        answered_bytes += payload.size();
        out[received].kind = Response::Kind::answered;
        out[received++].bytes = std::move(payload);
      }
      deadline = Clock::now() + call_limit_;
    }
  };
  while (received < requests.size()) {
    pollfd fds[3] = {{from_, POLLIN, 0}, {outbox.pending() ? to_ : -1, POLLOUT, 0}, {output_, POLLIN, 0}};
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (wait <= 0)
      return {Response::Kind::timed_out, "it did not answer within " +
                                             std::to_string(call_limit_.count() / 1000.0).substr(0, 4) +
                                             " s (the time limit of one call)"};
    const int ready = wait_ready(fds, wait);
    if (ready < 0 && errno != EINTR) return {Response::Kind::crashed, std::string("poll failed: ") + strerror(errno)};
    if (fds[2].revents & (POLLIN | POLLHUP | POLLERR)) drain_output();
    if (fds[1].revents & (POLLOUT | POLLERR | POLLHUP)) outbox.send(to_);
    if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
    char buffer[1 << 16];
    const ssize_t n = read(from_, buffer, sizeof buffer);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) return {Response::Kind::crashed, ended_how()};
    if (n > 0) frames.add(buffer, std::size_t(n));
    try {
      take_frames();
    } catch (const std::runtime_error& e) {
      return {Response::Kind::broken, std::string("its process wrote something that is not an answer: ") + e.what() +
                                          " (does the code write to file descriptor 4?)"};
    }
  }
  return {Response::Kind::answered, ""};
}

std::vector<Response> Answerer::exchange(const std::vector<std::string>& requests) {
  std::vector<Response> out(requests.size());
  std::size_t received = 0;
  int failed_starts = 0;
  while (received < requests.size()) {
    const auto fail_rest = [&](Response::Kind kind, const std::string& detail) {
      for (; received < requests.size(); ++received) out[received] = {kind, {}, detail, {}, {}};
    };
    if (!start_failure_.empty()) {
      fail_rest(Response::Kind::crashed, start_failure_);
      break;
    }
    if (timeouts_ >= kTimeoutsPerQuery) {
      fail_rest(Response::Kind::timed_out,
                "not run: the code under test already timed out " + std::to_string(timeouts_) + " times in this query");
      break;
    }
    if (pid_ < 0 && !start()) {
      start_failure_ = std::string("the code under test could not be started: ") + strerror(errno);
      continue;
    }
    // Send every request not answered yet, and read answers as they come.
    const auto [kind, problem] = serve(requests, received, out, failed_starts);
    if (problem.empty()) break;
    // This run of the answerer is over: the call it was on gets the blame, the rest
    // are sent again to a new one.
    if (kind == Response::Kind::timed_out) ++timeouts_;
    if (!greeted_ && kind == Response::Kind::crashed && ++failed_starts >= kFailedStarts) {
      start_failure_ = "the code under test's process ends before it can answer anything (" + problem +
                       "): a crash in a static initialiser, or a call of exit() before main?";
      if (!output_tail_.empty()) start_failure_ += "\nwhat it printed last:\n" + output_tail_;
      stop(true);
      continue;
    }
    stop(true);
    const std::string printed =
        output_tail_.substr(output_tail_.size() - std::min<std::size_t>(output_tail_.size(), 600));
    if (greeted_ || kind != Response::Kind::crashed) out[received++] = {kind, {}, problem, printed, {}};
  }
  return out;
}

const Response& Answerer::ask(const std::string& request) {
  if (batch.gathering && Fiber::inside()) {
    auto it = batch.answers.find(request);
    if (it == batch.answers.end()) {
      batch.pending.push_back(request);
      Fiber::wait();  // until flush() has the answer
      it = batch.answers.find(request);
      if (it == batch.answers.end())
        throw std::runtime_error("kit error: the batch that held this call ended without its answer");
    }
    return it->second;
  }
  last_ = std::move(exchange({request}).front());
  return last_;
}

void Answerer::flush() {
  // Each call once, in the order the cases asked for them: a time-out then falls on the
  // first case that loops, and the report shows that case.
  std::vector<std::string>& pending = batch.pending;
  std::unordered_set<std::string> seen;
  std::vector<std::string> unique;
  for (std::string& request : pending)
    if (seen.insert(request).second) unique.push_back(std::move(request));
  pending = std::move(unique);
  const std::vector<Response> responses = exchange(pending);
  for (std::size_t i = 0; i < pending.size(); ++i) batch.answers[pending[i]] = responses[i];
  pending.clear();
}

std::size_t largest_answer(std::size_t request_bytes) {
  return std::max(kSmallestLimit, kAnswerPerRequestByte * request_bytes);
}

DefaultAnswers::DefaultAnswers() { ++batch.default_answers; }
DefaultAnswers::~DefaultAnswers() { --batch.default_answers; }
bool answering_by_default() { return batch.default_answers > 0; }

RecordingExample::RecordingExample() { ++batch.examples; }
RecordingExample::~RecordingExample() { --batch.examples; }

std::string request_hash(const std::string& request) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : request) h = (h ^ c) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

void note_request(const std::string& request) {
  static const char* path = std::getenv("LABKIT_RECORD_EXAMPLES");
  if (batch.examples == 0 || !path || !*path) return;
  if (FILE* f = std::fopen(path, "a")) {
    std::fprintf(f, "%s\n", request_hash(request).c_str());
    std::fclose(f);
  }
}

void begin_batch() {
  batch.gathering = true;
  batch.pending.clear();
}

bool flush() {
  if (batch.pending.empty()) return false;
  Answerer::instance().flush();
  return true;
}

void end_batch() {
  batch.gathering = false;
  batch.pending.clear();
  batch.answers.clear();
}

void new_query() {
  if (started) Answerer::instance().timeouts_ = 0;
}

}  // namespace labkit::remote
