// Lab 05 scene: sphere-swept volumes, static and moving (handouts/05_sphere_sweeps.md).
//
// A replay token's query picks the mode:
//   cores                 point_segment, segment_segment, point_rectangle,          steps 1-3
//                         segment_rectangle, rectangle_rectangle, test_*
//   moving sphere, plane  sweep_sphere_plane                                         step 4
//   two moving spheres    sweep_sphere_sphere                                        step 5
//   sphere and capsule    sweep_sphere_capsule                                       step 6
//   moving box, plane     sweep_box_plane                                            step 7
// ("robust." tokens open the same modes.) In the cores mode the two cores (point,
// segment or rectangle) are drawn with their radii as wire hulls; the student's closest
// points and answers take the colour of their verdict. The exact answers (the toggle)
// are violet: the exact distance and status in the panel, rings at the exact contact.
#include "viewer/scenes/scenes.h"

#include "05_sphere_sweeps.judge.h"
#include "common/oracle/oracle.h"
#include "sphere_sweeps.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace viewer {
namespace {

using namespace labkit;
using namespace labkit::lab05;

enum class Mode { cores, sphere_plane, sphere_sphere, box_plane, sphere_capsule };
enum class Core { point, segment, rectangle };

const std::vector<Preset> kPresets = {
    {"capsules", "two capsules exactly touching: cores 2 apart, radii 1 + 1",
     "test_capsule_capsule:0,0,0,4,0,0,1,1,-1,2,1,3,2,1", true, -50, 20, 3},
    {"reproject", "the lines' pair is outside: the end b0 re-projected gives t = 0.3",
     "segment_segment:0,0,0,4,0,0,5,-2,1,7,2,1", true, -90, 70, 1},
    {"parallel", "parallel and overlapping: any closest pair, distance 3", "segment_segment:0,0,0,4,0,0,2,3,0,6,3,0"},
    {"rectangle", "a segment across a side of the rectangle: distance sqrt(2)",
     "segment_rectangle:3,-3,1,3,3,1,0,0,0,1,0,0,0,1,0,2,1", true, -30, 25, 2},
    {"lozenges", "a standing lozenge 1 above the floor one, radii 0.25 + 0.75: touching",
     "test_lozenge_lozenge:0,0,0,1,0,0,0,1,0,2,1,0.25,0,0,2,0,0,1,1,0,0,1,1,0.75", true, -70, 15, 3},
    {"sphere-plane", "a sphere falls on the plane z = 1 (normal of length 2): contact at t = 1.5",
     "sweep_sphere_plane:1,2,5,1,2,0,-2,0,0,2,-2,4", true, -80, 10, 4},
    {"spheres", "passing by: first contact at t = 3 - sqrt(3)/2",
     "sweep_sphere_sphere:0,0,0,1,0,0,0,6,1,0,1,-2,0,0,4", true, -90, 80, 5},
    {"graze", "an exact graze at t = 3 (b^2 = ac)", "sweep_sphere_sphere:0,0,0,1,0,0,0,6,2,0,1,-2,0,0,4"},
    {"sphere-capsule", "beyond the end: the side's root (t = 2) lies outside the slab; the cap's is t = 3 - sqrt(3)/2",
     "sweep_sphere_capsule:9,6,0,1,0,-2,0,0,0,0,8,0,0,1,4", true, -90, 80, 6},
    {"capsule-side", "toward the side: 6 - 2t = R = 2 at t = 2", "sweep_sphere_capsule:4,6,0,1,0,-2,0,0,0,0,8,0,0,1,4"},
    {"box", "a tilted box falls: reach 0.8 + 2 * 0.6 = 2, contact at t = 1",
     "sweep_box_plane:0,0,4,1,0,0,0,0.6,0.8,0,-0.8,0.6,1,1,2,0,0,-2,0,0,1,0,2", true, -80, 12, 7},
};

// One core of a sphere-swept volume, with its radius.
struct Shape {
  Core kind = Core::point;
  Vec3 p = Vec3::Zero();
  Segment s;
  Rectangle r;
  double radius = 0;
};

Vec3 perpendicular(const Vec3& d) {
  const Vec3 x = std::abs(d.x()) < 0.9 * d.norm() ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 n = d.cross(x);
  return n == Vec3::Zero() ? Vec3::UnitZ() : Vec3(n.normalized());
}

void circle(Renderer& r, const Vec3& c, const Vec3& e1, const Vec3& e2, double radius, Color col, float width = 1.2f) {
  constexpr int kSides = 48;
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * M_PI * i / kSides, b = 2 * M_PI * (i + 1) / kSides;
    r.line(c + radius * (std::cos(a) * e1 + std::sin(a) * e2), c + radius * (std::cos(b) * e1 + std::sin(b) * e2), col, width);
  }
}

// Half a circle: from e1 through e2 to -e1 (e2 points to the half drawn).
void arc(Renderer& r, const Vec3& c, const Vec3& e1, const Vec3& e2, double radius, Color col, float width = 1.2f) {
  constexpr int kSides = 24;
  for (int i = 0; i < kSides; ++i) {
    const double a = M_PI * i / kSides, b = M_PI * (i + 1) / kSides;
    r.line(c + radius * (std::cos(a) * e1 + std::sin(a) * e2), c + radius * (std::cos(b) * e1 + std::sin(b) * e2), col, width);
  }
}

// A capsule as a wire hull: the side's four lines, a ring at each end, and each end's
// hemispherical cap (two half circles across it, facing outward).
// `across`: a direction across the axis to draw the side's lines along (default: any).
void capsule_hull(Renderer& r, const Segment& axis, double radius, Color hull, float width = 1.2f,
                  const Vec3& across = Vec3::Zero());

