/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_leap
 * @brief Leap seconds: the built-in TAI-UTC table and the caller-owned
 *        leap-second state, updated at run time from GPS UTC parameters.
 */
#ifndef DRDC_TIME_LEAP_H
#define DRDC_TIME_LEAP_H

#include <stdint.h>

#include <drdc/types.h>

/**
 * @defgroup drdc_time_leap Leap seconds
 *
 * UTC has had an integer offset from TAI since 1972-01-01 (10 s then); a
 * leap second at the end of a UTC day changes it by one second. The
 * library keeps no global state: every function that needs TAI-UTC takes
 * a `const drdc_time_leap_t *`. NULL there means the built-in state,
 * drdc_time_leap_builtin(): the const table of the 28 TAI-UTC values
 * 1972-01-01 (10 s) .. 2017-01-01 (37 s), valid until
 * DRDC_TIME_LEAP_BUILTIN_EXPIRY_DAY.
 *
 * Firmware fed by a GPS receiver keeps its own copy, started with
 * drdc_time_leap_init() and refreshed with drdc_time_leap_update_gps()
 * whenever the receiver decodes the UTC parameters (subframe 4 page 18 of
 * the legacy navigation message), so that leap seconds announced after
 * the build are honoured without a new build.
 *
 * Past the expiry day the last known offset is used and the conversions
 * return the warning DRDC_W_LEAP_EXPIRED (outputs written): the result is
 * right unless a leap second nobody told us about has happened since.
 * @{
 */

/** Days since 1970-01-01 of 1972-01-01, the first day of integer
 *  TAI-UTC (earlier instants have no integer offset: DRDC_E_RANGE). */
#define DRDC_TIME_LEAP_FIRST_DAY INT32_C(730)

/**
 * Expiry of the built-in table: days since 1970-01-01 of 2027-06-28.
 *
 * IERS Bulletin C 72 (July 2026), the latest known here, announced no
 * leap second at the end of December 2026; the next possible one is at
 * the end of June 2027, and the IERS leap-second file issued with that
 * bulletin (Leap_Second.dat, "File expires on 28 June 2027") gives this
 * day. The test suite checks it against that file as shipped in the
 * pinned astropy-iers-data package. From this day on, conversions return
 * DRDC_W_LEAP_EXPIRED.
 */
#define DRDC_TIME_LEAP_BUILTIN_EXPIRY_DAY INT32_C(20997)

/** Number of entries of the built-in table (1972-01-01 .. 2017-01-01). */
#define DRDC_TIME_LEAP_BUILTIN_COUNT 28

/** Room for leap seconds learnt at run time, beyond the built-in table.
 *  At the historical rate (27 in 45 years) eight last decades. */
#define DRDC_TIME_LEAP_EXTRA_MAX 8

/** One step of TAI-UTC: from the start of UTC day `day` the offset is
 *  `tai_utc`. The leap second is at the end of day `day - 1`, positive
 *  when the offset grows by one, negative when it falls by one. */
typedef struct drdc_time_leap_entry {
  int32_t day;     /**< days since 1970-01-01 of the first day */
  int32_t tai_utc; /**< TAI - UTC from that day on, seconds */
} drdc_time_leap_entry_t;

/**
 * Leap-second state: the built-in table plus entries learnt at run time,
 * and the day the knowledge ends. Owned by the caller; treat the fields
 * as read-only and change them only through the functions below.
 */
typedef struct drdc_time_leap {
  const drdc_time_leap_entry_t *table; /**< the built-in const table */
  int32_t table_count;                 /**< entries in `table` */
  int32_t extra_count;                 /**< entries used in `extra` */
  /** entries learnt at run time, after the last of `table`, in order */
  drdc_time_leap_entry_t extra[DRDC_TIME_LEAP_EXTRA_MAX];
  /** days since 1970-01-01 of the first day the offset is not known for:
   *  conversions on or after it return DRDC_W_LEAP_EXPIRED */
  int32_t expiry_day;
} drdc_time_leap_t;

/**
 * The built-in leap-second state (what a NULL state argument means).
 *
 * @return a pointer to a const object; never NULL.
 */
const drdc_time_leap_t *drdc_time_leap_builtin(void);

/**
 * Start a caller-owned state from the built-in table.
 *
 * @param[out] leap state to initialise
 * @retval DRDC_OK     `*leap` is a copy of the built-in state
 * @retval DRDC_E_NULL `leap` is NULL
 */
drdc_status_t drdc_time_leap_init(drdc_time_leap_t *leap);

