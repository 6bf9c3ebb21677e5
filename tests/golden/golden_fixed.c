/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of fixed/: any 32- and 64-bit inputs
 *        through the arithmetic, roots, trigonometry and hyperbolic
 *        functions, statuses included.
 */
#include <drdc/fixed.h>

#include "golden.h"

void golden_fixed(golden_t *g)
{
  int i;

  for (i = 0; i < 4096; i++) {
    uint32_t u = golden_next(g);
    uint32_t v = golden_next(g);
    int32_t a = (int32_t)u;
    int32_t b = (int32_t)v;
    int64_t wide = (int64_t)(((uint64_t)u << 32) | v);
    int32_t r32 = 0;
    int64_t r64 = 0;
    drdc_q1_30_t s = 0;
    drdc_q1_30_t c = 0;
    drdc_bam32_t angle = 0;

    golden_fn(g, "drdc_fx_mul_q1_30");
    golden_in(g, "a", a);
    golden_in(g, "b", b);
    golden_i32(g, (int32_t)drdc_fx_mul_q1_30(a, b, &r32));
    golden_i32(g, r32);
    golden_fn(g, "drdc_fx_mul_q15_16_sat");
    golden_in(g, "a", a);
    golden_in(g, "b", b);
    golden_i32(g, (int32_t)drdc_fx_mul_q15_16_sat(a, b, &r32));
    golden_i32(g, r32);
    golden_fn(g, "drdc_fx_div_q15_16");
    golden_in(g, "a", a);
    golden_in(g, "b", b >> 8);
    golden_i32(g, (int32_t)drdc_fx_div_q15_16(a, b >> 8, &r32));
    golden_i32(g, r32);
    golden_fn(g, "drdc_fx_muldiv_s64");
    golden_in(g, "x", wide);
    golden_in(g, "a", a);
    golden_in(g, "b", b);
    golden_i32(g, (int32_t)drdc_fx_muldiv_s64(wide, a, b, &r64));
    golden_i64(g, r64);
    golden_fn(g, "drdc_fx_sqrt_u32");
    golden_in(g, "x", u);
    golden_u32(g, drdc_fx_sqrt_u32(u));
    golden_fn(g, "drdc_fx_sqrt_u64");
    golden_in(g, "x", wide);
    golden_u64(g, drdc_fx_sqrt_u64((uint64_t)wide));
    golden_fn(g, "drdc_fx_rsqrt_q1_30");
    golden_in(g, "x", a);
    golden_i32(g, (int32_t)drdc_fx_rsqrt_q1_30(a, &r32));
    golden_i32(g, r32);
    golden_fn(g, "drdc_fx_hypot_s64");
    golden_in(g, "x", wide);
    golden_in(g, "y", b);
    golden_u64(g, drdc_fx_hypot_s64(wide, (int64_t)b));
    golden_fn(g, "drdc_fx_sincos_bam32");
    golden_in(g, "angle", u);
    drdc_fx_sincos_bam32(u, &s, &c);
    golden_i32(g, s);
    golden_i32(g, c);
    golden_fn(g, "drdc_fx_tan_bam32");
    golden_in(g, "angle", v);
    golden_i32(g, (int32_t)drdc_fx_tan_bam32(v, &r32));
    golden_i32(g, r32);
    golden_fn(g, "drdc_fx_atan2_bam32");
    golden_in(g, "y", a);
    golden_in(g, "x", b);
    golden_i32(g, (int32_t)drdc_fx_atan2_bam32(a, b, &angle));
    golden_u32(g, angle);
    golden_fn(g, "drdc_fx_asin_q1_30");
    golden_in(g, "x", a >> 1);
    golden_i32(g, (int32_t)drdc_fx_asin_q1_30(a >> 1, &angle));
    golden_u32(g, angle);
    golden_fn(g, "drdc_fx_acos_q1_30");
    golden_in(g, "x", b >> 1);
    golden_i32(g, (int32_t)drdc_fx_acos_q1_30(b >> 1, &angle));
    golden_u32(g, angle);
    /* hyperbolic arguments over their domains and beyond (Q5.58) */
    golden_fn(g, "drdc_fx_sinh_q5_58");
    golden_in(g, "x", wide >> 4);
    golden_i32(g, (int32_t)drdc_fx_sinh_q5_58(wide >> 4, &r64));
    golden_i64(g, r64);
    golden_fn(g, "drdc_fx_cosh_q5_58");
    golden_in(g, "x", wide >> 6);
    golden_i32(g, (int32_t)drdc_fx_cosh_q5_58(wide >> 6, &r64));
    golden_i64(g, r64);
    golden_fn(g, "drdc_fx_atanh_q5_58");
    golden_in(g, "x", wide >> 5);
    golden_i32(g, (int32_t)drdc_fx_atanh_q5_58(wide >> 5, &r64));
    golden_i64(g, r64);
    golden_fn(g, "drdc_fx_asinh_q5_58");
    golden_in(g, "x", wide);
    golden_i32(g, (int32_t)drdc_fx_asinh_q5_58(wide, &r64));
    golden_i64(g, r64);
  }
}
