/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_time_leap
 * @brief The built-in leap-second table (TAI - UTC since 1972) and the
 *        lookups every conversion shares.
 */
#include "time_impl.h"

/* TAI - UTC from IERS Bulletin C; `day` is days since 1970-01-01 of the
 * first UTC day with the offset (the leap second ends the day before). */
static const drdc_time_leap_entry_t
    builtin_table[DRDC_TIME_LEAP_BUILTIN_COUNT] = {
        {730, 10},   /* 1972-01-01: start of integer TAI-UTC */
        {912, 11},   /* 1972-07-01 */
        {1096, 12},  /* 1973-01-01 */
        {1461, 13},  /* 1974-01-01 */
        {1826, 14},  /* 1975-01-01 */
        {2191, 15},  /* 1976-01-01 */
        {2557, 16},  /* 1977-01-01 */
        {2922, 17},  /* 1978-01-01 */
        {3287, 18},  /* 1979-01-01 */
        {3652, 19},  /* 1980-01-01 */
        {4199, 20},  /* 1981-07-01 */
        {4564, 21},  /* 1982-07-01 */
        {4929, 22},  /* 1983-07-01 */
        {5660, 23},  /* 1985-07-01 */
        {6574, 24},  /* 1988-01-01 */
        {7305, 25},  /* 1990-01-01 */
        {7670, 26},  /* 1991-01-01 */
        {8217, 27},  /* 1992-07-01 */
        {8582, 28},  /* 1993-07-01 */
        {8947, 29},  /* 1994-07-01 */
        {9496, 30},  /* 1996-01-01 */
        {10043, 31}, /* 1997-07-01 */
        {10592, 32}, /* 1999-01-01 */
        {13149, 33}, /* 2006-01-01 */
        {14245, 34}, /* 2009-01-01 */
        {15522, 35}, /* 2012-07-01 */
        {16617, 36}, /* 2015-07-01 */
        {17167, 37}, /* 2017-01-01 */
};

static const drdc_time_leap_t builtin_state = {
    builtin_table,
    DRDC_TIME_LEAP_BUILTIN_COUNT,
    0,
    {[0] = {0, 0}}, /* no entries learnt: all zero */
    DRDC_TIME_LEAP_BUILTIN_EXPIRY_DAY,
};

const drdc_time_leap_t *drdc_time_leap_builtin(void)
{
  return &builtin_state;
}

const drdc_time_leap_t *drdc_time_leap_or_builtin(const drdc_time_leap_t *l)
{
  return (l != NULL) ? l : &builtin_state;
}

int32_t drdc_time_leap_count(const drdc_time_leap_t *l)
{
  return l->table_count + l->extra_count;
}

drdc_time_leap_entry_t drdc_time_leap_entry(const drdc_time_leap_t *l,
                                            int32_t i)
{
  return (i < l->table_count) ? l->table[i] : l->extra[i - l->table_count];
}

int32_t drdc_time_leap_index(const drdc_time_leap_t *l, int32_t day)
{
  int32_t i = drdc_time_leap_count(l) - 1;

  /* Newest first: most instants a controller converts are recent. */
  while ((i >= 0) && (drdc_time_leap_entry(l, i).day > day)) {
    i--;
  }
  return i;
}

int drdc_time_leap_day_end(const drdc_time_leap_t *leap, int32_t day)
{
  const drdc_time_leap_t *l = drdc_time_leap_or_builtin(leap);
  int32_t i;
  drdc_time_leap_entry_t next;

  if (day >= INT32_MAX) {
    return 0;
  }
  i = drdc_time_leap_index(l, day + 1);
  /* The day ends with a leap second when the next day starts an entry
   * that is not the first (1972-01-01 was a fractional step). */
  if (i < 1) {
    return 0;
  }
  next = drdc_time_leap_entry(l, i);
  if (next.day != (day + 1)) {
    return 0;
  }
  return (next.tai_utc > drdc_time_leap_entry(l, i - 1).tai_utc) ? 1 : -1;
}
