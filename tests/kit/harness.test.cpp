// The harness's own guarantees: exact replay tokens, clear errors on bad tokens, the
// ambiguity test on cases whose answer is known, the given calls' ledger and the fibers
// that batch the judges' calls.
#include "common/generators/generators.h"
#include "common/given/segment_triangle.h"
#include "common/given/served.h"
#include "common/harness/check.h"
#include "common/oracle/oracle.h"
#include "common/protocol/fiber.h"
#include "common/protocol/report.h"

#include "common/harness/catch.h"

#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

using namespace labkit;

TEST_CASE("replay tokens rebuild the input bit for bit", "[kit]") {
  const double awkward[] = {0.1,
                            -0.0,
                            1e-310,
                            std::numeric_limits<double>::max(),
                            -3.0,
                            1.0 / 3.0,
                            std::numeric_limits<double>::denorm_min()};
  for (double x : awkward) {
    const SegmentTrianglePair in{{{x, 1, 2}, {3, x, 5}}, {{x, x, x}, {0, 1, 0}, {0, 0, 1}}};
    const SegmentTrianglePair back = input_from_token<SegmentTrianglePair>(parse_token(replay_token("q", in)));
    CHECK(std::memcmp(&back.segment.a.x(), &in.segment.a.x(), sizeof(double)) == 0);
    CHECK(back.triangle.v0 == in.triangle.v0);
    CHECK(back.segment.b == in.segment.b);
  }
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  const SegmentMeshPair in{{{0.25, 0.25, 1}, {0.25, 0.25, -1}}, m};
  const SegmentMeshPair back = input_from_token<SegmentMeshPair>(parse_token(replay_token("first_hit", in)));
  CHECK(back.mesh.vertices == m.vertices);
  CHECK(back.mesh.triangles == m.triangles);
}

TEST_CASE("malformed replay tokens give one clear reason", "[kit]") {
  CHECK_THROWS_WITH(parse_token("nonsense"), labkit::check::contains_text("query:"));
  CHECK_THROWS_WITH(parse_token("q:1,2,x"), labkit::check::contains_text("is not a number"));
  CHECK_THROWS_WITH(input_from_token<SegmentTrianglePair>(parse_token("q:1,2,3")),
                    labkit::check::contains_text("numbers"));
  // Every lab's input is finite: nan and inf are named, never handed to the oracle.
  for (const char* bad : {"nan", "inf", "-inf"}) {
    const std::string token = std::string("q:0,0,1,0,0,-1,0,0,0,1,0,0,0,1,") + bad;
    CHECK_THROWS_WITH(input_from_token<SegmentTrianglePair>(parse_token(token)),
                      labkit::check::contains_text("number 15 of the case is"));
  }
  // A mesh whose triangle names a vertex it does not have.
  CHECK_THROWS_WITH(input_from_token<SegmentMeshPair>(parse_token("q:0,0,0,1,1,1,3,0,0,0,1,0,0,0,1,0,1,0,1,7")),
                    labkit::check::contains_text("count from 0 to 2"));
}

