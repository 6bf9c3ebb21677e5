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

/* unit expressions: pairs of them converted (different dimensions give
 * their status), one with a byte changed parsed */
static const char *const expressions[] = {
    "km/h",
    "m/s",
    "kt",
    "N*m",
    "ft*lbf",
    "kg m/s^2",
    "lbf",
    "mAh",
    "C",
    "kWh",
    "J",
    "MeV",
    "psi",
    "kPa",
    "inHg",
    "rad/s",
    "rpm",
    "uT",
    "gauss",
    "(m/s)2",
    "m^2 s^-2",
    "degF",
    "K",
    "mph",
    "BTU/hr",
    "W",
    "kg/m^3",
    "g/cm3",
    "lightyear^2/ns",
    "h",
    "deg/s",
    "ft^3/min",
};

/* every field zero: what the digest reads after a failed parse */
static const drdc_nmea_t blank;

static size_t length_of(const char *s)
{
  size_t n = 0u;

  while (s[n] != '\0') {
    n++;
  }
  return n;
}

static void golden_expression(golden_t *g, const drdc_units_expr_t *e)
{
  size_t d;

  for (d = 0u; d < (size_t)DRDC_UNITS_DIMENSIONS; d++) {
    golden_i32(g, (int32_t)e->dimension[d]);
  }
  golden_i64(g, e->factor_num);
  golden_i64(g, e->factor_den);
  golden_i64(g, e->offset_num);
  golden_i32(g, (int32_t)e->rounded);
}

static void golden_expressions(golden_t *g)
{
  const size_t count = sizeof expressions / sizeof expressions[0];
  int i;

  for (i = 0; i < 512; i++) {
    const char *a = expressions[golden_next(g) % count];
    const char *b = expressions[golden_next(g) % count];
    int64_t raw = (int64_t)(int32_t)golden_next(g);
    drdc_units_expr_t from = {{0}, 1, 1, 0, 1, 0u};
    drdc_units_expr_t to = from;
    int64_t out = 0;
    char text[16];
    size_t n = length_of(a);
    size_t at;
    size_t k;

    golden_fn(g, "drdc_units_parse");
    golden_in_text(g, "text", a);
    golden_i32(g, (int32_t)drdc_units_parse(a, n, &from));
    golden_fn(g, "drdc_units_parse");
    golden_in_text(g, "text", b);
    golden_i32(g, (int32_t)drdc_units_parse(b, length_of(b), &to));
    golden_fn(g, "drdc_units_parse");
    golden_in_text(g, "text", a);
    golden_expression(g, &from);
    golden_fn(g, "drdc_units_convert_expr");
    golden_in(g, "raw_q16", raw);
    golden_in_text(g, "from", a);
    golden_in_text(g, "to", b);
    golden_i32(
        g, (int32_t)drdc_units_convert_expr(raw, 16u, &from, 16u, &to, &out));
    golden_i64(g, out);
    for (k = 0u; (k < n) && (k < sizeof text); k++) {
      text[k] = a[k];
    }
    at = (size_t)(golden_next(g) % k); /* one draw per statement, as above */
    text[at] = (char)(golden_next(g) & 0xFFu);
    golden_fn(g, "drdc_units_parse");
    golden_in_text(g, "text of", a);
    golden_in(g, "byte at", (int64_t)at);
    golden_in(g, "changed to", (unsigned char)text[at]);
    golden_i32(g, (int32_t)drdc_units_parse(text, k, &to));
    golden_expression(g, &to);
  }
}

void golden_interop(golden_t *g)
{
  size_t count = drdc_units_count();
  int i;

  for (i = 0; i < 2048; i++) {
    size_t from_index = (size_t)(golden_next(g) % count);
    size_t to_index = (size_t)(golden_next(g) % count);
    const drdc_unit_t *from = drdc_units_at(from_index);
    const drdc_unit_t *to = drdc_units_at(to_index);
    int64_t raw = (int64_t)(int32_t)golden_next(g);
    int64_t out = 0;
    int64_t integer = 0;
    char text[sizeof seed];
    drdc_nmea_t n = blank;
    drdc_jaus_type_t type;
    drdc_jaus_form_t form;
    size_t at;
    size_t k;

    golden_fn(g, "drdc_units_convert");
    golden_in(g, "raw_q16", raw);
    golden_in(g, "from unit number", (int64_t)from_index);
    golden_in(g, "to unit number", (int64_t)to_index);
    golden_i32(g, (int32_t)drdc_units_convert(raw, 16u, from, 16u, to, &out));
    golden_i64(g, out);
    /* one draw per statement: the order in which C evaluates the
     * arguments of a call differs between compilers and targets */
    type = (drdc_jaus_type_t)(golden_next(g) % 6u);
    form = (drdc_jaus_form_t)(golden_next(g) % 2u);
    golden_fn(g, "drdc_jaus_scaled_encode");
    golden_in(g, "value", raw);
    golden_in(g, "type", (int64_t)type);
    golden_in(g, "form", (int64_t)form);
    golden_i32(g, (int32_t)drdc_jaus_scaled_encode(raw, INT64_C(-2147483648),
                                                   INT64_C(2147483647), type,
                                                   form, &integer));
    golden_i64(g, integer);
    for (k = 0u; k < sizeof seed; k++) {
      text[k] = seed[k];
    }
    /* one byte replaced by any value, at any place */
    at = (size_t)(golden_next(g) % (sizeof seed - 1u));
    text[at] = (char)(golden_next(g) & 0xFFu);
    golden_fn(g, "drdc_nmea_parse");
    golden_in(g, "byte at", (int64_t)at);
    golden_in(g, "changed to", (unsigned char)text[at]);
    golden_i32(g, (int32_t)drdc_nmea_parse(text, sizeof seed - 1u, &n));
    golden_i64(g, n.latitude);
    golden_i64(g, n.altitude);
  }
  golden_expressions(g);
}
