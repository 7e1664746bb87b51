// A lab's functions as calls between two processes (see answerer.h for the picture).
//
// Each lab lists its functions once, in tests/NN_name/queries.h:
//
//   #define LABKIT_LAB02_CALLS(CALL, METHOD) ...
//     CALL(PlaneCrossing, segment_plane, (const Segment&, const Triangle&)) ...
//
// From that one list, common/protocol/lab_calls.cpp defines each function for the
// judge's process as labkit::lab02::answerer::segment_plane (it sends the call and
// returns the answer; see LABKIT_ANSWERER_CALLS below) and
// common/protocol/lab_answerer.cpp builds the answerer's table (it receives the call
// and runs the student's function). A non-const reference argument (lab 07's Random&)
// travels both ways: its new value comes back with the answer. METHOD(Class, name,
// params) does the same for a member function returning void, with *this in and out.
#pragma once

#include "common/not_implemented.h"
#include "common/protocol/answerer.h"
#include "common/protocol/wire.h"

#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

// ---- Naming a parenthesised parameter list: (const Segment&, double) -> const Segment& a1, double a2
#define LABKIT_CAT(a, b) LABKIT_CAT_(a, b)
#define LABKIT_CAT_(a, b) a##b
#define LABKIT_COUNT(...) LABKIT_COUNT_(__VA_ARGS__, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define LABKIT_COUNT_(_1, _2, _3, _4, _5, _6, _7, _8, n, ...) n
#define LABKIT_NAMED(...) LABKIT_CAT(LABKIT_NAMED_, LABKIT_COUNT(__VA_ARGS__))(__VA_ARGS__)
#define LABKIT_NAMED_1(A) A a1
#define LABKIT_NAMED_2(A, B) A a1, B a2
#define LABKIT_NAMED_3(A, B, C) A a1, B a2, C a3
#define LABKIT_NAMED_4(A, B, C, D) A a1, B a2, C a3, D a4
#define LABKIT_NAMED_5(A, B, C, D, E) A a1, B a2, C a3, D a4, E a5
#define LABKIT_NAMED_6(A, B, C, D, E, F) A a1, B a2, C a3, D a4, E a5, F a6
#define LABKIT_ARGS(...) LABKIT_CAT(LABKIT_ARGS_, LABKIT_COUNT(__VA_ARGS__))
#define LABKIT_ARGS_1 a1
#define LABKIT_ARGS_2 a1, a2
#define LABKIT_ARGS_3 a1, a2, a3
#define LABKIT_ARGS_4 a1, a2, a3, a4
#define LABKIT_ARGS_5 a1, a2, a3, a4, a5
#define LABKIT_ARGS_6 a1, a2, a3, a4, a5, a6
#define LABKIT_UNPAREN(...) __VA_ARGS__

namespace labkit::remote {

template <class P>
constexpr bool is_out = std::is_lvalue_reference_v<P> && !std::is_const_v<std::remove_reference_t<P>>;

// ---- What a call did besides answering -------------------------------------------------
// The given functions the code under test called during the call are served and counted
// in the judge's process (common/given/served.h): last_served() returns them after the
// answer. Lab 04's RecordingMotion asks for its poses that way too; the times it was
// asked for go into `sink`, which its argument's encoding names (take_sample_sink()
// hands it to the call being sent).
void sample_into(std::vector<double>* sink);
std::vector<double>* take_sample_sink();

// ---- The judge's side: send the call, return the answer ------------------------------

namespace detail {
// Turns an answerer's reply into the answer, or throws what the student's code threw.
wire::Reader open_reply(const std::string& id, const Response& response);
}  // namespace detail

// A non-const reference argument comes back with the answer; the others only go.
template <class P, class A> void get_out(wire::Reader& r, A& a) {
  if constexpr (is_out<P>) wire::get(r, a);
}
template <class P, class A> void put_out(wire::Writer& w, const A& a) {
  if constexpr (is_out<P>) wire::put(w, a);
}

// The given calls the last call made, as the judge served them (none for a default answer).
const given::Served& last_served();
namespace detail {
void set_last_served(const given::Served* served);
}  // namespace detail

template <class R, class... P> R call(const char* id, P... args) {
  detail::set_last_served(nullptr);
  if (answering_by_default()) {  // what a file that does nothing answers (DefaultAnswers)
    if constexpr (std::is_void_v<R>)
      return;
    else
      return R{};
  }
  wire::Writer w;
  wire::put(w, std::string(id));
  take_sample_sink();  // none left over from a call whose encoding failed
  (wire::put(w, args), ...);
  std::vector<double>* samples = take_sample_sink();  // this call's own: other cases' calls wait beside it
  note_request(w.bytes());
  const Response& response = Answerer::instance().ask(w.bytes());
  wire::Reader r = detail::open_reply(id, response);
  detail::set_last_served(&response.served);
  if (samples) samples->insert(samples->end(), response.served.samples.begin(), response.served.samples.end());
  try {
    if constexpr (std::is_void_v<R>) {
      (get_out<P>(r, args), ...);
      if (!r.done()) throw wire::Error("extra bytes after the answer");
    } else {
      R result{};
      wire::get(r, result);
      (get_out<P>(r, args), ...);
      if (!r.done()) throw wire::Error("extra bytes after the answer");
      return result;
    }
  } catch (const wire::Error& e) {
    throw Failed("an answer that cannot be read", std::string("the answer to ") + id + " is malformed: " + e.what() +
                                                      " (does the code write to file descriptor 4?)");
  }
}

// ---- The answerer's side: receive the call, run the student's function ---------------

using Handler = std::function<void(wire::Reader&, wire::Writer&)>;
using Table = std::map<std::string, Handler>;

template <class R, class... P, std::size_t... I>
void run_call(R (*function)(P...), wire::Reader& in, wire::Writer& out, std::index_sequence<I...>) {
  std::tuple<std::decay_t<P>...> args;
  (wire::get(in, std::get<I>(args)), ...);
  if (!in.done()) throw wire::Error("extra bytes after the arguments");
  if constexpr (std::is_void_v<R>) {
    function(std::get<I>(args)...);
  } else {
    const R result = function(std::get<I>(args)...);
    wire::put(out, result);
  }
  (put_out<P>(out, std::get<I>(args)), ...);
}

template <class R, class... P> Handler handler(R (*function)(P...)) {
  return
      [function](wire::Reader& in, wire::Writer& out) { run_call(function, in, out, std::index_sequence_for<P...>{}); };
}

// The answerer's main loop: greets, then answers calls until its input ends. With
// given_served, the lab's given functions are asked of the judge (served.h).
int serve(const Table& table, bool given_served);

// ---- The probe: has the lab been begun? --------------------------------------------------
// `./labkit check` builds a lab's checker (its judge, generators and tests) only once the
// lab's file answers something: before that, the answerer run as `answer_NN --probe`
// calls each of the lab's functions once, on a probe input, with no judge. A stub throws
// NotImplemented with its step's tag before it looks at the input; anything else (an
// answer, another exception, a crash, a hang) means the lab has begun.

// A probe input: the default value, with one default element in each list, so that a kit
// wrapper that loops over a list (lab 06's run_segments) reaches the student's function.
template <class T> struct ProbeValue {
  static T make() { return T{}; }
};
template <class T, class A> struct ProbeValue<std::vector<T, A>> {
  static std::vector<T, A> make() { return std::vector<T, A>(1, ProbeValue<T>::make()); }
};

using Probe = std::function<void()>;
using Probes = std::vector<std::pair<std::string, Probe>>;

template <class R, class... P> Probe prober(R (*function)(P...)) {
  return [function] {
    std::tuple<std::decay_t<P>...> args{ProbeValue<std::decay_t<P>>::make()...};
    std::apply([function](auto&... a) { function(a...); }, args);
  };
}

// Runs the probes and prints, as its last line, "labkit-probe: not implemented" when
// every one threw NotImplemented, or "labkit-probe: answers: CALL" for the first that
// did anything else.
int probe(const Probes& probes);

}  // namespace labkit::remote