/**
 * Update a state from the UTC parameters a GPS satellite broadcasts
 * (IS-GPS-200, 20.3.3.5.1.6: delta t_LS, WN_LSF, DN, delta t_LSF).
 *
 * The leap second they describe lies at the end of the UTC day that is
 * day DN (1 = Sunday .. 7 = Saturday) of GPS week WN_LSF; WN_LSF is sent
 * modulo 256 and resolved to the full week nearest to `week_now` (within
 * -128..+127 weeks, as the interface specification requires).
 *
 * - delta t_LSF = delta t_LS +-1: a leap second is scheduled (or has just
 *   happened); an entry with TAI-UTC = 19 + delta t_LSF from the next day
 *   is added when the state does not have it yet.
 * - delta t_LSF = delta t_LS: no leap second scheduled. If TAI-UTC = 19 +
 *   delta t_LS is one more or one less than the state's last offset, the
 *   broadcast event is the leap second that made it so and is added.
 *
 * An event the state already holds is accepted again. The expiry day then
 * becomes the later of the old one, the day after the event and the day
 * after week `week_now` ends: the broadcast is current for that week.
 *
 * @param[in,out] leap state to update; unchanged on error
 * @param week_now full GPS week of the time the parameters were received,
 *        0..DRDC_TIME_GPS_WEEK_MAX (from the receiver's clock)
 * @param dt_ls   delta t_LS: GPS - UTC now, seconds, -128..127 (int8)
 * @param wn_lsf  WN_LSF: week of the event modulo 256, 0..255
 * @param dn      DN: day of the event within that week, 1..7
 * @param dt_lsf  delta t_LSF: GPS - UTC after the event, seconds, -128..127
 *
 * @retval DRDC_OK          state updated (or confirmed)
 * @retval DRDC_E_NULL      `leap` is NULL
 * @retval DRDC_E_WEEK      `week_now` out of range
 * @retval DRDC_E_LEAP_TABLE a parameter is out of its field's range, the
 *         two offsets differ by more than one second, or the event
 *         contradicts the state (an earlier date than a known leap second
 *         with a different offset, or an offset that does not follow the
 *         state's last one)
 * @retval DRDC_E_OVERFLOW  the event is new but `extra` is full
 *
 * @code
 * drdc_time_leap_t leap;
 * drdc_time_leap_init(&leap);
 * // the broadcast of early 2017: 18 s, event week 1929 (mod 256 = 137),
 * // day 7, 18 s: confirms 2017-01-01 and extends the expiry
 * drdc_time_leap_update_gps(&leap, 1930, 18, 137, 7, 18);
 * @endcode
 */
drdc_status_t drdc_time_leap_update_gps(drdc_time_leap_t *leap,
                                        int32_t week_now, int32_t dt_ls,
                                        int32_t wn_lsf, int32_t dn,
                                        int32_t dt_lsf);

/**
 * TAI - UTC in force at a UTC instant.
 *
 * During a positive leap second (nsec >= 1e9) the offset of the day that
 * ends with it is returned (the new offset starts at the next midnight).
 *
 * @param leap leap state, NULL for the built-in one
 * @param utc  a valid UTC instant on or after 1972-01-01
 * @param[out] tai_utc offset in seconds; unchanged on error
 *
 * @retval DRDC_OK      `*tai_utc` written
 * @retval DRDC_W_LEAP_EXPIRED the instant is on or after the state's
 *         expiry day; the last known offset was written
 * @retval DRDC_E_NULL  `utc` or `tai_utc` is NULL
 * @retval DRDC_E_RANGE the instant is before 1972-01-01 or outside the
 *         calendar range
 * @retval DRDC_E_NANOSECOND, DRDC_E_SECOND  `utc` is not a valid instant
 *         (see drdc_time_check())
 *
 * Accuracy: exact; checked against ERFA's eraDat for every table entry.
 */
drdc_status_t drdc_time_leap_offset(const drdc_time_leap_t *leap,
                                    const drdc_time_t *utc, int32_t *tai_utc);

/**
 * Whether UTC day `day` ends with a leap second, by a leap state.
 *
 * @param leap leap state, NULL for the built-in one
 * @param day  days since 1970-01-01, any value
 * @return +1 when the day ends with a positive leap second (has 23:59:60),
 *         -1 when with a negative one (has no 23:59:59), 0 otherwise
 *         (including days past the expiry: a leap second not in the state
 *         is not known to exist).
 */
int drdc_time_leap_day_end(const drdc_time_leap_t *leap, int32_t day);

/** @} */

#endif /* DRDC_TIME_LEAP_H */
