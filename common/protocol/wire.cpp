#include "common/protocol/wire.h"

namespace labkit::wire {

void put(Writer& w, const Segment& s) { put(w, s.a), put(w, s.b); }
void get(Reader& r, Segment& s) { get(r, s.a), get(r, s.b); }
void put(Writer& w, const Triangle& t) { put(w, t.v0), put(w, t.v1), put(w, t.v2); }
void get(Reader& r, Triangle& t) { get(r, t.v0), get(r, t.v1), get(r, t.v2); }
void put(Writer& w, const Plane& p) { put(w, p.normal), put(w, p.offset); }
void get(Reader& r, Plane& p) { get(r, p.normal), get(r, p.offset); }
void put(Writer& w, const Frustum& f) { put(w, f.planes); }
void get(Reader& r, Frustum& f) { get(r, f.planes); }
void put(Writer& w, const Mesh& m) { put(w, m.vertices), put(w, m.triangles); }
void get(Reader& r, Mesh& m) { get(r, m.vertices), get(r, m.triangles); }
void put(Writer& w, const Sphere& s) { put(w, s.center), put(w, s.radius); }
void get(Reader& r, Sphere& s) { get(r, s.center), get(r, s.radius); }
void put(Writer& w, const Capsule& c) { put(w, c.axis), put(w, c.radius); }
void get(Reader& r, Capsule& c) { get(r, c.axis), get(r, c.radius); }
void put(Writer& w, const Rectangle& rect) {
  put(w, rect.center), put(w, rect.u), put(w, rect.v), put(w, rect.half_u), put(w, rect.half_v);
}
void get(Reader& r, Rectangle& rect) {
  get(r, rect.center), get(r, rect.u), get(r, rect.v), get(r, rect.half_u), get(r, rect.half_v);
}
void put(Writer& w, const Lozenge& l) { put(w, l.rectangle), put(w, l.radius); }
void get(Reader& r, Lozenge& l) { get(r, l.rectangle), get(r, l.radius); }
void put(Writer& w, const Box& b) { put(w, b.center), put(w, b.axes), put(w, b.half_extents); }
void get(Reader& r, Box& b) { get(r, b.center), get(r, b.axes), get(r, b.half_extents); }
void put(Writer& w, const Aabb& b) { put(w, b.min), put(w, b.max); }
void get(Reader& r, Aabb& b) { get(r, b.min), get(r, b.max); }

}  // namespace labkit::wire
