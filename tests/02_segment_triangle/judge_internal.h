// Inside lab 02's judge: the helpers its files share (tests/02_segment_triangle/judge*.cpp),
// defined in tests/02_segment_triangle/judge.cpp. Not for the tests or the viewer.
#pragma once

#include "02_segment_triangle/queries.h"
#include "common/harness/check.h"

#include "judging.h"

#include "common/oracle/oracle.h"

#include <string>
#include <vector>

namespace labkit::lab02::judge {

using check::ambiguous;
using check::Expect;
using check::fail;
using check::pass;
using judging::kRelative;
using judging::Status;
using judging::tolerance_of;

// check::verdict, with the rule the answer broke as its why (the exact answer, not in
// doubt: no input within tol answers otherwise).
Outcome verdict(bool got, bool expected, bool doubt, Rules rules, const std::string& yes, const std::string& no,
                const std::string& why);

// The same, with doubt found by perturbing the input (`exact` recomputes the answer).
template <class Input, class Exact>
Outcome yes_no(const Input& in, bool got, Rules rules, Exact&& exact, const std::string& yes, const std::string& no,
               const std::string& why) {
  const bool doubt = rules == Rules::random && check::flips_under_perturbation(in, exact);
  return verdict(got, exact(in), doubt, rules, yes, no, why);
}

// A needle's plane is known in doubles only to about 1e-16 times its aspect ratio: how
// much rounding its edges alone tilts it (the header's rule for needles).
double tilt_of(const Triangle& tri);
// The tolerance of a signed distance of p: tol, plus what that tilt moves it.
double distance_tolerance(const Vec3& p, const Triangle& tri, double tol);
// How loosely a crossing fixes t: tol / |d_a - d_b|, or tol / |b - a| in the plane.
double t_tolerance(const Segment& s, const Triangle& tri, double tol);

// The header's hit rule: the segment meets the closed triangle.
bool triangle_hit(const SegmentTrianglePair& p);
// Why the exact answer is a hit or a miss, in the header's rules, with the numbers.
std::string hit_rule(const Segment& s, const Triangle& tri);
std::string yours(bool hit);

// Could a perturbation of tol change whether the segment meets this triangle?
bool unstable(const Segment& s, const Triangle& tri, double tol, Rules rules);
// Is this triangle of the mesh hit, or is its hit ambiguous?
bool hit_or_ambiguous(const Segment& s, const Triangle& tri, double tol, Rules rules);
// Each triangle of a mesh: exactly hit or not, and whether that is in doubt.
std::vector<Status> statuses(const Segment& s, const Mesh& mesh, double tol, Rules rules);
// The verdict on "does the segment hit the mesh at all" (judging::AnyHit), with the rule
// of the triangle that decides it.
Outcome mesh_yes_no(const std::vector<Status>& all, bool got, Rules rules, const std::string& yes,
                    const std::string& no, const Segment& s, const Mesh& mesh);

// The checks every reported hit on a triangle must pass (the header's tolerances).
void check_hit(Expect& e, const Segment& s, const Triangle& tri, double t, const Vec3& point, const Vec3& weights,
               const Vec3& normal, double tol);

Triangle mesh_triangle(const Mesh& mesh, int index);
bool valid_index(const Mesh& mesh, int index);
std::string describe_hits(const std::vector<oracle::SegmentHit>& hits);
std::string describe_hits(const std::vector<MeshHit>& hits);

}  // namespace labkit::lab02::judge