void ball(Renderer& r, const Vec3& c, double radius, Color col, float width = 1.2f) {
  if (radius <= 0) return;
  circle(r, c, Vec3::UnitX(), Vec3::UnitY(), radius, col, width);
  circle(r, c, Vec3::UnitY(), Vec3::UnitZ(), radius, col, width);
  circle(r, c, Vec3::UnitZ(), Vec3::UnitX(), radius, col, width);
}

void capsule_hull(Renderer& r, const Segment& axis, double radius, Color hull, float width, const Vec3& across) {
  if (radius <= 0) return;
  const Vec3 d = axis.b - axis.a;
  if (d == Vec3::Zero()) {
    ball(r, axis.a, radius, hull, width);
    return;
  }
  const Vec3 along = d.normalized();
  const Vec3 side = across - across.dot(along) * along;
  const Vec3 e1 = side.norm() > 1e-9 * across.norm() && across != Vec3::Zero() ? Vec3(side.normalized()) : perpendicular(d);
  const Vec3 e2 = along.cross(e1).normalized();
  for (const Vec3& end : {axis.a, axis.b}) circle(r, end, e1, e2, radius, hull, width);
  for (const Vec3& off : {e1, Vec3(-e1), e2, Vec3(-e2)}) r.line(axis.a + radius * off, axis.b + radius * off, hull, width);
  for (const Vec3& e : {e1, e2}) {
    arc(r, axis.a, e, -along, radius, hull, width);
    arc(r, axis.b, e, along, radius, hull, width);
  }
}

Vec3 corner(const Rectangle& r, int k) {
  const double su = (k & 1) ? 1.0 : -1.0, sv = (k & 2) ? 1.0 : -1.0;  // which corner
  return r.center + su * r.half_u * r.u + sv * r.half_v * r.v;
}

// The core in `core`, its radius as a wire hull in `hull`.
void draw_shape(Renderer& r, const Shape& s, const char* name, Color core, Color hull) {
  switch (s.kind) {
    case Core::point:
      r.point(s.p, core, 6);
      r.label(s.p, name, core);
      ball(r, s.p, s.radius, hull);
      break;
    case Core::segment: {
      r.line(s.s.a, s.s.b, core, 2.5f);
      r.point(s.s.a, core, 5), r.point(s.s.b, core, 5);
      r.label(s.s.a, std::string(name) + ".a", core), r.label(s.s.b, std::string(name) + ".b", core);
      capsule_hull(r, s.s, s.radius, hull);
      break;
    }
    case Core::rectangle: {
      const Vec3 c[4] = {corner(s.r, 0), corner(s.r, 1), corner(s.r, 3), corner(s.r, 2)};  // around the border
      r.triangle(c[0], c[1], c[2], palette::surface.with_alpha(0.6f));
      r.triangle(c[0], c[2], c[3], palette::surface.with_alpha(0.6f));
      for (int i = 0; i < 4; ++i) r.line(c[i], c[(i + 1) % 4], core, 2);
      r.label(s.r.center, name, core);
      if (s.radius <= 0) break;
      const Vec3 n = s.r.u.cross(s.r.v).normalized();
      for (double side : {-1.0, 1.0})
        for (int i = 0; i < 4; ++i) r.line(c[i] + side * s.radius * n, c[(i + 1) % 4] + side * s.radius * n, hull, 1.2f);
      for (int i = 0; i < 4; ++i) circle(r, c[i], s.r.u, s.r.v, s.radius, hull);
      break;
    }
  }
}

void draw_box(Renderer& r, const Box& b, Color c, float width) {
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k)
      if (!((i >> k) & 1)) r.line(b.corner(i), b.corner(i | (1 << k)), c, width);
}

// The same plane with its normal scaled by a power of two (largest component in [1, 2)),
// for drawing only: n . n of a normal of length 1e200 or 1e-200 is then a normal double.
// The judge and the code under test always see the numbers as given.
Plane drawable(const Plane& p) {
  if (p.normal == Vec3::Zero() || !p.normal.allFinite()) return p;
  const int e = std::ilogb(p.normal.cwiseAbs().maxCoeff());
  return {Vec3(std::ldexp(p.normal.x(), -e), std::ldexp(p.normal.y(), -e), std::ldexp(p.normal.z(), -e)),
          std::ldexp(p.offset, -e)};
}

// A square of the plane around `near`, `size` across, and its normal.
void draw_plane(Renderer& r, const Plane& given, const Vec3& near, double size) {
  const Plane p = drawable(given);
  const double nn = p.normal.squaredNorm();
  if (nn == 0) return;
  const Vec3 n = p.normal / std::sqrt(nn), foot = near - p.value(near) / nn * p.normal;
  const Vec3 e1 = perpendicular(n), e2 = n.cross(e1);
  const Vec3 q[4] = {foot + size * (e1 + e2), foot + size * (-e1 + e2), foot + size * (-e1 - e2), foot + size * (e1 - e2)};
  r.triangle(q[0], q[1], q[2], palette::surface.with_alpha(0.35f));
  r.triangle(q[0], q[2], q[3], palette::surface.with_alpha(0.35f));
  for (int i = 0; i < 4; ++i) r.line(q[i], q[(i + 1) % 4], palette::surface, 1.5f);
  r.arrow(foot, foot + 0.3 * size * n, palette::muted, 2);
  r.label(foot + 0.3 * size * n, "n", palette::muted);
}


class SphereSweepsScene : public Scene {
 public:
  explicit SphereSweepsScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void read_cores(const std::string& query, const ParsedToken& token);
  void frame_inputs();
  void update_cores();
  void update_sweep();
  void follow_handles();
  void draw_cores(Frame& f) const;
  void draw_sweep(Frame& f) const;

