// SPDX-License-Identifier: MIT
// Natural logarithm of every lane of a GCC vector (double2, double4, double8: lanes.hpp), written in
// the lanes' own arithmetic: the same IEEE operations in every lane and no fused multiply-add (the
// kernels' files are built without contraction), so a lane's result does not depend on the vector
// width it ran at, and the whole register is done at once (two lanes per call of glibc's libmvec
// routine was 16 % of the fully integrated neo-Hookean step at four lanes:
// docs/measurements/2026-11-27-bench-element-kernels.md).
//
// Algorithm (the reduction and the minimax polynomial of Sun's fdlibm e_log.c, 1993, as described
// in its comments; the code is ours): x = 2^k (1 + f) with 1 + f in [sqrt(2)/2, sqrt(2)),
//   s = f / (2 + f),  log(1 + f) = f - f^2/2 + s (f^2/2 + R(s^2)),  R(z) = Lg1 z + ... + Lg7 z^7,
//   log x = k ln2_hi - ((f^2/2 - (s (f^2/2 + R) + k ln2_lo)) - f),
// ln2 split so that k ln2_hi is exact. fdlibm's error bound for this form is below 1 ulp
// (tests/materials/lane_log_test.cpp measures it against std::log). Subnormal x is scaled by 2^54
// first; x = 0 gives -inf, x < 0 and NaN give NaN, +inf gives +inf, as std::log.
#pragma once

namespace tribex::materials {

namespace detail {
/// The unsigned 64-bit integer vector as wide as a double vector of `Bytes` bytes.
template <unsigned long Bytes>
struct UnsignedLanes {
  typedef unsigned long type __attribute__((vector_size(Bytes)));
};
}  // namespace detail

template <class T>
[[gnu::always_inline]] inline T log_of_lanes(T x) {
  using Bits = typename detail::UnsignedLanes<sizeof(T)>::type;
  constexpr double ln2_hi = 0x1.62e42fee00000p-1, ln2_lo = 0x1.a39ef35793c76p-33;
  constexpr double Lg1 = 0x1.5555555555593p-1, Lg2 = 0x1.999999997fa04p-2, Lg3 = 0x1.2492494229359p-2,
                   Lg4 = 0x1.c71c51d8e78afp-3, Lg5 = 0x1.7466496cb03dep-3, Lg6 = 0x1.39a09d078c69fp-3,
                   Lg7 = 0x1.2f112df3e5244p-3;
  const T zero{};
  const auto subnormal = x < zero + 0x1p-1022;  // (x <= 0 too: replaced at the end)
  const T scaled = subnormal ? x * 0x1p54 : x;
  const T k_offset = subnormal ? zero + 54.0 : zero;
  // Add (1 - sqrt(2)/2)'s offset to the high word so that the exponent field counts k with the
  // mantissa in [sqrt(2)/2, sqrt(2)), then put that mantissa back under the exponent of 1/2.
  const Bits bits = __builtin_bit_cast(Bits, scaled) + (Bits{} + ((0x3ff00000UL - 0x3fe6a09eUL) << 32));
  // k as a double without an int64 conversion (none in AVX2): 2^52 + e, read as a double, minus 2^52
  const T biased_exponent = __builtin_bit_cast(T, (bits >> 52) | 0x4330000000000000UL) - 0x1p52;
  const T k = (biased_exponent - 1023.0) - k_offset;
  const Bits mantissa = (bits & 0x000fffffffffffffUL) + (Bits{} + (0x3fe6a09eUL << 32));
  const T f = __builtin_bit_cast(T, mantissa) - 1.0;

  const T half_f2 = 0.5 * f * f;
  const T s = f / (2.0 + f);
  const T z = s * s, w = z * z;
  const T odd = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
  const T even = w * (Lg2 + w * (Lg4 + w * Lg6));
  const T R = odd + even;
  const T result = k * ln2_hi - ((half_f2 - (s * (half_f2 + R) + k * ln2_lo)) - f);

  const T inf = zero + __builtin_inf();
  const T special = x == zero ? -inf : (x < zero ? zero + __builtin_nan("") : x);  // x = +inf or NaN: x
  return (x > zero) & (x < inf) ? result : special;
}

}  // namespace tribex::materials
