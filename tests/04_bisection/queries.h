// Lab 04's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too. A Motion crosses as the numbers of its StandardMotion (the tests
// build every motion from one), or of a RecordingMotion.
#pragma once

#include "bisection.h"

#include "common/fields.h"
#include "common/given/served.h"
#include "common/harness/codec.h"
#include "common/harness/outcome.h"
#include "common/harness/query.h"
#include "common/protocol/calls.h"

#include <memory>
#include <string>
#include <vector>

namespace labkit::lab04 {

LABKIT_FIELDS(TimeOfImpact, hit, overlapping_at_start, t, t_contact, steps, iterations)
LABKIT_FIELDS(StandardMotion, start, velocity, acceleration, axis, spin)
LABKIT_FIELDS(Shape, kind, sphere, box)
LABKIT_FIELDS(MovingPair, a, motion_a, b, motion_b)

// A motion that writes down every time it is asked for a pose (step 2's example shows
// the lecture's midpoints with it). Sent to the answerer it is opaque, a number: each
// pose the code asks for is served by the judge's process (common/given/served.h), which
// writes the time down there and sends it back with the answer, into `asked`.
struct RecordingMotion {
  StandardMotion standard;
  std::shared_ptr<std::vector<double>> asked = std::make_shared<std::vector<double>>();
  RigidTransform operator()(double t) const {
    asked->push_back(t);
    return standard(t);
  }
};

// In the judge's process: the recording motions sent so far, by number.
inline std::vector<StandardMotion>& recording_motions() {
  static std::vector<StandardMotion> motions;
  return motions;
}
inline int recording_handle(const StandardMotion& m) {
  std::vector<StandardMotion>& all = recording_motions();
  const auto same = [&](const StandardMotion& o) {
    wire::Writer a, b;
    wire::put(a, m), wire::put(b, o);
    return a.bytes() == b.bytes();
  };
  for (std::size_t k = 0; k < all.size(); ++k)
    if (same(all[k])) return int(k);
  all.push_back(m);
  return int(all.size()) - 1;
}

// The judge serves a recording motion's poses, and writes their times down.
inline void serve_given() {
  given::serve("recorded_pose", [](wire::Reader& in, wire::Writer& out, given::Served& served) {
    int handle = -1;
    double t = 0;
    wire::get(in, handle), wire::get(in, t);
    if (handle < 0 || handle >= int(recording_motions().size())) throw wire::Error("no such recording motion");
    served.samples.push_back(t);
    wire::put(out, recording_motions()[std::size_t(handle)](t));
  });
}
#define LABKIT_LAB_SERVED ::labkit::lab04::serve_given

}  // namespace labkit::lab04

template <> struct labkit::wire::Codec<labkit::lab04::Motion> {
  static void put(Writer& w, const lab04::Motion& m) {
    if (const auto* recording = m.target<lab04::RecordingMotion>()) {
      wire::put(w, true);
      wire::put(w, lab04::recording_handle(recording->standard));
      remote::sample_into(recording->asked.get());
      return;
    }
    const auto* standard = m.target<lab04::StandardMotion>();
    if (!standard) throw Error("only a StandardMotion or a RecordingMotion can be sent to the answerer");
    wire::put(w, false);
    wire::put(w, *standard);
  }
  static void get(Reader& r, lab04::Motion& m) {
    bool recording = false;
    wire::get(r, recording);
    if (recording) {
      int handle = -1;
      wire::get(r, handle);
      m = [handle](double t) { return given::ask<RigidTransform>("recorded_pose", handle, t); };
      return;
    }
    lab04::StandardMotion standard;
    wire::get(r, standard);
    m = standard;
  }
};

// clang-format off
#define LABKIT_LAB04_CALLS(CALL, METHOD)                                                            \
  CALL(Sphere, placed, (const Sphere&, const RigidTransform&))                                      \
  CALL(Box, placed, (const Box&, const RigidTransform&))                                            \
  CALL(bool, overlap, (const Sphere&, const Sphere&))                                               \
  CALL(Vec3, closest_point, (const Box&, const Vec3&))                                              \
  CALL(bool, overlap, (const Sphere&, const Box&))                                                  \
  CALL(bool, overlap_at, (const MovingPair&, double))                                               \
  CALL(TimeOfImpact, bisect, (const MovingPair&, double, double, double))                           \
  CALL(double, smallest_size, (const Shape&))                                                       \
  CALL(double, closing_speed,                                                                       \
       (const Sphere&, const StandardMotion&, const Shape&, const StandardMotion&, double, double))     \
  CALL(int, substeps_for, (double, double, double))                                                 \
  CALL(TimeOfImpact, sample_then_bisect, (const MovingPair&, double, double, int, double))          \
  CALL(double, distance, (const Sphere&, const Sphere&))                                            \
  CALL(double, distance, (const Sphere&, const Box&))                                               \
  CALL(double, distance_at, (const MovingPair&, double))                                            \
  CALL(TimeOfImpact, advance, (const MovingPair&, double, double, double, double))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab04, LABKIT_LAB04_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 04's inputs: what each query of bisection.h is given, one struct per query, and
