// What every lab's judge shares: the headers' relative tolerance and the tol it gives an
// input, and the verdict on a segment against a mesh's triangles (labs 02, 06 and 07). A
// helper used by two judges or more belongs here, once.
#pragma once

#include "common/harness/check.h"
#include "common/harness/segment_doubt.h"

#include <vector>

namespace labkit::judging {

// tol = 1e-9 S, the tolerance every lab header states (S: the input's scale, its largest
// coordinate magnitude, check::scale_of_input). It is the harness's ambiguity band too.
inline constexpr double kRelative = check::kAmbiguity;

template <class Input> double tolerance_of(const Input& in) { return kRelative * check::scale_of_input(in); }

// ---- A segment against a mesh's triangles, each by the lab's own hit rule --------------

// One triangle (or surface): exactly hit or not, and whether that is in doubt.
struct Status {
  bool hit = false;
  bool unstable = false;
};

// Could a perturbation of tol change whether `hit` (a predicate on SegmentTrianglePair)
// holds for this triangle? Only random cases have doubt; exact input is judged exactly.
template <class Hit> bool unstable(const Segment& s, const Triangle& tri, double tol, check::Rules rules, Hit&& hit) {
  return rules == check::Rules::random && check::segment_triangle_in_doubt(s, tri, tol, hit);
}

// Every triangle of the mesh, in order.
template <class Hit>
std::vector<Status> statuses(const Segment& s, const Mesh& mesh, double tol, check::Rules rules, Hit&& hit) {
  std::vector<Status> all(mesh.size());
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    const Triangle tri = mesh.triangle(i);
    all[i] = {hit(SegmentTrianglePair{s, tri}), unstable(s, tri, tol, rules, hit)};
  }
  return all;
}

// "Is any triangle hit": the exact answer stands when some hit is not in doubt, or when
// no triangle is in doubt.
struct AnyHit {
  bool hit = false;         // the exact answer: some triangle is hit
  bool stable_hit = false;  // some triangle is hit, beyond doubt
  bool unstable = false;    // some triangle's answer is in doubt
  void add(const Status& st) {
    hit = hit || st.hit;
    stable_hit = stable_hit || (st.hit && !st.unstable);
    unstable = unstable || st.unstable;
  }
  bool in_doubt() const { return !stable_hit && unstable; }
};

inline AnyHit any_hit(const std::vector<Status>& all) {
  AnyHit any;
  for (const Status& st : all) any.add(st);
  return any;
}

}  // namespace labkit::judging
