// Lab 02's judges of a segment against a mesh (steps 5 and 6: any, first and all hits, a
// mesh moving rigidly) and of two meshes moving by translations (step 7).
#include "02_segment_triangle/judge_internal.h"

#include "common/oracle/moving_meshes.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace labkit::lab02::judge {

Outcome any_hit(const SegmentMeshPair& in, bool got, Rules rules) {
  return mesh_yes_no(statuses(in.segment, in.mesh, tolerance_of(in), rules), got, rules, "hit", "miss", in.segment,
                     in.mesh);
}

Outcome first_hit(const SegmentMeshPair& in, const MeshHit& got, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<Status> all = statuses(in.segment, in.mesh, tol, rules);
  const Outcome decision = mesh_yes_no(all, got.hit, rules, "a hit", "no hit", in.segment, in.mesh);
  const bool expected = std::any_of(all.begin(), all.end(), [](const Status& st) { return st.hit; });
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  const std::vector<oracle::SegmentHit> hits = oracle::segment_mesh_hits(in.segment, in.mesh);
  if (!valid_index(in.mesh, got.triangle))
    return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle), "that triangle index is out of range");
  const Triangle tri = mesh_triangle(in.mesh, got.triangle);
  if (!hit_or_ambiguous(in.segment, tri, tol, rules))
    return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
                "the segment does not meet triangle " + std::to_string(got.triangle));
  Expect e(
      "a hit is where the segment meets the triangle: t along a to b, point a + t (b - a), weights of v0, v1, v2 that "
      "give the point");
  check_hit(e, in.segment, tri, got.t, got.point, got.barycentric, got.normal, tol);
  // The first hit whose existence is not in doubt bounds t from above.
  for (const oracle::SegmentHit& h : hits) {
    if (all[std::size_t(h.triangle)].unstable) continue;
    const Triangle first = mesh_triangle(in.mesh, h.triangle);
    const double slack = t_tolerance(in.segment, first, tol) + t_tolerance(in.segment, tri, tol);
    e.that("first", got.t <= h.t + slack, "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
           "triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t),
           "first_hit is the hit with the smallest t: triangle " + std::to_string(h.triangle) + " at t = " + fmt(h.t) +
               " comes before yours");
    break;
  }
  const Outcome o = e.outcome();
  return o.verdict == Outcome::Verdict::fail ? o : decision;
}

Outcome all_hits(const SegmentMeshPair& in, const std::vector<MeshHit>& got, Rules rules) {
  const double tol = tolerance_of(in);
  const std::vector<oracle::SegmentHit> hits = oracle::segment_mesh_hits(in.segment, in.mesh);
  const std::string expected = describe_hits(hits), answer = describe_hits(got);
  bool doubt = false;
  std::set<int> reported;
  for (std::size_t k = 0; k < got.size(); ++k) {
    const MeshHit& h = got[k];
    if (!h.hit) return fail(expected, answer, "entry " + std::to_string(k) + " has hit = false");
    if (!valid_index(in.mesh, h.triangle)) return fail(expected, answer, "a triangle index is out of range");
    if (!reported.insert(h.triangle).second)
      return fail(expected, answer, "triangle " + std::to_string(h.triangle) + " is reported twice");
    const Triangle tri = mesh_triangle(in.mesh, h.triangle);
    if (!triangle_hit({in.segment, tri})) {
      if (!hit_or_ambiguous(in.segment, tri, tol, rules))
        return fail(expected, answer, "the segment does not meet triangle " + std::to_string(h.triangle));
      doubt = true;
    }
    Expect e(
        "a hit is where the segment meets the triangle: t along a to b, point a + t (b - a), weights of v0, v1, v2 "
        "that give the point");
    check_hit(e, in.segment, tri, h.t, h.point, h.barycentric, h.normal, tol);
    const Outcome o = e.outcome();
    if (o.verdict == Outcome::Verdict::fail)
      return fail(o.expected, o.got, "triangle " + std::to_string(h.triangle) + ": " + o.why);
    if (k + 1 < got.size() && valid_index(in.mesh, got[k + 1].triangle)) {
      const double slack =
          t_tolerance(in.segment, tri, tol) + t_tolerance(in.segment, mesh_triangle(in.mesh, got[k + 1].triangle), tol);
      if (got[k + 1].t + slack < h.t)
        return fail(expected, answer,
                    "all_hits must be sorted by t: triangle " + std::to_string(got[k + 1].triangle) +
                        " (t = " + fmt(got[k + 1].t) + ") comes before triangle " + std::to_string(h.triangle) +
                        " (t = " + fmt(h.t) + ")");
    }
  }
  for (const oracle::SegmentHit& h : hits) {
    if (reported.count(h.triangle)) continue;
    const Triangle tri = mesh_triangle(in.mesh, h.triangle);
    if (unstable(in.segment, tri, tol, rules)) {
      doubt = true;
      continue;
    }
    std::string why = "triangle " + std::to_string(h.triangle) + " (hit at t = " + fmt(h.t) + ") is missing";
    for (const MeshHit& other : got)
      if (std::abs(other.t - h.t) <= t_tolerance(in.segment, tri, tol))
        why += ": it is met at the same t as triangle " + std::to_string(other.triangle) +
               ", and every triangle met is listed once (a segment through a shared edge or face meets each)";
    return fail(expected, answer, why);
  }
  return doubt ? ambiguous() : pass();
}