  Mode mode_ = Mode::cores;
  Shape a_, b_;
  bool test_query_ = false;  // the token named a test (step 3), not a distance
  // Moving shapes: sphere 0 (and 1), the box, the plane, the step.
  Sphere s0_{{0, 0, 5}, 1}, s1_;
  Vec3 v0_ = Vec3::Zero(), v1_ = Vec3::Zero();
  Box box_;
  Capsule capsule_;
  Plane plane_{{0, 0, 1}, 0};
  double duration_ = 1;
  // Handles on derived points: the ends of the motions (centre + v T) and a point of
  // the plane. A moved handle sets its source; otherwise it follows it.
  Vec3 end0_, end1_, plane_point_;
  Vec3 last_end0_, last_end1_, last_plane_point_;
  double turn_ = 0, tilt_ = 0;  // the panel's box rotation, in degrees

  // The student's answers and the exact ones.
  std::optional<Vec3> closest0_, closest1_;
  Attempt<bool> meet_;
  Attempt<Sweep> sweep_;
  double exact_time_ = -1;  // the exact first contact (rounded), -1: none
  bool exact_overlapping_ = false;
  Verdict verdict_[8] = {};
};

// ---- setup ---------------------------------------------------------------------------

void SphereSweepsScene::read_cores(const std::string& q, const ParsedToken& token) {
  const auto kinds = [&](Core k0, Core k1) { a_.kind = k0, b_.kind = k1; };
  const auto radii = [&](double r0, double r1) { a_.radius = r0, b_.radius = r1; };
  if (q == "point_segment") {
    const auto in = input_from_token<PointSegmentPair>(token);
    kinds(Core::point, Core::segment), a_.p = in.p, b_.s = in.segment;
  } else if (q == "segment_segment") {
    const auto in = input_from_token<SegmentPair>(token);
    kinds(Core::segment, Core::segment), a_.s = in.first, b_.s = in.second;
  } else if (q == "point_rectangle") {
    const auto in = input_from_token<PointRectanglePair>(token);
    kinds(Core::point, Core::rectangle), a_.p = in.p, b_.r = in.rectangle;
  } else if (q == "segment_rectangle") {
    const auto in = input_from_token<SegmentRectanglePair>(token);
    kinds(Core::segment, Core::rectangle), a_.s = in.segment, b_.r = in.rectangle;
  } else if (q == "rectangle_rectangle") {
    const auto in = input_from_token<RectanglePair>(token);
    kinds(Core::rectangle, Core::rectangle), a_.r = in.first, b_.r = in.second;
  } else if (q == "test_sphere_sphere") {
    const auto in = input_from_token<SpherePair>(token);
    kinds(Core::point, Core::point), a_.p = in.a.center, b_.p = in.b.center, radii(in.a.radius, in.b.radius);
  } else if (q == "test_sphere_capsule") {
    const auto in = input_from_token<SphereCapsule>(token);
    kinds(Core::point, Core::segment), a_.p = in.a.center, b_.s = in.b.axis, radii(in.a.radius, in.b.radius);
  } else if (q == "test_sphere_lozenge") {
    const auto in = input_from_token<SphereLozenge>(token);
    kinds(Core::point, Core::rectangle), a_.p = in.a.center, b_.r = in.b.rectangle, radii(in.a.radius, in.b.radius);
  } else if (q == "test_capsule_capsule") {
    const auto in = input_from_token<CapsulePair>(token);
    kinds(Core::segment, Core::segment), a_.s = in.a.axis, b_.s = in.b.axis, radii(in.a.radius, in.b.radius);
  } else if (q == "test_capsule_lozenge") {
    const auto in = input_from_token<CapsuleLozenge>(token);
    kinds(Core::segment, Core::rectangle), a_.s = in.a.axis, b_.r = in.b.rectangle, radii(in.a.radius, in.b.radius);
  } else if (q == "test_lozenge_lozenge") {
    const auto in = input_from_token<LozengePair>(token);
    kinds(Core::rectangle, Core::rectangle), a_.r = in.a.rectangle, b_.r = in.b.rectangle, radii(in.a.radius, in.b.radius);
  } else {
    throw unknown_query("05", q, "point_segment, segment_segment, point_rectangle, segment_rectangle, rectangle_rectangle, "
                                  "test_sphere_sphere, test_sphere_capsule, test_sphere_lozenge, test_capsule_capsule, "
                                  "test_capsule_lozenge, test_lozenge_lozenge, sweep_sphere_plane, sweep_sphere_sphere, "
                                  "sweep_sphere_capsule, sweep_box_plane");
  }
  test_query_ = q.rfind("test_", 0) == 0;
}

