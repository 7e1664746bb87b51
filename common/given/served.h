// The given functions a verdict counts are counted in the judge's process.
//
// A lab's given function (lab 06's given::segment_triangle, compare_ends and its ball,
// box and triangle tests; lab 04's recorded motion) is plain code wherever the code under
// test shares a process with its caller: the viewer, a benchmark. In the answerer (the
// process that runs a student's file, common/protocol/answerer.h) every call of one also
// crosses to the judge's process, which counts it in that call's ledger (Served): nothing
// in the student's process holds a count the verdict reads, so nothing there can lower
// one. Two kinds:
//
//  - counted: a public, pure test (its code is in the kit for anyone to read). The
//    answerer writes a "counted" frame on fd 4 and computes the result itself; the judge
//    counts the frame. No round trip, and the frames go out together with the next frame
//    the judge waits for (or 64 KB at a time), so a query's thousands of tests stay cheap.
//  - served: the answerer cannot compute the result (lab 04's recording motion reaches
//    it as a bare number). It writes a "given" frame on 4 and waits; the judge computes
//    the result, writes down what the verdict needs (the time asked for), and sends the
//    result on fd 3, between two requests (the answerer keeps requests that come first).
//
//   answerer, inside the student's code                      judge's process
//   compare_ends(a, b)       --- counted frame, fd 4 --->    ++ledger["compare_ends"]
//   motion(t)                --- given frame, fd 4 ----->    ledger.samples += t
//     the pose               <--- reply frame, fd 3 -----    pose of the hidden motion
//
// A kit wrapper that runs several queries in one call (lab 06's run_segments) marks
// each with part(k): the judge also counts per part, and refuses parts out of order.
#pragma once

#include "common/protocol/wire.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace labkit::given {

// What the judge counted and served during one call of the code under test.
struct Served {
  std::map<std::string, long long> calls;               // by given function's name
  std::vector<std::map<std::string, long long>> parts;  // the same, per part() (in order)
  std::vector<double> samples;                          // lab 04: the times a recorded motion was asked
  std::string problem;  // a frame the judge could not accept: the whole answer fails with it

  long long count(const std::string& name) const {
    const auto it = calls.find(name);
    return it == calls.end() ? 0 : it->second;
  }
  long long count(std::size_t part, const std::string& name) const {
    if (part >= parts.size()) return 0;
    const auto it = parts[part].find(name);
    return it == parts[part].end() ? 0 : it->second;
  }
};

// The first byte of the two frames (remote::Status::given, remote::Status::counted).
constexpr unsigned char kServedFrame = 5, kCountedFrame = 6;

// ---- In the answerer --------------------------------------------------------------------

// True in an answerer whose lab's given functions are counted (set by remote::serve).
bool served();
void serve_from_judge();

// A counted call: the frame goes to the judge, nothing comes back.
void count(const char* name);
// Starts the next part of a kit wrapper's batch (numbered from 0, in order).
void part(int index);

// The answerer's two pipes, framed (an 8-byte length, then the bytes): the next request
// (one kept while a served call waited, or the next on fd 3; false when the judge is
// done), and a frame written on fd 4 (false when the judge is gone).
bool read_frame(std::string& request);
bool write_frame(const std::string& payload);

// A served call `name(args...)`: asked of the judge, its result read back. Requests the
// judge sent meanwhile are kept for read_frame.
std::string ask_judge(const std::string& request);
template <class R, class... A> R ask(const char* name, const A&... args) {
  wire::Writer w;
  wire::put(w, std::string(name));
  (wire::put(w, args), ...);
  const std::string reply = ask_judge(w.bytes());
  wire::Reader r(reply);
  R result{};
  wire::get(r, result);
  return result;
}

// ---- In a process that runs the given functions itself (the viewer) -------------------

// How many times the given function `name` ran here: for display only, never a verdict.
std::uint64_t local_calls(const std::string& name);
void count_local(const std::string& name);

// What a counted given function does first: in the answerer, a counted frame to the
// judge; anywhere else, a local count for the viewer.
inline void note_call(const char* name) {
  if (served())
    count(name);
  else
    count_local(name);
}

// ---- In the judge's process -------------------------------------------------------------

// The lab's counted functions, by name: any other name in a counted frame is refused.
void countable(const std::string& name);
// A served function: reads its arguments, writes its result, notes what the verdict needs.
using Server = std::function<void(wire::Reader&, wire::Writer&, Served&)>;
void serve(const std::string& name, Server server);

// One frame of either kind, as the judge's process takes it (the frame without its first
// byte): true and the reply for a served call; false for a counted one. What it cannot
// accept (an unknown name, arguments that do not read, parts out of order) becomes
// `served.problem`, and a served call's reply is then empty.
bool take_frame(unsigned char kind, const std::string& frame, Served& served, std::string& reply);

}  // namespace labkit::given