Outcome first_hit_moving(const MovingMesh& in, const MeshHit& got) {
  // Doubt is judged in the mesh's frame, on the particle's path there.
  const double tol = tolerance_of(in);
  const Segment local = oracle::moving_local_path(in.segment, in.m0, in.m1);
  std::vector<Status> all = statuses(local, in.mesh, tol, Rules::random);
  const bool expected = oracle::moving_mesh_hit_any(in.segment, in.mesh, in.m0, in.m1);
  if (!expected)
    for (Status& st : all) st.hit = false;  // the rounded path must not overrule the exact one
  const Outcome decision = mesh_yes_no(all, got.hit, Rules::random, "a hit", "no hit", local, in.mesh);
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !expected) return decision;
  const std::vector<oracle::SegmentHit> hits = oracle::moving_mesh_hits(in.segment, in.mesh, in.m0, in.m1);
  std::string problem =
      oracle::check_moving_hit(in.segment, in.mesh, in.m0, in.m1, got.triangle, got.t, got.point, tol);
  if (!problem.empty() && valid_index(in.mesh, got.triangle)) {
    // The header's rule for points, in the mesh's frame: within tol of the path, and
    // within tol + |path| (t's tolerance) of the triangle (a needle's plane, or a path
    // nearly along it, fixes the crossing only that well).
    const Triangle tri = mesh_triangle(in.mesh, got.triangle);
    const Vec3 p = in.m1.inverse() * got.point;
    const double along = tol + (local.b - local.a).norm() * t_tolerance(local, tri, tol);
    if (oracle::within(p, tri, along) && oracle::within(p, local, tol) &&
        oracle::parameter_reproduces(local, got.t, p, 2 * tol))
      problem.clear();
  }
  if (!problem.empty())
    return fail(
        describe_hits(hits),
        "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t) + ", point " + fmt(got.point),
        "the point must be the contact on the mesh at its end pose (m1 times the point found in the mesh's frame, "
        "on the path m0^-1 a -> m1^-1 b there): " +
            problem);
  // In the mesh's frame the path is m0^-1 a -> m1^-1 b; t is compared there, against
  // the first hit whose existence is not in doubt.
  for (const oracle::SegmentHit& h : hits) {
    if (all[std::size_t(h.triangle)].unstable) continue;
    const double slack = t_tolerance(local, mesh_triangle(in.mesh, h.triangle), tol) +
                         t_tolerance(local, mesh_triangle(in.mesh, got.triangle), tol);
    if (got.t > h.t + slack)
      return fail(describe_hits(hits), "triangle " + std::to_string(got.triangle) + " at t = " + fmt(got.t),
                  "first_hit is the hit with the smallest t: triangle " + std::to_string(h.triangle) +
                      " at t = " + fmt(h.t) + " comes before yours");
    break;
  }
  const Vec3 n = in.m1.linear() * oracle::unit_normal(mesh_triangle(in.mesh, got.triangle));
  if ((got.normal - n).norm() > 1e-8)
    return fail(fmt(n), fmt(got.normal),
                "the normal must be the triangle's unit normal as wound, turned by m1 (the mesh at its end pose)");
  return decision;
}

