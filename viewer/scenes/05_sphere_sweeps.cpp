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
#include "viewer/scenes/05_sphere_sweeps.h"
#include "viewer/scenes/scenes.h"

#include "common/oracle/oracle.h"

#include <algorithm>
#include <cmath>

namespace viewer::sphere_sweeps {

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
    {"spheres", "passing by: first contact at t = 3 - sqrt(3)/2", "sweep_sphere_sphere:0,0,0,1,0,0,0,6,1,0,1,-2,0,0,4",
     true, -90, 80, 5},
    {"graze", "an exact graze at t = 3 (b^2 = ac)", "sweep_sphere_sphere:0,0,0,1,0,0,0,6,2,0,1,-2,0,0,4"},
    {"sphere-capsule", "beyond the end: the side's root (t = 2) lies outside the slab; the cap's is t = 3 - sqrt(3)/2",
     "sweep_sphere_capsule:9,6,0,1,0,-2,0,0,0,0,8,0,0,1,4", true, -90, 80, 6},
    {"capsule-side", "toward the side: 6 - 2t = R = 2 at t = 2", "sweep_sphere_capsule:4,6,0,1,0,-2,0,0,0,0,8,0,0,1,4"},
    {"box", "a tilted box falls: reach 0.8 + 2 * 0.6 = 2, contact at t = 1",
     "sweep_box_plane:0,0,4,1,0,0,0,0.6,0.8,0,-0.8,0.6,1,1,2,0,0,-2,0,0,1,0,2", true, -80, 12, 7},
};

Vec3 corner(const Rectangle& r, int k) {
  const double su = (k & 1) ? 1.0 : -1.0, sv = (k & 2) ? 1.0 : -1.0;  // which corner
  return r.center + su * r.half_u * r.u + sv * r.half_v * r.v;
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

// ---- setup ---------------------------------------------------------------------------

SphereSweepsScene::SphereSweepsScene(const Setup& setup) {
  view_preset(kPresets, setup);
  const ParsedToken token = parse_token(starting_token(setup, kPresets, kPresets[0].token));
  const auto kinds = [&](Core k0, Core k1) { a_.kind = k0, b_.kind = k1; };
  // A test of step 3 (two shapes with radii) is drawn as its cores and radii; its token
  // names the test again, not a distance.
  const auto shapes = [&](auto q, Core k0, Core k1, double r0, double r1) {
    kinds(k0, k1), a_.radius = r0, b_.radius = r1;
    test_query_ = std::string(q.name).find("test_") != std::string::npos;
  };
  load_token(
      "05", query::table, token,
      Loaders{[&](auto, const SpherePlaneMotion& in) {
    mode_ = Mode::sphere_plane, s0_ = in.sphere, v0_ = in.velocity, plane_ = in.plane, duration_ = in.duration;
              },
              [&](auto, const SphereSphereMotion& in) {
    mode_ = Mode::sphere_sphere, s0_ = in.s0, v0_ = in.v0, s1_ = in.s1, v1_ = in.v1, duration_ = in.duration;
      },
      [&](auto, const SphereCapsuleMotion& in) {
    mode_ = Mode::sphere_capsule, s0_ = in.sphere, v0_ = in.velocity, capsule_ = in.capsule;
    duration_ = in.duration;
      },
      [&](auto, const BoxPlaneMotion& in) {
    mode_ = Mode::box_plane, box_ = in.box, v0_ = in.velocity, plane_ = in.plane, duration_ = in.duration;
  },
      [&](auto, const PointSegmentPair& in) { kinds(Core::point, Core::segment), a_.p = in.p, b_.s = in.segment; },
      [&](auto, const SegmentPair& in) { kinds(Core::segment, Core::segment), a_.s = in.first, b_.s = in.second; },
      [&](auto, const PointRectanglePair& in) {
    kinds(Core::point, Core::rectangle), a_.p = in.p, b_.r = in.rectangle;
      },
      [&](auto, const SegmentRectanglePair& in) {
    kinds(Core::segment, Core::rectangle), a_.s = in.segment, b_.r = in.rectangle;
      },
      [&](auto, const RectanglePair& in) {
    kinds(Core::rectangle, Core::rectangle), a_.r = in.first, b_.r = in.second;
      },
      [&](auto q, const SpherePair& in) {
    shapes(q, Core::point, Core::point, in.a.radius, in.b.radius), a_.p = in.a.center, b_.p = in.b.center;
      },
      [&](auto q, const SphereCapsule& in) {
    shapes(q, Core::point, Core::segment, in.a.radius, in.b.radius), a_.p = in.a.center, b_.s = in.b.axis;
      },
      [&](auto q, const SphereLozenge& in) {
    shapes(q, Core::point, Core::rectangle, in.a.radius, in.b.radius), a_.p = in.a.center;
    b_.r = in.b.rectangle;
      },
      [&](auto q, const CapsulePair& in) {
    shapes(q, Core::segment, Core::segment, in.a.radius, in.b.radius), a_.s = in.a.axis, b_.s = in.b.axis;
      },
      [&](auto q, const CapsuleLozenge& in) {
    shapes(q, Core::segment, Core::rectangle, in.a.radius, in.b.radius), a_.s = in.a.axis;
    b_.r = in.b.rectangle;
      }, [&](auto q, const LozengePair& in) {
        shapes(q, Core::rectangle, Core::rectangle, in.a.radius, in.b.radius), a_.r = in.a.rectangle;
        b_.r = in.b.rectangle;
      }});
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
  const auto ball_box = [&](const Vec3& c, double r) {
    box.extend(c - Vec3::Constant(r)), box.extend(c + Vec3::Constant(r));
  };
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
    if (mode_ == Mode::sphere_sphere)
      ball_box(s1_.center, s1_.radius), ball_box(end1_, s1_.radius);
    else if (mode_ == Mode::sphere_capsule)
      ball_box(capsule_.axis.a, capsule_.radius + s0_.radius), ball_box(capsule_.axis.b, capsule_.radius + s0_.radius);
    else
      box.extend(plane_point_);
  }
  frame(box);
}

