// Lab 02's random families (segment against triangle and mesh): the whole input domain
// of its header, drawn so that a case is decisive unless it must be ambiguous.
//
//  - Every scale the header promises, 2^-166 (about 1e-50) to 2^166 (about 1e50), and
//    far from the origin.
//  - Needle triangles: aspect ratios from 16 up to 2^27 (about 1.3e8), as spikes (one
//    short edge) and slivers (a vertex near the long edge, or beyond its end), in every
//    orientation, any vertex first.
//  - Near-degenerate cases moved just outside the ambiguity band instead of onto it: a
//    crossing a little inside or outside an edge, an end a little above or below the
//    triangle, a segment a little off its plane, short steep segments. The exactly
//    degenerate families (ends on the triangle, through edges, coplanar) belong to the
//    robustness step (gen::exact_segment_triangle), with a small share kept here for the
//    points and parameters that are checked even when the yes/no is ambiguous:
//    coplanar segments, among them nearly collinear with an edge.
//  - The thinnest needles crossed steeply near their long edge (needle_crossed_steeply):
//    only a normal taken to full precision puts the crossing on the plane within tol.
//  - Meshes: soups with needles, terrains, octahedra, and double-sided faces (the same
//    triangle twice, wound both ways): a segment through one crosses two triangles at
//    the same t, decisively.
#pragma once

#include "common/generators/generators.h"

namespace labkit::gen {

// 2^k for k in {-166, -20, -10, 0, 10, 20, 166}: mostly 1.
rc::Gen<double> wide_scale();
// A needle triangle (non-zero area) of length scale `s`, its aspect ratio 2^thinnest to 2^27.
rc::Gen<Triangle> needle(double s, int thinnest = 4);
// Ordinary triangles (mostly) and needles.
rc::Gen<Triangle> any_triangle(double s);

rc::Gen<SegmentTrianglePair> decisive_segment_triangle();
// The thinnest needles (aspect ratio 2^24 and up) crossed by short, steep segments near
// their long edge: the robustness step's, for many of their yes/no answers are in doubt.
rc::Gen<SegmentTrianglePair> needle_crossed_steeply();
rc::Gen<SegmentMeshPair> decisive_segment_mesh();

}  // namespace labkit::gen
