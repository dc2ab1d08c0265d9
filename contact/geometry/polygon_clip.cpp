// SPDX-License-Identifier: MIT
#include "contact/geometry/polygon_clip.hpp"

#include <algorithm>
#include <cmath>

namespace tribex::contact {

double signed_area(const Polygon2& p) {
  double a = 0.0;
  for (int i = 0; i < p.count; ++i) {
    const int j = (i + 1) % p.count;
    a += p.x[i] * p.y[j] - p.x[j] * p.y[i];
  }
  return 0.5 * a;
}

Polygon2 clip_convex(const Polygon2& subject, const Polygon2& clip) {
  Polygon2 in = subject, out;
  // Points within `tolerance` of a clip edge (relative to the clip size) count as inside, so that
  // coincident edges of matching meshes do not produce slivers or lose their shared vertices.
  double size = 0.0;
  for (int i = 0; i < clip.count; ++i) size = std::max({size, std::abs(clip.x[i] - clip.x[0]), std::abs(clip.y[i] - clip.y[0])});
  const double tolerance = 1e-12 * size;
  for (int e = 0; e < clip.count && in.count > 0; ++e) {
    const double ax = clip.x[e], ay = clip.y[e];
    const double bx = clip.x[(e + 1) % clip.count], by = clip.y[(e + 1) % clip.count];
    const double ex = bx - ax, ey = by - ay;
    const double length = std::sqrt(ex * ex + ey * ey);
    if (length == 0.0) continue;
    // Signed distance left of the edge a -> b (inside of a counter-clockwise polygon).
    auto side = [&](double px, double py) { return (ex * (py - ay) - ey * (px - ax)) / length; };
    out.count = 0;
    for (int i = 0; i < in.count; ++i) {
      const int j = (i + 1) % in.count;
      const double si = side(in.x[i], in.y[i]), sj = side(in.x[j], in.y[j]);
      const bool inside_i = si >= -tolerance, inside_j = sj >= -tolerance;
      if (inside_i && out.count < Polygon2::capacity) {
        out.x[out.count] = in.x[i];
        out.y[out.count++] = in.y[i];
      }
      // The edge i -> j crosses the clip line: add the intersection point. With the tolerance a
      // vertex can count as inside while slightly outside (si in [-tolerance, 0)); the line
      // parameter then leaves [0, 1] (an edge nearly along the clip line: t = si / (si - sj) with
      // both tiny can be any number) and is clamped: the crossing is on the edge, never an
      // extrapolation (found in the contact patch test: coincident free edges of the two meshes
      // gave a sliver of 4e-4 of a face's area on some steps, and a kick to the whole model).
      if (inside_i != inside_j && out.count < Polygon2::capacity) {
        const double t = std::clamp(si / (si - sj), 0.0, 1.0);
        out.x[out.count] = in.x[i] + t * (in.x[j] - in.x[i]);
        out.y[out.count++] = in.y[i] + t * (in.y[j] - in.y[i]);
      }
    }
    in = out;
  }
  // Drop repeated vertices (a vertex on a clip edge appears twice): zero-length edges would give
  // zero-area triangles downstream, harmless but wasted.
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const int prev = out.count ? out.count - 1 : -1;
    if (prev >= 0 && std::abs(in.x[i] - out.x[prev]) <= tolerance && std::abs(in.y[i] - out.y[prev]) <= tolerance) continue;
    out.x[out.count] = in.x[i];
    out.y[out.count++] = in.y[i];
  }
  if (out.count > 1 && std::abs(out.x[0] - out.x[out.count - 1]) <= tolerance &&
      std::abs(out.y[0] - out.y[out.count - 1]) <= tolerance)
    --out.count;
  in = out;
  if (in.count < 3) in.count = 0;
  return in;
}

}  // namespace tribex::contact
