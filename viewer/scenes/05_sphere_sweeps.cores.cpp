// Lab 05 scene, the cores mode (steps 1 to 3): the distance between two cores, point,
// segment or rectangle, and the test of the two sphere-swept volumes around them.
#include "viewer/scenes/05_sphere_sweeps.h"

namespace viewer::sphere_sweeps {

// A distance step: the student's answer judged, its squared distance beside the exact one.
template <class In, class Got, class Call, class Judge>
Step distance_step(const char* tag, const char* title, const In& in, Call&& call, Judge&& judge,
                   const oracle::SquaredDistance& exact, Attempt<Got>& got) {
  got = attempt(call);
  Step s = judged(tag, title, got, [&](const Got& g) { return judge(in, g); });
  s.rows.push_back({"squared distance", got ? num(got->squared_distance) : "", num(exact.value())});
  return s;
}

// Step 3: the student's test beside "the cores' exact distance <= r0 + r1".
template <class Pair, class Test>
Step test_step(const char* title, const Pair& in, Test&& test, const oracle::SquaredDistance& cores,
               Attempt<bool>& got) {
  got = attempt([&] { return test(in.a, in.b); });
  Step s = judged("L05S3", title, got, [&](bool g) { return judge::test_pair(in, g); });
  const bool exact = cores.compare(in.a.radius, in.b.radius) <= 0;
  s.rows = {{"meet", got ? yes_no(*got) : "", yes_no(exact)},
            {"cores apart; r0 + r1", "", num(cores.distance()) + "; " + num(in.a.radius + in.b.radius)}};
  return s;
}

void SphereSweepsScene::update_cores() {
  closest0_.reset(), closest1_.reset();
  const Core k0 = a_.kind, k1 = b_.kind;
  const Sphere sa{a_.p, a_.radius}, sb{b_.p, b_.radius};
  const Capsule ca{a_.s, a_.radius}, cb{b_.s, b_.radius};
  const Lozenge la{a_.r, a_.radius}, lb{b_.r, b_.radius};
  const auto keep = [&](const Vec3& p, const Vec3& q) { closest0_ = p, closest1_ = q; };
  if (k0 == Core::point && k1 == Core::point) {
    steps.push_back({"L05S1", "two points", Verdict::none, {}, "two spheres: the centres' distance, nothing to write"});
    const oracle::SquaredDistance d = oracle::squared_distance(a_.p, b_.p);
    steps.push_back(test_step("test_sphere_sphere", SpherePair{sa, sb}, test_sphere_sphere, d, meet_));
  } else if (k0 == Core::point && k1 == Core::segment) {
    const PointSegmentPair in{a_.p, b_.s};
    const oracle::SquaredDistance d = oracle::squared_distance(in.p, in.segment);
    Attempt<PointSegmentDistance> got;
    Step s = distance_step(
        "L05S1", "point_segment", in, [&] { return point_segment(in.p, in.segment); }, judge::point_segment, d, got);
    if (got) s.rows.push_back({"t", num(got->t), ""}), keep(in.p, got->closest);
    steps.push_back(s);
    steps.push_back(test_step("test_sphere_capsule", SphereCapsule{sa, cb}, test_sphere_capsule, d, meet_));
  } else if (k0 == Core::segment && k1 == Core::segment) {
    const SegmentPair in{a_.s, b_.s};
    const oracle::SquaredDistance d = oracle::squared_distance(in.first, in.second);
    Attempt<SegmentSegmentDistance> got;
    Step s = distance_step(
        "L05S1", "segment_segment", in, [&] { return segment_segment(in.first, in.second); }, judge::segment_segment, d,
        got);
    if (got) s.rows.push_back({"s, t", num(got->s) + ", " + num(got->t), ""}), keep(got->closest0, got->closest1);
    steps.push_back(s);
    steps.push_back(test_step("test_capsule_capsule", CapsulePair{ca, cb}, test_capsule_capsule, d, meet_));
  } else if (k0 == Core::point && k1 == Core::rectangle) {
    const PointRectanglePair in{a_.p, b_.r};
    const oracle::SquaredDistance d = oracle::squared_distance(in.p, in.rectangle);
    Attempt<PointRectangleDistance> got;
    Step s = distance_step(
        "L05S2", "point_rectangle", in, [&] { return point_rectangle(in.p, in.rectangle); }, judge::point_rectangle, d,
        got);
    if (got) s.rows.push_back({"s, t", num(got->s) + ", " + num(got->t), ""}), keep(in.p, got->closest);
    steps.push_back(s);
    steps.push_back(test_step("test_sphere_lozenge", SphereLozenge{sa, lb}, test_sphere_lozenge, d, meet_));
  } else if (k0 == Core::segment && k1 == Core::rectangle) {
    const SegmentRectanglePair in{a_.s, b_.r};
    const oracle::SquaredDistance d = oracle::squared_distance(in.segment, in.rectangle);
    Attempt<SegmentRectangleDistance> got;
    Step s = distance_step(
        "L05S2", "segment_rectangle", in, [&] { return segment_rectangle(in.segment, in.rectangle); },
        judge::segment_rectangle, d, got);
    if (got)
      s.rows.push_back({"r; s, t", num(got->r) + "; " + num(got->s) + ", " + num(got->t), ""}),
          keep(got->closest0, got->closest1);
    steps.push_back(s);
    steps.push_back(test_step("test_capsule_lozenge", CapsuleLozenge{ca, lb}, test_capsule_lozenge, d, meet_));
  } else {
    const RectanglePair in{a_.r, b_.r};
    const oracle::SquaredDistance d = oracle::squared_distance(in.first, in.second);
    Attempt<RectangleRectangleDistance> got;
    Step s = distance_step(
        "L05S2", "rectangle_rectangle", in, [&] { return rectangle_rectangle(in.first, in.second); },
        judge::rectangle_rectangle, d, got);
    if (got) keep(got->closest0, got->closest1);
    steps.push_back(s);
    steps.push_back(test_step("test_lozenge_lozenge", LozengePair{la, lb}, test_lozenge_lozenge, d, meet_));
  }
  verdict_[1] = verdict_[2] = steps[0].verdict;
  verdict_[3] = steps[1].verdict;
}

}  // namespace viewer::sphere_sweeps