std::string SphereSweepsScene::token() const {
  switch (mode_) {
    case Mode::sphere_plane:
      return replay_token(query::sweep_sphere_plane, SpherePlaneMotion{s0_, v0_, plane_, duration_});
    case Mode::sphere_sphere:
      return replay_token(query::sweep_sphere_sphere, SphereSphereMotion{s0_, v0_, s1_, v1_, duration_});
    case Mode::box_plane: return replay_token(query::sweep_box_plane, BoxPlaneMotion{box_, v0_, plane_, duration_});
    case Mode::sphere_capsule:
      return replay_token(query::sweep_sphere_capsule, SphereCapsuleMotion{s0_, v0_, capsule_, duration_});
    case Mode::cores: break;
  }
  const Sphere sa{a_.p, a_.radius}, sb{b_.p, b_.radius};
  const Capsule ca{a_.s, a_.radius}, cb{b_.s, b_.radius};
  const Lozenge la{a_.r, a_.radius}, lb{b_.r, b_.radius};
  const Core k0 = a_.kind, k1 = b_.kind;
  if (k0 == Core::point && k1 == Core::point) return replay_token(query::test_sphere_sphere, SpherePair{sa, sb});
  if (k0 == Core::point && k1 == Core::segment)
    return test_query_ ? replay_token(query::test_sphere_capsule, SphereCapsule{sa, cb})
                       : replay_token(query::point_segment, PointSegmentPair{a_.p, b_.s});
  if (k0 == Core::segment && k1 == Core::segment)
    return test_query_ ? replay_token(query::test_capsule_capsule, CapsulePair{ca, cb})
                       : replay_token(query::segment_segment, SegmentPair{a_.s, b_.s});
  if (k0 == Core::point && k1 == Core::rectangle)
    return test_query_ ? replay_token(query::test_sphere_lozenge, SphereLozenge{sa, lb})
                       : replay_token(query::point_rectangle, PointRectanglePair{a_.p, b_.r});
  if (k0 == Core::segment && k1 == Core::rectangle)
    return test_query_ ? replay_token(query::test_capsule_lozenge, CapsuleLozenge{ca, lb})
                       : replay_token(query::segment_rectangle, SegmentRectanglePair{a_.s, b_.r});
  return test_query_ ? replay_token(query::test_lozenge_lozenge, LozengePair{la, lb})
                     : replay_token(query::rectangle_rectangle, RectanglePair{a_.r, b_.r});
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
  if (mode_ == Mode::cores) {
    update_cores();
    return;
  }
  follow_handles();
  switch (mode_) {
    case Mode::sphere_plane: update_sphere_plane(); break;
    case Mode::sphere_sphere: update_sphere_sphere(); break;
    case Mode::sphere_capsule: update_sphere_capsule(); break;
    case Mode::box_plane: update_box_plane(); break;
    case Mode::cores: break;
  }
  verdict_[step_of(mode_)] = steps[0].verdict;
}

