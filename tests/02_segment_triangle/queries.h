// Lab 02's queries, declared in one place: the functions the judge's process calls in
// the answerer and the lab's types as they cross (first), the input each query is
// given (then), the table of the queries, and how each input is drawn and each answer
// judged (last): a new query is written here, then defined in generators*.cpp and
// judge*.cpp. Both processes include it; the answerer uses only its first part.
//
// The protocol (common/protocol/answerer.h) copies the lab's types by their fields, which
// reports print too.
#pragma once

#include "segment_triangle.h"

#include "common/fields.h"
#include "common/harness/outcome.h"
#include "common/harness/query.h"
#include "common/inputs/inputs.h"
#include "common/protocol/calls.h"

namespace labkit::lab02 {

LABKIT_FIELDS(PlaneCrossing, d_a, d_b, crosses, t, point)
LABKIT_FIELDS(Barycentric, dropped_axis, alpha, beta)
LABKIT_FIELDS(SegmentTriangleHit, hit, t, point, barycentric, normal)
LABKIT_FIELDS(MeshHit, hit, triangle, t, point, barycentric, normal)

LABKIT_FIELDS(MeshContact, hit, t, point, normal)

using MeshHits = std::vector<MeshHit>;

}  // namespace labkit::lab02

// clang-format off
#define LABKIT_LAB02_CALLS(CALL, METHOD)                                                          \
  CALL(PlaneCrossing, segment_plane, (const Segment&, const Triangle&))                           \
  CALL(bool, point_in_triangle_edges, (const Vec3&, const Triangle&))                             \
  CALL(Barycentric, barycentric, (const Vec3&, const Triangle&))                                  \
  CALL(bool, point_in_triangle_barycentric, (const Vec3&, const Triangle&))                       \
  CALL(bool, test_segment_triangle, (const Segment&, const Triangle&))                            \
  CALL(SegmentTriangleHit, find_segment_triangle, (const Segment&, const Triangle&))              \
  CALL(MeshHit, first_hit, (const Segment&, const Mesh&))                                         \
  CALL(bool, any_hit, (const Segment&, const Mesh&))                                              \
  CALL(MeshHits, all_hits, (const Segment&, const Mesh&))                                         \
  CALL(MeshHit, first_hit_moving, (const Segment&, const Mesh&, const RigidTransform&, const RigidTransform&)) \
  CALL(MeshContact, first_contact_moving_meshes, (const Mesh&, const Vec3&, const Mesh&, const Vec3&))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab02, LABKIT_LAB02_CALLS)

// ---- The inputs ------------------------------------------------------------------------
// Lab 02's inputs beyond the shared pairs (common/inputs/inputs.h): each query's
// arguments as one struct, whose fields() let reports print it and replay tokens carry it
// (the answers' fields are in above).
namespace labkit::lab02 {

struct PointTriangle {
  Vec3 x = Vec3::Zero();
  Triangle triangle;
};
LABKIT_FIELDS(PointTriangle, x, triangle)

struct MovingMesh {
  Segment segment;
  Mesh mesh;
  RigidTransform m0 = RigidTransform::Identity();
  RigidTransform m1 = RigidTransform::Identity();
};
LABKIT_FIELDS(MovingMesh, segment, mesh, m0, m1)

// Step 7: two meshes, each moving by a translation over [0, 1].
struct MovingMeshes {
  Mesh a;
  Vec3 velocity_a = Vec3::Zero();
  Mesh b;
  Vec3 velocity_b = Vec3::Zero();
};
LABKIT_FIELDS(MovingMeshes, a, velocity_a, b, velocity_b)

}  // namespace labkit::lab02