// ---- The expansions of a lab's list ----------------------------------------------------

#define LABKIT_CALL_ID(R, name, params) #name #params

// In the judge's process, the functions it calls across the boundary, in the lab's
// namespace `answerer`: a test reads `answerer::segment_plane(s, t)`, a call that goes
// to the answerer's process and returns its answer. A member function is called with
// its object first: answerer::step(system, dt) runs system.step(dt) there and brings the
// system back. The test program does not define the lab's own functions at all, so a
// call that does not say `answerer::` fails to link.
#define LABKIT_DECLARE_CALL(R, name, params) R name(LABKIT_UNPAREN params);
#define LABKIT_DECLARE_METHOD(Class, name, params) void name(Class&, LABKIT_UNPAREN params);
#define LABKIT_ANSWERER_CALLS(lab, CALLS)           \
  namespace labkit::lab::answerer {                 \
  CALLS(LABKIT_DECLARE_CALL, LABKIT_DECLARE_METHOD) \
  }

// Their definitions (common/protocol/lab_calls.cpp): each sends its call and returns the answer.
#define LABKIT_DEFINE_CALL(R, name, params)                                                                       \
  R name(LABKIT_NAMED params) {                                                                                   \
    return ::labkit::remote::call<R, LABKIT_UNPAREN params>(LABKIT_CALL_ID(R, name, params), LABKIT_ARGS params); \
  }
#define LABKIT_DEFINE_METHOD(Class, name, params)                                                                     \
  void name(Class& self, LABKIT_NAMED params) {                                                                       \
    ::labkit::remote::call<void, Class&, LABKIT_UNPAREN params>(#Class "::" #name #params, self, LABKIT_ARGS params); \
  }

// In the answerer run with --probe: the probe of the student's function.
#define LABKIT_PROBE_CALL(R, name, params) \
  probes.emplace_back(LABKIT_CALL_ID(R, name, params), ::labkit::remote::prober<R, LABKIT_UNPAREN params>(&name));
#define LABKIT_PROBE_METHOD(Class, name, params)                                     \
  probes.emplace_back(#Class "::" #name #params,                                     \
                      ::labkit::remote::prober<void, Class&, LABKIT_UNPAREN params>( \
                          +[](Class& self, LABKIT_NAMED params) { self.name(LABKIT_ARGS params); }));

// In the answerer: the table entry that runs the student's function.
#define LABKIT_TABLE_CALL(R, name, params) \
  table[LABKIT_CALL_ID(R, name, params)] = ::labkit::remote::handler<R, LABKIT_UNPAREN params>(&name);
#define LABKIT_TABLE_METHOD(Class, name, params)                                                     \
  table[#Class "::" #name #params] = ::labkit::remote::handler<void, Class&, LABKIT_UNPAREN params>( \
      +[](Class& self, LABKIT_NAMED params) { self.name(LABKIT_ARGS params); });
