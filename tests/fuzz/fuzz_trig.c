/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Differential fuzzer of fixed/ trigonometry and roots against a
 *        long double model (libm): sin and cos of any binary angle within
 *        their documented 1 LSB of Q1.30, atan2 of any int32 pair within 1
 *        unit of the binary angle, and sqrt of any Q15.16 value correctly
 *        rounded. The model's own error (about 1e-19) is far below the
 *        bounds, so a margin of 1e-6 LSB absorbs it. Host only.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/fixed.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const long double TWO_PI = 6.283185307179586476925286766559L;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  uint32_t in[3] = {0u, 0u, 0u};
  drdc_q1_30_t s = 0;
  drdc_q1_30_t c = 0;
  drdc_bam32_t a = 0u;
  drdc_q15_16_t r = 0;
  long double x;
  long double err;

  memcpy(in, data, size < sizeof in ? size : sizeof in);
  x = (long double)in[0] * TWO_PI / 4294967296.0L;
  drdc_fx_sincos_bam32(in[0], &s, &c);
  if ((fabsl((long double)s - sinl(x) * 1073741824.0L) > 1.000001L) ||
      (fabsl((long double)c - cosl(x) * 1073741824.0L) > 1.000001L)) {
    abort();
  }
  if (drdc_fx_atan2_bam32((int32_t)in[1], (int32_t)in[2], &a) == DRDC_OK) {
    long double want =
        atan2l((long double)(int32_t)in[1], (long double)(int32_t)in[2]) *
        4294967296.0L / TWO_PI;
    err = (long double)(int32_t)a - want;
    err = fmodl(err + 6442450944.0L, 4294967296.0L) - 2147483648.0L; /* wrap */
    if (fabsl(err) > 1.000001L) {
      abort();
    }
  } else if (((int32_t)in[1] != 0) || ((int32_t)in[2] != 0)) {
    abort(); /* only atan2(0, 0) is a domain error */
  }
  if (drdc_fx_sqrt_q15_16((drdc_q15_16_t)(in[1] >> 1), &r) != DRDC_OK) {
    abort();
  }
  /* correctly rounded: |r - sqrt(v 2^16)| <= 0.5 */
  if (fabsl((long double)r - sqrtl((long double)(in[1] >> 1) * 65536.0L)) >
      0.500001L) {
    abort();
  }
  return 0;
}