// ---- The queries -------------------------------------------------------------------------
// Each question the tests ask and the input it takes, by the step that asks it first:
// X(name, Input) is the query "name", X_IN(group, name, Input) the query "group.name"
// (common/harness/query.h). The tests, the viewer's scene and its presets read this table:
// a query is added or renamed here and nowhere else.
// clang-format off
#define LABKIT_LAB02_QUERIES(X, X_IN)                                                                           \
  /* step 1 */ X(segment_plane, SegmentTrianglePair)                                                            \
  /* step 2 */ X(point_in_triangle_edges, PointTriangle)                                                        \
  /* step 3 */ X(barycentric, PointTriangle) X(point_in_triangle_barycentric, PointTriangle)                    \
  /* step 4 */ X(test_segment_triangle, SegmentTrianglePair) X(find_segment_triangle, SegmentTrianglePair)      \
  /* step 5 */ X(any_hit, SegmentMeshPair) X(first_hit, SegmentMeshPair) X(all_hits, SegmentMeshPair)           \
  /* step 6 */ X(first_hit_moving, MovingMesh)                                                                  \
  /* step 7 */ X(first_contact_moving_meshes, MovingMeshes)                                                     \
  /* step 8 */ X_IN(robust, point_in_triangle, PointTriangle)                                                   \
               X_IN(robust, find_segment_triangle, SegmentTrianglePair) X_IN(robust, all_hits, SegmentMeshPair) \
               X_IN(needle, find_segment_triangle, SegmentTrianglePair)                                         \
  /* step 9 */ X_IN(robust, first_contact_moving_meshes, MovingMeshes)
// clang-format on

namespace labkit::lab02::query {
LABKIT_QUERIES(LABKIT_LAB02_QUERIES)
}  // namespace labkit::lab02::query

// ---- How each input is drawn, and the verdicts -----------------------------------------
// Declared here, beside the queries they serve; defined in generators*.cpp (gen::) and
// judge*.cpp (judge::). RapidCheck is included where the generators are called.
namespace rc {
template <typename T> class Gen;
}  // namespace rc

// Lab 02's own random inputs, beside the shared segment-triangle and mesh families
// (common/generators/generators.h, needles.h): points in a triangle's plane, meshes
// moving rigidly, and two meshes translating toward a contact.
namespace labkit::gen {

// Inputs for the point-in-triangle steps: points exactly in the triangle's plane, many
// of them exactly on an edge or a vertex, or a tiny step inside or outside one.
rc::Gen<lab02::PointTriangle> point_triangle();
// The same on integer coordinates: exact input for the robustness step.
rc::Gen<lab02::PointTriangle> exact_point_triangle();
rc::Gen<lab02::MovingMesh> moving_mesh();
// Two small meshes (tetrahedra, tents, single triangles) apart at t = 0, aimed so that a
// chosen vertex-face or edge-edge pair meets at a chosen time, or passing just beside
// it, or stopping short: decisive, at every scale of the header.
rc::Gen<lab02::MovingMeshes> moving_meshes();
// The same meshes on integers, apart at t = 0 and aimed exactly: a vertex onto a vertex,
// an edge or a face, an edge onto an edge (at its end or its middle), touching exactly
// at t = 1, two flat triangles sliding in one plane, or no relative motion. Every
// number is a small integer over a power of two: exact input for the robustness step.
rc::Gen<lab02::MovingMeshes> exact_moving_meshes();

}  // namespace labkit::gen

// Lab 02's verdicts: each judge compares one answer with the exact oracle, following the
// tolerances and degenerate rules of labs/02_segment_triangle/segment_triangle.h. The
// tests and the viewer both use them, so a red mark in the viewer and a failing case in
// `./labkit check` always agree. The inputs are in tests/02_segment_triangle/queries.h,
// their random draws below.
namespace labkit::lab02::judge {

using check::Outcome;
using check::Rules;  // random cases, or a robustness step's exact input

Outcome segment_plane(const SegmentTrianglePair& in, const PlaneCrossing& got, Rules rules = Rules::random);
Outcome point_in_triangle(const PointTriangle& in, bool got, Rules rules = Rules::random);
Outcome barycentric(const PointTriangle& in, const Barycentric& got);
Outcome test_segment_triangle(const SegmentTrianglePair& in, bool got, Rules rules = Rules::random);
Outcome find_segment_triangle(const SegmentTrianglePair& in, const SegmentTriangleHit& got,
                              Rules rules = Rules::random);
Outcome any_hit(const SegmentMeshPair& in, bool got, Rules rules = Rules::random);
Outcome first_hit(const SegmentMeshPair& in, const MeshHit& got, Rules rules = Rules::random);
Outcome all_hits(const SegmentMeshPair& in, const std::vector<MeshHit>& got, Rules rules = Rules::random);
Outcome first_hit_moving(const MovingMesh& in, const MeshHit& got);
Outcome first_contact_moving_meshes(const MovingMeshes& in, const MeshContact& got, Rules rules = Rules::random);

}  // namespace labkit::lab02::judge
