/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Differential fuzzer of unit conversion: two table units and any
 *        raw value and formats, against a long double model of the exact
 *        rational result; unit names of any bytes for the lookup; and the
 *        same bytes as a unit expression, whose result must keep the
 *        documented invariants and convert to itself exactly.
 *        Host only; long double is fine here.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/units.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The `n` bytes at `text` (a block of exactly that size, so ASan sees any
 * read past it) as a unit expression: on success a positive factor in
 * lowest terms, an offset only for a lone temperature, and a conversion
 * of any value to the expression itself that gives the value back; on
 * error the output unchanged. Then the same text in parentheses, which
 * must give the same factor whenever the depth allows it. */
static void check_expression(const char *text, size_t n, int64_t raw)
{
  drdc_units_expr_t e = {{0}, 7, 7, 7, 7, 7u};
  drdc_status_t st = drdc_units_parse(text, n, &e);
  int64_t out = 0;
  long double ratio;

  if (st != DRDC_OK) {
    if (e.factor_num != 7 || e.factor_den != 7 || e.rounded != 7u) {
      abort();
    }
    return;
  }
  if (n > DRDC_UNITS_EXPR_LENGTH_MAX || e.factor_num <= 0 ||
      e.factor_den <= 0 || e.offset_den <= 0 || e.rounded > 1u) {
    abort();
  }
  ratio = (long double)e.factor_num / (long double)e.factor_den;
  if (!(ratio > 0.0L) || !isfinite(ratio)) {
    abort();
  }
  if (e.offset_num == 0 &&
      drdc_units_convert_expr(raw, 16u, &e, 16u, &e, &out) != DRDC_OK) {
    abort();
  }
  if (e.offset_num == 0 && out != raw) {
    abort();
  }
  if (n + 2u <= DRDC_UNITS_EXPR_LENGTH_MAX && e.offset_num == 0) {
    char *wrapped = malloc(n + 2u);
    drdc_units_expr_t w = e;

    if (wrapped != NULL) {
      wrapped[0] = '(';
      memcpy(&wrapped[1], text, n);
      wrapped[n + 1u] = ')';
      st = drdc_units_parse(wrapped, n + 2u, &w);
      if (st == DRDC_OK &&
          (w.factor_num != e.factor_num || w.factor_den != e.factor_den)) {
        abort();
      }
      if (st != DRDC_OK && st != DRDC_E_RANGE) {
        abort();
      }
      free(wrapped);
    }
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  uint8_t in[12] = {0};
  size_t count = drdc_units_count();
  const drdc_unit_t *ua;
  const drdc_unit_t *ub;
  const drdc_unit_t *found = NULL;
  drdc_unit_info_t ia;
  drdc_unit_info_t ib;
  drdc_unit_info_t ifound;
  const drdc_unit_info_t *a = &ia;
  const drdc_unit_info_t *b = &ib;
  int64_t raw;
  int64_t out = 7;
  unsigned ff;
  unsigned tf;
  drdc_status_t st;
  char *name;

  memcpy(in, data, size < sizeof in ? size : sizeof in);
  ua = drdc_units_at(in[0] % count);
  ub = drdc_units_at(in[1] % count);
  if (drdc_units_describe(ua, &ia) != DRDC_OK ||
      drdc_units_describe(ub, &ib) != DRDC_OK) {
    abort();
  }
  ff = in[2] % 64u;
  tf = in[3] % 64u;
  memcpy(&raw, &in[4], sizeof raw);
  st = drdc_units_convert(raw, ff, ua, tf, ub, &out);
  if (st == DRDC_OK) {
    long double x =
        ((long double)raw / ldexpl(1.0L, (int)ff) +
         (long double)a->offset_num / (long double)a->offset_den) *
            (long double)a->factor_num / (long double)a->factor_den *
            (long double)b->factor_den / (long double)b->factor_num -
        (long double)b->offset_num / (long double)b->offset_den;
    long double want = x * ldexpl(1.0L, (int)tf);
    long double tol = 2.0L + fabsl(want) * ldexpl(1.0L, -56) +
                      (long double)b->offset_num / (long double)b->offset_den *
                          ldexpl(1.0L, (int)tf - 60);

    if (drdc_units_compatible(ua, ub) != DRDC_OK || ff > 62 || tf > 62 ||
        fabsl((long double)out - want) > tol) {
      abort();
    }
  } else if (out != 7) {
    abort();
  }
  /* lookup of the rest as a name, from a block of exactly its length */
  if (size > sizeof in) {
    size_t n = size - sizeof in;

    name = malloc(n);
    if (name != NULL) {
      memcpy(name, data + sizeof in, n);
      if (drdc_units_find(name, n, &found) == DRDC_OK &&
          (drdc_units_describe(found, &ifound) != DRDC_OK ||
           strlen(ifound.name) != n || memcmp(ifound.name, name, n) != 0)) {
        abort();
      }
      check_expression(name, n, raw);
      free(name);
    }
  }
  return 0;
}