TEST_CASE("ambiguity: exact degeneracies flip, clear cases do not", "[kit]") {
  const Triangle floor{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const auto hit = [](const SegmentTrianglePair& p) { return oracle::segment_hits_triangle(p.segment, p.triangle); };
  // Through the middle: stays a hit. Far beside it: stays a miss.
  CHECK_FALSE(check::flips_under_perturbation(SegmentTrianglePair{{{1, 1, 1}, {1, 1, -1}}, floor}, hit));
  CHECK_FALSE(check::flips_under_perturbation(SegmentTrianglePair{{{9, 9, 1}, {9, 9, -1}}, floor}, hit));
  // Exactly through an edge, or ending exactly on the plane: either answer is fair.
  CHECK(check::flips_under_perturbation(SegmentTrianglePair{{{2, 0, 1}, {2, 0, -1}}, floor}, hit));
  CHECK(check::flips_under_perturbation(SegmentTrianglePair{{{1, 1, 1}, {1, 1, 0}}, floor}, hit));
  // In the plane but far away: a stable miss, however the rounding of d goes.
  CHECK_FALSE(check::flips_under_perturbation(SegmentTrianglePair{{{9, 9, 0}, {12, 9, 0}}, floor}, hit));
  CHECK_FALSE(oracle::segment_triangle_in_doubt({{9, 9, 0}, {12, 9, 0}}, floor, 1e-8));
  // An end 1e-11 from a vertex, the other end on the plane: the conservative test doubts it.
  CHECK(oracle::segment_triangle_in_doubt({{1e-11, 1e-11, 1e-11}, {-5, -3, 0}}, floor, 1e-8));
}

TEST_CASE("the oracle's orientation follows the right-hand rule", "[kit]") {
  CHECK(oracle::orientation({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == 1);
  CHECK(oracle::side(Plane{{0, 0, 2}, -2}, {5, 5, 1}) == 0);
  CHECK(oracle::side(Plane{{0, 0, 2}, -2}, {5, 5, 1.0000001}) == 1);
  const oracle::SegmentHit h = oracle::segment_triangle({{1, 1, 3}, {1, 1, -1}}, {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}});
  CHECK(h.hit);
  CHECK(h.t == 0.75);
  CHECK(h.point == Vec3(1, 1, 0));
}

TEST_CASE("Expect words a mismatch field by field", "[kit]") {
  check::Expect e("t is the fraction of the way from a to b");
  e.near("t", 0.5, 0.75, 1e-12);
  e.equal("hit", true, true);
  const check::Outcome o = e.outcome();
  CHECK(o.verdict == check::Outcome::Verdict::fail);
  // The rule first, then the field and its numbers: never a field and a number alone.
  CHECK(o.why.rfind("t is the fraction of the way from a to b: t is off by 0.25", 0) == 0);
  CHECK_THAT(o.expected, labkit::check::contains_text("t = 0.75"));
  CHECK_THAT(o.got, labkit::check::contains_text("t = 0.5"));
}

TEST_CASE("Expect names the likely cause a wrong number shows", "[kit]") {
  const auto why = [](auto got, auto expected) {
    check::Expect e("rule");
    e.near("x", got, expected, 1e-12);
    return e.outcome().why;
  };
  CHECK_THAT(why(-2.0, 2.0), labkit::check::contains_text("opposite sign"));
  CHECK_THAT(why(6.0, 2.0), labkit::check::contains_text("3 times the answer"));
  CHECK_THAT(why(1.0, 4.0), labkit::check::contains_text("1/4 of the answer"));
  CHECK_THAT(why(std::sqrt(2.0) * 3, 3.0), labkit::check::contains_text("sqrt(2) times"));
  CHECK(why(2.5, 2.0) == "rule: x is off by 0.5 (tolerance 1e-12)");  // nothing simple: no guess
  CHECK_THAT(why(Vec3(0, 0, -1), Vec3(0, 0, 1)), labkit::check::contains_text("opposite way"));
  CHECK_THAT(why(Vec3(0, 0, 2), Vec3(0, 0, 1)), labkit::check::contains_text("right direction but 2 times"));
  CHECK_THAT(why(Vec3(0, 1, 0), Vec3(1, 0, 0)), labkit::check::contains_text("another order"));
  CHECK_THAT(why(Vec3(0.6, 0.8, 0), Vec3(1, 0, 0)), labkit::check::contains_text("right length in another direction"));
  CHECK_THAT(why(Vec3(0, 0, 0), Vec3(1, 2, 3)), labkit::check::contains_text("zero vector"));

  check::Expect swapped("closest0 is on the first body, closest1 on the second");
  swapped.near("closest0", Vec3(4, 5, 6), Vec3(1, 2, 3), 1e-12);
  swapped.near("closest1", Vec3(1, 2, 3), Vec3(4, 5, 6), 1e-12);
  CHECK_THAT(swapped.outcome().why, labkit::check::contains_text("closest0 and closest1 are swapped"));

  check::Expect counted("a query tests each triangle once");
  counted.equal("tests", 4, 3);
  CHECK(counted.outcome().why ==
        "a query tests each triangle once: tests is 4, not 3; one more than the answer (an off-by-one?)");
}

TEST_CASE("the given segment-triangle test agrees with the oracle and is watertight", "[kit]") {
  // Random cases away from doubt must agree with the exact answer.
  int compared = 0;
  rc::Random random(7);
  const rc::Gen<SegmentTrianglePair> gen = gen::segment_triangle();
  for (int i = 0; i < 4000; ++i) {
    random = rc::Random(std::uint64_t(i) * 7919 + 1);
    const SegmentTrianglePair p = gen(random, 100).value();
    const double delta = 1e-9 * check::scale_of_input(p);
    if (oracle::segment_triangle_in_doubt(p.segment, p.triangle, delta)) continue;
    const given::SegmentHit h = given::segment_triangle(p.segment, p.triangle);
    CHECK(h.hit == oracle::segment_hits_triangle(p.segment, p.triangle));
    if (h.hit) CHECK(oracle::within(h.point, p.triangle, delta));
    ++compared;
  }
  CHECK(compared > 1500);  // over half the cases are deliberately in doubt
  // A segment through the shared diagonal of a square, or its shared corner, hits it.
  const Triangle t0{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}}, t1{{0, 0, 0}, {4, 4, 0}, {0, 4, 0}};
  for (const Segment& s : {Segment{{2, 2, 1}, {2, 2, -1}}, Segment{{1.3, 1.3, 0.7}, {1.1, 1.1, -0.3}},
                           Segment{{4, 4, 3}, {4, 4, -3}}, Segment{{0.1, 0.1, 1}, {1.0 / 3, 1.0 / 3, -1}}})
    CHECK((given::segment_triangle(s, t0).hit || given::segment_triangle(s, t1).hit));
}

TEST_CASE("a step's report reads back what was written, and a bad one names the field", "[kit]") {
  report::Step step;
  step.seed = "42";
  step.cases_per_query = 100;
  step.finished = true;
  step.test_cases.push_back({"L02S1 worked examples", {"lab02", "step1"}, false, true, {"REQUIRE failed"}, ""});
  report::Query q;
  q.query = "segment_plane";
  q.kind = "random";
  q.failure = report::Failure{"random case 6 of 100", "a segment", "a hit", "no hit", "the rule", "segment_plane:1", 3};
  step.queries.push_back(q);
  step.queries.push_back({});
  const report::Step back = report::step_from_json(report::to_json(step));
  CHECK(report::to_json(back) == report::to_json(step));
  REQUIRE(back.queries[0].failure);
  CHECK(back.queries[0].failure->why == "the rule");
  CHECK(!back.queries[1].failure);

  nlohmann::json bad = report::to_json(step);
  bad["queries"][0]["failure"].erase("why");
  CHECK_THROWS_WITH(report::step_from_json(bad), "the report's \"queries\"[0]'s \"failure\" has no \"why\"");
  bad = report::to_json(step);
  bad["test_cases"][0]["passed"] = "yes";
  CHECK_THROWS_WITH(report::step_from_json(bad),
                    "the report's \"test_cases\"[0]'s \"passed\" has the wrong type (string)");
}

// The judge's side of the given calls (common/given/served.h): what it counts, and what it
// refuses from a process that writes frames of its own.
namespace {
std::string counted_frame(const std::string& name) {
  wire::Writer w;
  wire::put(w, name);
  return w.take();
}
std::string part_frame(int index) {
  wire::Writer w;
  wire::put(w, std::string("part"));
  wire::put(w, index);
  return w.take();
}
}  // namespace

TEST_CASE("the judge counts given calls per answer and per part, and refuses forged frames", "[kit]") {
  std::string reply;
  given::Served served;
  CHECK_FALSE(given::take_frame(given::kCountedFrame, counted_frame("segment_triangle"), served, reply));
  CHECK_FALSE(given::take_frame(given::kCountedFrame, part_frame(0), served, reply));
  given::take_frame(given::kCountedFrame, counted_frame("segment_triangle"), served, reply);
  given::take_frame(given::kCountedFrame, part_frame(1), served, reply);
  given::take_frame(given::kCountedFrame, counted_frame("segment_triangle"), served, reply);
  given::take_frame(given::kCountedFrame, counted_frame("segment_triangle"), served, reply);
  CHECK(served.count("segment_triangle") == 4);
  CHECK(served.count(0, "segment_triangle") == 1);
  CHECK(served.count(1, "segment_triangle") == 2);
  CHECK(served.problem.empty());

  given::Served forged;  // a name nobody counts, then a part out of order
  given::take_frame(given::kCountedFrame, counted_frame("my_own_test"), forged, reply);
  CHECK(forged.problem.find("my_own_test") != std::string::npos);
  given::Served skipped;
  given::take_frame(given::kCountedFrame, part_frame(3), skipped, reply);
  CHECK(skipped.problem.find("part 3 where part 0") != std::string::npos);

  given::Served flood;  // parts without end: the ledger stops growing
  for (int k = 0; k < 50000; ++k) given::take_frame(given::kCountedFrame, part_frame(k), flood, reply);
  CHECK(flood.parts.size() < 50000 / 2);
  CHECK(flood.problem.find("parts in one call") != std::string::npos);

  given::Served unread;  // a served call the judge does not serve: refused, an empty reply
  CHECK(given::take_frame(given::kServedFrame, counted_frame("no_such_pose"), unread, reply));
  CHECK_FALSE(unread.problem.empty());
}

TEST_CASE("a judge's fiber waits at its call and goes on from there, once", "[kit]") {
  using remote::Fiber;
  CHECK_FALSE(Fiber::inside());
  std::vector<std::string> log;
  Fiber a([&] {
    log.push_back("a before its call");  // a side effect before the call happens once
    Fiber::wait();
    log.push_back("a after its call");
  });
  Fiber b([&] {
    CHECK(Fiber::inside());
    log.push_back("b before");
    Fiber::wait();
    Fiber::wait();  // a second, dependent call
    log.push_back("b after");
  });
  CHECK_FALSE(a.resume());
  CHECK_FALSE(b.resume());
  CHECK(a.resume());
  CHECK_FALSE(b.resume());
  CHECK(b.resume());
  CHECK(a.resume());  // done stays done
  CHECK(log == std::vector<std::string>{"a before its call", "b before", "a after its call", "b after"});

  Fiber thrower([] {
    Fiber::wait();
    throw std::runtime_error("from the judge");
  });
  CHECK_FALSE(thrower.resume());
  CHECK_THROWS_WITH(thrower.resume(), "from the judge");
}

TEST_CASE("fibers that wait inside catch blocks each keep their own exception", "[kit]") {
  using remote::Fiber;
  std::vector<std::string> seen;
  const auto judge = [&seen](std::string name) {
    return [&seen, name] {
      try {
        throw std::runtime_error(name);
      } catch (const std::exception&) {
        Fiber::wait();  // a call made from a catch block (a judge's second try)
        try {
          throw;  // the exception this fiber is handling, not the other's
        } catch (const std::exception& again) {
          seen.push_back(again.what());
        }
      }
      seen.push_back(std::uncaught_exceptions() == 0 ? "clean" : "left over");
    };
  };
  Fiber one(judge("one")), two(judge("two"));
  CHECK_FALSE(one.resume());
  CHECK_FALSE(two.resume());
  CHECK(one.resume());
  CHECK(two.resume());
  CHECK(seen == std::vector<std::string>{"one", "clean", "two", "clean"});
  CHECK_FALSE(std::current_exception());
}

TEST_CASE("code that refuses a case with a NaN is not blamed: the kit drew it", "[kit]") {
  const Triangle floor{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto refuses = [](const SegmentTrianglePair&) -> check::Outcome {
    throw remote::Rejected("test_segment_triangle: segment.a must be finite");
  };
  check::detail::QueryReport valid, broken;
  const check::Outcome blamed =
      check::detail::run_judge(refuses, SegmentTrianglePair{{{1, 1, 1}, {1, 1, -1}}, floor}, valid);
  CHECK_THAT(blamed.why, check::contains_text("rejected a valid input"));
  CHECK(valid.error.empty());
  const check::Outcome kit =
      check::detail::run_judge(refuses, SegmentTrianglePair{{{nan, 1, 1}, {1, 1, -1}}, floor}, broken);
  CHECK_THAT(kit.why, check::contains_text("not finite"));
  CHECK_THAT(broken.error, check::contains_text("kit error"));
}