SphereSweepsScene::SphereSweepsScene(const Setup& setup) {
  view_preset(kPresets, setup);
  const ParsedToken token = parse_token(starting_token(setup, kPresets, kPresets[0].token));
  std::string q = token.query;
  if (q.rfind("robust.", 0) == 0) q = q.substr(7);
  if (q == "sweep_sphere_plane") {
    const auto in = input_from_token<SpherePlaneMotion>(token);
    mode_ = Mode::sphere_plane, s0_ = in.sphere, v0_ = in.velocity, plane_ = in.plane, duration_ = in.duration;
  } else if (q == "sweep_sphere_sphere") {
    const auto in = input_from_token<SphereSphereMotion>(token);
    mode_ = Mode::sphere_sphere, s0_ = in.s0, v0_ = in.v0, s1_ = in.s1, v1_ = in.v1, duration_ = in.duration;
  } else if (q == "sweep_sphere_capsule") {
    const auto in = input_from_token<SphereCapsuleMotion>(token);
    mode_ = Mode::sphere_capsule, s0_ = in.sphere, v0_ = in.velocity, capsule_ = in.capsule, duration_ = in.duration;
  } else if (q == "sweep_box_plane") {
    const auto in = input_from_token<BoxPlaneMotion>(token);
    mode_ = Mode::box_plane, box_ = in.box, v0_ = in.velocity, plane_ = in.plane, duration_ = in.duration;
  } else {
    read_cores(q, token);
  }
  const Vec3 c = mode_ == Mode::box_plane ? box_.center : s0_.center;
  end0_ = last_end0_ = c + duration_ * v0_;
  end1_ = last_end1_ = s1_.center + duration_ * v1_;
  const Plane plane = drawable(plane_);
  const double nn = plane.normal.squaredNorm();
  plane_point_ = last_plane_point_ = nn > 0 ? Vec3(c - plane.value(c) / nn * plane.normal) : c;
  frame_inputs();
}

void SphereSweepsScene::frame_inputs() {
  const char* names[] = {"sphere-swept cores", "moving sphere and plane", "two moving spheres", "moving box and plane",
                         "moving sphere and capsule"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  const auto ball_box = [&](const Vec3& c, double r) { box.extend(c - Vec3::Constant(r)), box.extend(c + Vec3::Constant(r)); };
  const auto add = [&](const Shape& s) {
    if (s.kind == Core::point) ball_box(s.p, s.radius);
    if (s.kind == Core::segment) ball_box(s.s.a, s.radius), ball_box(s.s.b, s.radius);
    if (s.kind == Core::rectangle)
      for (int k = 0; k < 4; ++k) ball_box(corner(s.r, k), s.radius);
  };
  if (mode_ == Mode::cores) {
    add(a_), add(b_);
  } else if (mode_ == Mode::box_plane) {
    for (int i = 0; i < 8; ++i) box.extend(box_.corner(i)), box.extend(box_.corner(i) + duration_ * v0_);
    box.extend(plane_point_);
  } else {
    ball_box(s0_.center, s0_.radius), ball_box(end0_, s0_.radius);
    if (mode_ == Mode::sphere_sphere) ball_box(s1_.center, s1_.radius), ball_box(end1_, s1_.radius);
    else if (mode_ == Mode::sphere_capsule)
      ball_box(capsule_.axis.a, capsule_.radius + s0_.radius), ball_box(capsule_.axis.b, capsule_.radius + s0_.radius);
    else box.extend(plane_point_);
  }
  frame(box);
}

// ---- update --------------------------------------------------------------------------

// A moved end handle sets the velocity, a moved plane point the offset; otherwise they
// follow their sources (so that a replayed token keeps its exact numbers).
void SphereSweepsScene::follow_handles() {
  const Vec3& c0 = mode_ == Mode::box_plane ? box_.center : s0_.center;
  if (end0_ != last_end0_ && duration_ > 0) v0_ = (end0_ - c0) / duration_;
  if (end1_ != last_end1_ && duration_ > 0) v1_ = (end1_ - s1_.center) / duration_;
  if (plane_point_ != last_plane_point_) plane_.offset = -plane_.normal.dot(plane_point_);
  end0_ = last_end0_ = c0 + duration_ * v0_;
  end1_ = last_end1_ = s1_.center + duration_ * v1_;
  const Plane plane = drawable(plane_);
  const double nn = plane.normal.squaredNorm();
  if (nn > 0) plane_point_ -= plane.value(plane_point_) / nn * plane.normal;
  last_plane_point_ = plane_point_;
}

void SphereSweepsScene::update() {
  steps.clear();
  for (Verdict& v : verdict_) v = Verdict::none;
  if (mode_ == Mode::cores) update_cores();
  else update_sweep();
}

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
Step test_step(const char* title, const Pair& in, Test&& test, const oracle::SquaredDistance& cores, Attempt<bool>& got) {
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
    Step s = distance_step("L05S1", "point_segment", in, [&] { return point_segment(in.p, in.segment); },
                           [](const PointSegmentPair& i, const PointSegmentDistance& g) { return judge::point_segment(i, g); }, d, got);
    if (got) s.rows.push_back({"t", num(got->t), ""}), keep(in.p, got->closest);
    steps.push_back(s);
    steps.push_back(test_step("test_sphere_capsule", SphereCapsule{sa, cb}, test_sphere_capsule, d, meet_));
  } else if (k0 == Core::segment && k1 == Core::segment) {
    const SegmentPair in{a_.s, b_.s};
    const oracle::SquaredDistance d = oracle::squared_distance(in.first, in.second);
    Attempt<SegmentSegmentDistance> got;
    Step s = distance_step("L05S1", "segment_segment", in, [&] { return segment_segment(in.first, in.second); },
                           [](const SegmentPair& i, const SegmentSegmentDistance& g) { return judge::segment_segment(i, g); }, d, got);
    if (got) s.rows.push_back({"s, t", num(got->s) + ", " + num(got->t), ""}), keep(got->closest0, got->closest1);
    steps.push_back(s);
    steps.push_back(test_step("test_capsule_capsule", CapsulePair{ca, cb}, test_capsule_capsule, d, meet_));
  } else if (k0 == Core::point && k1 == Core::rectangle) {
    const PointRectanglePair in{a_.p, b_.r};
    const oracle::SquaredDistance d = oracle::squared_distance(in.p, in.rectangle);
    Attempt<PointRectangleDistance> got;
    Step s = distance_step("L05S2", "point_rectangle", in, [&] { return point_rectangle(in.p, in.rectangle); },
                           [](const PointRectanglePair& i, const PointRectangleDistance& g) { return judge::point_rectangle(i, g); }, d, got);
    if (got) s.rows.push_back({"s, t", num(got->s) + ", " + num(got->t), ""}), keep(in.p, got->closest);
    steps.push_back(s);
    steps.push_back(test_step("test_sphere_lozenge", SphereLozenge{sa, lb}, test_sphere_lozenge, d, meet_));
  } else if (k0 == Core::segment && k1 == Core::rectangle) {
    const SegmentRectanglePair in{a_.s, b_.r};
    const oracle::SquaredDistance d = oracle::squared_distance(in.segment, in.rectangle);
    Attempt<SegmentRectangleDistance> got;
    Step s = distance_step("L05S2", "segment_rectangle", in, [&] { return segment_rectangle(in.segment, in.rectangle); },
                           [](const SegmentRectanglePair& i, const SegmentRectangleDistance& g) { return judge::segment_rectangle(i, g); }, d, got);
    if (got) s.rows.push_back({"r; s, t", num(got->r) + "; " + num(got->s) + ", " + num(got->t), ""}), keep(got->closest0, got->closest1);
    steps.push_back(s);
    steps.push_back(test_step("test_capsule_lozenge", CapsuleLozenge{ca, lb}, test_capsule_lozenge, d, meet_));
  } else {
    const RectanglePair in{a_.r, b_.r};
    const oracle::SquaredDistance d = oracle::squared_distance(in.first, in.second);
    Attempt<RectangleRectangleDistance> got;
    Step s = distance_step("L05S2", "rectangle_rectangle", in, [&] { return rectangle_rectangle(in.first, in.second); },
                           [](const RectanglePair& i, const RectangleRectangleDistance& g) { return judge::rectangle_rectangle(i, g); }, d, got);
    if (got) keep(got->closest0, got->closest1);
    steps.push_back(s);
    steps.push_back(test_step("test_lozenge_lozenge", LozengePair{la, lb}, test_lozenge_lozenge, d, meet_));
  }
  verdict_[1] = verdict_[2] = steps[0].verdict;
  verdict_[3] = steps[1].verdict;
}

