// SPDX-License-Identifier: MIT
// Moving nodal vectors between the [node][3] arrays and an element batch's [component][node]
// registers (T = double, double2, double4, double8: materials/lanes.hpp), for the element kernels.
//   gather_nodal:     out[8 i + I] lane l = a[3 nodes[l][I] + i]
//   subtract_nodal:   f[3 nodes[l][I] + i] -= in[8 i + I] lane l for the lanes set in `lanes`
//                     (bit l: lane l; an inverted element's lane is left out), lane by lane in element order
//                     (lane 0's 8 nodes, then lane 1's, ...), so that nodes shared by the
//                     elements of one batch get their contributions in the order a loop over
//                     single elements would add them: the sums do not depend on the lane width.
// The double4 versions move a node's (x, y) as one 16-byte load or store and z on its own, and
// transpose in registers (the generic versions insert and extract one double at a time, which
// was about a third of the kernel's instructions).
#pragma once

#include "materials/lanes.hpp"

#ifdef __AVX2__
#include <immintrin.h>
#endif

namespace tribex::solver::hex8 {

template <class T>
inline void gather_nodal(const double* a, const int* const nodes[], T out[24]) {
  for (int I = 0; I < 8; ++I)
    for (int i = 0; i < 3; ++i)
      out[8 * i + I] = materials::from_lanes<T>([&](int l) { return a[3 * nodes[l][I] + i]; });
}

template <class T>
inline void subtract_nodal(double* f, const int* const nodes[], const T in[24], unsigned lanes) {
  for (int l = 0; l < materials::lane_count<T>; ++l)
    for (int I = 0; I < 8 && (lanes >> l & 1u); ++I) {
      double* fn = f + 3 * nodes[l][I];
      fn[0] -= materials::lane(in[I], l);
      fn[1] -= materials::lane(in[8 + I], l);
      fn[2] -= materials::lane(in[16 + I], l);
    }
}

#ifdef __AVX2__
inline void gather_nodal(const double* a, const int* const nodes[], materials::double4 out[24]) {
  for (int I = 0; I < 8; ++I) {
    const double* p0 = a + 3 * nodes[0][I];
    const double* p1 = a + 3 * nodes[1][I];
    const double* p2 = a + 3 * nodes[2][I];
    const double* p3 = a + 3 * nodes[3][I];
    // [x0 y0 | x2 y2] and [x1 y1 | x3 y3], then unpack into [x0 x1 x2 x3] and [y0 y1 y2 y3]
    const __m256d xy02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0)), _mm_loadu_pd(p2), 1);
    const __m256d xy13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1)), _mm_loadu_pd(p3), 1);
    out[I] = reinterpret_cast<materials::double4>(_mm256_unpacklo_pd(xy02, xy13));
    out[8 + I] = reinterpret_cast<materials::double4>(_mm256_unpackhi_pd(xy02, xy13));
    out[16 + I] = materials::double4{p0[2], p1[2], p2[2], p3[2]};
  }
}

inline void subtract_nodal(double* f, const int* const nodes[], const materials::double4 in[24], unsigned lanes) {
  __m128d xy[4][8];  // [lane][node] (x, y)
  double z[4][8];
  for (int I = 0; I < 8; ++I) {
    const __m256d x = reinterpret_cast<__m256d>(in[I]), y = reinterpret_cast<__m256d>(in[8 + I]);
    const __m256d lo = _mm256_unpacklo_pd(x, y);  // [x0 y0 | x2 y2]
    const __m256d hi = _mm256_unpackhi_pd(x, y);  // [x1 y1 | x3 y3]
    xy[0][I] = _mm256_castpd256_pd128(lo);
    xy[1][I] = _mm256_castpd256_pd128(hi);
    xy[2][I] = _mm256_extractf128_pd(lo, 1);
    xy[3][I] = _mm256_extractf128_pd(hi, 1);
    for (int l = 0; l < 4; ++l) z[l][I] = in[16 + I][l];
  }
  for (int l = 0; l < 4; ++l)
    for (int I = 0; I < 8 && (lanes >> l & 1u); ++I) {
      double* fn = f + 3 * nodes[l][I];
      _mm_storeu_pd(fn, _mm_sub_pd(_mm_loadu_pd(fn), xy[l][I]));
      fn[2] -= z[l][I];
    }
}
#endif

