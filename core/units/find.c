/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Look a unit up by name, reading exactly `length` characters;
 *        decode a unit's row.
 */
#include "units_impl.h"

/* Whether the table name at `s` (NUL-terminated) equals the `length`
 * characters of `name` (read only below `length`); `*next` is set to the
 * name after it. One pass over the table name, none past `length` in
 * `name`. */
static int name_equals(const char *s, const char *name, size_t length,
                       const char **next)
{
  size_t i = 0u;
  int equal = 1;

  while (s[i] != '\0') {
    if ((i >= length) || (s[i] != name[i])) {
      equal = 0;
    }
    i++;
  }
  if (i != length) {
    equal = 0;
  }
  *next = &s[i + 1u];
  return equal;
}

drdc_status_t drdc_units_find(const char *name, size_t length,
                              const drdc_unit_t **unit)
{
  size_t count = drdc_units_count();
  const char *s = drdc__units_names_first();
  size_t i;

  if ((name == NULL) || (unit == NULL)) {
    return DRDC_E_NULL;
  }
  if (length == 0u) {
    return DRDC_E_UNKNOWN_UNIT;
  }
  for (i = 0u; i < count; i++) {
    const char *next = s;

    if (name_equals(s, name, length, &next) != 0) {
      *unit = drdc_units_at(i);
      return DRDC_OK;
    }
    s = next;
  }
  return DRDC_E_UNKNOWN_UNIT;
}

drdc_status_t drdc_units_describe(const drdc_unit_t *unit,
                                  drdc_unit_info_t *info)
{
  const char *s = drdc__units_names_first();
  size_t row;
  size_t i = 0u;
  units_rat_t offset;

  if ((unit == NULL) || (info == NULL)) {
    return DRDC_E_NULL;
  }
  row = drdc__units_index(unit);
  if (row >= drdc_units_count()) {
    return DRDC_E_UNKNOWN_UNIT;
  }
  /* the row's name follows `row` NULs */
  while (row > 0u) {
    if (s[i] == '\0') {
      row--;
    }
    i++;
  }
  info->name = &s[i];
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    info->dimension[i] = drdc__units_dimension(unit, i);
  }
  info->factor_num = drdc__units_number(unit->factor_num);
  info->factor_den = drdc__units_number(unit->factor_den);
  offset = drdc__units_offset(unit);
  info->offset_num = offset.num;
  info->offset_den = offset.den;
  return DRDC_OK;
}
