/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Differential fuzzer of unit conversion: two table units and any
 *        raw value and formats, against a long double model of the exact
 *        rational result; and unit names of any bytes for the lookup.
 *        Host only; long double is fine here.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/units.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

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
      free(name);
    }
  }
  return 0;
}
