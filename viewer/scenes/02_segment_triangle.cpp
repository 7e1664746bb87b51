// Lab 02 scene: segment against triangle and mesh (handouts/02_segment_triangle.md).
//
// A replay token's query picks the mode:
//   segment and triangle  segment_plane, test/find_segment_triangle   steps 1-4
//   point and triangle    point_in_triangle_*, barycentric            steps 2-3
//   segment and mesh      any_hit, first_hit, all_hits                step 5
//   moving mesh           first_hit_moving                            step 6
//   two moving meshes     first_contact_moving_meshes                 step 7
// The student's answers are drawn in the colour of their verdict; the exact answers
// (the toggle) are violet rings and arrows beside them.
#include "viewer/scenes/02_segment_triangle.h"
#include "viewer/scenes/scenes.h"

#include "common/generators/meshes.h"
#include "common/oracle/oracle.h"

#include <cmath>

namespace viewer::segment_triangle {

const std::vector<Preset> kPresets = {
    {"crossing", "the crossing point: d_a = 3, d_b = -1, so t = 3/4",
     "find_segment_triangle:0.5,0.5,3,2.5,1.5,-1,0,0,0,4,0,0,0,4,0", true, -75, 14, 1},
    {"barycentric", "barycentric coordinates: x = v0 + 0.25 (v1 - v0) + 0.5 (v2 - v0)",
     "barycentric:1,2,0,0,0,0,4,0,0,0,4,0", true, -90, 62, 3},
    {"miss", "crosses the plane beside the triangle: a miss", "find_segment_triangle:3,3,1,3,3,-1,0,0,0,4,0,0,0,4,0"},
    {"edge", "slanted through the long edge at t = 1/3", "find_segment_triangle:2,2,1,0,1,-2,0,0,0,3,0,0,0,3,0"},
    {"coplanar", "in the plane, entering at t = 1/6", "find_segment_triangle:-1,1,0,5,1,0,0,0,0,3,0,0,0,3,0"},
    {"shelf", "a mesh: the shelf is hit before the floor", nullptr, true, -35, 18},
    {"moving", "a rising floor meets a falling particle", nullptr, true, -60, 12},
    {"extrusion", "edge against edge: A's lowest edge sweeps a parallelogram, B's top edge pierces it at t = 1/2",
     "first_contact_moving_meshes:3,-2,0,1,2,0,1,0,0,3,1,0,1,2,0,0,-2,3,1,-2,0,1,2,0,1,0,-2,1,0,1,2,0,0,0", true, -52,
     8, 7},
    {"mesh-100k", "a terrain of 100,352 triangles", nullptr},
};

// Weights (w0, w1, w2) of x in the triangle, in long double: the "exact" column of
// step 3 and 4 (the judges check that the student's weights reproduce the point).
Vec3 weights(const Vec3& x, const Triangle& t) {
  using L = long double;
  const Eigen::Matrix<L, 3, 1> e1 = (t.v1 - t.v0).cast<L>(), e2 = (t.v2 - t.v0).cast<L>(), p = (x - t.v0).cast<L>();
  const Eigen::Matrix<L, 3, 1> n = e1.cross(e2);
  const L area = n.squaredNorm();
  if (area == 0) return Vec3::Zero();
  const L alpha = p.cross(e2).dot(n) / area, beta = e1.cross(p).dot(n) / area;
  return Vec3(double(1 - alpha - beta), double(alpha), double(beta));
}

// ---- setup ---------------------------------------------------------------------------

SegmentTriangleScene::SegmentTriangleScene(const Setup& setup) {
  const Preset* preset = view_preset(kPresets, setup);
  if (setup.token.empty() && preset && !preset->token) {
    mode_ = preset->name == std::string("moving") ? Mode::moving : Mode::mesh;
    if (preset->name == std::string("mesh-100k")) {
      mesh_ = gen::height_field(224, 0, 8, 0, 8,
                                [](double x, double y) { return 0.6 * std::sin(x * 1.3) * std::cos(y * 0.9); });
      segment_ = {{1.5, 6.5, 3}, {6.5, 1.5, -1}};
    } else {
      gen::add_square(mesh_, 4, 0);  // the tests' floor, and the shelf above it
      if (mode_ == Mode::mesh)
        gen::add_square(mesh_, 4, 2), segment_ = {{1, 3, 5}, {1, 3, -1}};
      else
        m1_.translation() = Vec3(0, 0, 2), segment_ = {{1, 2.5, 3}, {1, 2.5, 0.5}};
    }
    frame_inputs();
    return;
  }
  const ParsedToken token =
      parse_token(starting_token(setup, kPresets, "find_segment_triangle:1,1,3,1,1,-1,0,0,0,4,0,0,0,4,0"));
  load_token(
      "02", query::table, token,
      Loaders{[&](auto, const SegmentTrianglePair& in) { segment_ = in.segment, triangle_ = in.triangle; },
              [&](auto, const PointTriangle& in) { mode_ = Mode::point, x_ = in.x, triangle_ = in.triangle; },
              [&](auto, const SegmentMeshPair& in) { mode_ = Mode::mesh, segment_ = in.segment, mesh_ = in.mesh; },
              [&](auto, const MovingMesh& in) {
    mode_ = Mode::moving, segment_ = in.segment, mesh_ = in.mesh, m0_ = in.m0, m1_ = in.m1;
              },
              [&](auto, const MovingMeshes& in) { mode_ = Mode::contact, meshes_ = in; }});
  frame_inputs();
}

void SegmentTriangleScene::frame_inputs() {
  const char* names[] = {"segment and triangle", "point and triangle", "segment and mesh", "moving mesh",
                         "two moving meshes"};
  mode = names[int(mode_)];
  std::vector<Vec3> points{segment_.a, segment_.b};
  if (mode_ == Mode::contact) {  // both meshes at the start and at the end of the frame
    points.clear();
    for (const Vec3& v : meshes_.a.vertices) points.insert(points.end(), {v, v + meshes_.velocity_a});
    for (const Vec3& v : meshes_.b.vertices) points.insert(points.end(), {v, v + meshes_.velocity_b});
  }
  if (mode_ == Mode::point) points = {x_};
  if (mode_ <= Mode::point) points.insert(points.end(), {triangle_.v0, triangle_.v1, triangle_.v2});
  for (const Vec3& v : mesh_.vertices) points.push_back(mode_ == Mode::moving ? m1_ * v : v);
  if (mode_ == Mode::moving) points.push_back(m1_ * (m0_.inverse() * segment_.a));
  Eigen::AlignedBox3d box;
  for (const Vec3& p : points) box.extend(p);
  frame(box);
}

std::string SegmentTriangleScene::token() const {
  switch (mode_) {
    case Mode::triangle: return replay_token(query::find_segment_triangle, SegmentTrianglePair{segment_, triangle_});
    case Mode::point: return replay_token(query::barycentric, PointTriangle{x_, triangle_});
    case Mode::mesh: return replay_token(query::first_hit, SegmentMeshPair{segment_, mesh_});
    case Mode::moving: break;
    case Mode::contact: return replay_token(query::first_contact_moving_meshes, meshes_);
  }
  return replay_token(query::first_hit_moving, MovingMesh{segment_, mesh_, m0_, m1_});
}

// ---- update --------------------------------------------------------------------------

std::string describe_hits(const std::vector<MeshHit>& hits) {
  std::string s;
  for (const MeshHit& h : hits) s += (s.empty() ? "" : ", ") + std::to_string(h.triangle) + " at " + num(h.t);
  return s.empty() ? "none" : s;
}

void SegmentTriangleScene::update() {
  steps.clear();
  switch (mode_) {
    case Mode::triangle: update_triangle(); break;
    case Mode::point: update_point(); break;
    case Mode::mesh: update_mesh(); break;
    case Mode::moving: update_moving(); break;
    case Mode::contact: update_contact(); break;
  }
}

// Steps 1 to 4: the crossing point, tested as step 2 and 3 test a point, then the hit.
void SegmentTriangleScene::update_triangle() {
  const Segment& s = segment_;
  const Triangle& tri = triangle_;
  const SegmentTrianglePair in{s, tri};
  crossing_ = attempt([&] { return segment_plane(s, tri); });
  exact_crossing_ = oracle::segment_plane(s, tri);
  Step one = judged("L02S1", "segment_plane: d_a, d_b, the crossing", crossing_,
                    [&](const PlaneCrossing& got) { return judge::segment_plane(in, got); });
  const auto& c = crossing_;
  const auto& e = exact_crossing_;
  one.rows = {{"d_a", c ? num(c->d_a) : "", num(e.d_a)},
              {"d_b", c ? num(c->d_b) : "", num(e.d_b)},
              {"crosses", c ? yes_no(c->crosses) : "", yes_no(e.crosses)}};
  if (e.crosses || (c && c->crosses))
    one.rows.push_back({"t, x", c && c->crosses ? num(c->t) + ", " + num(c->point) : "",
                        e.crosses ? num(e.t) + ", " + num(e.point) : ""});
  verdict_[1] = one.verdict;
  steps.push_back(one);
  probe_.reset();
  if (e.crosses) probe_ = e.point;
  update_probe();

  test_ = attempt([&] { return test_segment_triangle(s, tri); });
  find_ = attempt([&] { return find_segment_triangle(s, tri); });
  exact_hit_ = oracle::segment_triangle(s, tri);
  Step four = judged("L02S4", "test_ and find_segment_triangle", find_,
                     [&](const SegmentTriangleHit& got) { return judge::find_segment_triangle(in, got); });
  join(four, test_, [&](bool got) { return judge::test_segment_triangle(in, got); });
  const auto& f = find_;
  const bool hit = f && f->hit, exact = exact_hit_.hit;
  four.rows = {{"test", test_ ? yes_no(*test_, "hit", "miss") : "", yes_no(exact, "hit", "miss")},
               {"find: hit", f ? yes_no(f->hit) : "", yes_no(exact)}};
  if (hit || exact) {
    four.rows.push_back({"t", hit ? num(f->t) : "", exact ? num(exact_hit_.t) : ""});
    four.rows.push_back({"point", hit ? num(f->point) : "", exact ? num(exact_hit_.point) : ""});
    four.rows.push_back({"weights", hit ? num(f->barycentric) : "", exact ? num(weights(exact_hit_.point, tri)) : ""});
    four.rows.push_back({"normal", hit ? num(f->normal) : "", num(oracle::unit_normal(tri))});
  }
  verdict_[4] = four.verdict;
  steps.push_back(four);
}

// Steps 2 and 3 on the point x, which slides along the triangle's plane when it moves.
void SegmentTriangleScene::update_point() {
  const Triangle& tri = triangle_;
  plane_ = {tri.normal(), -tri.normal().dot(tri.v0)};
  const bool moved =
      last_triangle_ && (last_triangle_->v0 != tri.v0 || last_triangle_->v1 != tri.v1 || last_triangle_->v2 != tri.v2);
  if (moved && plane_.normal != Vec3::Zero()) x_ -= plane_.value(x_) / plane_.normal.squaredNorm() * plane_.normal;
  last_triangle_ = tri;
  probe_ = x_;
  update_probe();
}

// Steps 2 and 3: is the probe inside, by the edges and by its barycentric weights?
void SegmentTriangleScene::update_probe() {
  const Triangle& tri = triangle_;
  if (!probe_) {
    steps.push_back({"L02S2", "point_in_triangle_edges", Verdict::none, {}, "no crossing point: nothing to test"});
    steps.push_back({"L02S3", "barycentric", Verdict::none, {}, "no crossing point: nothing to test"});
    verdict_[2] = verdict_[3] = Verdict::none;
    return;
  }
  const PointTriangle in{*probe_, tri};
  const bool inside = oracle::point_in_triangle_projected(*probe_, tri);
  inside_edges_ = attempt([&] { return point_in_triangle_edges(*probe_, tri); });
  Step edges = judged("L02S2", "point_in_triangle_edges at x", inside_edges_,
                      [&](bool got) { return judge::point_in_triangle(in, got); });
  edges.rows = {{"inside", inside_edges_ ? yes_no(*inside_edges_) : "", yes_no(inside)}};
  barycentric_ = attempt([&] { return barycentric(*probe_, tri); });
  inside_barycentric_ = attempt([&] { return point_in_triangle_barycentric(*probe_, tri); });
  Step bary = judged("L02S3", "barycentric, point_in_triangle_barycentric", barycentric_,
                     [&](const Barycentric& got) { return judge::barycentric(in, got); });
  join(bary, inside_barycentric_, [&](bool got) { return judge::point_in_triangle(in, got); });
  const Vec3 w = weights(*probe_, tri);
  Vec3 n = oracle::unit_normal(tri).cwiseAbs();
  int axis = -1;
  if (n != Vec3::Zero()) n.maxCoeff(&axis);
  const auto& b = barycentric_;
  bary.rows = {{"dropped axis", b ? std::to_string(b->dropped_axis) : "", std::to_string(axis)},
               {"alpha, beta", b ? num(b->alpha) + ", " + num(b->beta) : "", num(w[1]) + ", " + num(w[2])},
               {"inside", inside_barycentric_ ? yes_no(*inside_barycentric_) : "", yes_no(inside)}};
  verdict_[2] = edges.verdict, verdict_[3] = bary.verdict;
  steps.push_back(edges);
  steps.push_back(bary);
}

void SegmentTriangleScene::update_mesh() {
  const Segment& s = segment_;
  const SegmentMeshPair in{s, mesh_};
  first_ = attempt([&] { return first_hit(s, mesh_); });
  any_ = attempt([&] { return any_hit(s, mesh_); });
  all_ = attempt([&] { return all_hits(s, mesh_); });
  exact_hits_ = oracle::segment_mesh_hits(s, mesh_);
  Step step = judged("L02S5", "first_hit, any_hit, all_hits", first_,
                     [&](const MeshHit& got) { return judge::first_hit(in, got); });
  join(step, any_, [&](bool got) { return judge::any_hit(in, got); });
  join(step, all_, [&](const std::vector<MeshHit>& got) { return judge::all_hits(in, got); });
  std::vector<MeshHit> exact;
  for (const oracle::SegmentHit& h : exact_hits_)
    exact.push_back({true, h.triangle, h.t, h.point, Vec3::Zero(), Vec3::Zero()});
  const auto& f = first_;
  step.rows = {
      {"any_hit", any_ ? yes_no(*any_) : "", yes_no(!exact.empty())},
      {"first: triangle", f ? (f->hit ? std::to_string(f->triangle) : "none") : "",
       exact.empty() ? "none" : std::to_string(exact[0].triangle)},
      {"first: t, point", f && f->hit ? num(f->t) + ", " + num(f->point) : "",
       exact.empty() ? "" : num(exact[0].t) + ", " + num(exact[0].point)},
      {"all (triangle at t)", all_ ? describe_hits(*all_).substr(0, 60) : "", describe_hits(exact).substr(0, 60)}};
  verdict_[5] = step.verdict;
  steps.push_back(step);
}

void SegmentTriangleScene::update_moving() {
  const Segment& s = segment_;
  const MovingMesh in{s, mesh_, m0_, m1_};
  first_ = attempt([&] { return first_hit_moving(s, mesh_, m0_, m1_); });
  exact_hits_ = oracle::moving_mesh_hits(s, mesh_, m0_, m1_);
  Step step =
      judged("L02S6", "first_hit_moving", first_, [&](const MeshHit& got) { return judge::first_hit_moving(in, got); });
  const auto& f = first_;
  const oracle::SegmentHit* e = exact_hits_.empty() ? nullptr : &exact_hits_[0];
  step.rows = {{"hit: triangle", f ? (f->hit ? std::to_string(f->triangle) : "none") : "",
                e ? std::to_string(e->triangle) : "none"},
               {"t", f && f->hit ? num(f->t) : "", e ? num(e->t) : ""},
               {"point (at m1)", f && f->hit ? num(f->point) : "", e ? num(e->point) : ""}};
  verdict_[6] = step.verdict;
  steps.push_back(step);
}

void SegmentTriangleScene::update_contact() {
  const MovingMeshes& in = meshes_;
  contact_ = attempt([&] { return first_contact_moving_meshes(in.a, in.velocity_a, in.b, in.velocity_b); });
  exact_contact_ = oracle::first_contact_translating(in.a, in.velocity_a, in.b, in.velocity_b);
  Step step = judged("L02S7", "first_contact_moving_meshes", contact_,
                     [&](const MeshContact& got) { return judge::first_contact_moving_meshes(in, got); });
  const auto& c = contact_;
  const auto& e = exact_contact_;
  const char* kinds[] = {"vertex of A on a face of B", "vertex of B on a face of A", "edge against edge"};
  step.rows = {{"contact", c ? yes_no(c->hit) : "", yes_no(e.hit)},
               {"t", c && c->hit ? num(c->t) : "", e.hit ? num(e.t) : ""},
               {"point", c && c->hit ? num(c->point) : "", e.hit ? num(e.point) : ""},
               {"normal", c && c->hit ? num(c->normal) : "", e.hit ? num(e.normal) : ""},
               {"family", "", e.hit ? kinds[e.kind] : ""}};
  verdict_[7] = step.verdict;
  steps.push_back(step);
}

// ---- draw: in 02_segment_triangle.draw.cpp, with inputs() and handles() -------------

}  // namespace viewer::segment_triangle

LABKIT_SCENE(segment_triangle, SegmentTriangleScene)
