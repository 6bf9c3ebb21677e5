/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of units, JAUS scaled integers and the
 *        NMEA parser (sentences with random bytes changed, so that every
 *        error path contributes its status too).
 */
#include <stddef.h>

#include <drdc/jaus_scaled.h>
#include <drdc/nmea.h>
#include <drdc/units.h>

#include "golden.h"

static const char seed[] = "$GNGGA,170001.00,5016.20050,N,11110.20080,W,4,12,0."
                           "7,754.4,M,-16.2,M,1.0,0001*6D\r\n";

/* every field zero: what the digest reads after a failed parse */
static const drdc_nmea_t blank;

void golden_interop(golden_t *g)
{
  size_t count = drdc_units_count();
  int i;

  for (i = 0; i < 2048; i++) {
    const drdc_unit_t *from = drdc_units_at(golden_next(g) % count);
    const drdc_unit_t *to = drdc_units_at(golden_next(g) % count);
    int64_t raw = (int64_t)(int32_t)golden_next(g);
    int64_t out = 0;
    int64_t integer = 0;
    char text[sizeof seed];
    drdc_nmea_t n = blank;
    drdc_jaus_type_t type;
    drdc_jaus_form_t form;
    size_t at;
    size_t k;

    golden_i32(g, (int32_t)drdc_units_convert(raw, 16u, from, 16u, to, &out));
    golden_i64(g, out);
    /* one draw per statement: the order in which C evaluates the
     * arguments of a call differs between compilers and targets */
    type = (drdc_jaus_type_t)(golden_next(g) % 6u);
    form = (drdc_jaus_form_t)(golden_next(g) % 2u);
    golden_i32(g, (int32_t)drdc_jaus_scaled_encode(raw, INT64_C(-2147483648),
                                                   INT64_C(2147483647), type,
                                                   form, &integer));
    golden_i64(g, integer);
    for (k = 0u; k < sizeof seed; k++) {
      text[k] = seed[k];
    }
    /* one byte replaced by any value, at any place */
    at = golden_next(g) % (sizeof seed - 1u);
    text[at] = (char)(golden_next(g) & 0xFFu);
    golden_i32(g, (int32_t)drdc_nmea_parse(text, sizeof seed - 1u, &n));
    golden_i64(g, n.latitude);
    golden_i64(g, n.altitude);
  }
}