// their fields() (the names a report prints and a replay token reads). The generators
// (gen::, declared below) draw them, the judge and the viewer read them.
namespace labkit {

// A standard motion, as the kit describes it (lab 04's StandardMotion holds the same):
//   pose(t) x = start + velocity t + acceleration t^2 / 2 + R(t) x,
// R(t) the turn by spin * t radians about `axis` through the body's origin.
struct MotionParameters {
  Vec3 start = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double spin = 0.0;
};

// One body: a sphere, or (is_box) an oriented box, in its own frame, and its motion.
struct MovingBody {
  bool is_box = false;
  Sphere sphere;
  Box box;
  MotionParameters motion;
};

// The times of a search: the interval [t0, t1] and the tolerance.
struct SearchTimes {
  double t0 = 0.0;
  double t1 = 1.0;
  double tolerance = 1.0 / 64;
};

// A pair (the first body is always a sphere) and a search.
struct MovingPairCase {
  MovingBody a;
  MovingBody b;
  SearchTimes times;
};

// A point and a box, for the closest point.
struct PointBox {
  Vec3 point = Vec3::Zero();
  Box box;
};

// The numbers the sub-step rule takes.
struct SubstepRule {
  double max_speed = 0.0;
  double step = 0.0;
  double smallest_size = 0.0;
};

// A pair searched by point sampling with this many sub-steps.
struct SampledPair {
  MovingPairCase pair;
  int substeps = 1;
};

// A pair searched by conservative advancement, with the closing-speed bound of its
// standard motions times speed_factor (>= 1: a looser bound is still a bound).
struct AdvancedPair {
  MovingPairCase pair;
  double speed_factor = 1.0;
};

LABKIT_FIELDS(MovingBody, is_box, sphere, box, motion)
LABKIT_FIELDS(MovingPairCase, a, b, times)
LABKIT_FIELDS(PointBox, point, box)
LABKIT_FIELDS(SubstepRule, max_speed, step, smallest_size)
LABKIT_FIELDS(SampledPair, pair, substeps)
LABKIT_FIELDS(AdvancedPair, pair, speed_factor)

// Times, spins and axes are unit-free for the ambiguity check: they move by 1e-9, not by
// 1e-9 S, and they do not count toward the length scale S.
namespace codec {
void encode(Writer& w, const MotionParameters& m);
void decode(Reader& r, MotionParameters& m);
void encode(Writer& w, const SearchTimes& t);
void decode(Reader& r, SearchTimes& t);
}  // namespace codec
// How reports print them (defined, like the codec above, in tests/04_bisection/judge.cpp:
// the viewer and the generators share them).
std::string describe(const MotionParameters& m);  // only the parts that are not zero
std::string describe(const SearchTimes& t);
std::string describe(const MovingBody& b);  // the shape it is, and its motion

}  // namespace labkit

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB04_QUERIES(X, X_IN)                                                                            \
  /* step 1 */ X(placed, Sphere) X_IN(overlap, spheres, Sphere) X_IN(overlap, sphere_box, Sphere)                \
               X(closest_point, PointBox) X(overlap_at, MovingPairCase)                                          \
  /* step 2 */ X(bisect, MovingPairCase)                                                                         \
  /* step 3 */ X(tunnelling, MovingPairCase) X(smallest_size, MovingPairCase) X(closing_speed, MovingPairCase)   \
               X(substeps_for, SubstepRule) X(sample_then_bisect, SampledPair)                                   \
  /* step 4 */ X_IN(distance, spheres, Sphere) X_IN(distance, sphere_box, Sphere) X(distance_at, MovingPairCase) \
               X(advance, AdvancedPair)                                                                          \
  /* step 5 */ X_IN(robust, closest_point, PointBox) X_IN(robust, overlap_at, MovingPairCase)                    \
               X_IN(robust, bisect, MovingPairCase) X_IN(robust, substeps_for, SubstepRule)                      \
               X_IN(robust, sample_then_bisect, SampledPair) X_IN(robust, advance, AdvancedPair)
// clang-format on

