#include "common/given/served.h"

#include <poll.h>
#include <sched.h>
#include <unistd.h>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <limits>
#include <set>

namespace labkit::given {

namespace {

// A reply frame opens with this where a request opens with its name's length.
constexpr std::uint64_t kReplyMark = std::numeric_limits<std::uint64_t>::max();
constexpr int kRequests = 3, kAnswers = 4;
constexpr std::size_t kLongestName = 64;
// Parts in one call: the kit's wrappers make at most 750 (lab 06's run_segments); a flood
// of part frames must not grow the judge's ledger without end.
constexpr std::size_t kMostParts = std::size_t(1) << 14;

bool serving = false;
std::deque<std::string> queued;  // requests that came while a served call waited

// A served call's reply comes within microseconds: ask for it a few times before
// sleeping in read(), since waking a sleeping process can cost 50 us on a virtual machine,
// ten times the round trip itself. Each look yields the processor, so that on a busy
// machine the judge it waits for runs instead.
void spin_until_readable(int fd) {
  constexpr int kSpins = 200;
  for (int spin = 0; spin < kSpins; ++spin) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 0) != 0) return;
    sched_yield();
  }
}

bool read_all(int fd, void* data, std::size_t n) {
  auto* at = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t got = read(fd, at, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    at += got, n -= std::size_t(got);
  }
  return true;
}

bool write_all(int fd, const std::string& bytes) {
  const char* at = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t put = write(fd, at, left);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    at += put, left -= std::size_t(put);
  }
  return true;
}

// Frames written but not sent yet: counted frames wait here, in order, until a frame that
// the judge must see at once (an answer, a served call) or 64 KB of them, and then go in
// one write. A brute force that tests millions of triangles costs millions of bytes, not
// millions of system calls. The judge reads the same stream either way; counts still
// waiting when the process dies belong to a call that failed anyway.
std::string unsent;
constexpr std::size_t kUnsentLimit = std::size_t(1) << 16;

// A payload as it goes on the pipe: its 8-byte length, then its bytes.
std::string framed(const std::string& payload) {
  const std::uint64_t n = payload.size();
  return std::string(reinterpret_cast<const char*>(&n), sizeof n) + payload;
}
void append_frame(const std::string& payload) { unsent += framed(payload); }

bool flush_unsent() {
  std::string bytes;
  bytes.swap(unsent);
  return write_all(kAnswers, bytes);
}

// A counted frame, already framed, sent with the next write (or now, past 64 KB).
void send_counted(const std::string& frame) {
  unsent += frame;
  if (unsent.size() >= kUnsentLimit && !flush_unsent()) std::_Exit(0);
}
std::string counted(const std::string& bytes) { return framed(std::string(1, char(kCountedFrame)) + bytes); }

// A given call's counted frame, framed once per name: a brute force makes millions.
const std::string& counted_frame(const char* name) {
  static std::map<const char*, std::string> frames;  // the names are the kit's literals
  std::string& frame = frames[name];
  if (frame.empty()) {
    wire::Writer w;
    wire::put(w, std::string(name));
    frame = counted(w.bytes());
  }
  return frame;
}

// A frame on fd 4 whose first byte says its kind. The judge gone, the answerer ends.
void send_frame(unsigned char kind, const std::string& bytes) {
  if (!write_frame(std::string(1, char(kind)) + bytes)) std::_Exit(0);
}

// The next frame on fd 3, false when the judge is done.
bool read_request(std::string& payload) {
  std::uint64_t size = 0;
  spin_until_readable(kRequests);
  if (!read_all(kRequests, &size, sizeof size)) return false;
  if (size > (std::uint64_t(1) << 32)) std::_Exit(2);
  payload.assign(size, '\0');
  return read_all(kRequests, payload.data(), size);
}

std::set<std::string>& countables() {
  static std::set<std::string> names{"segment_triangle"};
  return names;
}

std::map<std::string, Server>& servers() {
  static std::map<std::string, Server> table;
  return table;
}

std::map<std::string, std::uint64_t>& local() {
  static std::map<std::string, std::uint64_t> counts;
  return counts;
}

void start_part(wire::Reader& in, Served& served) {
  int index = -1;
  wire::get(in, index);
  if (served.parts.size() >= kMostParts)
    throw wire::Error("more than " + std::to_string(kMostParts) +
                      " parts in one call, more than any of the kit's makes");
  if (index != int(served.parts.size()))
    throw wire::Error("the kit's wrapper started part " + std::to_string(index) + " where part " +
                      std::to_string(served.parts.size()) + " was due (does the code call given::part?)");
  served.parts.emplace_back();
}

}  // namespace

bool served() { return serving; }
void serve_from_judge() { serving = true; }

void count(const char* name) { send_counted(counted_frame(name)); }

void part(int index) {
  if (!served()) return;
  wire::Writer w;
  wire::put(w, std::string("part"));
  wire::put(w, index);
  send_counted(counted(w.bytes()));
}

bool write_frame(const std::string& payload) {
  append_frame(payload);
  return flush_unsent();
}

bool read_frame(std::string& request) {
  if (queued.empty()) return read_request(request);
  request = std::move(queued.front());
  queued.pop_front();
  return true;
}

std::string ask_judge(const std::string& request) {
  send_frame(kServedFrame, request);
  for (std::string payload;;) {
    if (!read_request(payload)) std::_Exit(0);  // the judge is gone
    std::uint64_t mark = 0;
    if (payload.size() >= sizeof mark) std::memcpy(&mark, payload.data(), sizeof mark);
    if (mark == kReplyMark) return payload.substr(sizeof mark);
    queued.push_back(std::move(payload));
  }
}

std::uint64_t local_calls(const std::string& name) {
  const auto it = local().find(name);
  return it == local().end() ? 0 : it->second;
}
void count_local(const std::string& name) { ++local()[name]; }

void countable(const std::string& name) { countables().insert(name); }
void serve(const std::string& name, Server server) { servers()[name] = std::move(server); }

bool take_frame(unsigned char kind, const std::string& frame, Served& served, std::string& reply) {
  const bool served_call = kind == kServedFrame;
  wire::Writer out;
  const std::uint64_t mark = kReplyMark;
  out.raw(&mark, sizeof mark);
  try {
    wire::Reader in(frame);
    std::string name;
    wire::get(in, name);
    if (name.size() > kLongestName)
      throw wire::Error("a given function's name of " + std::to_string(name.size()) + " bytes");
    if (served_call) {
      const auto it = servers().find(name);
      if (it == servers().end()) throw wire::Error("no given function \"" + name + "\" is served");
      it->second(in, out, served);
    } else if (name == "part") {
      start_part(in, served);
      return false;
    } else if (!countables().count(name)) {
      throw wire::Error("no given function \"" + name + "\" is counted");
    }
    ++served.calls[name];
    if (!served.parts.empty()) ++served.parts.back()[name];
  } catch (const std::exception& e) {
    if (served.problem.empty()) served.problem = e.what();
  }
  if (served_call) reply = out.take();
  return served_call;
}

}  // namespace labkit::given
