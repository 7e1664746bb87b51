// Lab 03 scene: separating axes (handouts/03_separating_axes.md).
//
// A replay token's query picks the mode:
//   two boxes        project_box, separated_on_axis, box_axis, test_boxes, find_boxes  steps 1-3
//   two triangles    triangles_by_intervals, test_triangles                            step 4
//   moving boxes     test_moving_boxes, find_moving_boxes                              step 5
// The student's answers are drawn in the colour of their verdict; the exact answers
// (the toggle) are violet beside them.
#include "viewer/scenes/03_separating_axes.h"
#include "viewer/scenes/scenes.h"

#include "common/oracle/oracle.h"

#include <Eigen/Geometry>
#include <cmath>

namespace viewer::separating_axes {

const std::vector<Preset> kPresets = {
    {"edge-axis", "least penetration along the edge axis A_0 x B_0: depth 25 / (4 sqrt 10) = 1.976", nullptr, true, -20,
     20, 3},
    {"edge-apart", "apart along A_0 x B_0 only: every face axis overlaps", nullptr, true, -20, 20, 2},
    {"projection", "the projections onto x: radius 5 (0.6) + 2.5 (0.8) = 5, apart as 7 > 1 + 5", nullptr, true, -90, 80,
     1},
    {"near-parallel", "B turned by 2^-54: the tiny axis A_0 x B_0 must not separate", nullptr},
    {"triangles", "crossing triangles: t1's vertex t1.v2 lies in t0's plane; they intersect", nullptr, true, -50, 25,
     4},
    {"intervals", "the lecture's intervals on the line of the planes (read on y): t0 [0, 3], t1 [-5/3, 1] overlap",
     nullptr, true, -8, 38, 4},
    {"coplanar", "coplanar triangles sharing the long edge", nullptr},
    {"plate", "through a thin plate within one step: contact from 0.46875 to 0.53125", nullptr, true, -70, 30, 5},
    {"corner", "past a corner: only W x A_2 separates the swept boxes", nullptr, true, -90, 80, 5},
};

Mat3 three_four_five() {
  Mat3 m;
  m << 0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1;
  return m;
}

std::string axis_name(int index) {
  if (index < 0 || index > 14) return std::to_string(index);
  static const char* names[] = {"A_0", "A_1", "A_2", "B_0", "B_1", "B_2"};
  if (index < 6) return std::to_string(index) + " " + names[index];
  return std::to_string(index) + " A_" + std::to_string((index - 6) / 3) + " x B_" + std::to_string((index - 6) % 3);
}

Vec3 angles_of(const Mat3& axes) { return axes.eulerAngles(2, 1, 0) * (180.0 / M_PI); }
Mat3 axes_of(const Vec3& degrees) {
  const Vec3 r = degrees * (M_PI / 180.0);
  return (Eigen::AngleAxisd(r[0], Vec3::UnitZ()) * Eigen::AngleAxisd(r[1], Vec3::UnitY()) *
          Eigen::AngleAxisd(r[2], Vec3::UnitX()))
      .toRotationMatrix();
}

// ---- setup ---------------------------------------------------------------------------

void SeparatingAxesScene::preset(const std::string& name) {
  const Box cube = make_box({0, 0, 0}, {1, 1, 1});
  if (name == "edge-axis") a_ = cube, b_ = make_box({0, 0.25, 0.5}, {1, 1, 1}, sevenths()), axis_ = Vec3(0, 2, 6) / 7;
  if (name == "edge-apart") a_ = cube, b_ = make_box({0, 0.75, 2.5}, {1, 1, 1}, sevenths()), axis_ = Vec3(0, 2, 6) / 7;
  if (name == "projection") a_ = cube, b_ = make_box({7, 2, 0}, {5, 2.5, 1}, three_four_five()), axis_ = Vec3::UnitX();
  if (name == "near-parallel") {
    const double e = std::ldexp(1.0, -54);
    Mat3 tilted;
    tilted << 1, 0, e, 0, 1, 0, -2 * e, 0, 1;
    a_ = cube, b_ = make_box({0, 1.75, 0}, {1, 1, 1}, tilted), axis_ = Vec3::UnitY();
  }
  if (name == "triangles") mode_ = Mode::triangles;
  if (name == "intervals") mode_ = Mode::triangles, t1_ = {{1, 1, -2}, {1, 1, 2}, {1, -3, 1}};
  if (name == "coplanar") mode_ = Mode::triangles, t1_ = {{4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
  if (name == "plate") {
    mode_ = Mode::moving;
    a_ = make_box({0, 0, 0}, {0.0625, 1, 1}), b_ = make_box({-3, 0, 0}, {0.125, 0.125, 0.125});
    vb_ = {6, 0, 0}, duration_ = 1, shown_time_ = 0.46875;
  }
  if (name == "corner") {
    mode_ = Mode::moving;
    a_ = cube, b_ = make_box({5, 0.5, 0}, {1, 1, 1}), vb_ = {-6, 6, 0}, duration_ = 1, shown_time_ = 0.5;
  }
}

SeparatingAxesScene::SeparatingAxesScene(const Setup& setup) {
  const Preset* p = view_preset(kPresets, setup);
  if (setup.token.empty()) {
    preset(p ? p->name : "edge-axis");
  } else {
    const ParsedToken token = parse_token(setup.token);
    load_token("03", query::table, token,
               Loaders{[&](auto, const BoxOnAxis& in) {
      a_ = in.box, axis_ = in.axis;
      b_ = make_box(in.box.center + Vec3(0, 0, 3 * in.box.half_extents.maxCoeff() + 1), Vec3(0.5, 0.5, 0.5));
                       },
                       [&](auto, const BoxPairOnAxis& in) { a_ = in.a, b_ = in.b, axis_ = in.axis; },
                       [&](auto, const BoxPair& in) { a_ = in.a, b_ = in.b; },
                       [&](auto, const TrianglePair& in) { mode_ = Mode::triangles, t0_ = in.t0, t1_ = in.t1; },
                       [&](auto, const MovingBoxes& in) {
      mode_ = Mode::moving, a_ = in.a, va_ = in.velocity_a, b_ = in.b, vb_ = in.velocity_b;
      duration_ = in.duration;
               }});
  }
  angles_a_ = angles_of(a_.axes), angles_b_ = angles_of(b_.axes);
  frame_inputs();
}

void SeparatingAxesScene::frame_inputs() {
  const char* names[] = {"two boxes", "two triangles", "moving boxes"};
  mode = names[int(mode_)];
  Eigen::AlignedBox3d box;
  if (mode_ == Mode::triangles) {
    for (int i = 0; i < 3; ++i) box.extend(t0_[i]), box.extend(t1_[i]);
  } else {
    for (int i = 0; i < 8; ++i) {
      box.extend(a_.corner(i)), box.extend(b_.corner(i));
      if (mode_ == Mode::moving) box.extend(a_.corner(i) + duration_ * va_), box.extend(b_.corner(i) + duration_ * vb_);
    }
  }
  frame(box);
}

std::string SeparatingAxesScene::token() const {
  switch (mode_) {
    case Mode::boxes: return replay_token(query::find_boxes, BoxPair{a_, b_});
    case Mode::triangles: return replay_token(query::test_triangles, TrianglePair{t0_, t1_});
    case Mode::moving: break;
  }
  return replay_token(query::find_moving_boxes, MovingBoxes{a_, va_, b_, vb_, duration_});
}

// ---- update --------------------------------------------------------------------------

void SeparatingAxesScene::update() {
  steps.clear();
  if (mode_ == Mode::boxes) update_boxes();
  if (mode_ == Mode::triangles) update_triangles();
  if (mode_ == Mode::moving) update_moving();
}

void SeparatingAxesScene::update_boxes() {
  const BoxPair pair{a_, b_};
  // Step 1: both boxes projected onto L, and the strict test along it.
  proj_a_ = attempt([&] { return project_box(a_, axis_); });
  proj_b_ = attempt([&] { return project_box(b_, axis_); });
  separated_ = attempt([&] { return separated_on_axis(a_, b_, axis_); });
  Step s1 = judged("L03S1", "project_box, separated_on_axis along L", proj_a_, [&](const Projection& got) {
    return judge::project_box(BoxOnAxis{a_, axis_}, got);
  });
  join(s1, proj_b_, [&](const Projection& got) { return judge::project_box(BoxOnAxis{b_, axis_}, got); });
  join(s1, separated_, [&](bool got) { return judge::separated_on_axis(BoxPairOnAxis{a_, b_, axis_}, got); });
  const oracle::BoxProjection ea = oracle::box_projection(a_, axis_), eb = oracle::box_projection(b_, axis_);
  s1.rows = {{"A: centre, radius", proj_a_ ? num(proj_a_->center) + ", " + num(proj_a_->radius) : "",
              num(ea.center) + ", " + num(ea.radius)},
             {"B: centre, radius", proj_b_ ? num(proj_b_->center) + ", " + num(proj_b_->radius) : "",
              num(eb.center) + ", " + num(eb.radius)},
             {"separated along L", separated_ ? yes_no(*separated_) : "",
              yes_no(oracle::boxes_separated_along(a_, b_, axis_))}};
  verdict_[1] = s1.verdict;
  steps.push_back(s1);

  // Step 2: the 15 axes and the test.
  axes_ = attempt([&] {
    std::array<Vec3, 15> axes;
    for (int k = 0; k < 15; ++k) axes[std::size_t(k)] = box_axis(a_, b_, k);
    return axes;
  });
  test_ = attempt([&] { return test_boxes(a_, b_); });
  exact_intersect_ = oracle::boxes_intersect(a_, b_);
  Step s2 = judged("L03S2", "box_axis, test_boxes", test_, [&](bool got) { return judge::test_boxes(pair, got); });
  join(s2, axes_, [&](const std::array<Vec3, 15>& got) { return judge::box_axes(pair, got); });
  double worst = 0;
  if (axes_)
    for (int k = 0; k < 15; ++k)
      worst = std::max(worst, ((*axes_)[std::size_t(k)] - oracle::box_pair_axis(a_, b_, k)).norm());
  s2.rows = {{"the 15 axes: largest error", axes_ ? num(worst) : "", "0"},
             {"test_boxes", test_ ? yes_no(*test_, "intersecting", "separated") : "",
              yes_no(exact_intersect_, "intersecting", "separated")},
             {"exact margin", "", num(oracle::box_pair_margin(a_, b_))}};
  verdict_[2] = s2.verdict;
  steps.push_back(s2);

  // Step 3: the exact answer over the same 15 axes: separated: the axis with the largest
  // gap; intersecting: the least depth among the axes the contract includes.
  exact_index_ = -1;
  for (int k = 0; k < 15; ++k) {
    const Vec3 l = oracle::box_pair_axis(a_, b_, k);
    if (l == Vec3::Zero() || (exact_intersect_ && k >= 6 && l.norm() < 1e-6)) continue;
    const Vec3 toward = (b_.center - a_.center).dot(l) < 0 ? Vec3(-l) : l;
    const double d = oracle::box_depth_along(a_, b_, toward);
    if (exact_index_ < 0 || d < exact_depth_) exact_index_ = k, exact_depth_ = d, exact_axis_ = toward.normalized();
  }
  find_ = attempt([&] { return find_boxes(a_, b_); });
  Step s3 = judged("L03S3", "find_boxes: separating or least-penetration axis", find_,
                   [&](const BoxContact& got) { return judge::find_boxes(pair, got); });
  const auto& f = find_;
  s3.rows = {{"intersecting", f ? yes_no(f->intersecting) : "", yes_no(exact_intersect_)},
             {"axis", f ? axis_name(f->axis_index) : "", exact_index_ >= 0 ? axis_name(exact_index_) : ""},
             {"unit axis", f ? num(f->axis) : "", num(exact_axis_)},
             {"depth", f ? num(f->depth) : "", num(exact_depth_)}};
  if (!exact_intersect_) s3.rows.back().exact += " (the widest gap; any separating axis passes)";
  verdict_[3] = s3.verdict;
  steps.push_back(s3);
}

void SeparatingAxesScene::update_triangles() {
  const TrianglePair in{t0_, t1_};
  // The lecture's intervals (graded on their domain only), then the sign-based test.
  line_ = attempt([&] { return triangles_by_intervals(t0_, t1_); });
  tri_ = attempt([&] { return test_triangles(t0_, t1_); });
  Step s = judged("L03S4", "triangles_by_intervals, test_triangles", tri_,
                  [&](bool got) { return judge::test_triangles(in, got); });
  join(s, line_, [&](const LineIntervals& got) { return judge::triangles_by_intervals(in, got); });
  const auto interval = [](double low, double high) { return "[" + num(low) + ", " + num(high) + "]"; };
  const bool domain = judge::in_interval_domain(in);
  const int k = line_ && line_->crossing ? line_->axis : 0;
  const oracle::TriangleIntervals exact = oracle::triangle_intervals(t0_, t1_, k);
  const auto& l = line_;
  s.rows = {{"intervals: crossing, axis", l ? yes_no(l->crossing) + ", " + std::to_string(l->axis) : "",
             yes_no(exact.crossing) + (domain ? "" : " (outside the method's domain)")},
            {"t0 in t1's plane", l && l->crossing ? interval(l->low0, l->high0) : "",
             exact.crossing ? interval(exact.low0, exact.high0) : ""},
            {"t1 in t0's plane", l && l->crossing ? interval(l->low1, l->high1) : "",
             exact.crossing ? interval(exact.low1, exact.high1) : ""},
            {"intersect", tri_ ? yes_no(*tri_) : "", yes_no(oracle::triangles_intersect(t0_, t1_))}};
  verdict_[4] = s.verdict;
  steps.push_back(s);
}

void SeparatingAxesScene::update_moving() {
  const MovingBoxes in{a_, va_, b_, vb_, duration_};
  moving_test_ = attempt([&] { return test_moving_boxes(a_, va_, b_, vb_, duration_); });
  interval_ = attempt([&] { return find_moving_boxes(a_, va_, b_, vb_, duration_); });
  exact_times_ = oracle::moving_boxes_contact(a_, va_, b_, vb_, duration_);
  Step s = judged("L03S5", "test_ and find_moving_boxes", interval_,
                  [&](const ContactInterval& got) { return judge::find_moving_boxes(in, got); });
  join(s, moving_test_, [&](bool got) { return judge::test_moving_boxes(in, got); });
  const auto& c = interval_;
  s.rows = {{"test", moving_test_ ? yes_no(*moving_test_, "contact", "never") : "",
             yes_no(exact_times_.contact, "contact", "never")},
            {"first", c && c->contact ? num(c->first) : "", exact_times_.contact ? num(exact_times_.first) : ""},
            {"last", c && c->contact ? num(c->last) : "", exact_times_.contact ? num(exact_times_.last) : ""}};
  verdict_[5] = s.verdict;
  steps.push_back(s);
}

// ---- draw: in 03_separating_axes.draw.cpp, with inputs() and handles() --------------

}  // namespace viewer::separating_axes

LABKIT_SCENE(separating_axes, SeparatingAxesScene)