// ---- Step 7: two meshes moving by translations -----------------------------------------

namespace {

// The exact first contact, in the header's words: which family, which features, when.
std::string contact_rule(const MovingMeshes& in, const oracle::MeshContact& c) {
  const Vec3 d = in.velocity_a - in.velocity_b;
  const std::string seen = " (seen from B, A moves by va - vb = " + fmt(d) + ")";
  if (!c.hit) return "the meshes never touch during the frame, 0 <= t <= 1" + seen;
  const std::string at = " at t = " + fmt(c.t) + ", point " + fmt(c.point);
  if (c.kind == 0)
    return "the meshes first touch" + at + ": vertex " + std::to_string(c.feature_a) +
           " of A, on its path p -> p + d, meets face " + std::to_string(c.feature_b) + " of B" + seen;
  if (c.kind == 1)
    return "the meshes first touch" + at + ": vertex " + std::to_string(c.feature_b) +
           " of B, on its path q -> q - d (the other delta matrix), meets face " + std::to_string(c.feature_a) +
           " of A" + seen;
  const auto ea = in.a.edges()[std::size_t(c.feature_a)], eb = in.b.edges()[std::size_t(c.feature_b)];
  return "the meshes first touch" + at + ": edge-edge, edge (" + std::to_string(ea[0]) + ", " + std::to_string(ea[1]) +
         ") of A, sweeping its quad (two triangles), meets edge (" + std::to_string(eb[0]) + ", " +
         std::to_string(eb[1]) + ") of B" + seen;
}

// What is wrong with a contact's normal n, given the normals of the features in contact
// by then (the header's rule); empty when nothing is.
std::string contact_normal_error(const Vec3& n, const Vec3& d, const std::vector<oracle::ContactNormal>& normals) {
  if (!n.allFinite() || std::abs(n.norm() - 1) > 1e-9)
    return "the normal must have unit length (yours has length " + fmt(n.norm()) + ")";
  bool turned = false;
  for (const oracle::ContactNormal& c : normals) {
    const double bound = 1e-8 * c.spread;
    if (c.perpendicular_to_direction) {
      if (std::abs(n.dot(c.direction)) > bound) continue;
      if (n.dot(d) <= bound * d.norm()) return {};
      turned = true;
      continue;
    }
    const Vec3 m = c.direction.dot(d) > 0 ? Vec3(-c.direction) : c.direction;  // from B toward A
    if ((n - m).norm() <= bound) return {};
    if ((n + m).norm() <= bound) {
      if (std::abs(m.dot(d)) <= bound * d.norm()) return {};  // d . normal = 0: either sign
      turned = true;
    }
  }
  if (turned)
    return "the normal points from B toward A, so that d . normal <= 0 (A closes on B against it); yours points "
           "the other way";
  return "the normal is that of the features in contact by your t (or within tol of it): the unit normal of the face "
         "a vertex meets, or (e x f) / |e x f| for two edges; yours is none of those (tolerance 1e-8 |e| |f| / |e x "
         "f|)";
}

}  // namespace

