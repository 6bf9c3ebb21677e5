/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_scales
 * @brief UTC <-> TAI, GPS week and time of week, Unix/POSIX seconds, RTEMS
 *        seconds since 1988 and the RTEMS time-of-day record.
 */
#ifndef DRDC_TIME_SCALES_H
#define DRDC_TIME_SCALES_H

#include <stdint.h>

#include <drdc/time.h>
#include <drdc/time_leap.h>

/**
 * @defgroup drdc_time_scales Time scales
 *
 * UTC (drdc_time_t) is the hub: every scale converts to and from it.
 * All conversions are exact integer arithmetic to the nanosecond; there
 * is no rounding except where a function says so (RTEMS ticks).
 *
 * | scale | epoch | seconds per day | leap second |
 * |---|---|---|---|
 * | TAI  | 1958-01-01T00:00:00 TAI | 86 400 (SI) | counted |
 * | GPS  | 1980-01-06T00:00:00 UTC = TAI - 19 s | 86 400 (SI) | counted |
 * | Unix | 1970-01-01T00:00:00Z | 86 400 by definition | not counted |
 * | RTEMS | 1988-01-01T00:00:00Z | 86 400 by definition | not counted |
 *
 * TAI and GPS need TAI-UTC and so a leap state (NULL = built-in); they
 * exist from 1972-01-01 (integer TAI-UTC) and 1980-01-06 on. Past the
 * state's expiry they return DRDC_W_LEAP_EXPIRED with the outputs written.
 * @{
 */

/**
 * A count of seconds of a uniform time scale since its epoch: TAI since
 * 1958-01-01, Unix since 1970-01-01, RTEMS since 1988-01-01. The value is
 * sec + nsec / 1e9 with nsec in [0, 1e9): -1.5 s is {-2, 500000000}.
 */
typedef struct drdc_time_count {
  int64_t sec;  /**< whole seconds (floor), may be negative */
  int32_t nsec; /**< nanoseconds, 0..999 999 999 */
} drdc_time_count_t;

/** GPS time as full week number and time of week. */
typedef struct drdc_time_gps {
  int32_t week; /**< full week since 1980-01-06, 0..DRDC_TIME_GPS_WEEK_MAX */
  int32_t tow;  /**< seconds of the week, 0..604 799 */
  int32_t nsec; /**< nanoseconds, 0..999 999 999 */
} drdc_time_gps_t;

/** Last full GPS week whose every instant is within DRDC_YEAR_MAX. */
#define DRDC_TIME_GPS_WEEK_MAX INT32_C(418461)
/** Seconds in a GPS week. */
#define DRDC_TIME_GPS_SECONDS_PER_WEEK INT32_C(604800)
/** The broadcast week number of the legacy navigation message has 10 bits
 *  and rolls over every 1024 weeks (1999-08-22, 2019-04-07, 2038-11-21). */
#define DRDC_TIME_GPS_WEEK_ROLLOVER INT32_C(1024)

/** Unix seconds of 1988-01-01T00:00:00Z, the RTEMS epoch. */
#define DRDC_TIME_RTEMS_EPOCH_UNIX INT64_C(567993600)
/** TAI seconds since 1958-01-01 at UTC 1970-01-01T00:00:00, minus
 *  TAI-UTC: 4383 days of 86 400 s. */
#define DRDC_TIME_TAI_EPOCH_TO_UNIX INT64_C(378691200)

/**
 * UTC -> TAI seconds since 1958-01-01T00:00:00 TAI.
 *
 * @param leap leap state, NULL for the built-in one
 * @param utc  valid UTC instant (drdc_time_check()) on or after 1972-01-01
 * @param[out] tai TAI count; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_W_LEAP_EXPIRED written with the last known offset: the
 *         instant is on or after the state's expiry day
 * @retval DRDC_E_NULL `utc` or `tai` is NULL
 * @retval DRDC_E_RANGE before 1972-01-01, or outside the calendar
 * @retval DRDC_E_NANOSECOND, DRDC_E_SECOND  invalid `utc`
 *
 * Accuracy: exact. Checked against ERFA (eraDtf2d + eraUtctai) at every
 * leap second since 1972 and at random instants 1972..2100.
 *
 * @code
 * drdc_time_t t = { 1483228799, 1000000000 }; // 2016-12-31T23:59:60
 * drdc_time_count_t tai;
 * drdc_time_utc_to_tai(NULL, &t, &tai);       // tai.sec = 1861920036
 * @endcode
 */
drdc_status_t drdc_time_utc_to_tai(const drdc_time_leap_t *leap,
                                   const drdc_time_t *utc,
                                   drdc_time_count_t *tai);

