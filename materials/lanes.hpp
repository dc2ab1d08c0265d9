// SPDX-License-Identifier: MIT
// One element, two per SSE register, four per AVX2 register or eight per AVX-512 register (double4,
// double8 below). The fully integrated kernel runs the same code for a lone
// element (T = double) and for a pair (T = double2, GCC's vector extension: + - * / act lane by
// lane and a double operand is broadcast). The arithmetic is IEEE lane by lane and x86-64-v2 has
// no fused multiply-add, so an element's forces are bitwise the same alone or in a pair (tested:
// LanesTest.ElementsGiveBitwiseTheSameResultsAtEveryLaneWidthAndAlone); with lane_log below, for every material.
//
// lane_log: lane_log.hpp, the whole register in the lanes' own arithmetic (below 1 ulp), so a
// result does not depend on the lane an element ran in. Elsewhere: std::log.
#pragma once

#include <cmath>
#include <cstring>

#include "materials/lane_log.hpp"

#ifdef __AVX512F__
#include <immintrin.h>
#endif

namespace tribex::materials {

using double2 = double __attribute__((vector_size(16)));

template <class T>
inline constexpr int lane_count = 1;
template <>
inline constexpr int lane_count<double2> = 2;

inline double lane(double x, int) { return x; }
inline double lane(double2 x, int l) { return x[l]; }

/// T from its lanes: f(l) for l < lane_count<T>.
template <class T, class F>
inline T from_lanes(F&& f) {
  if constexpr (lane_count<T> == 1)
    return f(0);
  else if constexpr (lane_count<T> == 2)
    return T{f(0), f(1)};
  else if constexpr (lane_count<T> == 4)
    return T{f(0), f(1), f(2), f(3)};
  else
    return T{f(0), f(1), f(2), f(3), f(4), f(5), f(6), f(7)};
}

/// lane_count<T> consecutive doubles from p (a pair-interleaved array's two lanes).
template <class T>
inline T load_lanes(const double* p) {
  T x;
  std::memcpy(&x, p, sizeof(T));
  return x;
}

/// min(x, 0) lane by lane.
inline double negative_part(double x) { return x < 0.0 ? x : 0.0; }
inline double2 negative_part(double2 x) { return x < double2{} ? x : double2{}; }

inline double2 lane_log(double2 x) { return log_of_lanes(x); }
/// max(x, 0), max(x, y) and sqrt lane by lane (sqrt is correctly rounded: a lane's result does
/// not depend on its partner).
inline double positive_part(double x) { return x > 0.0 ? x : 0.0; }
inline double2 positive_part(double2 x) { return x > double2{} ? x : double2{}; }
inline double lane_max(double x, double y) { return x > y ? x : y; }
inline double2 lane_max(double2 x, double y) {
  const double2 yy{y, y};
  return x > yy ? x : yy;
}
inline double lane_sqrt(double x) { return std::sqrt(x); }
inline double2 lane_sqrt(double2 x) { return double2{std::sqrt(x[0]), std::sqrt(x[1])}; }

/// Store the lanes of x at p (the inverse of load_lanes).
template <class T>
inline void store_lanes(double* p, const T& x) {
  std::memcpy(p, &x, sizeof(T));
}

/// One lane as it would be in a register (not std::log, whose last bit may differ).
inline double lane_log(double x) { return log_of_lanes(double2{x, x})[0]; }

// Four elements per AVX2 register: defined only where the translation unit is compiled for AVX2
// (solver/hex8/avx2_kernels.cpp), so no other object file holds AVX code. The same IEEE operations
// lane by lane as double and double2, no fused multiply-add (the file is built with -mavx2, not
// -mfma), and the logarithm of lane_log.hpp, so an element's result does not depend on the lane
// width it ran at.
#ifdef __AVX2__
using double4 = double __attribute__((vector_size(32)));
template <>
inline constexpr int lane_count<double4> = 4;
inline double lane(double4 x, int l) { return x[l]; }
inline double4 negative_part(double4 x) { return x < double4{} ? x : double4{}; }
inline double4 positive_part(double4 x) { return x > double4{} ? x : double4{}; }
inline double4 lane_max(double4 x, double y) {
  const double4 yy{y, y, y, y};
  return x > yy ? x : yy;
}
inline double4 lane_sqrt(double4 x) { return double4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])}; }
inline double4 lane_log(double4 x) { return log_of_lanes(x); }
#endif

// Eight elements per AVX-512 register, likewise only where the translation unit is compiled for
// AVX-512 (solver/hex8/avx512_kernels.cpp, built with -mavx512f -ffp-contract=off: AVX-512F has
// fused multiply-add of its own, so -mno-fma alone would not keep GCC from contracting a * b + c).
// sqrt is correctly rounded, so the vector instruction gives each lane what std::sqrt gives; the
// logarithm is lane_log.hpp's, as for double4.
#ifdef __AVX512F__
using double8 = double __attribute__((vector_size(64)));
template <>
inline constexpr int lane_count<double8> = 8;
inline double lane(double8 x, int l) { return x[l]; }
inline double8 negative_part(double8 x) { return x < double8{} ? x : double8{}; }
inline double8 positive_part(double8 x) { return x > double8{} ? x : double8{}; }
inline double8 lane_max(double8 x, double y) {
  const double8 yy = double8{} + y;
  return x > yy ? x : yy;
}
// (_mm512_mask_sqrt_pd with every lane selected: the unmasked intrinsic passes GCC 12 an
// undefined register that -Wmaybe-uninitialized reports, GCC bug 105593)
inline double8 lane_sqrt(double8 x) {
  const __m512d v = reinterpret_cast<__m512d>(x);
  return reinterpret_cast<double8>(_mm512_mask_sqrt_pd(v, 0xff, v));
}
inline double8 lane_log(double8 x) { return log_of_lanes(x); }
/// Lanes 0-3 from lo and 4-7 from hi (two groups of an array interleaved by four:
/// solver/element_block.hpp load_record).
inline double8 join_lanes(double4 lo, double4 hi) { return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7); }
#endif

}  // namespace tribex::materials
