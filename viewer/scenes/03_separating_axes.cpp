// Lab 03 scene: separating axes (handouts/03_separating_axes.md).
//
// A replay token's query picks the mode:
//   two boxes        project_box, separated_on_axis, box_axis, test_boxes, find_boxes  steps 1-3
//   two triangles    triangles_by_intervals, test_triangles                            step 4
//   moving boxes     test_moving_boxes, find_moving_boxes                              step 5
// The student's answers are drawn in the colour of their verdict; the exact answers
// (the toggle) are violet beside them.
#include "viewer/scenes/scenes.h"

#include "03_separating_axes.judge.h"
#include "common/oracle/oracle.h"
#include "separating_axes.h"

#include <imgui.h>

#include <Eigen/Geometry>

#include <cmath>

namespace viewer {
namespace {

using namespace labkit;
using namespace labkit::lab03;

enum class Mode { boxes, triangles, moving };

const std::vector<Preset> kPresets = {
    {"edge-axis", "least penetration along the edge axis A_0 x B_0: depth 25 / (4 sqrt 10) = 1.976", nullptr, true, -20, 20, 3},
    {"edge-apart", "apart along A_0 x B_0 only: every face axis overlaps", nullptr, true, -20, 20, 2},
    {"projection", "the projections onto x: radius 5 (0.6) + 2.5 (0.8) = 5, apart as 7 > 1 + 5", nullptr, true, -90, 80, 1},
    {"near-parallel", "B turned by 2^-54: the tiny axis A_0 x B_0 must not separate", nullptr},
    {"triangles", "crossing triangles: t1's vertex t1.v2 lies in t0's plane; they intersect", nullptr, true, -50, 25, 4},
    {"intervals", "the lecture's intervals on the line of the planes (read on y): t0 [0, 3], t1 [-5/3, 1] overlap", nullptr, true, -8, 38, 4},
    {"coplanar", "coplanar triangles sharing the long edge", nullptr},
    {"plate", "through a thin plate within one step: contact from 0.46875 to 0.53125", nullptr, true, -70, 30, 5},
    {"corner", "past a corner: only W x A_2 separates the swept boxes", nullptr, true, -90, 80, 5},
};

Box make_box(Vec3 center, Vec3 half, Mat3 axes = Mat3::Identity()) {
  Box b;
  b.center = center, b.half_extents = half, b.axes = axes;
  return b;
}

Mat3 sevenths() {
  Mat3 m;
  m << 3, -2, 6, 6, 3, -2, -2, 6, 3;
  return m / 7.0;
}

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

// Euler angles (degrees, z then y then x) for editing a box's axes.
Vec3 angles_of(const Mat3& axes) { return axes.eulerAngles(2, 1, 0) * (180.0 / M_PI); }
Mat3 axes_of(const Vec3& degrees) {
  const Vec3 r = degrees * (M_PI / 180.0);
  return (Eigen::AngleAxisd(r[0], Vec3::UnitZ()) * Eigen::AngleAxisd(r[1], Vec3::UnitY()) *
          Eigen::AngleAxisd(r[2], Vec3::UnitX()))
      .toRotationMatrix();
}

class SeparatingAxesScene : public Scene {
 public:
  explicit SeparatingAxesScene(const Setup& setup);
  void update() override;
  void draw(Frame& frame) override;
  bool inputs() override;
  std::vector<Handle> handles() override;
  std::string token() const override;

 private:
  void preset(const std::string& name);
  void frame_inputs();
  void update_boxes();
  void update_triangles();
  void update_moving();
  void draw_box(Renderer& r, const Box& b, Color c, float alpha, float width = 2) const;
  void draw_projection(Frame& f) const;
  void draw_line_intervals(Frame& f) const;