namespace labkit::lab04::query {
LABKIT_QUERIES(LABKIT_LAB04_QUERIES)
}  // namespace labkit::lab04::query

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Seeded inputs for time of impact (lab 04): a sphere and a sphere or an oriented box,
// each moving by a standard motion, and the times of a search.
//
// Families on purpose: bodies that run into each other (so that a search has something to
// bracket), bodies that start overlapping, bodies that touch exactly at an end, at a
// midpoint or at a sample time, bodies that graze (touch for one instant) or miss by a
// hair, fast thin bodies that pass right through each other between two samples
// (tunnelling), spinning, screwing, orbiting and accelerating bodies, zero radii and zero
// half extents, every scale from 2^-20 to 2^20 and both ends of the header's domain
// (2^-300 and 2^300), and far from the origin. The exact families use integer coordinates
// and short binary times, so that every pose is exact.
namespace labkit::gen {

// Pairs for the overlap, bisection and advancement queries: mostly bodies that run into
// each other during [t0, t1], with starts that overlap, exact and near touching and
// grazing, and unrelated motions; every kind of standard motion; tolerances from 2^-30
// to 1/2 of the interval.
rc::Gen<MovingPairCase> moving_pair();
// Tolerances no finer than 2^-12 of the interval: conservative advancement may crawl
// forward one tolerance at a time past a near miss.
rc::Gen<MovingPairCase> advancing_pair();
// Exact input for the robustness step: integer coordinates (multiples of 8, times a power
// of two), radii that are multiples of 35 (so that Pythagorean directions give exact
// touching points), boxes with signed permutations for axes, motions without spin, and
// times that are short binary fractions; touching at t0, t1, midpoints and samples,
// grazing, zero radii and zero half extents.
rc::Gen<MovingPairCase> exact_moving_pair();
// A fast small sphere and a thin wall (or a small sphere): clear at t0 and at t1, and
// right through each other in between, faster than one sub-step of the lecture's rule
// can miss.
rc::Gen<MovingPairCase> tunnelling_pair();

rc::Gen<PointBox> point_box();
rc::Gen<PointBox> exact_point_box();
rc::Gen<SubstepRule> substep_rule();
// Mostly whole ratios (on the rule's boundary), exact in doubles: the robustness step's.
rc::Gen<SubstepRule> exact_substep_rule();
rc::Gen<SampledPair> sampled_pair();
rc::Gen<SampledPair> exact_sampled_pair();
rc::Gen<AdvancedPair> advanced_pair();
rc::Gen<AdvancedPair> exact_advanced_pair();

}  // namespace labkit::gen

// Lab 04's verdicts: each judge checks one answer against the exact oracle, following the
// tolerances and degenerate rules of labs/04_bisection/bisection.h. The tests and the
// viewer both use them, so a red mark in the viewer and a failing case in `./labkit
// check` always agree.
//
// Times are certified, never compared with another floating-point root: the oracle poses
// the bodies with the motion's own numbers at the reported times and decides overlap
// exactly there. A configuration is in doubt when the bodies' signed gap is within what a
// perturbation of the input by a relative 1e-9 can move it (they touch, or nearly:
// grazing contact); a verdict that hangs on such a configuration is ambiguous.
namespace labkit::lab04::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

Outcome closest_point(const PointBox& in, const Vec3& got, Rules rules = Rules::random);
// Overlap at t0 and at t1 of the case's search.
Outcome overlap_at(const MovingPairCase& in, bool got_t0, bool got_t1, Rules rules = Rules::random);
Outcome bisect(const MovingPairCase& in, const TimeOfImpact& got, Rules rules = Rules::random);
Outcome substeps_for(const SubstepRule& in, int got, Rules rules = Rules::random);
Outcome sample_then_bisect(const SampledPair& in, const TimeOfImpact& got, Rules rules = Rules::random);
// closing_speed of the pair on [t0, t1]: max_speed of a plus max_speed of b.
Outcome closing_speed(const MovingPairCase& in, double got);
// The tunnelling demonstration: the pair's closing speed, the sub-step count for it and
// the pair's size, point sampling at the frame's ends only (which must miss) and with
// that many sub-steps (which must find the contact).
Outcome tunnelling(const MovingPairCase& in, double got_speed, int got_substeps, const TimeOfImpact& frame_only,
                   const TimeOfImpact& substepped);
// The distance at t0 and at t1 of the case's search.
Outcome distance_at(const MovingPairCase& in, double got_t0, double got_t1);
Outcome advance(const AdvancedPair& in, const TimeOfImpact& got, Rules rules = Rules::random);

}  // namespace labkit::lab04::judge
