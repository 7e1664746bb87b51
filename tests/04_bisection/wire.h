// Lab 04 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A Motion crosses as the numbers
// of its StandardMotion (the tests build every motion from one), or of a RecordingMotion.
#pragma once

#include "bisection.h"

#include "common/fields.h"
#include "common/given/served.h"
#include "common/protocol/calls.h"

#include <memory>
#include <vector>

namespace labkit::lab04 {

LABKIT_FIELDS(TimeOfImpact, hit, overlapping_at_start, t, t_contact, steps, iterations)
LABKIT_FIELDS(StandardMotion, start, velocity, acceleration, axis, spin)
LABKIT_FIELDS(Shape, kind, sphere, box)
LABKIT_FIELDS(MovingPair, a, motion_a, b, motion_b)

// A motion that writes down every time it is asked for a pose (step 2's example shows
// the lecture's midpoints with it). Sent to the answerer it is opaque, a number: each
// pose the code asks for is served by the judge's process (common/given/served.h), which
// writes the time down there and sends it back with the answer, into `asked`.
struct RecordingMotion {
  StandardMotion standard;
  std::shared_ptr<std::vector<double>> asked = std::make_shared<std::vector<double>>();
  RigidTransform operator()(double t) const {
    asked->push_back(t);
    return standard(t);
  }
};

// In the judge's process: the recording motions sent so far, by number.
inline std::vector<StandardMotion>& recording_motions() {
  static std::vector<StandardMotion> motions;
  return motions;
}
inline int recording_handle(const StandardMotion& m) {
  std::vector<StandardMotion>& all = recording_motions();
  const auto same = [&](const StandardMotion& o) {
    wire::Writer a, b;
    wire::put(a, m), wire::put(b, o);
    return a.bytes() == b.bytes();
  };
  for (std::size_t k = 0; k < all.size(); ++k)
    if (same(all[k])) return int(k);
  all.push_back(m);
  return int(all.size()) - 1;
}

// The judge serves a recording motion's poses, and writes their times down.
inline void serve_given() {
  given::serve("recorded_pose", [](wire::Reader& in, wire::Writer& out, given::Served& served) {
    int handle = -1;
    double t = 0;
    wire::get(in, handle), wire::get(in, t);
    if (handle < 0 || handle >= int(recording_motions().size())) throw wire::Error("no such recording motion");
    served.samples.push_back(t);
    wire::put(out, recording_motions()[std::size_t(handle)](t));
  });
}
#define LABKIT_LAB_SERVED ::labkit::lab04::serve_given

}  // namespace labkit::lab04

template <> struct labkit::wire::Codec<labkit::lab04::Motion> {
  static void put(Writer& w, const lab04::Motion& m) {
    if (const auto* recording = m.target<lab04::RecordingMotion>()) {
      wire::put(w, true);
      wire::put(w, lab04::recording_handle(recording->standard));
      remote::sample_into(recording->asked.get());
      return;
    }
    const auto* standard = m.target<lab04::StandardMotion>();
    if (!standard) throw Error("only a StandardMotion or a RecordingMotion can be sent to the answerer");
    wire::put(w, false);
    wire::put(w, *standard);
  }
  static void get(Reader& r, lab04::Motion& m) {
    bool recording = false;
    wire::get(r, recording);
    if (recording) {
      int handle = -1;
      wire::get(r, handle);
      m = [handle](double t) { return given::ask<RigidTransform>("recorded_pose", handle, t); };
      return;
    }
    lab04::StandardMotion standard;
    wire::get(r, standard);
    m = standard;
  }
};

// clang-format off
#define LABKIT_LAB04_CALLS(CALL, METHOD)                                                            \
  CALL(Sphere, placed, (const Sphere&, const RigidTransform&))                                      \
  CALL(Box, placed, (const Box&, const RigidTransform&))                                            \
  CALL(bool, overlap, (const Sphere&, const Sphere&))                                               \
  CALL(Vec3, closest_point, (const Box&, const Vec3&))                                              \
  CALL(bool, overlap, (const Sphere&, const Box&))                                                  \
  CALL(bool, overlap_at, (const MovingPair&, double))                                               \
  CALL(TimeOfImpact, bisect, (const MovingPair&, double, double, double))                           \
  CALL(double, smallest_size, (const Shape&))                                                       \
  CALL(double, closing_speed,                                                                       \
       (const Sphere&, const StandardMotion&, const Shape&, const StandardMotion&, double, double))     \
  CALL(int, substeps_for, (double, double, double))                                                 \
  CALL(TimeOfImpact, sample_then_bisect, (const MovingPair&, double, double, int, double))          \
  CALL(double, distance, (const Sphere&, const Sphere&))                                            \
  CALL(double, distance, (const Sphere&, const Box&))                                               \
  CALL(double, distance_at, (const MovingPair&, double))                                            \
  CALL(TimeOfImpact, advance, (const MovingPair&, double, double, double, double))
// clang-format on

// The judge's process calls the code under test only as answerer::name(...) (calls.h).
LABKIT_ANSWERER_CALLS(lab04, LABKIT_LAB04_CALLS)
