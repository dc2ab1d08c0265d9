// SPDX-License-Identifier: MIT
// Natural logarithm of a short array, two values per call on x86-64 glibc: the SSE variant of glibc's
// vector math library (libmvec, `_ZGVbN2v_log`, the symbol GCC itself calls for a vectorised log;
// glibc manual "Errors in Math Functions": at most 4 ulp, against < 1 ulp for the scalar log). The
// element kernels take the 8 Gauss-point logs of a neo-Hookean element this way (tools/bench/README.md).
// libm.so's linker script pulls libmvec in as needed. Elsewhere: std::log one at a time.
#pragma once

#include <cmath>

#if defined(__x86_64__) && defined(__GLIBC__)
#include <emmintrin.h>
extern "C" __m128d _ZGVbN2v_log(__m128d);  // NOLINT(bugprone-reserved-identifier): glibc's ABI name
#define TRIBEX_HAVE_LIBMVEC_LOG 1
#endif

namespace tribex::materials {

/// out[k] = log(x[k]) for k < n, n even; non-positive x give NaN or -inf as std::log does.
inline void log_pairs(const double* x, double* out, int n) {
#ifdef TRIBEX_HAVE_LIBMVEC_LOG
  for (int k = 0; k < n; k += 2) _mm_storeu_pd(out + k, _ZGVbN2v_log(_mm_loadu_pd(x + k)));
#else
  for (int k = 0; k < n; ++k) out[k] = std::log(x[k]);
#endif
}

}  // namespace tribex::materials