/**
 * TAI seconds since 1958-01-01 -> UTC; inverse of drdc_time_utc_to_tai().
 * A TAI second that is a leap second gives 23:59:60 (nsec >= 1e9).
 *
 * @param leap leap state, NULL for the built-in one
 * @param tai  TAI count, nsec 0..999 999 999, not before
 *             1972-01-01T00:00:10 TAI
 * @param[out] utc UTC instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_W_LEAP_EXPIRED written; the UTC day is on or after expiry
 * @retval DRDC_E_NULL `tai` or `utc` is NULL
 * @retval DRDC_E_NANOSECOND nsec out of 0..999 999 999
 * @retval DRDC_E_RANGE before 1972-01-01 UTC, or after year 9999
 */
drdc_status_t drdc_time_tai_to_utc(const drdc_time_leap_t *leap,
                                   const drdc_time_count_t *tai,
                                   drdc_time_t *utc);

/**
 * UTC -> GPS week and time of week (GPS time = TAI - 19 s).
 *
 * @param leap leap state, NULL for the built-in one
 * @param utc  valid UTC instant on or after 1980-01-06T00:00:00Z
 * @param[out] gps full week, TOW and nanoseconds; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_W_LEAP_EXPIRED written; on or after the expiry day
 * @retval DRDC_E_NULL `utc` or `gps` is NULL
 * @retval DRDC_E_RANGE before the GPS epoch, or past week
 *         DRDC_TIME_GPS_WEEK_MAX
 * @retval DRDC_E_NANOSECOND, DRDC_E_SECOND  invalid `utc`
 *
 * Accuracy: exact; checked against ERFA at every leap second and both
 * week rollovers (1999-08-22, 2019-04-07).
 */
drdc_status_t drdc_time_utc_to_gps(const drdc_time_leap_t *leap,
                                   const drdc_time_t *utc,
                                   drdc_time_gps_t *gps);

/**
 * GPS week and time of week -> UTC; inverse of drdc_time_utc_to_gps().
 *
 * @param leap leap state, NULL for the built-in one
 * @param gps  full week 0..DRDC_TIME_GPS_WEEK_MAX, TOW 0..604 799,
 *             nsec 0..999 999 999
 * @param[out] utc UTC instant (23:59:60 at a leap second); unchanged on
 *             error
 * @retval DRDC_OK written
 * @retval DRDC_W_LEAP_EXPIRED written; on or after the expiry day
 * @retval DRDC_E_NULL `gps` or `utc` is NULL
 * @retval DRDC_E_WEEK week negative or above DRDC_TIME_GPS_WEEK_MAX
 * @retval DRDC_E_TIME_OF_WEEK TOW negative or >= 604 800
 * @retval DRDC_E_NANOSECOND nsec out of range
 *
 * @code
 * drdc_time_gps_t g = { 1024, 0, 0 };  // the first rollover
 * drdc_time_t t;
 * drdc_time_gps_to_utc(NULL, &g, &t);  // 1999-08-21T23:59:47Z
 * @endcode
 */
drdc_status_t drdc_time_gps_to_utc(const drdc_time_leap_t *leap,
                                   const drdc_time_gps_t *gps,
                                   drdc_time_t *utc);

/**
 * Full GPS week from the 10-bit broadcast week, by a pivot date.
 *
 * The result is the first week on or after the pivot's GPS week that
 * equals `week10` modulo 1024, so a receiver whose pivot is, say, its
 * firmware's build date reads weeks right for 1024 weeks (19.6 years)
 * after it. The pivot's week is taken from its UTC day (a GPS week starts
 * 13..37 s before UTC Sunday midnight; a pivot is a date, not an instant).
 *
 * @param week10 broadcast week, 0..1023
 * @param pivot  valid UTC instant on or after 1980-01-06
 * @param[out] week full week; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `pivot` or `week` is NULL
 * @retval DRDC_E_WEEK `week10` outside 0..1023, or the result above
 *         DRDC_TIME_GPS_WEEK_MAX
 * @retval DRDC_E_RANGE the pivot is before the GPS epoch or invalid
 *
 * @code
 * // pivot 2020-01-01 (week 2086): broadcast week 0 -> 3072 (2038-11-21),
 * // broadcast week 38 -> 2086, broadcast week 37 -> 3109
 * @endcode
 */
drdc_status_t drdc_time_gps_week_resolve(int32_t week10,
                                         const drdc_time_t *pivot,
                                         int32_t *week);

/**
 * UTC -> Unix (POSIX) seconds since 1970-01-01T00:00:00Z.
 *
 * POSIX counts 86 400 s a day, so a leap second has no Unix value of its
 * own: 23:59:60.f maps to 00:00:00.f of the next day (the POSIX formula
 * of seconds since the epoch with tm_sec = 60), the same value as the
 * second after it. Every other instant maps one to one.
 *
 * @param leap leap state (validates 23:59:60), NULL for the built-in one
 * @param utc  valid UTC instant
 * @param[out] unix_time Unix count; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL, DRDC_E_RANGE, DRDC_E_NANOSECOND, DRDC_E_SECOND
 *         as drdc_time_check()
 */
