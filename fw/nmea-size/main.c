/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief What a GGA-only node links of the NMEA parser: built twice, with
 *        NMEA_SIZE_EVERY 1 (drdc_nmea_parse(), every sentence's decoder)
 *        and 0 (drdc_nmea_parse_some() with the GGA decoder alone); the
 *        bench reads both link maps (docs/performance.md).
 */
#include <stddef.h>

#include <drdc/nmea.h>

#include "console.h"
#include "drdc_board.h"

static const char gga[] = "$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,12,"
                          "0.7,754.3,M,-16.2,M,1.0,0001*66\r\n";

int main(void)
{
  drdc_nmea_t fix;
  drdc_status_t st;
#if NMEA_SIZE_EVERY
  st = drdc_nmea_parse(gga, sizeof gga - 1u, &fix);
#else
  static const drdc_nmea_decoder_t *const fixes[] = {&drdc_nmea_gga_decoder};

  st = drdc_nmea_parse_some(gga, sizeof gga - 1u, 0u, fixes, 1u, &fix);
#endif
  bsp_puts((st == DRDC_OK) ? "fix quality " : "no fix\n");
  if (st == DRDC_OK) {
    console_put_i64(fix.quality);
    bsp_putc('\n');
  }
  bsp_exit(st == DRDC_OK ? 0 : 1);
}
