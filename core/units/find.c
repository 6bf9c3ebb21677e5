/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Look a unit up by name, reading exactly `length` characters.
 */
#include <drdc/units.h>

/* Whether the table name `s` (NUL-terminated) equals the `length`
 * characters of `name`; reads `name` only below `length`. */
static int name_equals(const char *s, const char *name, size_t length)
{
  size_t i = 0u;
  int equal = 1;

  while ((equal != 0) && (i < length)) {
    if ((s[i] == '\0') || (s[i] != name[i])) {
      equal = 0;
    }
    i++;
  }
  if ((equal != 0) && (s[length] != '\0')) {
    equal = 0;
  }
  return equal;
}

drdc_status_t drdc_units_find(const char *name, size_t length,
                              const drdc_unit_t **unit)
{
  size_t count = drdc_units_count();
  size_t i;

  if ((name == NULL) || (unit == NULL)) {
    return DRDC_E_NULL;
  }
  if (length == 0u) {
    return DRDC_E_UNKNOWN_UNIT;
  }
  for (i = 0u; i < count; i++) {
    const drdc_unit_t *u = drdc_units_at(i);

    if ((u != NULL) && (name_equals(u->name, name, length) != 0)) {
      *unit = u;
      return DRDC_OK;
    }
  }
  return DRDC_E_UNKNOWN_UNIT;
}
