#include "common/protocol/calls.h"

#include "common/given/segment_triangle.h"

#include <unistd.h>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <typeinfo>

namespace labkit::remote {

namespace {
std::vector<double> samples;          // the answerer's, for the current call
std::vector<double>* sink = nullptr;  // the judge's, for the next answer
}  // namespace

void record_sample(double x) { samples.push_back(x); }
void sample_into(std::vector<double>* into) { sink = into; }

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
  wire::Reader r(response.bytes);
  Status status;
  std::string message;
  try {
    wire::get(r, status);
    if (status == Status::answered) {
      std::uint64_t given_calls = 0;
      std::vector<double> recorded;
      wire::get(r, given_calls);
      wire::get(r, recorded);
      given::count_segment_triangle_calls(given_calls);
      if (sink) sink->insert(sink->end(), recorded.begin(), recorded.end());
      sink = nullptr;
      return r;
    }
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

bool write_all(int fd, const std::string& payload) {
  const std::uint64_t n = payload.size();
  std::string bytes(reinterpret_cast<const char*>(&n), sizeof n);
  bytes += payload;
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
    const std::uint64_t before = given::segment_triangle_calls();
    samples.clear();
    wire::Writer data;
    it->second(in, data);
    wire::Writer out;
    wire::put(out, Status::answered);
    wire::put(out, given::segment_triangle_calls() - before);
    wire::put(out, samples);
    out.raw(data.bytes().data(), data.bytes().size());
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

int serve(const Table& table) {
  constexpr int requests = 3, answers = 4;
  if (!write_all(answers, "labkit-answerer 1")) return 2;
  for (;;) {
    std::uint64_t n = 0;
    if (!read_all(requests, &n, sizeof n)) return 0;  // the judge is done
    if (n > (std::uint64_t(1) << 32)) return 2;
    std::string request(n, '\0');
    if (!read_all(requests, request.data(), n)) return 0;
    if (!write_all(answers, answer(table, request))) return 0;
  }
}

}  // namespace labkit::remote