// One sweep's step: the answer, the exact first contact and overlap at t = 0 (kept for the
// picture), and the rows that set them side by side.
template <class Motion, class Exact, class Run>
Step SphereSweepsScene::sweep_step(const char* tag, const char* title, const Motion& in, const Exact& exact, Run run,
                                   Judge<Motion> judge_it) {
  sweep_ = attempt(run);
  exact_time_ = oracle::first_contact(exact, in.duration), exact_overlapping_ = oracle::gap_sign(exact, 0.0, 0.0) <= 0;
  Step s = judged(tag, title, sweep_, [&](const Sweep& got) { return judge_it(in, got, judge::Rules::random); });
  const std::string status = exact_overlapping_ ? "overlapping" : (exact_time_ < 0 ? "none" : "contact");
  s.rows = {{"status", sweep_ ? describe(sweep_->status) : "", status}};
  const bool contact = sweep_ && sweep_->status == SweepStatus::contact;
  if (contact || status == "contact")
    s.rows.push_back({"time", contact ? num(sweep_->time) : "", status == "contact" ? num(exact_time_) : ""});
  if (contact) s.rows.push_back({"point", num(sweep_->point), ""});
  return s;
}

void SphereSweepsScene::update_sphere_plane() {
  steps.push_back(sweep_step(
      "L05S4", "sweep_sphere_plane", SpherePlaneMotion{s0_, v0_, plane_, duration_},
      oracle::SpherePlaneSweep{s0_, v0_, plane_}, [&] { return sweep_sphere_plane(s0_, v0_, plane_, duration_); },
      judge::sweep_sphere_plane));
}

void SphereSweepsScene::update_sphere_sphere() {
  Step s = sweep_step(
      "L05S5", "sweep_sphere_sphere", SphereSphereMotion{s0_, v0_, s1_, v1_, duration_},
      oracle::SphereSphereSweep{s0_, s1_, v0_, v1_}, [&] { return sweep_sphere_sphere(s0_, v0_, s1_, v1_, duration_); },
      judge::sweep_sphere_sphere);
  // The quadratic's coefficients (rounded), for the handout's special cases.
  const Vec3 A = s0_.center - s1_.center, B = v0_ - v1_;
  const double R = s0_.radius + s1_.radius;
  s.rows.push_back({"a, b, c", "", num(B.squaredNorm()) + ", " + num(A.dot(B)) + ", " + num(A.squaredNorm() - R * R)});
  steps.push_back(s);
}

void SphereSweepsScene::update_sphere_capsule() {
  Step s = sweep_step(
      "L05S6", "sweep_sphere_capsule", SphereCapsuleMotion{s0_, v0_, capsule_, duration_},
      oracle::SphereCapsuleSweep{s0_, v0_, capsule_},
      [&] { return sweep_sphere_capsule(s0_, v0_, capsule_, duration_); }, judge::sweep_sphere_capsule);
  s.rows.push_back({"grown radius R = r + rc", "", num(s0_.radius + capsule_.radius)});
  steps.push_back(s);
}

void SphereSweepsScene::update_box_plane() {
  Step s = sweep_step(
      "L05S7", "sweep_box_plane", BoxPlaneMotion{box_, v0_, plane_, duration_},
      oracle::BoxPlaneSweep{box_, v0_, plane_}, [&] { return sweep_box_plane(box_, v0_, plane_, duration_); },
      judge::sweep_box_plane);
  const Plane plane = drawable(plane_);
  const double n = plane.normal.norm();
  double reach = 0;
  for (int i = 0; i < 3; ++i) reach += box_.half_extents[i] * std::abs(plane.normal.dot(box_.axes.col(i)));
  s.rows.push_back({"projected radius", "", n > 0 ? num(reach / n) : "no plane"});
  steps.push_back(s);
}

// ---- draw: in 05_sphere_sweeps.draw.cpp, with inputs() and handles() ----------------

}  // namespace viewer::sphere_sweeps

LABKIT_SCENE(sphere_sweeps, SphereSweepsScene)
