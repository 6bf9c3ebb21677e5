/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_rtems
 * @brief RTEMS glue: the library's UTC time and the RTEMS clock.
 */
#ifndef DRDC_RTEMS_H
#define DRDC_RTEMS_H

#include <rtems.h>
#include <time.h>

#include <drdc/time.h>
#include <drdc/time_leap.h>

/**
 * @defgroup drdc_rtems RTEMS glue
 *
 * Conversions between drdc_time_t (UTC, leap seconds included) and the
 * RTEMS clock: the Classic API rtems_time_of_day (ticks with the
 * system's ticks per second) and the POSIX struct timespec of
 * CLOCK_REALTIME. RTEMS keeps POSIX time, which has no second 60: a leap
 * second maps to 00:00:00 of the next day, as drdc_time_utc_to_unix()
 * documents, and RTEMS time never gives back a leap second.
 * Compiled only for RTEMS BSPs.
 * @{
 */

/**
 * UTC of an RTEMS time of day.
 *
 * @param tod   RTEMS time of day (year 1988..9999, ticks below
 *              rtems_clock_get_ticks_per_second())
 * @param[out] utc UTC instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL an argument is NULL
 * @retval others as drdc_time_rtems_tod_to_utc()
 */
drdc_status_t drdc_rtems_utc_from_tod(const rtems_time_of_day *tod,
                                      drdc_time_t *utc);

/**
 * RTEMS time of day of a UTC instant (ticks truncated).
 *
 * @param leap leap-second state, NULL for the built-in one
 * @param utc  valid UTC instant in 1988..9999
 * @param[out] tod RTEMS time of day; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` or `tod` is NULL
 * @retval others as drdc_time_utc_to_rtems_tod()
 */
drdc_status_t drdc_rtems_tod_from_utc(const drdc_time_leap_t *leap,
                                      const drdc_time_t *utc,
                                      rtems_time_of_day *tod);

/**
 * UTC of a CLOCK_REALTIME timespec (POSIX seconds since 1970).
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL an argument is NULL
 * @retval DRDC_E_NANOSECOND tv_nsec outside 0..999 999 999
 * @retval others as drdc_time_unix_to_utc()
 */
drdc_status_t drdc_rtems_utc_from_timespec(const struct timespec *ts,
                                           drdc_time_t *utc);

/**
 * CLOCK_REALTIME timespec of a UTC instant.
 *
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` or `ts` is NULL
 * @retval DRDC_E_OVERFLOW the seconds do not fit this target's time_t
 * @retval others as drdc_time_utc_to_unix()
 */
drdc_status_t drdc_rtems_timespec_from_utc(const drdc_time_leap_t *leap,
                                           const drdc_time_t *utc,
                                           struct timespec *ts);

/**
 * The RTEMS real-time clock as UTC.
 *
 * @param[out] utc UTC now; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `utc` is NULL
 * @retval DRDC_E_RANGE the clock is not set (rtems_clock_get_tod() failed)
 */
drdc_status_t drdc_rtems_clock_get_utc(drdc_time_t *utc);

/**
 * Set the RTEMS real-time clock from UTC (for example from a GNSS fix).
 *
 * @retval DRDC_OK set
 * @retval DRDC_E_NULL `utc` is NULL
 * @retval DRDC_E_RANGE RTEMS refused the time of day
 * @retval others as drdc_rtems_tod_from_utc()
 */
drdc_status_t drdc_rtems_clock_set_utc(const drdc_time_leap_t *leap,
                                       const drdc_time_t *utc);

/** @} */

#endif /* DRDC_RTEMS_H */