  Mode mode_ = Mode::boxes;
  Box a_ = make_box({0, 0, 0}, {1, 1, 1});
  Box b_ = make_box({0, 0.25, 0.5}, {1, 1, 1}, sevenths());
  Vec3 axis_ = Vec3::UnitX();  // step 1's axis L
  Vec3 angles_a_ = Vec3::Zero(), angles_b_ = Vec3::Zero();
  Triangle t0_{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, t1_{{1, 1, -2}, {1, 1, 2}, {1, -3, 0}};
  Vec3 va_ = Vec3::Zero(), vb_ = Vec3::Zero();
  double duration_ = 1, shown_time_ = 0;

  // The student's answers and the exact ones.
  Attempt<Projection> proj_a_, proj_b_;
  Attempt<bool> separated_, test_, tri_, moving_test_;
  Attempt<std::array<Vec3, 15>> axes_;
  Attempt<BoxContact> find_;
  Attempt<ContactInterval> interval_;
  Attempt<LineIntervals> line_;
  bool exact_intersect_ = false;
  int exact_index_ = -1;
  Vec3 exact_axis_ = Vec3::Zero();
  double exact_depth_ = 0;
  oracle::ContactTimes exact_times_;
  Verdict verdict_[7] = {};
};

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
    const std::string& q = token.query;
    if (q == "project_box") {
      const auto in = input_from_token<BoxOnAxis>(token);
      a_ = in.box, axis_ = in.axis, b_ = make_box(in.box.center + Vec3(0, 0, 3 * in.box.half_extents.maxCoeff() + 1), Vec3(0.5, 0.5, 0.5));
    } else if (q == "separated_on_axis") {
      const auto in = input_from_token<BoxPairOnAxis>(token);
      a_ = in.a, b_ = in.b, axis_ = in.axis;
    } else if (q == "box_axis" || q == "test_boxes" || q == "find_boxes" || q == "robust.boxes") {
      const auto in = input_from_token<BoxPair>(token);
      a_ = in.a, b_ = in.b;
    } else if (q == "test_triangles" || q == "triangles_by_intervals" || q == "robust.triangles") {
      const auto in = input_from_token<TrianglePair>(token);
      mode_ = Mode::triangles, t0_ = in.t0, t1_ = in.t1;
    } else if (q == "test_moving_boxes" || q == "find_moving_boxes" || q == "robust.moving_boxes" ||
               q == "find_moving_boxes") {
      const auto in = input_from_token<MovingBoxes>(token);
      mode_ = Mode::moving, a_ = in.a, va_ = in.velocity_a, b_ = in.b, vb_ = in.velocity_b, duration_ = in.duration;
    } else {
      throw unknown_query("03", q, "project_box, separated_on_axis, box_axis, test_boxes, find_boxes, "
                                   "triangles_by_intervals, test_triangles, test_moving_boxes, find_moving_boxes");
    }
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
  Step s1 = judged("L03S1", "project_box, separated_on_axis along L", proj_a_,
                   [&](const Projection& got) { return judge::project_box(BoxOnAxis{a_, axis_}, got); });
  for (const Step& other :
       {judged("", "", proj_b_, [&](const Projection& got) { return judge::project_box(BoxOnAxis{b_, axis_}, got); }),
        judged("", "", separated_, [&](bool got) { return judge::separated_on_axis(BoxPairOnAxis{a_, b_, axis_}, got); })}) {
    join(s1, other);
  }
  const oracle::BoxProjection ea = oracle::box_projection(a_, axis_), eb = oracle::box_projection(b_, axis_);
  s1.rows = {{"A: centre, radius", proj_a_ ? num(proj_a_->center) + ", " + num(proj_a_->radius) : "", num(ea.center) + ", " + num(ea.radius)},
             {"B: centre, radius", proj_b_ ? num(proj_b_->center) + ", " + num(proj_b_->radius) : "", num(eb.center) + ", " + num(eb.radius)},
             {"separated along L", separated_ ? yes_no(*separated_) : "", yes_no(oracle::boxes_separated_along(a_, b_, axis_))}};
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
  const Step axes_step = judged("", "", axes_, [&](const std::array<Vec3, 15>& got) { return judge::box_axes(pair, got); });
  join(s2, axes_step);
  double worst = 0;
  if (axes_)
    for (int k = 0; k < 15; ++k) worst = std::max(worst, ((*axes_)[std::size_t(k)] - oracle::box_pair_axis(a_, b_, k)).norm());
  s2.rows = {{"the 15 axes: largest error", axes_ ? num(worst) : "", "0"},
             {"test_boxes", test_ ? yes_no(*test_, "intersecting", "separated") : "", yes_no(exact_intersect_, "intersecting", "separated")},
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
  Step s = judged("L03S4", "triangles_by_intervals, test_triangles", tri_, [&](bool got) { return judge::test_triangles(in, got); });
  const Step by_intervals =
      judged("", "", line_, [&](const LineIntervals& got) { return judge::triangles_by_intervals(in, got); });
  join(s, by_intervals);
  const auto interval = [](double low, double high) { return "[" + num(low) + ", " + num(high) + "]"; };
  const bool domain = gen::in_interval_domain(in);
  const int k = line_ && line_->crossing ? line_->axis : 0;
  const oracle::TriangleIntervals exact = oracle::triangle_intervals(t0_, t1_, k);
  const auto& l = line_;
  s.rows = {{"intervals: crossing, axis", l ? yes_no(l->crossing) + ", " + std::to_string(l->axis) : "",
             yes_no(exact.crossing) + (domain ? "" : " (outside the method's domain)")},
            {"t0 in t1's plane", l && l->crossing ? interval(l->low0, l->high0) : "", exact.crossing ? interval(exact.low0, exact.high0) : ""},
            {"t1 in t0's plane", l && l->crossing ? interval(l->low1, l->high1) : "", exact.crossing ? interval(exact.low1, exact.high1) : ""},
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
  const Step t = judged("", "", moving_test_, [&](bool got) { return judge::test_moving_boxes(in, got); });
  join(s, t);
  const auto& c = interval_;
  s.rows = {{"test", moving_test_ ? yes_no(*moving_test_, "contact", "never") : "", yes_no(exact_times_.contact, "contact", "never")},
            {"first", c && c->contact ? num(c->first) : "", exact_times_.contact ? num(exact_times_.first) : ""},
            {"last", c && c->contact ? num(c->last) : "", exact_times_.contact ? num(exact_times_.last) : ""}};
  verdict_[5] = s.verdict;
  steps.push_back(s);
}

// ---- draw ----------------------------------------------------------------------------

void SeparatingAxesScene::draw_box(Renderer& r, const Box& b, Color c, float alpha, float width) const {
  // Edges join corners whose numbers differ in one bit (Box::corner's numbering).
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k)
      if (!(i & (1 << k))) r.line(b.corner(i), b.corner(i | (1 << k)), c, width);
  if (alpha <= 0) return;
  static const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : faces) {
    r.triangle(b.corner(q[0]), b.corner(q[1]), b.corner(q[2]), c.with_alpha(alpha));
    r.triangle(b.corner(q[0]), b.corner(q[2]), b.corner(q[3]), c.with_alpha(alpha));
  }
}

// Step 1: the line through the origin along L, below the boxes, with each box's interval
// drawn on it (in world units: the projections divided by |L|).
void SeparatingAxesScene::draw_projection(Frame& f) const {
  Renderer& r = f.render;
  const double n = axis_.norm();
  if (n == 0) return;
  const Vec3 u = axis_ / n;
  // Beside the boxes as seen: across L in the picture (perpendicular to L and to the view).
  Vec3 side = r.view().forward.cast<double>().cross(u);
  if (side.norm() < 0.2) side = std::abs(u.z()) < 0.9 ? u.cross(Vec3::UnitZ()) : u.cross(Vec3::UnitX());
  side.normalize();
  const Vec3 base = side * (0.8 * radius) + center - u * u.dot(center);
  r.line(base - 1.6 * radius * u, base + 1.6 * radius * u, palette::muted, 1.5f);
  r.label(base + 1.6 * radius * u, "L", palette::muted);
  const Color c = colour(verdict_[1]);
  const auto interval = [&](const Attempt<Projection>& p, const Box& b, double lift, const char* name) {
    const Vec3 up = -side * lift;  // between the line and the boxes
    if (p) {
      const double lo = (p->center - p->radius) / n, hi = (p->center + p->radius) / n;
      r.line(base + up + lo * u, base + up + hi * u, c, 5);
      r.label(base + up + hi * u, std::string(name) + " [" + num(lo) + ", " + num(hi) + "]", c);
      // The two corners that project to the ends, and their projectors.
      for (const double end : {-1.0, 1.0}) {
        Vec3 corner = b.center;
        for (int k = 0; k < 3; ++k) corner += end * (b.axes.col(k).dot(u) >= 0 ? 1 : -1) * b.half_extents[k] * b.axes.col(k);
        r.dashed(corner, base + up + corner.dot(u) * u, palette::muted, 1.0f, 5.0f);
      }
    }
    if (f.show_exact) {
      const oracle::BoxProjection e = oracle::box_projection(b, axis_);
      r.ring(base + up + (e.center - e.radius) / n * u, palette::exact, 6);
      r.ring(base + up + (e.center + e.radius) / n * u, palette::exact, 6);
    }
  };
  interval(proj_a_, a_, 0.08 * radius, "A");
  interval(proj_b_, b_, 0.16 * radius, "B");
  if (proj_a_ && proj_b_) {
    // The gap between the intervals (or their overlap), on the line itself.
    const bool b_after = proj_b_->center >= proj_a_->center;
    const Projection& first = b_after ? *proj_a_ : *proj_b_;
    const Projection& second = b_after ? *proj_b_ : *proj_a_;
    const double from = (first.center + first.radius) / n, to = (second.center - second.radius) / n;
    r.line(base + from * u, base + to * u, c, 7);
    r.point(base + from * u, c, 4), r.point(base + to * u, c, 4);
    const std::string verdict = separated_ ? (*separated_ ? ": separated along L" : ": not separated along L") : "";
    r.label(base + 0.5 * (from + to) * u, (from < to ? "gap " + num(to - from) : "overlap " + num(from - to)) + verdict, c, 8, 18);
  }
}

// Step 4, the lecture's method: the line of the two planes, and on it each triangle's
// interval from the student's triangles_by_intervals, drawn a little inside its own
// triangle (t0's in t0's plane, t1's in t1's) so that both show where they overlap.
void SeparatingAxesScene::draw_line_intervals(Frame& f) const {
  if (!line_ || !line_->crossing || line_->axis < 0 || line_->axis > 2) return;
  Renderer& r = f.render;
  const Vec3 n0 = t0_.normal(), n1 = t1_.normal(), D = n0.cross(n1);
  const int k = line_->axis;
  if (D[k] == 0) return;
  // A point of both planes: n0 . x = h0, n1 . x = h1.
  const double h0 = n0.dot(t0_.v0), h1 = n1.dot(t1_.v0);
  const Vec3 origin = (h0 * n1.cross(D) + h1 * D.cross(n0)) / D.squaredNorm();
  const auto at = [&](double value) -> Vec3 { return origin + (value - origin[k]) / D[k] * D; };
  const double lo = std::min(line_->low0, line_->low1), hi = std::max(line_->high0, line_->high1);
  const double pad = 0.25 * (hi - lo) + 1e-12;
  const char* coordinate[] = {"x", "y", "z"};
  r.dashed(at(lo - pad), at(hi + pad), palette::muted, 1.5f);
  r.label(at(hi + pad), std::string("line of the planes, read on ") + coordinate[k], palette::muted);
  const Color c = colour(verdict_[4]);
  const auto interval = [&](double low, double high, const Vec3& normal, const char* name, bool label_low) {
    const Vec3 inside = D.cross(normal).normalized() * (0.06 * radius);
    const Vec3 toward = (t0_.v0 + t0_.v1 + t0_.v2 + t1_.v0 + t1_.v1 + t1_.v2) / 6 - at(low);
    const Vec3 shift = inside.dot(toward) < 0 ? Vec3(-inside) : inside;
    r.line(at(low) + shift, at(high) + shift, c, 5);
    r.point(at(low), c, 5), r.point(at(high), c, 5);
    const std::string text = std::string(name) + " [" + num(low) + ", " + num(high) + "]";
    r.label((label_low ? at(low) : at(high)) + 2 * shift, text, c, label_low ? -110 : 10, 0);
  };
  interval(line_->low0, line_->high0, n0, "t0", false);
  interval(line_->low1, line_->high1, n1, "t1", true);
  if (f.show_exact) {
    const oracle::TriangleIntervals e = oracle::triangle_intervals(t0_, t1_, k);
    for (const double v : {e.low0, e.high0, e.low1, e.high1})
      if (e.crossing) r.ring(at(v), palette::exact, 8);
  }
}

void SeparatingAxesScene::draw(Frame& f) {
  Renderer& r = f.render;
  draw_ground(r);
  if (mode_ == Mode::triangles) {
    const Color c = tri_ ? colour(verdict_[4]) : palette::surface;
    r.triangle(t0_.v0, t0_.v1, t0_.v2, palette::surface.with_alpha(0.6f));
    r.triangle(t1_.v0, t1_.v1, t1_.v2, palette::input.with_alpha(0.45f));
    // The header's names, t0.v0 ... t1.v2, and where each triangle straddles the other's
    // plane, the vertex roles of the text: p alone on its side, then q and r.
    // (The header's rule: p alone on its side, q and r on the other side or in the plane;
    // or p in the plane and q, r strictly on one side.)
    const auto sides = [](const Triangle& t, const Triangle& other, int side[3]) {
      for (int i = 0; i < 3; ++i) side[i] = oracle::orientation(other.v0, other.v1, other.v2, t[i]);
      const bool one_side = (side[0] > 0 && side[1] > 0 && side[2] > 0) || (side[0] < 0 && side[1] < 0 && side[2] < 0);
      return !one_side && (side[0] != 0 || side[1] != 0 || side[2] != 0);
    };
    const auto roles = [](const int side[3], std::string names[3]) {
      for (int k = 0; k < 3; ++k)
        for (const int flip : {1, -1}) {
          const int p = flip * side[k], q = flip * side[(k + 1) % 3], r = flip * side[(k + 2) % 3];
          if (p >= 0 && q <= 0 && r <= 0 && (p > 0 || (q < 0 && r < 0))) {
            names[k] += " = p", names[(k + 1) % 3] += " = q", names[(k + 2) % 3] += " = r";
            return;
          }
        }
    };
    std::string n0[3], n1[3];
    for (int i = 0; i < 3; ++i) n0[i] = "t0.v" + std::to_string(i), n1[i] = "t1.v" + std::to_string(i);
    int s0[3], s1[3];
    if (t0_.normal() != Vec3::Zero() && t1_.normal() != Vec3::Zero() && sides(t0_, t1_, s0) && sides(t1_, t0_, s1))
      roles(s0, n0), roles(s1, n1);
    for (int i = 0; i < 3; ++i) {
      r.line(t0_[i], t0_[(i + 1) % 3], palette::surface, 2);
      r.line(t1_[i], t1_[(i + 1) % 3], c, 2.5f);
      r.label(t0_[i], n0[i], palette::surface);
      r.label(t1_[i], n1[i], palette::input);
    }
    draw_line_intervals(f);
    if (tri_) r.label((t1_.v0 + t1_.v1 + t1_.v2) / 3, *tri_ ? "intersect" : "apart", c, 12, 34);
    if (f.show_exact && oracle::triangles_intersect(t0_, t1_))
      r.ring((t0_.v0 + t0_.v1 + t0_.v2) / 3, palette::exact, 9);  // violet: they do intersect
    return;
  }
  if (mode_ == Mode::moving) {
    // The start (faint), the end (faint, dashed path), the boxes at the shown time, and
    // B at the student's first contact time.
    draw_box(r, a_, palette::muted, 0, 1);
    draw_box(r, b_, palette::muted, 0, 1);
    r.dashed(b_.center, b_.center + duration_ * vb_, palette::muted);
    if (va_ != Vec3::Zero()) r.dashed(a_.center, a_.center + duration_ * va_, palette::muted);
    const auto moved = [](Box b, const Vec3& v, double t) { b.center += t * v; return b; };
    draw_box(r, moved(a_, va_, shown_time_), palette::surface, 0.35f);
    draw_box(r, moved(b_, vb_, shown_time_), palette::input, 0.25f);
    r.label(b_.center + shown_time_ * vb_, "t = " + num(shown_time_), palette::input);
    if (interval_ && interval_->contact && f.shows(5)) {
      const Color c = colour(verdict_[5]);
      draw_box(r, moved(b_, vb_ - va_, interval_->first), c, 0, 2.5f);
      r.label(b_.center + interval_->first * (vb_ - va_), "first " + num(interval_->first) + " (seen from A)", c, 10, 14);
    }
    if (interval_ && !interval_->contact && f.shows(5))
      r.label(b_.center + 0.5 * duration_ * vb_, "no contact in [0, " + num(duration_) + "]", colour(verdict_[5]), 12, 14);
    if (f.show_exact && exact_times_.contact) r.ring(b_.center + exact_times_.first * (vb_ - va_), palette::exact, 9);
    return;
  }
  draw_box(r, a_, palette::surface, 0.35f);
  draw_box(r, b_, palette::input, 0.2f);
  r.label(a_.center, "A", palette::surface), r.label(b_.center, "B", palette::input);
  if (f.shows(1) || f.shows(2) || f.shows(3)) draw_projection(f);  // steps 2 and 3 work on these intervals too
  if (find_ && f.shows(3)) {
    const Color c = colour(verdict_[3]);
    const double len = std::max(std::abs(find_->depth), 0.3 * radius);
    r.arrow(a_.center, a_.center + len * find_->axis, c, 3);
    r.label(a_.center + len * find_->axis, "axis " + axis_name(find_->axis_index) + ", depth " + num(find_->depth), c, 10, -10);
  }
  if (f.show_exact && exact_index_ >= 0 && (f.shows(3) || f.shows(2)))
    r.arrow(a_.center, a_.center + 0.8 * std::max(std::abs(exact_depth_), 0.3 * radius) * exact_axis_, palette::exact, 1.5f);
  if (test_ && f.shows(2))
    r.label(b_.center, *test_ ? "test: intersecting" : "test: separated", colour(verdict_[2]), 12, 14);
}

bool SeparatingAxesScene::inputs() {
  bool changed = false;
  if (mode_ == Mode::triangles) {
    for (int i = 0; i < 3; ++i) changed |= edit(("t0.v" + std::to_string(i)).c_str(), t0_[i]);
    for (int i = 0; i < 3; ++i) changed |= edit(("t1.v" + std::to_string(i)).c_str(), t1_[i]);
    return changed;
  }
  changed |= edit("A centre", a_.center) | edit("A half extents", a_.half_extents);
  if (edit("A turn (z, y, x degrees)", angles_a_, 1.0f)) a_.axes = axes_of(angles_a_), changed = true;
  changed |= edit("B centre", b_.center) | edit("B half extents", b_.half_extents);
  if (edit("B turn (z, y, x degrees)", angles_b_, 1.0f)) b_.axes = axes_of(angles_b_), changed = true;
  a_.half_extents = a_.half_extents.cwiseMax(0.0), b_.half_extents = b_.half_extents.cwiseMax(0.0);
  if (mode_ == Mode::boxes) changed |= edit("L (step 1)", axis_);
  if (mode_ == Mode::moving) {
    changed |= edit("A velocity", va_) | edit("B velocity", vb_) | edit("duration", duration_, 0.05f, 0, 100);
    edit("shown time", shown_time_, 0.01f, 0, duration_);
  }
  return changed;
}

std::vector<Handle> SeparatingAxesScene::handles() {
  if (mode_ == Mode::triangles)
    return {{&t0_.v0, "t0.v0"}, {&t0_.v1, "t0.v1"}, {&t0_.v2, "t0.v2"},
            {&t1_.v0, "t1.v0"}, {&t1_.v1, "t1.v1"}, {&t1_.v2, "t1.v2"}};
  return {{&a_.center, "A"}, {&b_.center, "B"}};
}

std::string SeparatingAxesScene::token() const {
  switch (mode_) {
    case Mode::boxes: return replay_token("find_boxes", BoxPair{a_, b_});
    case Mode::triangles: return replay_token("test_triangles", TrianglePair{t0_, t1_});
    case Mode::moving: break;
  }
  return replay_token("find_moving_boxes", MovingBoxes{a_, va_, b_, vb_, duration_});
}

}  // namespace

std::unique_ptr<Scene> make_separating_axes(const Setup& setup) { return std::make_unique<SeparatingAxesScene>(setup); }
const std::vector<Preset>& separating_axes_presets() { return kPresets; }

}  // namespace viewer