int step_of(Mode m) {
  switch (m) {
    case Mode::sphere_plane: return 4;
    case Mode::sphere_sphere: return 5;
    case Mode::sphere_capsule: return 6;
    case Mode::box_plane: return 7;
    case Mode::cores: break;
  }
  return 3;
}

template <class Motion, class Judge>
Step sweep_step(const char* tag, const char* title, const Motion& in, const Attempt<Sweep>& got, Judge&& judge,
                double exact_time, bool exact_overlapping) {
  Step s = judged(tag, title, got, [&](const Sweep& g) { return judge(in, g); });
  const std::string exact = exact_overlapping ? "overlapping" : (exact_time < 0 ? "none" : "contact");
  s.rows = {{"status", got ? describe(got->status) : "", exact}};
  const bool contact = got && got->status == SweepStatus::contact;
  if (contact || exact == "contact") s.rows.push_back({"time", contact ? num(got->time) : "", exact == "contact" ? num(exact_time) : ""});
  if (contact) s.rows.push_back({"point", num(got->point), ""});
  return s;
}

void SphereSweepsScene::update_sweep() {
  follow_handles();
  if (mode_ == Mode::sphere_plane) {
    const SpherePlaneMotion in{s0_, v0_, plane_, duration_};
    const oracle::SpherePlaneSweep m{s0_, v0_, plane_};
    sweep_ = attempt([&] { return sweep_sphere_plane(s0_, v0_, plane_, duration_); });
    exact_time_ = oracle::first_contact(m, duration_), exact_overlapping_ = oracle::gap_sign(m, 0.0, 0.0) <= 0;
    steps.push_back(sweep_step("L05S4", "sweep_sphere_plane", in, sweep_,
                               [](const SpherePlaneMotion& i, const Sweep& g) { return judge::sweep_sphere_plane(i, g); },
                               exact_time_, exact_overlapping_));
  } else if (mode_ == Mode::sphere_sphere) {
    const SphereSphereMotion in{s0_, v0_, s1_, v1_, duration_};
    const oracle::SphereSphereSweep m{s0_, s1_, v0_, v1_};
    sweep_ = attempt([&] { return sweep_sphere_sphere(s0_, v0_, s1_, v1_, duration_); });
    exact_time_ = oracle::first_contact(m, duration_), exact_overlapping_ = oracle::gap_sign(m, 0.0, 0.0) <= 0;
    Step s = sweep_step("L05S5", "sweep_sphere_sphere", in, sweep_,
                        [](const SphereSphereMotion& i, const Sweep& g) { return judge::sweep_sphere_sphere(i, g); },
                        exact_time_, exact_overlapping_);
    // The quadratic's coefficients (rounded), for the handout's special cases.
    const Vec3 A = s0_.center - s1_.center, B = v0_ - v1_;
    const double R = s0_.radius + s1_.radius;
    s.rows.push_back({"a, b, c", "", num(B.squaredNorm()) + ", " + num(A.dot(B)) + ", " + num(A.squaredNorm() - R * R)});
    steps.push_back(s);
  } else if (mode_ == Mode::sphere_capsule) {
    const SphereCapsuleMotion in{s0_, v0_, capsule_, duration_};
    const oracle::SphereCapsuleSweep m{s0_, v0_, capsule_};
    sweep_ = attempt([&] { return sweep_sphere_capsule(s0_, v0_, capsule_, duration_); });
    exact_time_ = oracle::first_contact(m, duration_), exact_overlapping_ = oracle::gap_sign(m, 0.0, 0.0) <= 0;
    Step s = sweep_step("L05S6", "sweep_sphere_capsule", in, sweep_,
                        [](const SphereCapsuleMotion& i, const Sweep& g) { return judge::sweep_sphere_capsule(i, g); },
                        exact_time_, exact_overlapping_);
    s.rows.push_back({"grown radius R = r + rc", "", num(s0_.radius + capsule_.radius)});
    steps.push_back(s);
  } else {
    const BoxPlaneMotion in{box_, v0_, plane_, duration_};
    const oracle::BoxPlaneSweep m{box_, v0_, plane_};
    sweep_ = attempt([&] { return sweep_box_plane(box_, v0_, plane_, duration_); });
    exact_time_ = oracle::first_contact(m, duration_), exact_overlapping_ = oracle::gap_sign(m, 0.0, 0.0) <= 0;
    Step s = sweep_step("L05S7", "sweep_box_plane", in, sweep_,
                        [](const BoxPlaneMotion& i, const Sweep& g) { return judge::sweep_box_plane(i, g); },
                        exact_time_, exact_overlapping_);
    const Plane plane = drawable(plane_);
    const double n = plane.normal.norm();
    double reach = 0;
    for (int i = 0; i < 3; ++i) reach += box_.half_extents[i] * std::abs(plane.normal.dot(box_.axes.col(i)));
    s.rows.push_back({"projected radius", "", n > 0 ? num(reach / n) : "no plane"});
    steps.push_back(s);
  }
  verdict_[step_of(mode_)] = steps[0].verdict;
}

