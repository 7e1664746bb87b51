// Lab 04 across the process boundary (common/protocol/answerer.h): the fields of the
// lab's types, which reports print and the protocol copies, and the list of the
// functions the judge's process calls in the answerer. A Motion crosses as the numbers
// of its StandardMotion (the tests build every motion from one), or of a RecordingMotion.
#pragma once

#include "bisection.h"

#include "common/fields.h"
#include "common/protocol/calls.h"

#include <memory>
#include <vector>

namespace labkit::lab04 {

LABKIT_FIELDS(TimeOfImpact, hit, overlapping_at_start, t, t_contact, steps, iterations)
LABKIT_FIELDS(StandardMotion, start, velocity, acceleration, axis, spin)
LABKIT_FIELDS(Shape, kind, sphere, box)
LABKIT_FIELDS(MovingPair, a, motion_a, b, motion_b)

// A motion that writes down every time it is asked for a pose (step 2's example shows
// the lecture's midpoints with it). In the answerer, the times are recorded there and
// come back with the answer, into `asked`.
struct RecordingMotion {
  StandardMotion standard;
  std::shared_ptr<std::vector<double>> asked = std::make_shared<std::vector<double>>();
  RigidTransform operator()(double t) const {
    asked->push_back(t);
    return standard(t);
  }
};

}  // namespace labkit::lab04

template <> struct labkit::wire::Codec<labkit::lab04::Motion> {
  static void put(Writer& w, const lab04::Motion& m) {
    if (const auto* recording = m.target<lab04::RecordingMotion>()) {
      wire::put(w, true);
      wire::put(w, recording->standard);
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
    lab04::StandardMotion standard;
    wire::get(r, recording);
    wire::get(r, standard);
    if (recording)
      m = [standard](double t) {
        remote::record_sample(t);
        return standard(t);
      };
    else
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