#ifdef __AVX512F__
// Eight lanes: as the four-lane versions, with the (x, y) pairs of lanes 0, 2, 4, 6 and of 1, 3, 5, 7
// in one register each, so that one unpack gives the eight x and another the eight y in lane order.
// Written as GCC vector shuffles, not intrinsics: GCC 12's AVX-512 unpack and insert intrinsics
// pass an undefined register that -Wmaybe-uninitialized reports (GCC bug 105593); the same
// instructions come out.
inline materials::double8 pairs_of_lanes(const double* p0, const double* p1, const double* p2, const double* p3) {
  using materials::double2;
  using materials::load_lanes;
  const materials::double4 lo = __builtin_shufflevector(load_lanes<double2>(p0), load_lanes<double2>(p1), 0, 1, 2, 3);
  const materials::double4 hi = __builtin_shufflevector(load_lanes<double2>(p2), load_lanes<double2>(p3), 0, 1, 2, 3);
  return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7);
}

inline void gather_nodal(const double* a, const int* const nodes[], materials::double8 out[24]) {
  for (int I = 0; I < 8; ++I) {
    const double* p[8];
    for (int l = 0; l < 8; ++l) p[l] = a + 3 * nodes[l][I];
    const materials::double8 even = pairs_of_lanes(p[0], p[2], p[4], p[6]);  // [x0 y0 | x2 y2 | x4 y4 | x6 y6]
    const materials::double8 odd = pairs_of_lanes(p[1], p[3], p[5], p[7]);
    out[I] = __builtin_shufflevector(even, odd, 0, 8, 2, 10, 4, 12, 6, 14);       // x0 .. x7
    out[8 + I] = __builtin_shufflevector(even, odd, 1, 9, 3, 11, 5, 13, 7, 15);   // y0 .. y7
    out[16 + I] = materials::double8{p[0][2], p[1][2], p[2][2], p[3][2], p[4][2], p[5][2], p[6][2], p[7][2]};
  }
}

inline void subtract_nodal(double* f, const int* const nodes[], const materials::double8 in[24], unsigned lanes) {
  // [lane][node] (x, y) and z, taken out of the registers in the sizes they are read back in, as at
  // four lanes (storing whole registers and reading 16-byte pieces back measured the same)
  materials::double2 xy[8][8];
  double z[8][8];
  for (int I = 0; I < 8; ++I) {
    const materials::double8 even = __builtin_shufflevector(in[I], in[8 + I], 0, 8, 2, 10, 4, 12, 6, 14);  // [x0 y0 | x2 y2 | ...]
    const materials::double8 odd = __builtin_shufflevector(in[I], in[8 + I], 1, 9, 3, 11, 5, 13, 7, 15);   // [x1 y1 | x3 y3 | ...]
    xy[0][I] = __builtin_shufflevector(even, even, 0, 1);
    xy[1][I] = __builtin_shufflevector(odd, odd, 0, 1);
    xy[2][I] = __builtin_shufflevector(even, even, 2, 3);
    xy[3][I] = __builtin_shufflevector(odd, odd, 2, 3);
    xy[4][I] = __builtin_shufflevector(even, even, 4, 5);
    xy[5][I] = __builtin_shufflevector(odd, odd, 4, 5);
    xy[6][I] = __builtin_shufflevector(even, even, 6, 7);
    xy[7][I] = __builtin_shufflevector(odd, odd, 6, 7);
    for (int l = 0; l < 8; ++l) z[l][I] = in[16 + I][l];
  }
  for (int l = 0; l < 8; ++l)
    for (int I = 0; I < 8 && (lanes >> l & 1u); ++I) {
      double* fn = f + 3 * nodes[l][I];
      materials::store_lanes(fn, materials::load_lanes<materials::double2>(fn) - xy[l][I]);
      fn[2] -= z[l][I];
    }
}
#endif

}  // namespace tribex::solver::hex8