// ---- draw ----------------------------------------------------------------------------

void SphereSweepsScene::draw_cores(Frame& f) const {
  Renderer& r = f.render;
  const bool hulls = f.shows(3);
  const Color hull = verdict_[3] == Verdict::none ? palette::muted : colour(verdict_[3]).with_alpha(0.8f);
  Shape a = a_, b = b_;
  if (!hulls) a.radius = b.radius = 0;
  draw_shape(r, a, "0", palette::input, hull);
  draw_shape(r, b, "1", palette::input, hull);
  const int distance = a_.kind == Core::rectangle || b_.kind == Core::rectangle ? 2 : 1;
  if (closest0_ && closest1_ && (f.shows(distance) || f.shows(3))) {
    const Color c = colour(verdict_[distance]);
    r.line(*closest0_, *closest1_, c, 3);
    r.point(*closest0_, c, 5), r.point(*closest1_, c, 5);
    r.label(0.5 * (*closest0_ + *closest1_), "d = " + num((*closest0_ - *closest1_).norm()), c, 10, 8);
  }
  // Two segments whose lines' closest pair lies outside: the classic mistake clamps both
  // parameters into [0, 1] at once. Its pair (dashed, red) is farther apart than the
  // closest pair, which re-projects the clamped end onto the other segment.
  if (a_.kind == Core::segment && b_.kind == Core::segment && f.shows(1)) {
    const Vec3 d0 = a_.s.b - a_.s.a, d1 = b_.s.b - b_.s.a, w = b_.s.a - a_.s.a, n = d0.cross(d1);
    const double nn = n.squaredNorm();
    if (nn > 1e-12 * d0.squaredNorm() * d1.squaredNorm()) {
      const double s = w.cross(d1).dot(n) / nn, t = w.cross(d0).dot(n) / nn;
      const Vec3 p = a_.s.a + std::clamp(s, 0.0, 1.0) * d0, q = b_.s.a + std::clamp(t, 0.0, 1.0) * d1;
      const double wrong = (p - q).norm(), right = oracle::squared_distance(a_.s, b_.s).distance();
      if ((s < 0 || s > 1 || t < 0 || t > 1) && wrong > right * (1 + 1e-9) + 1e-12) {
        r.dashed(p, q, palette::disagree, 2.5f);
        r.point(p, palette::disagree, 4), r.point(q, palette::disagree, 4);
        r.label(q, "wrong, clamped: s = " + num(std::clamp(s, 0.0, 1.0)) + ", t = " + num(std::clamp(t, 0.0, 1.0)) +
                       ", d = " + num(wrong),
                palette::disagree, 12, -14);
      }
    }
  }
  const Vec3 anchor = a_.kind == Core::point ? a_.p : a_.kind == Core::segment ? a_.s.a : a_.r.center;
  if (meet_ && hulls) r.label(anchor, *meet_ ? "they meet" : "apart", colour(verdict_[3]), 12, -28);
  // The exact answer is a number (the panel's exact column); the closest points are
  // ringed when the judge accepts them as a closest pair.
  if (f.show_exact && closest0_ && closest1_ && verdict_[distance] == Verdict::agree)
    r.ring(*closest0_, palette::exact, 9), r.ring(*closest1_, palette::exact, 9);
}

