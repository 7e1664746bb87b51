// LABKIT_FIELDS(Type, a, b, c) lists a struct's fields once, by their member names:
//
//   struct PointSegmentPair { Vec3 p; Segment segment; };
//   LABKIT_FIELDS(PointSegmentPair, p, segment)
//
// expands to the fields() that reports, replay tokens and the process protocol walk:
//
//   template <class Visit> void fields(PointSegmentPair& x, Visit&& visit) {
//     visit("p", x.p);
//     visit("segment", x.segment);
//   }
//
// A field's key is its member's name, so the two cannot drift apart, and a misspelt or
// removed member does not compile. Write the macro in the struct's own namespace (ADL
// finds fields() there). Up to 16 fields.
#pragma once

// clang-format off
#define LABKIT_FIELDS(Type, ...)                                                                 \
  template <class Visit> void fields(Type& x, Visit&& visit) {                                   \
    LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_PICK_(__VA_ARGS__, 16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, -)(__VA_ARGS__)) \
  }

// The machinery: count the names to pick LABKIT_FIELDS_N_, which visits the first and
// hands the rest to LABKIT_FIELDS_(N-1)_. (The trailing "-" keeps "..." never empty.)
#define LABKIT_FIELDS_EXPAND_(x) x
#define LABKIT_FIELDS_PICK_(_1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, n, ...) LABKIT_FIELDS_##n##_
#define LABKIT_FIELD_(m) visit(#m, x.m);
#define LABKIT_FIELDS_1_(a) LABKIT_FIELD_(a)
#define LABKIT_FIELDS_2_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_1_(__VA_ARGS__))
#define LABKIT_FIELDS_3_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_2_(__VA_ARGS__))
#define LABKIT_FIELDS_4_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_3_(__VA_ARGS__))
#define LABKIT_FIELDS_5_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_4_(__VA_ARGS__))
#define LABKIT_FIELDS_6_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_5_(__VA_ARGS__))
#define LABKIT_FIELDS_7_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_6_(__VA_ARGS__))
#define LABKIT_FIELDS_8_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_7_(__VA_ARGS__))
#define LABKIT_FIELDS_9_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_8_(__VA_ARGS__))
#define LABKIT_FIELDS_10_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_9_(__VA_ARGS__))
#define LABKIT_FIELDS_11_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_10_(__VA_ARGS__))
#define LABKIT_FIELDS_12_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_11_(__VA_ARGS__))
#define LABKIT_FIELDS_13_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_12_(__VA_ARGS__))
#define LABKIT_FIELDS_14_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_13_(__VA_ARGS__))
#define LABKIT_FIELDS_15_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_14_(__VA_ARGS__))
#define LABKIT_FIELDS_16_(a, ...) LABKIT_FIELD_(a) LABKIT_FIELDS_EXPAND_(LABKIT_FIELDS_15_(__VA_ARGS__))
// clang-format on
