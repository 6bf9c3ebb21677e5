/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_types
 * @brief The one representation of each quantity of the data standard.
 *
 * docs/conventions.md holds the same table with the reasons. Every module
 * uses these types; none defines a second representation of a quantity.
 */
#ifndef DRDC_TYPES_H
#define DRDC_TYPES_H

#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>

/**
 * @defgroup drdc_types Core representations
 * @{
 */

/**
 * Latitude or longitude: int64_t count of nano-arcseconds
 * (1e-9 arcsecond = 1/3.6e12 degree = 4.85e-15 rad).
 *
 * Decimal on purpose: every degree text with up to 12 decimals, every
 * NMEA ddmm.mmmm field with up to 10 decimals of minutes and every
 * integer zone or band edge (6 and 8 degree multiples) is an exact value,
 * so text round-trips exactly and a point on a zone edge is on the edge,
 * not a rounding error beside it. Range +-2.5e6 degrees.
 */
typedef int64_t drdc_nas_t;

/** Nano-arcseconds per degree: 3600 arcseconds times 1e9. */
#define DRDC_NAS_PER_DEGREE INT64_C(3600000000000)

/** Nanoseconds per second. */
#define DRDC_NS_PER_SECOND INT32_C(1000000000)

/**
 * A UTC instant: POSIX-style seconds since 1970-01-01T00:00:00Z counting
 * 86 400 s every day, plus nanoseconds.
 *
 * `nsec` is in [0, 1e9) except during a positive leap second, which is
 * written as 23:59:59 with `nsec` in [1e9, 2e9): the instant 23:59:60.25
 * is {sec of 23:59:59, 1 250 000 000}. Range of `sec`: the years
 * DRDC_YEAR_MIN..DRDC_YEAR_MAX.
 */
typedef struct drdc_time {
  int64_t sec;  /**< UTC seconds since 1970-01-01, 86 400 per day */
  int32_t nsec; /**< nanoseconds, [0, 2e9) as described above */
} drdc_time_t;

/** Earliest year of every calendar function: proleptic Gregorian year 1. */
#define DRDC_YEAR_MIN 1
/** Latest year of every calendar function. Years have four digits in ISO
 *  8601 text without an expanded representation. */
#define DRDC_YEAR_MAX 9999

/** @} */

#endif /* DRDC_TYPES_H */
