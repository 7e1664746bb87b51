#include "common/protocol/calls.h"

#include "common/given/served.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <typeinfo>
#include <utility>

namespace labkit::remote {

namespace {
std::vector<double>* sink = nullptr;  // named by the argument being encoded
given::Served last;                   // what the last call made the judge serve
}  // namespace

void sample_into(std::vector<double>* into) { sink = into; }
std::vector<double>* take_sample_sink() { return std::exchange(sink, nullptr); }
const given::Served& last_served() { return last; }
void detail::set_last_served(const given::Served* served) { last = served ? *served : given::Served{}; }

namespace detail {

wire::Reader open_reply(const std::string& id, const Response& response) {
  switch (response.kind) {
    case Response::Kind::crashed:
      throw Failed("a crash", "your code crashed during this call (" + response.detail +
                                  "); add --debug to the replay command below to see the line it crashed on" +
                                  (response.output.empty() ? "" : "\nwhat it printed last:\n" + response.output));
    case Response::Kind::timed_out:
      throw Failed(kNoAnswer, "your code did not finish this call: " + response.detail +
                                  ". Every loop needs a bound that the header's rules guarantee");
    case Response::Kind::broken: throw Failed("an answer that cannot be read", response.detail);
    case Response::Kind::answered: break;
  }
  if (!response.served.problem.empty())
    throw Failed("a given call the kit cannot accept",
                 "during this call your code's process sent the kit a given function's call it cannot accept (" +
                     response.served.problem + "): call the given functions only as the header declares them");
  wire::Reader r(response.bytes);
  Status status;
  std::string message;
  try {
    wire::get(r, status);
    if (status == Status::answered) return r;
    wire::get(r, message);
  } catch (const wire::Error& e) {
    throw Failed("an answer that cannot be read",
                 std::string("the reply is malformed: ") + e.what() + " (does the code write to file descriptor 4?)");
  }
  switch (status) {
    case Status::not_implemented: {
      // "not implemented yet (L02S1)" -> the tag, so that the message reads the same.
      const auto open = message.find('('), close = message.rfind(')');
      throw NotImplemented(open != std::string::npos && close > open ? message.substr(open + 1, close - open - 1)
                                                                     : message);
    }
    case Status::threw:
      if (message == "std::bad_alloc")
        throw Failed("an exception: std::bad_alloc",
                     "your code ran out of memory during this call: an allocation "
                     "too large for the memory limit, or one that never stops growing?");
      throw Threw(message);
    case Status::rejected: throw Rejected(message);
    case Status::unknown_call:
      throw std::logic_error("kit error: the answerer cannot run " + id + ": " + message +
                             " (is it built from the same kit as the tests?)");
    default: throw Failed("an answer that cannot be read", "the reply has an unknown status");
  }
}

}  // namespace detail

namespace {

std::string failure(Status status, const std::string& message) {
  wire::Writer w;
  wire::put(w, status);
  wire::put(w, message);
  return w.take();
}

// One call: the student's answer, or what it threw.
std::string answer(const Table& table, const std::string& request) {
  wire::Reader in(request);
  std::string id;
  try {
    wire::get(in, id);
  } catch (const wire::Error& e) {
    return failure(Status::unknown_call, e.what());
  }
  const auto it = table.find(id);
  if (it == table.end()) return failure(Status::unknown_call, "no such call");
  try {
    wire::Writer out;
    wire::put(out, Status::answered);
    it->second(in, out);
    return out.take();
  } catch (const wire::Error& e) {
    return failure(Status::unknown_call, std::string("its arguments cannot be read: ") + e.what());
  } catch (const NotImplemented& e) {
    return failure(Status::not_implemented, e.what());
  } catch (const std::invalid_argument& e) {
    return failure(Status::rejected, e.what());
  } catch (const std::exception& e) {
    return failure(Status::threw, e.what());
  } catch (...) {
    return failure(Status::threw, "something not derived from std::exception");
  }
}

}  // namespace

int probe(const Probes& probes) {
  for (const auto& [id, run] : probes) {
    try {
      run();
    } catch (const NotImplemented&) {
      continue;
    } catch (...) {}
    std::printf("\nlabkit-probe: answers: %s\n", id.c_str());
    std::fflush(stdout);
    return 0;
  }
  std::printf("\nlabkit-probe: not implemented\n");
  std::fflush(stdout);
  return 0;
}

int serve(const Table& table, bool given_served) {
  if (given_served) given::serve_from_judge();
  if (!given::write_frame("labkit-answerer 1")) return 2;
  std::string request;
  while (given::read_frame(request))  // until the judge is done
    if (!given::write_frame(answer(table, request))) return 0;
  return 0;
}

}  // namespace labkit::remote
