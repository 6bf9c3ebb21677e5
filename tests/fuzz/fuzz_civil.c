/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Differential fuzzer of the calendar: any three int32 (year,
 *        month, day) and any day count, against an independent model in
 *        double precision (Python-style floor arithmetic), which is exact
 *        for these magnitudes. Host only; doubles are fine here.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/time.h>

static int leap(double y)
{
  return (fmod(y, 4.0) == 0.0) &&
         ((fmod(y, 100.0) != 0.0) || (fmod(y, 400.0) == 0.0));
}

/* Days from 1970-01-01 by counting whole years and months: another method
 * than the library's era arithmetic. */
static double model_days(double y, double m, double d)
{
  static const double cum[12] = {0,   31,  59,  90,  120, 151,
                                 181, 212, 243, 273, 304, 334};
  double yy = y - 1.0;
  double days =
      365.0 * yy + floor(yy / 4.0) - floor(yy / 100.0) + floor(yy / 400.0);

  days += cum[(int)m - 1] + ((m > 2.0 && leap(y)) ? 1.0 : 0.0) + d - 1.0;
  return days - 719162.0; /* days from 0001-01-01 to 1970-01-01 */
}

static int valid(int32_t y, int32_t m, int32_t d)
{
  static const int32_t len[12] = {31, 28, 31, 30, 31, 30,
                                  31, 31, 30, 31, 30, 31};

  if (y < DRDC_YEAR_MIN || y > DRDC_YEAR_MAX || m < 1 || m > 12 || d < 1) {
    return 0;
  }
  return d <= len[m - 1] + ((m == 2 && leap((double)y)) ? 1 : 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  int32_t in[4] = {0, 0, 0, 0};
  int32_t days = 123;
  int32_t y = 7;
  int32_t m = 7;
  int32_t d = 7;
  drdc_status_t st;

  memcpy(in, data, size < sizeof in ? size : sizeof in);
  st = drdc_time_days_from_civil(in[0], in[1], in[2], &days);
  if (valid(in[0], in[1], in[2])) {
    if (st != DRDC_OK || (double)days != model_days(in[0], in[1], in[2])) {
      abort();
    }
  } else if (st == DRDC_OK || days != 123) {
    abort(); /* an error must leave the output alone */
  }
  st = drdc_time_civil_from_days(in[3], &y, &m, &d);
  if (in[3] >= DRDC_TIME_DAYS_MIN && in[3] <= DRDC_TIME_DAYS_MAX) {
    if (st != DRDC_OK || !valid(y, m, d) ||
        model_days(y, m, d) != (double)in[3]) {
      abort();
    }
  } else if (st != DRDC_E_RANGE || y != 7 || m != 7 || d != 7) {
    abort();
  }
  return 0;
}
