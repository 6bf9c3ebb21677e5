/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_leap
 * @brief Run-time update of the caller-owned leap-second state from GPS
 *        UTC parameters: apart from leap.c, whose TAI-UTC lookup is on
 *        the timed conversions, so that it can be compiled for flash.
 */
#include <drdc/time_scales.h>

#include <stdbool.h>

#include "time_impl.h"

/* Field ranges of the GPS UTC parameters (IS-GPS-200 table 20-IX):
 * delta t_LS and delta t_LSF are 8-bit two's complement, WN_LSF 8 bits
 * (the full week modulo 256), DN 1..7. */
#define GPS_DT_MIN         (-128)
#define GPS_DT_MAX         127
#define GPS_WN_LSF_MODULUS 256
#define GPS_WN_LSF_HALF    128

static int32_t max32(int32_t a, int32_t b)
{
  return (a > b) ? a : b;
}

drdc_status_t drdc_time_leap_update_gps(drdc_time_leap_t *leap,
                                        int32_t week_now, int32_t dt_ls,
                                        int32_t wn_lsf, int32_t dn,
                                        int32_t dt_lsf)
{
  drdc_time_leap_entry_t last;
  int32_t expiry;
  int32_t delta;
  int32_t week;
  int32_t entry_day;
  int32_t new_off;
  int32_t prev_off;
  bool add = false;

  if (leap == NULL) {
    return DRDC_E_NULL;
  }
  if ((week_now < 0) || (week_now > DRDC_TIME_GPS_WEEK_MAX)) {
    return DRDC_E_WEEK;
  }
  if ((dt_ls < GPS_DT_MIN) || (dt_ls > GPS_DT_MAX) || (dt_lsf < GPS_DT_MIN) ||
      (dt_lsf > GPS_DT_MAX) || (wn_lsf < 0) || (wn_lsf >= GPS_WN_LSF_MODULUS) ||
      (dn < 1) || (dn > 7) || ((dt_lsf - dt_ls) > 1) ||
      ((dt_lsf - dt_ls) < -1)) {
    return DRDC_E_LEAP_TABLE;
  }
  /* WN_LSF is within -128..+127 weeks of the current week: the difference
   * of the low 8 bits, brought into that window. Both terms are 0..255,
   * so the sum below is 129..639 before the remainder: never negative. */
  delta = (((wn_lsf - (week_now % GPS_WN_LSF_MODULUS)) + GPS_WN_LSF_MODULUS +
            GPS_WN_LSF_HALF) %
           GPS_WN_LSF_MODULUS) -
          GPS_WN_LSF_HALF;
  week = week_now + delta;
  if (week < 0) {
    return DRDC_E_LEAP_TABLE;
  }
  /* The leap second ends GPS day DN (1 = Sunday) of that week; the new
   * offset starts the next UTC day. week <= WEEK_MAX + 127: no overflow. */
  entry_day = DAYS_1970_TO_GPS + (week * 7) + dn;

  /* Validate everything before the first write: on error the state is
   * unchanged. */
  last = drdc_time_leap_entry(leap, drdc_time_leap_count(leap) - 1);
  expiry = leap->expiry_day;
  new_off = TAI_MINUS_GPS + dt_lsf;
  prev_off = TAI_MINUS_GPS + dt_ls;
  if (dt_lsf == dt_ls) {
    /* Nothing scheduled; the event fields name the last leap second. */
    if (new_off != last.tai_utc) {
      if (((new_off - last.tai_utc) != 1) && ((new_off - last.tai_utc) != -1)) {
        return DRDC_E_LEAP_TABLE;
      }
      prev_off = last.tai_utc;
      add = true;
    }
  } else {
    add = true;
  }
  if (add) {
    if (entry_day <= last.day) {
      /* A known event: it must be exactly one of the state's entries. */
      drdc_time_leap_entry_t e =
          drdc_time_leap_entry(leap, drdc_time_leap_index(leap, entry_day));

      if ((e.day != entry_day) || (e.tai_utc != new_off)) {
        return DRDC_E_LEAP_TABLE;
      }
    } else {
      if (prev_off != last.tai_utc) {
        return DRDC_E_LEAP_TABLE; /* does not follow the known offset */
      }
      if (leap->extra_count >= DRDC_TIME_LEAP_EXTRA_MAX) {
        return DRDC_E_OVERFLOW;
      }
      leap->extra[leap->extra_count].day = entry_day;
      leap->extra[leap->extra_count].tai_utc = new_off;
      leap->extra_count++;
    }
    expiry = max32(expiry, entry_day);
  }
  /* The broadcast is current through the end of week_now. */
  leap->expiry_day = max32(expiry, DAYS_1970_TO_GPS + ((week_now + 1) * 7));
  return DRDC_OK;
}