Outcome first_contact_moving_meshes(const MovingMeshes& in, const MeshContact& got, Rules rules) {
  const double tol = tolerance_of(in);
  const oracle::MeshContact exact = oracle::first_contact_translating(in.a, in.velocity_a, in.b, in.velocity_b);
  const auto touches = [](const MovingMeshes& m) {
    return oracle::touch_during_frame_fast(m.a, m.velocity_a, m.b, m.velocity_b);
  };
  const bool doubt = rules == Rules::random && check::flips_under_perturbation(in, touches, 4);
  // What A's motion alone would give (the mistake of moving A by va, not by va - vb):
  // computed only for a failure's message.
  const auto telltale = [&](bool hit, double t) {
    if (in.velocity_b == Vec3::Zero()) return std::string();
    const oracle::MeshContact absolute = oracle::first_contact_translating(in.a, in.velocity_a, in.b, Vec3::Zero());
    if (hit != absolute.hit || (hit && std::abs(t - absolute.t) > 1e-6)) return std::string();
    return std::string(
        "; yours is what A's own motion va gives against a still B: B moves too, so use the relative motion va - vb");
  };
  Outcome decision =
      verdict(got.hit, exact.hit, doubt, rules, "contact", "no contact", contact_rule(in, exact) + yours(got.hit));
  if (decision.verdict == Outcome::Verdict::fail) decision.why += telltale(got.hit, got.t);
  if (decision.verdict == Outcome::Verdict::fail || !got.hit || !exact.hit) return decision;
  // t, certified: no contact before t - dt, contact by t + dt. dt = tol over the closing
  // speed along the contact's normal; exact input is held to 1e-9.
  const Vec3 d = in.velocity_a - in.velocity_b;
  const double dt = rules == Rules::exact ? 1e-9 : exact.approach > 0 ? tol / exact.approach : 1.0;
  const std::string got_t = "t = " + fmt(got.t) + ", point " + fmt(got.point);
  const std::string exact_t = "t = " + fmt(exact.t) + ", point " + fmt(exact.point);
  // Whether a perturbation of tol changes "touching by time x": then either side passes
  // (a near miss earlier than the exact first contact, or a contact that a hair removes).
  const auto in_doubt = [&](double x) {
    return rules == Rules::random && check::flips_under_perturbation(in, [x](const MovingMeshes& m) {
             return oracle::contact_by(m.a, m.velocity_a, m.b, m.velocity_b, x);
           });
  };
  if (oracle::contact_by(in.a, in.velocity_a, in.b, in.velocity_b, got.t - dt)) {
    if (in_doubt(got.t - dt)) return ambiguous();
    return fail(exact_t, got_t,
                contact_rule(in, exact) + ": the meshes already touch before your t = " + fmt(got.t) + " (tolerance " +
                    fmt(dt) + "): report the first contact, the smallest t of all three families" +
                    telltale(true, got.t));
  }
  if (!oracle::contact_by(in.a, in.velocity_a, in.b, in.velocity_b, got.t + dt)) {
    if (in_doubt(got.t + dt)) return ambiguous();
    return fail(exact_t, got_t,
                contact_rule(in, exact) + ": the meshes do not touch yet at your t = " + fmt(got.t) + " (tolerance " +
                    fmt(dt) + ")" + telltale(true, got.t));
  }
  const double reach = 2 * tol + d.norm() * std::min(dt, 1.0);
  const bool on_a = oracle::within_translated(got.point, in.a, got.t * in.velocity_a, reach);
  const bool on_b = oracle::within_translated(got.point, in.b, got.t * in.velocity_b, reach);
  if (!on_a || !on_b)
    return fail(
        exact_t, got_t,
        std::string("the point must be where the meshes touch, in the world at your t: on A moved by t va and on B "
                    "moved by t vb (within ") +
            fmt(reach) + "), and yours is off " + (on_a ? "B" : "A") +
            " (a point found in B's frame moves on by t vb; in A's frame by t va)");
  const double slack = rules == Rules::exact ? 1e-9 : dt;
  const double by = got.t + slack;
  std::string wrong =
      contact_normal_error(got.normal, d, oracle::contact_normals_by(in.a, in.velocity_a, in.b, in.velocity_b, by));
  // Features within tol of touching by then count too (a perturbation of tol makes them
  // touch): a vertex that passes a hair outside an edge the first contact is on.
  if (!wrong.empty() && rules == Rules::random)
    wrong = contact_normal_error(got.normal, d,
                                 oracle::contact_normals_by(in.a, in.velocity_a, in.b, in.velocity_b, by, tol));
  if (!wrong.empty()) return fail(fmt(exact.normal), fmt(got.normal), wrong + "; " + contact_rule(in, exact));
  return decision;
}

}  // namespace labkit::lab02::judge
