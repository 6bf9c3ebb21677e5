/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The operands of the timed calls (operands.h), spread over each
 *        function's domain by the bits of one 32-bit word per input.
 */
#include <drdc/fixed.h>

#include "operands.h"

drdc_quat_t bench_qa[BENCH_INPUTS];
drdc_quat_t bench_qb[BENCH_INPUTS];
drdc_vec3_q15_16_t bench_vec[BENCH_INPUTS];
drdc_euler_t bench_euler[BENCH_INPUTS];
drdc_nas_t bench_utm_lat[BENCH_INPUTS];
drdc_nas_t bench_utm_lon[BENCH_INPUTS];
drdc_geo_utm_t bench_utm[BENCH_INPUTS];
drdc_geo_point_t bench_geodetic[BENCH_INPUTS];
drdc_vec3_q47_16_t bench_ecef[BENCH_INPUTS];
drdc_time_t bench_instant[BENCH_INPUTS];
drdc_time_gps_t bench_gps[BENCH_INPUTS];
bench_civil_t bench_civil[BENCH_INPUTS];
int32_t bench_days[BENCH_INPUTS];

/* parts of magnitude below 2^29 (0.5) from the bits of x */
static drdc_quat_t quat_of(uint32_t x)
{
  drdc_quat_t q;

  q.s = (int32_t)(x >> 3);
  q.x = (int32_t)((x << 7) >> 3) - (INT32_C(1) << 28);
  q.y = (int32_t)((x << 13) >> 3) - (INT32_C(1) << 28);
  q.z = (int32_t)((x << 21) >> 3) - (INT32_C(1) << 28);
  return q;
}

/* a point on a sphere of radius 6 357 .. 7 380 km (integer sin/cos of
 * fixed_trig.h), Q47.16 metres */
static drdc_vec3_q47_16_t ecef_point(uint32_t x)
{
  drdc_vec3_q47_16_t e;
  drdc_q1_30_t sp = 0;
  drdc_q1_30_t cp = 0;
  drdc_q1_30_t sl = 0;
  drdc_q1_30_t cl = 0;
  int64_t r = 6357000 + (int64_t)(x >> 22) * 1000;
  int64_t h;

  drdc_fx_sincos_bam32(
      (drdc_bam32_t)((uint32_t)(int32_t)((int32_t)(x << 21) / 2)), &sp, &cp);
  drdc_fx_sincos_bam32((drdc_bam32_t)((x >> 11) << 21), &sl, &cl);
  /* r cos(lat) < 2^39 m, times a Q1.22 cosine < 2^61 */
  h = (r * cp) / 16384;
  e.x = (h * (cl / 256)) / 4194304;
  e.y = (h * (sl / 256)) / 4194304;
  e.z = (r * sp) / 16384;
  return e;
}

void bench_operands_init(void)
{
  uint32_t k;

  for (k = 0u; k < BENCH_INPUTS; k++) {
    uint32_t x = bench_u32[k];
    int64_t northing;

    bench_qa[k] = quat_of(x);
    bench_qb[k] = quat_of(x * 2654435761u);
    bench_vec[k].x = (int32_t)(x & 0xFFFFFu);
    bench_vec[k].y = (int32_t)(x >> 12);
    bench_vec[k].z = -(int32_t)(x & 0xFFFFu);
    bench_euler[k].yaw = x;
    bench_euler[k].pitch = (x * 2654435761u) >> 2;
    bench_euler[k].roll = x * 40503u;
    bench_utm_lat[k] = ((int64_t)(x & 0xFFFFu) - 32768) * INT64_C(8800000000);
    bench_utm_lon[k] = ((int64_t)(x >> 16) - 32768) * INT64_C(19700000000);
    bench_utm[k].zone = (int32_t)(x % 60u) + 1;
    bench_utm[k].north = ((x >> 6) & 1u) != 0u;
    bench_utm[k].easting =
        ((int64_t)180000 + (int64_t)((x >> 7) & 0x3FFu) * 625) * 65536;
    northing = (int64_t)((x >> 17) & 0x7FFFu) * 244;
    bench_utm[k].northing =
        (bench_utm[k].north ? northing : 10000000 - northing) * 65536;
    bench_geodetic[k].lat =
        ((int64_t)(x & 0xFFFFu) - 32768) * INT64_C(9880000000);
    bench_geodetic[k].lon =
        ((int64_t)((x >> 16) & 0x7FFFu) - 16384) * INT64_C(39500000000);
    bench_geodetic[k].height = ((int64_t)(x >> 31) * 1000000 - 10000 +
                                (int64_t)((x >> 8) & 0xFFu) * 40) *
                               65536;
    bench_ecef[k] = ecef_point(x);
    bench_instant[k].sec = INT64_C(631152000) + (int64_t)(x % 1136073600u);
    bench_instant[k].nsec = (int32_t)((x >> 3) % 1000000000u);
    bench_gps[k].week = 522 + (int32_t)(x % 1900u);
    bench_gps[k].tow = (int32_t)((x >> 11) % 604800u);
    bench_gps[k].nsec = 0;
    bench_civil[k].year = 1900 + (int32_t)(x % 200u);
    bench_civil[k].month = 1 + (int32_t)((x >> 8) % 12u);
    bench_civil[k].day = 1 + (int32_t)((x >> 16) % 28u);
    bench_days[k] = (int32_t)(x % 73000u) - 25000;
  }
}
