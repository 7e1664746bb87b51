// The code under test runs in a process of its own, the answerer; the judge, the exact
// oracle and the harness never share an address space with it. The judge's process
// sends it calls ("segment_plane" and its arguments) and reads back answers, nothing
// else: whatever the student's file does (declares names, reads its own binary, scans
// memory, crashes, loops), it can only answer, never judge.
//
//   judge's process                                answerer (student's code)
//   answerer::segment_plane(s, t)  --- request --->  serve(): decode, call the real
//     (common/protocol/lab_calls.cpp)                segment_plane, encode the answer
//   answer, or remote::Failed     <--- response ---  (common/protocol/lab_answerer.cpp)
//
// Requests travel on the answerer's file descriptor 3 and answers on 4, each framed as
// an 8-byte length and the bytes (common/protocol/wire.h). What the answerer prints goes
// on to the judge's stderr, and its last lines come with a crash's report.
//
// Given functions: while it answers a call, the code under test may call a given
// function the verdict counts (lab 06's given::segment_triangle, say). That call comes
// to the judge as a frame on 4 with status `counted` (the judge counts it in the call's
// Response::served) or `given` (the judge also computes it and sends the result on 3,
// ahead of any request not yet begun; the answerer keeps the requests that arrive
// meanwhile). common/given/served.h has the picture.
//
// Batches: the harness asks for thousands of random cases at a time, each case's judge
// running as a fiber of its own (fiber.h). Between begin_batch() and end_batch(), a call
// from a fiber whose answer is not known yet is recorded and the fiber waits; flush()
// sends every recorded call at once (the answers stream back in order, with no round
// trip per call) and keeps the answers, and the harness resumes the waiting fibers, each
// inside its call. A crash or a time-out costs the one call it happened on: that call's
// answer says so, the answerer is started again, and the rest go on.
#pragma once

#include "common/given/served.h"

#include <sys/types.h>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace labkit::remote {

// The answer to one call, as the judge's process saw it.
struct Response {
  enum class Kind { answered, crashed, timed_out, broken };
  Kind kind = Kind::answered;
  std::string bytes;     // answered: the answerer's reply (a status byte, then its data)
  std::string detail;    // otherwise: what happened, in words
  std::string output;    // crashed: the last of what it printed
  given::Served served;  // the given functions the judge served during the call
};

// What the answerer replies, in the first byte of an answered call.
// rejected: the code threw std::invalid_argument, a precondition of the header it checks
// (the judge's side throws it again, with its message, so a test can ask for exactly that).
// given and counted: not an answer but a given function's call, served or counted
// before the answer comes (common/given/served.h).
enum class Status : unsigned char {
  answered = 0,
  not_implemented = 1,
  threw = 2,
  unknown_call = 3,
  rejected = 4,
  given = given::kServedFrame,
  counted = given::kCountedFrame
};

// The call could not be answered: it crashed, timed out, or sent something unreadable.
// `got` and `why` are ready for a failure report.
struct Failed : std::runtime_error {
  Failed(std::string got, std::string why) : std::runtime_error(why), got(std::move(got)) {}
  std::string got;
};

// Failed::got of a call that timed out.
constexpr const char* kNoAnswer = "no answer";

// What the code under test threw (Status::threw): its own exception, never the kit's, so
// that a verdict blames the student only for what came from the student's process.
struct Threw : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// What it rejected (Status::rejected): a std::invalid_argument, as the header's
// preconditions ask, so that a test of a precondition catches it as one.
struct Rejected : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The largest answer the judge reads for a request of `request_bytes` once its batch has
// used up its allowance of answers (answerer.cpp): a larger frame is that call's failure,
// refused before anything is allocated for it.
std::size_t largest_answer(std::size_t request_bytes);

class Answerer {
 public:
  // The one answerer of this process, run as LABKIT_ANSWERER says: a program's path, or
  // a JSON array of a command line (the grader's confinement around the program).
  static Answerer& instance();

  // The answer to one call: asked now, or, from a fiber in a batch, recorded for the next
  // flush while the fiber waits (fiber.h). The reference stays valid until the batch ends
  // or the next call.
  const Response& ask(const std::string& request);
  // Sends the recorded calls at once and keeps their answers.
  void flush();

  ~Answerer();

 private:
  explicit Answerer(std::vector<std::string> argv);
  std::vector<Response> exchange(const std::vector<std::string>& requests);
  // One run of the running answerer over requests[received...]: sends them, reads the
  // answers into `out`. The problem that ended it early and its kind; "" when all came.
  std::pair<Response::Kind, std::string> serve(const std::vector<std::string>& requests, std::size_t& received,
                                               std::vector<Response>& out, int& failed_starts);
  bool start();
  void stop(bool kill_it);
  std::string ended_how();
  void drain_output();  // what the answerer printed: passed on, its tail kept

  std::vector<std::string> argv_;
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1, output_ = -1;
  std::string output_tail_;  // the last of what the running answerer printed
  bool greeted_ = false;
  std::string start_failure_;  // set when the program cannot answer anything at all

  int timeouts_ = 0;
  std::chrono::milliseconds call_limit_{5000};
  Response last_;  // the answer to the last call asked outside a batch
  friend void new_query();
};

// Batches, for the harness; they cost nothing in a process that never calls the answerer.
void begin_batch();  // a fiber's call whose answer is not known yet is recorded, and waits
bool flush();        // sends them (false: there were none) and keeps the answers
void end_batch();    // forgets the answers
void new_query();    // a new query: the time-out budget starts afresh

// Graded runs score a case only where an answer that does nothing would fail it
// (README, "Scoring"): the judge runs each case again inside this scope, where every call
// answers its result type's default (no hit, false, zeros) without reaching the answerer.
class DefaultAnswers {
 public:
  DefaultAnswers();
  ~DefaultAnswers();
  DefaultAnswers(const DefaultAnswers&) = delete;
  DefaultAnswers& operator=(const DefaultAnswers&) = delete;
};
bool answering_by_default();

// The kit's test of its own scoring (runner/fake.cpp) needs the requests of the worked
// examples: with LABKIT_RECORD_EXAMPLES set, the calls made inside this scope append a
// hash of each request to that file. A graded run never sets it.
class RecordingExample {
 public:
  RecordingExample();
  ~RecordingExample();
  RecordingExample(const RecordingExample&) = delete;
  RecordingExample& operator=(const RecordingExample&) = delete;
};
void note_request(const std::string& request);
// The hash the recording writes (16 hex digits), shared with the fake answerer.
std::string request_hash(const std::string& request);

// How many time-outs a query tolerates before its remaining calls are not run.
constexpr int kTimeoutsPerQuery = 2;

}  // namespace labkit::remote
