// SPDX-License-Identifier: MIT
// Convex polygon clipping in a plane (Sutherland-Hodgman) for the mortar segment integration
// (contact/mortar/): the overlap of a projected slave face and a projected master face. Fixed
// capacity, no allocation: two convex quads overlap in at most 8 vertices.
#pragma once

namespace tribex::contact {

struct Polygon2 {
  static constexpr int capacity = 16;
  int count = 0;
  double x[capacity] = {}, y[capacity] = {};
};

/// Signed area (> 0 counter-clockwise), shoelace formula A = 1/2 sum (x_i y_{i+1} - x_{i+1} y_i).
double signed_area(const Polygon2& p);

/// The part of `subject` inside the convex, counter-clockwise polygon `clip` (Sutherland-Hodgman:
/// `subject` cut by the half-plane left of each clip edge in turn). `subject` may have either
/// orientation; the result keeps it. Empty (count 0) when the overlap has no area.
Polygon2 clip_convex(const Polygon2& subject, const Polygon2& clip);

}  // namespace tribex::contact