drdc_status_t drdc_time_utc_to_unix(const drdc_time_leap_t *leap,
                                    const drdc_time_t *utc,
                                    drdc_time_count_t *unix_time);

/**
 * Unix seconds -> UTC. Never returns a leap second (see
 * drdc_time_utc_to_unix()).
 *
 * @param unix_time Unix count within years 1..9999, nsec 0..999 999 999
 * @param[out] utc UTC instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_NANOSECOND nsec out of range
 * @retval DRDC_E_RANGE outside the calendar
 */
drdc_status_t drdc_time_unix_to_utc(const drdc_time_count_t *unix_time,
                                    drdc_time_t *utc);

/**
 * UTC -> RTEMS seconds since 1988-01-01T00:00:00Z (POSIX style, 86 400 s
 * a day; a leap second maps as for drdc_time_utc_to_unix(), to the next
 * midnight). Negative before 1988.
 *
 * @param leap leap state (validates 23:59:60), NULL for the built-in one
 * @param utc  valid UTC instant
 * @param[out] rtems RTEMS count; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` or `rtems` is NULL
 * @retval DRDC_E_RANGE, DRDC_E_NANOSECOND, DRDC_E_SECOND invalid `utc`
 *         (drdc_time_check())
 *
 * Accuracy: exact; checked against Python's calendar.timegm.
 */
drdc_status_t drdc_time_utc_to_rtems(const drdc_time_leap_t *leap,
                                     const drdc_time_t *utc,
                                     drdc_time_count_t *rtems);

/**
 * RTEMS seconds since 1988-01-01 -> UTC. Never returns a leap second.
 *
 * @param rtems RTEMS count within years 1..9999, nsec 0..999 999 999
 * @param[out] utc UTC instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_NANOSECOND nsec out of range
 * @retval DRDC_E_RANGE outside the calendar
 */
drdc_status_t drdc_time_rtems_to_utc(const drdc_time_count_t *rtems,
                                     drdc_time_t *utc);

/** The RTEMS time-of-day record (the fields of rtems_time_of_day). */
typedef struct drdc_time_rtems_tod {
  uint32_t year;   /**< DRDC_TIME_RTEMS_YEAR_MIN..DRDC_YEAR_MAX */
  uint32_t month;  /**< 1..12 */
  uint32_t day;    /**< 1..days in the month */
  uint32_t hour;   /**< 0..23 */
  uint32_t minute; /**< 0..59 */
  uint32_t second; /**< 0..59 (RTEMS has no second 60) */
  uint32_t ticks;  /**< 0..ticks per second - 1 */
} drdc_time_rtems_tod_t;

/** RTEMS's time of day starts with its epoch year (TOD_BASE_YEAR). */
#define DRDC_TIME_RTEMS_YEAR_MIN 1988

/**
 * UTC -> RTEMS time of day.
 *
 * ticks = floor(nsec * ticks_per_second / 1e9): exact when
 * ticks_per_second divides 1e9, otherwise truncated toward the start of
 * the second. RTEMS's record has no second 60: a leap second maps as in
 * drdc_time_utc_to_unix(), to 00:00:00 of the next day.
 *
 * @param leap leap state, NULL for the built-in one
 * @param utc  valid UTC instant in 1988..9999
 * @param ticks_per_second 1..1 000 000 000
 * @param[out] tod record; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_TICKS ticks_per_second 0 or above 1e9
 * @retval DRDC_E_RANGE before 1988 or outside the calendar
 * @retval DRDC_E_NANOSECOND, DRDC_E_SECOND invalid `utc`
 */
drdc_status_t drdc_time_utc_to_rtems_tod(const drdc_time_leap_t *leap,
                                         const drdc_time_t *utc,
                                         uint32_t ticks_per_second,
                                         drdc_time_rtems_tod_t *tod);

/**
 * RTEMS time of day -> UTC (validated like RTEMS's _TOD_Validate).
 *
 * nsec = floor(ticks * 1e9 / ticks_per_second): exact when
 * ticks_per_second divides 1e9.
 *
 * @param tod record to convert
 * @param ticks_per_second 1..1 000 000 000
 * @param[out] utc instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_TICKS ticks_per_second 0 or above 1e9, or ticks >=
 *         ticks_per_second
 * @retval DRDC_E_YEAR year before 1988 or after DRDC_YEAR_MAX
 * @retval DRDC_E_MONTH, DRDC_E_DAY, DRDC_E_HOUR, DRDC_E_MINUTE
 *         field out of range
 * @retval DRDC_E_SECOND second above 59
 */
drdc_status_t drdc_time_rtems_tod_to_utc(const drdc_time_rtems_tod_t *tod,
                                         uint32_t ticks_per_second,
                                         drdc_time_t *utc);

/** @} */

#endif /* DRDC_TIME_SCALES_H */