void SphereSweepsScene::draw_sweep(Frame& f) const {
  Renderer& r = f.render;
  const int step = step_of(mode_);
  const Color c = colour(verdict_[step]);
  const Vec3 start0 = mode_ == Mode::box_plane ? box_.center : s0_.center;
  if (mode_ == Mode::sphere_plane || mode_ == Mode::box_plane) draw_plane(r, plane_, start0 + 0.5 * duration_ * v0_, radius);
  if (mode_ == Mode::sphere_capsule) {
    // The capsule (its axis and hull), and the Minkowski sum the centre runs into: the
    // same axis grown to R = r + rc, dashed ends of the slab where the side stops.
    const Segment& axis = capsule_.axis;
    const double R = capsule_.radius + s0_.radius;
    r.line(axis.a, axis.b, palette::surface, 2.5f);
    r.point(axis.a, palette::surface, 5), r.point(axis.b, palette::surface, 5);
    r.label(axis.a, "a", palette::surface), r.label(axis.b, "b", palette::surface);
    // Across the axis toward the sphere's start, so that a view along the motion's plane
    // shows the side's lines, the slab's ends and the caps in profile.
    const Vec3 d = axis.b - axis.a;
    Vec3 e1 = d == Vec3::Zero() ? Vec3::UnitY() : perpendicular(d);
    if (d != Vec3::Zero()) {
      const Vec3 off = (s0_.center - axis.a) - (s0_.center - axis.a).dot(d) / d.squaredNorm() * d;
      if (off.norm() > 1e-9 * d.norm()) e1 = off.normalized();
    }
    capsule_hull(r, axis, capsule_.radius, palette::surface, 1.8f, e1);
    capsule_hull(r, axis, R, palette::muted.with_alpha(0.8f), 1.2f, e1);
    if (d != Vec3::Zero()) {
      r.label(axis.a - R * e1, "grown capsule: R = r + rc = " + num(R), palette::muted, -40, 22);
      // The slab's end planes, across the grown capsule: the side counts only between them.
      for (const Vec3& end : {axis.a, axis.b}) r.dashed(end - 1.5 * R * e1, end + 1.5 * R * e1, palette::muted, 1.5f);
      // The side's root (the infinite cylinder's), when it falls outside the slab.
      const Vec3 m = s0_.center - axis.a, md = m.cross(d), vd = v0_.cross(d);
      const double qa = vd.squaredNorm(), qb = md.dot(vd), qc = md.squaredNorm() - R * R * d.squaredNorm();
      if (qa > 0 && qb < 0 && qc > 0 && qb * qb - qa * qc >= 0) {
        const double t = qc / (-qb + std::sqrt(qb * qb - qa * qc));
        const Vec3 x = s0_.center + t * v0_;
        const double along = (x - axis.a).dot(d) / d.squaredNorm();
        if (t <= duration_ && (along < 0 || along > 1)) {
          r.point(x, palette::disagree, 5);
          r.label(x, "cylinder's root t = " + num(t) + ": outside the slab", palette::disagree, 30, -6);
        }
      }
    }
  }
  // The shapes at t = 0 (input colours) and at T (faint), and their paths.
  r.dashed(start0, end0_, palette::muted, 1.5f);
  r.label(end0_, "t = T", palette::muted);
  if (mode_ == Mode::box_plane) {
    draw_box(r, box_, palette::input, 2);
    Box at_end = box_;
    at_end.center = end0_;
    draw_box(r, at_end, palette::muted.with_alpha(0.5f), 1);
  } else {
    ball(r, s0_.center, s0_.radius, palette::input, 1.8f);
    ball(r, end0_, s0_.radius, palette::muted.with_alpha(0.5f), 1);
    r.point(s0_.center, palette::input, 5);
  }
  if (mode_ == Mode::sphere_sphere) {
    ball(r, s1_.center, s1_.radius, palette::surface, 1.8f);
    ball(r, end1_, s1_.radius, palette::muted.with_alpha(0.5f), 1);
    r.point(s1_.center, palette::surface, 5);
    r.dashed(s1_.center, end1_, palette::muted, 1.5f);
  }
  // The student's contact: the shapes then, and the point.
  if (sweep_ && sweep_->status == SweepStatus::contact && std::isfinite(sweep_->time)) {
    const double t = sweep_->time;
    if (mode_ == Mode::box_plane) {
      Box then = box_;
      then.center = box_.center + t * v0_;
      draw_box(r, then, c, 2.5f);
    } else {
      ball(r, s0_.center + t * v0_, s0_.radius, c, 2);
      if (mode_ == Mode::sphere_capsule) r.point(s0_.center + t * v0_, c, 4);
      if (mode_ == Mode::sphere_sphere) ball(r, s1_.center + t * v1_, s1_.radius, c, 2);
    }
    r.point(sweep_->point, c, 6);
    r.label(sweep_->point, "contact  t = " + num(t), c, 12, 10);
  } else if (sweep_) {
    r.label(start0, sweep_->status == SweepStatus::overlapping ? "overlapping at t = 0" : "no contact", c, 12, -24);
  }
  if (f.show_exact && exact_time_ >= 0) {  // the exact first contact: the centres then
    r.ring(start0 + exact_time_ * v0_, palette::exact, 9);
    if (mode_ == Mode::sphere_sphere) r.ring(s1_.center + exact_time_ * v1_, palette::exact, 9);
  }
}

void SphereSweepsScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::cores) draw_cores(f);
  else draw_sweep(f);
}

