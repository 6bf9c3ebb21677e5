/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The operands of the timed calls, made once before any timing
 *        from the 32-bit words of bench_u32[], in the library's formats.
 *        cases_double.c converts them to double, also before timing, so
 *        that every implementation's timed loop holds the call alone.
 */
#ifndef DRDC_BENCH_OPERANDS_H
#define DRDC_BENCH_OPERANDS_H

#include <drdc/geo.h>
#include <drdc/geo_ecef.h>
#include <drdc/orient.h>
#include <drdc/time.h>
#include <drdc/time_scales.h>

#include "bench.h"

/** A civil date. */
typedef struct bench_civil {
  int32_t year;
  int32_t month;
  int32_t day;
} bench_civil_t;

/** Quaternion pairs (Q1.30, every part below 0.5 in magnitude). */
extern drdc_quat_t bench_qa[BENCH_INPUTS];
extern drdc_quat_t bench_qb[BENCH_INPUTS];
/** Vectors to rotate (Q15.16 metres, |part| < 16 m). */
extern drdc_vec3_q15_16_t bench_vec[BENCH_INPUTS];
/** Euler angles (binary angles, every value). */
extern drdc_euler_t bench_euler[BENCH_INPUTS];
/** Geographic points for UTM: latitude +-80, longitude +-180 degrees. */
extern drdc_nas_t bench_utm_lat[BENCH_INPUTS];
extern drdc_nas_t bench_utm_lon[BENCH_INPUTS];
/** UTM positions: zones 1..60, both hemispheres, eastings 180..820 km,
 *  0..8 000 km from the equator. */
extern drdc_geo_utm_t bench_utm[BENCH_INPUTS];
/** Geodetic points for ECEF: latitude +-90, longitude +-180 degrees,
 *  heights -10 km .. 1 000 km. */
extern drdc_geo_point_t bench_geodetic[BENCH_INPUTS];
/** ECEF points near the surface (radius 6 357 .. 7 380 km). */
extern drdc_vec3_q47_16_t bench_ecef[BENCH_INPUTS];
/** UTC instants 1990..2026 with nanoseconds. */
extern drdc_time_t bench_instant[BENCH_INPUTS];
/** GPS times: weeks 522..2421, whole seconds of the week. */
extern drdc_time_gps_t bench_gps[BENCH_INPUTS];
/** Civil dates 1900..2099 (days 1..28). */
extern bench_civil_t bench_civil[BENCH_INPUTS];
/** Day numbers from 1970-01-01, -25 000 .. 47 999. */
extern int32_t bench_days[BENCH_INPUTS];

/** Fills the tables above from bench_u32[] (after bench_inputs_init()). */
void bench_operands_init(void);

#endif /* DRDC_BENCH_OPERANDS_H */
