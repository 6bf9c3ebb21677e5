/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Demo firmware: what the library computes, printed on the board
 *        console. For now the calendar slice; the pose-node demo grows here
 *        with the time, orientation, geodesy and interop modules.
 */
#include <drdc/time.h>
#include <drdc/version.h>

#include "bsp.h"
#include "console.h"

/* Dates every robot clock meets: the epochs of the time scales it
 * converts between, and the days that test calendar code. */
static const struct {
  const char *what;
  int32_t year, month, day;
} dates[] = {
  { "Unix epoch      ", 1970, 1, 1 },
  { "GPS epoch       ", 1980, 1, 6 },
  { "RTEMS epoch     ", 1988, 1, 1 },
  { "leap day 2000   ", 2000, 2, 29 },
  { "Y2038 (int32)   ", 2038, 1, 19 },
  { "no leap day 2100", 2100, 2, 29 },
};

static void put_date(int32_t y, int32_t m, int32_t d)
{
  console_put_i64(y);
  bsp_putc('-');
  if (m < 10) {
    bsp_putc('0');
  }
  console_put_i64(m);
  bsp_putc('-');
  if (d < 10) {
    bsp_putc('0');
  }
  console_put_i64(d);
}

int main(void)
{
  unsigned i;

  bsp_puts("libdrdc-fx " DRDC_VERSION_STRING " demo on ");
  bsp_puts(bsp_name);
  bsp_puts(": integer-only calendar (days since 1970-01-01)\n");
  for (i = 0; i < sizeof dates / sizeof dates[0]; i++) {
    int32_t days = 0;
    drdc_status_t st = drdc_time_days_from_civil(dates[i].year, dates[i].month,
                                                 dates[i].day, &days);

    bsp_puts("  ");
    bsp_puts(dates[i].what);
    bsp_puts("  ");
    put_date(dates[i].year, dates[i].month, dates[i].day);
    bsp_puts("  -> ");
    if (st == DRDC_OK) {
      int32_t y = 0;
      int32_t m = 0;
      int32_t d = 0;

      console_put_i64(days);
      (void)drdc_time_civil_from_days(days, &y, &m, &d);
      bsp_puts(" days -> ");
      put_date(y, m, d);
    } else {
      bsp_puts(drdc_status_name(st));
    }
    bsp_putc('\n');
  }
  return 0;
}