bool SphereSweepsScene::inputs() {
  bool changed = false;
  const auto shape = [&](const char* name, Shape& s) {
    ImGui::PushID(name);
    ImGui::TextDisabled("%s", name);
    if (s.kind == Core::point) changed |= edit("centre", s.p);
    if (s.kind == Core::segment) changed |= edit("a", s.s.a) | edit("b", s.s.b);
    if (s.kind == Core::rectangle) {
      changed |= edit("centre", s.r.center) | edit("half u", s.r.half_u, 0.05f, 0, 1e9) | edit("half v", s.r.half_v, 0.05f, 0, 1e9);
      Vec3 u = s.r.u;
      if (edit("u", u, 0.01f) && u != Vec3::Zero()) {  // keep u, v orthonormal
        s.r.u = u.normalized();
        const Vec3 v = s.r.v - s.r.v.dot(s.r.u) * s.r.u;
        s.r.v = v == Vec3::Zero() ? perpendicular(s.r.u) : Vec3(v.normalized());
        changed = true;
      }
    }
    changed |= edit("radius", s.radius, 0.02f, 0, 1e9);
    ImGui::PopID();
  };
  if (mode_ == Mode::cores) {
    shape("core 0", a_), shape("core 1", b_);
    return changed;
  }
  if (mode_ == Mode::box_plane) {
    changed |= edit("box centre", box_.center) | edit("half extents", box_.half_extents);
    if (edit("turn about z (deg)", turn_, 0.5f) | edit("tilt about x (deg)", tilt_, 0.5f)) {
      box_.axes = (Eigen::AngleAxisd(turn_ * M_PI / 180, Vec3::UnitZ()) * Eigen::AngleAxisd(tilt_ * M_PI / 180, Vec3::UnitX()))
                      .toRotationMatrix();
      changed = true;
    }
  } else {
    changed |= edit("centre 0", s0_.center) | edit("radius 0", s0_.radius, 0.02f, 0, 1e9);
  }
  changed |= edit(mode_ == Mode::sphere_sphere ? "velocity 0" : "velocity", v0_);
  if (mode_ == Mode::sphere_capsule)
    changed |= edit("capsule a", capsule_.axis.a) | edit("capsule b", capsule_.axis.b) |
               edit("capsule radius", capsule_.radius, 0.02f, 0, 1e9);
  else if (mode_ == Mode::sphere_sphere)
    changed |= edit("centre 1", s1_.center) | edit("radius 1", s1_.radius, 0.02f, 0, 1e9) | edit("velocity 1", v1_);
  else
    changed |= edit("plane normal", plane_.normal, 0.01f) | edit("plane offset", plane_.offset);
  changed |= edit("duration T", duration_, 0.02f, 0, 1e9);
  if (changed) {  // the handles follow the edited values
    const Vec3 c = mode_ == Mode::box_plane ? box_.center : s0_.center;
    end0_ = last_end0_ = c + duration_ * v0_;
    end1_ = last_end1_ = s1_.center + duration_ * v1_;
    last_plane_point_ = plane_point_;
  }
  return changed;
}

std::vector<Handle> SphereSweepsScene::handles() {
  std::vector<Handle> h;
  const auto shape = [&](Shape& s, const std::string& name) {
    if (s.kind == Core::point) h.push_back({&s.p, name});
    if (s.kind == Core::segment) h.insert(h.end(), {{&s.s.a, name + ".a"}, {&s.s.b, name + ".b"}});
    if (s.kind == Core::rectangle) h.push_back({&s.r.center, name + " centre"});
  };
  if (mode_ == Mode::cores) {
    shape(a_, "0"), shape(b_, "1");
    return h;
  }
  h.push_back({mode_ == Mode::box_plane ? &box_.center : &s0_.center, "centre"});
  h.push_back({&end0_, "centre at T"});
  if (mode_ == Mode::sphere_sphere) h.insert(h.end(), {{&s1_.center, "centre 1"}, {&end1_, "centre 1 at T"}});
  else if (mode_ == Mode::sphere_capsule) h.insert(h.end(), {{&capsule_.axis.a, "capsule a"}, {&capsule_.axis.b, "capsule b"}});
  else h.push_back({&plane_point_, "plane", &plane_});
  return h;
}

std::string SphereSweepsScene::token() const {
  switch (mode_) {
    case Mode::sphere_plane: return replay_token("sweep_sphere_plane", SpherePlaneMotion{s0_, v0_, plane_, duration_});
    case Mode::sphere_sphere: return replay_token("sweep_sphere_sphere", SphereSphereMotion{s0_, v0_, s1_, v1_, duration_});
    case Mode::box_plane: return replay_token("sweep_box_plane", BoxPlaneMotion{box_, v0_, plane_, duration_});
    case Mode::sphere_capsule:
      return replay_token("sweep_sphere_capsule", SphereCapsuleMotion{s0_, v0_, capsule_, duration_});
    case Mode::cores: break;
  }
  const Sphere sa{a_.p, a_.radius}, sb{b_.p, b_.radius};
  const Capsule ca{a_.s, a_.radius}, cb{b_.s, b_.radius};
  const Lozenge la{a_.r, a_.radius}, lb{b_.r, b_.radius};
  const Core k0 = a_.kind, k1 = b_.kind;
  if (k0 == Core::point && k1 == Core::point) return replay_token("test_sphere_sphere", SpherePair{sa, sb});
  if (k0 == Core::point && k1 == Core::segment)
    return test_query_ ? replay_token("test_sphere_capsule", SphereCapsule{sa, cb}) : replay_token("point_segment", PointSegmentPair{a_.p, b_.s});
  if (k0 == Core::segment && k1 == Core::segment)
    return test_query_ ? replay_token("test_capsule_capsule", CapsulePair{ca, cb}) : replay_token("segment_segment", SegmentPair{a_.s, b_.s});
  if (k0 == Core::point && k1 == Core::rectangle)
    return test_query_ ? replay_token("test_sphere_lozenge", SphereLozenge{sa, lb})
                       : replay_token("point_rectangle", PointRectanglePair{a_.p, b_.r});
  if (k0 == Core::segment && k1 == Core::rectangle)
    return test_query_ ? replay_token("test_capsule_lozenge", CapsuleLozenge{ca, lb})
                       : replay_token("segment_rectangle", SegmentRectanglePair{a_.s, b_.r});
  return test_query_ ? replay_token("test_lozenge_lozenge", LozengePair{la, lb})
                     : replay_token("rectangle_rectangle", RectanglePair{a_.r, b_.r});
}

}  // namespace

std::unique_ptr<Scene> make_sphere_sweeps(const Setup& setup) { return std::make_unique<SphereSweepsScene>(setup); }
const std::vector<Preset>& sphere_sweeps_presets() { return kPresets; }

}  // namespace viewer
