/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief Unit expressions: products, quotients, powers, parentheses and
 *        SI prefixes over the unit table, parsed without recursion.
 */
#include "units_impl.h"

/* Parentheses open a level each; level 0 is the whole expression. */
#define EXPR_LEVELS (DRDC_UNITS_EXPR_DEPTH_MAX + 1u)

/* Largest dimension exponent (int8_t). */
#define EXPR_DIMENSION_MAX 127

/* 10^18, the largest power of ten of int64_t: prefixes beyond it are
 * applied in two steps. */
#define EXPR_POW10_STEP 18

/*
 * A running product may leave the 2^+-61 that a rational of int64_t
 * holds (`parsec^2/lightyear^2` passes 9.5e32 on its way to 10.6), so a
 * level and a factor carry a binary scale beside their rational: the
 * value is rational x 2^(UNITS_SCALE_BITS x scale), the scale in steps
 * of 32 bits in an int8_t, which fills the structs' padding (the levels
 * live on the stack of drdc_units_parse(), within its 512-byte budget).
 * drdc__units_rat_mul() moves steps into the scale only where the
 * product has no rational form, so an expression whose running products
 * fit keeps the factor it had without the scale.
 */

/* An SI prefix: its spelling (NUL-terminated) and power of ten. */
typedef struct expr_prefix {
  const char *text;
  int8_t exponent;
} expr_prefix_t;

/* One level of the expression: the product so far, and whether the
 * current term (after a `/`) divides. */
typedef struct expr_level {
  units_rat_t factor; /* times 2^(UNITS_SCALE_BITS x scale) */
  int8_t dimension[DRDC_UNITS_DIMENSIONS];
  uint8_t divide;
  int8_t scale;
} expr_level_t;

/* A factor before its power: the SI value num / den (> 0) and the
 * dimension. */
typedef struct expr_factor {
  units_rat_t value; /* times 2^(UNITS_SCALE_BITS x scale) */
  int8_t dimension[DRDC_UNITS_DIMENSIONS];
  int8_t scale;
} expr_factor_t;

static int is_blank(char c)
{
  return (c == ' ') || (c == '\t');
}

static int expr_is_digit(char c)
{
  return (c >= '0') && (c <= '9');
}

/* Letters, `_` and the bytes of UTF-8 sequences (the micro sign). */
static int is_name_char(char c)
{
  unsigned char u = (unsigned char)c;

  return ((u >= (unsigned char)'a') && (u <= (unsigned char)'z')) ||
         ((u >= (unsigned char)'A') && (u <= (unsigned char)'Z')) ||
         (c == '_') || (u >= 0x80u);
}

static void level_start(expr_level_t *level)
{
  size_t i;

  level->factor.num = 1;
  level->factor.den = 1;
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    level->dimension[i] = 0;
  }
  level->divide = 0u;
  level->scale = 0;
}

/* *scale + add, DRDC_E_OVERFLOW beyond +-UNITS_SCALE_MAX. */
static drdc_status_t scale_add(int8_t *scale, int add)
{
  int sum = (int)*scale + add;

  if ((sum > UNITS_SCALE_MAX) || (sum < -UNITS_SCALE_MAX)) {
    return DRDC_E_OVERFLOW;
  }
  *scale = (int8_t)sum;
  return DRDC_OK;
}

/* value x 2^(UNITS_SCALE_BITS x steps), one exact step at a time;
 * DRDC_E_OVERFLOW when a step leaves what a rational holds. */
static drdc_status_t rat_shift(units_rat_t *value, int steps, uint8_t *rounded)
{
  const int64_t step = (int64_t)(UINT64_C(1) << UNITS_SCALE_BITS);
  int left = (steps < 0) ? -steps : steps;

  while (left > 0) {
    int64_t num = (steps > 0) ? step : 1;
    int64_t den = (steps > 0) ? 1 : step;

    if (drdc__units_rat_mul(value, num, den, value, NULL, rounded) != DRDC_OK) {
      return DRDC_E_OVERFLOW;
    }
    left--;
  }
  return DRDC_OK;
}

/* level x factor^power, the power negated when the level's current term
 * divides. DRDC_E_RANGE for a dimension exponent beyond +-127,
 * DRDC_E_OVERFLOW for a scale beyond +-UNITS_SCALE_MAX steps. */
static drdc_status_t level_apply(expr_level_t *level,
                                 const expr_factor_t *factor, int power,
                                 uint8_t *rounded)
{
  int p = (level->divide != 0u) ? -power : power;
  int n = (p < 0) ? -p : p;
  int64_t num = (p < 0) ? factor->value.den : factor->value.num;
  int64_t den = (p < 0) ? factor->value.num : factor->value.den;
  size_t i;

  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    int d = (int)level->dimension[i] + (p * (int)factor->dimension[i]);

    if ((d > EXPR_DIMENSION_MAX) || (d < -EXPR_DIMENSION_MAX)) {
      return DRDC_E_RANGE;
    }
  }
  /* the factor's own scale, n times (at most 9 x 127 steps) */
  if (scale_add(&level->scale, n * ((p < 0) ? -(int)factor->scale
                                            : (int)factor->scale)) != DRDC_OK) {
    return DRDC_E_OVERFLOW;
  }
  while (n > 0) {
    if (drdc__units_rat_mul(&level->factor, num, den, &level->factor,
                            &level->scale, rounded) != DRDC_OK) {
      return DRDC_E_OVERFLOW;
    }
    n--;
  }
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    level->dimension[i] =
        (int8_t)((int)level->dimension[i] + (p * (int)factor->dimension[i]));
  }
  return DRDC_OK;
}

/* An optional power at text[*at]: `^` [+-] digits, or digits directly.
 * *power is 1 when there is none. */
static drdc_status_t read_power(const char *text, size_t length, size_t *at,
                                int *power)
{
  size_t i = *at;
  int negative = 0;
  int value = 0;
  size_t digits = 0u;

  if ((i < length) && (text[i] == '^')) {
    i++;
    if ((i < length) && ((text[i] == '-') || (text[i] == '+'))) {
      if (text[i] == '-') {
        negative = 1;
      }
      i++;
    }
    if ((i >= length) || !expr_is_digit(text[i])) {
      return DRDC_E_SYNTAX;
    }
  }
  while ((i < length) && expr_is_digit(text[i])) {
    if (value <= DRDC_UNITS_EXPR_POWER_MAX) {
      value = (value * 10) + ((int)text[i] - (int)'0');
    }
    digits++;
    i++;
  }
  if (digits == 0u) {
    value = 1;
  }
  if (value > DRDC_UNITS_EXPR_POWER_MAX) {
    return DRDC_E_RANGE;
  }
  *power = (negative != 0) ? -value : value;
  *at = i;
  return DRDC_OK;
}

/* The `length` characters at `text` equal the NUL-terminated `word`
 * for its whole length, and the name is longer than it. */
static int starts_with(const char *text, size_t length, const char *word,
                       size_t *word_length)
{
  size_t i = 0u;

  while ((word[i] != '\0') && (i < length) && (text[i] == word[i])) {
    i++;
  }
  *word_length = i;
  return (word[i] == '\0') && (i < length);
}

/* A name: the whole name in the table, else the first prefix followed
 * by a unit that takes prefixes. *exponent gets the prefix's power of
 * ten (0 for a whole name). */
static drdc_status_t find_name(const char *name, size_t length,
                               const drdc_unit_t **unit, int *exponent)
{
  /* The order of the search: words first (`milli`, not `m` + `illi...`),
   * `da` before `d`, then the micro signs (UTF-8 of U+00B5 and U+03BC),
   * then single letters. The first prefix after which the rest of the name
   * is a unit that takes prefixes wins. */
  static const expr_prefix_t expr_prefixes[] = {
      {"yotta", 24},  {"zetta", 21},  {"exa", 18},      {"peta", 15},
      {"tera", 12},   {"giga", 9},    {"mega", 6},      {"kilo", 3},
      {"hecto", 2},   {"deka", 1},    {"deca", 1},      {"deci", -1},
      {"centi", -2},  {"milli", -3},  {"micro", -6},    {"nano", -9},
      {"pico", -12},  {"femto", -15}, {"atto", -18},    {"zepto", -21},
      {"yocto", -24}, {"da", 1},      {"\xC2\xB5", -6}, {"\xCE\xBC", -6},
      {"Y", 24},      {"Z", 21},      {"E", 18},        {"P", 15},
      {"T", 12},      {"G", 9},       {"M", 6},         {"k", 3},
      {"h", 2},       {"d", -1},      {"c", -2},        {"m", -3},
      {"u", -6},      {"n", -9},      {"p", -12},       {"f", -15},
      {"a", -18},     {"z", -21},     {"y", -24},
  };
  const size_t count = (sizeof expr_prefixes) / (sizeof expr_prefixes[0]);
  size_t k;

  if (drdc_units_find(name, length, unit) == DRDC_OK) {
    *exponent = 0;
    return DRDC_OK;
  }
  for (k = 0u; k < count; k++) {
    size_t n = 0u;
    const drdc_unit_t *u = NULL;

    if ((starts_with(name, length, expr_prefixes[k].text, &n) != 0) &&
        (drdc_units_find(&name[n], length - n, &u) == DRDC_OK) &&
        (units_takes_prefix(u) != 0)) {
      *unit = u;
      *exponent = (int)expr_prefixes[k].exponent;
      return DRDC_OK;
    }
  }
  return DRDC_E_UNKNOWN_UNIT;
}

/* 10^n, n = 0..18. */
static int64_t expr_pow10(int n)
{
  int64_t p = 1;
  int i;

  for (i = 0; i < n; i++) {
    p *= 10;
  }
  return p;
}

/* A unit's factor times 10^exponent (the prefix), exponent -24..24. */
static drdc_status_t unit_factor(const drdc_unit_t *unit, int exponent,
                                 expr_factor_t *factor, uint8_t *rounded)
{
  int rest = exponent;
  size_t i;

  factor->value.num = drdc__units_number(unit->factor_num);
  factor->value.den = drdc__units_number(unit->factor_den);
  factor->scale = 0;
  while (rest != 0) {
    int step = (rest > EXPR_POW10_STEP)    ? EXPR_POW10_STEP
               : (rest < -EXPR_POW10_STEP) ? -EXPR_POW10_STEP
                                           : rest;
    int64_t p = expr_pow10((step < 0) ? -step : step);

    if (drdc__units_rat_mul(&factor->value, (step < 0) ? 1 : p,
                            (step < 0) ? p : 1, &factor->value, &factor->scale,
                            rounded) != DRDC_OK) {
      return DRDC_E_OVERFLOW;
    }
    rest -= step;
  }
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    factor->dimension[i] = drdc__units_dimension(unit, i);
  }
  return DRDC_OK;
}

/* A number 1..DRDC_UNITS_EXPR_NUMBER_MAX at text[*at] as a factor. */
static drdc_status_t read_number(const char *text, size_t length, size_t *at,
                                 expr_factor_t *factor)
{
  size_t i = *at;
  int64_t value = 0;
  size_t d;

  while ((i < length) && expr_is_digit(text[i])) {
    if (value <= DRDC_UNITS_EXPR_NUMBER_MAX) {
      value = (value * 10) + ((int64_t)text[i] - (int64_t)'0');
    }
    i++;
  }
  if ((value == 0) || (value > DRDC_UNITS_EXPR_NUMBER_MAX)) {
    return DRDC_E_SYNTAX;
  }
  factor->value.num = value;
  factor->value.den = 1;
  factor->scale = 0;
  for (d = 0u; d < (size_t)DRDC_UNITS_DIMENSIONS; d++) {
    factor->dimension[d] = 0;
  }
  *at = i;
  return DRDC_OK;
}

/* What the parse has seen of a temperature with an offset: it may only
 * be the whole expression. */
typedef struct expr_offset_use {
  const drdc_unit_t *unit; /* the unit with an offset, or NULL */
  size_t factors;          /* factors of the whole expression */
  uint8_t combined;        /* an operator, a power or parentheses seen */
} expr_offset_use_t;

/* One name at text[*at] and its power, into `level`. */
static drdc_status_t parse_name(const char *text, size_t length, size_t *at,
                                expr_level_t *level, expr_offset_use_t *use,
                                uint8_t *rounded)
{
  size_t start = *at;
  size_t i = start;
  const drdc_unit_t *unit = NULL;
  int exponent = 0;
  int power = 1;
  expr_factor_t factor;
  drdc_status_t st;

  while ((i < length) && is_name_char(text[i])) {
    i++;
  }
  st = find_name(&text[start], i - start, &unit, &exponent);
  if (st == DRDC_OK) {
    st = read_power(text, length, &i, &power);
  }
  if (st == DRDC_OK) {
    if (units_offset_row(unit) != 0u) {
      use->unit = unit;
    }
    if ((power != 1) || (exponent != 0)) {
      use->combined = 1u;
    }
    st = unit_factor(unit, exponent, &factor, rounded);
  }
  if (st == DRDC_OK) {
    st = level_apply(level, &factor, power, rounded);
  }
  *at = i;
  return st;
}

/* A number at text[*at] and its power, into `level`. */
static drdc_status_t parse_number(const char *text, size_t length, size_t *at,
                                  expr_level_t *level, expr_offset_use_t *use,
                                  uint8_t *rounded)
{
  expr_factor_t factor;
  int power = 1;
  drdc_status_t st = read_number(text, length, at, &factor);

  if (st == DRDC_OK) {
    st = read_power(text, length, at, &power);
  }
  if (st == DRDC_OK) {
    use->combined = 1u;
    st = level_apply(level, &factor, power, rounded);
  }
  return st;
}

/* The closing parenthesis at text[*at] and its power: the inner level
 * into the outer one. */
static drdc_status_t parse_close(const char *text, size_t length, size_t *at,
                                 const expr_level_t *inner, expr_level_t *outer,
                                 uint8_t *rounded)
{
  expr_factor_t factor;
  int power = 1;
  size_t i;
  drdc_status_t st;

  *at += 1u;
  st = read_power(text, length, at, &power);
  if (st == DRDC_OK) {
    factor.value = inner->factor;
    factor.scale = inner->scale;
    for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
      factor.dimension[i] = inner->dimension[i];
    }
    st = level_apply(outer, &factor, power, rounded);
  }
  return st;
}

/* The expression into level 0 of `levels`; `use` tells what a
 * temperature with an offset was part of. */
static drdc_status_t parse_levels(const char *text, size_t length,
                                  expr_level_t *levels, expr_offset_use_t *use,
                                  uint8_t *rounded)
{
  size_t depth = 0u;
  size_t i = 0u;
  int operand = 0; /* the last token ended a factor */
  drdc_status_t st = DRDC_OK;

  level_start(&levels[0]);
  while ((i < length) && (st == DRDC_OK)) {
    char c = text[i];

    if (is_blank(c) != 0) {
      i++;
    } else if ((c == '*') || (c == '/')) {
      if (operand == 0) {
        st = DRDC_E_SYNTAX;
      }
      levels[depth].divide = (c == '/') ? 1u : 0u;
      use->combined = 1u;
      operand = 0;
      i++;
    } else if (c == '(') {
      if ((depth + 1u) >= EXPR_LEVELS) {
        st = DRDC_E_RANGE;
      } else {
        depth++;
        level_start(&levels[depth]);
        use->combined = 1u;
        operand = 0;
        i++;
      }
    } else if (c == ')') {
      if ((operand == 0) || (depth == 0u)) {
        st = DRDC_E_SYNTAX;
      } else {
        st = parse_close(text, length, &i, &levels[depth], &levels[depth - 1u],
                         rounded);
        depth--;
      }
    } else if (expr_is_digit(c) != 0) {
      st = parse_number(text, length, &i, &levels[depth], use, rounded);
      use->factors++;
      operand = 1;
    } else if (is_name_char(c) != 0) {
      st = parse_name(text, length, &i, &levels[depth], use, rounded);
      use->factors++;
      operand = 1;
    } else {
      st = DRDC_E_SYNTAX;
    }
  }
  if ((st == DRDC_OK) && ((operand == 0) || (depth != 0u))) {
    st = DRDC_E_SYNTAX;
  }
  return st;
}

drdc_status_t drdc_units_parse(const char *text, size_t length,
                               drdc_units_expr_t *expr)
{
  expr_level_t levels[EXPR_LEVELS];
  expr_offset_use_t use;
  uint8_t rounded = 0u;
  units_rat_t offset;
  size_t i;
  drdc_status_t st;

  if ((text == NULL) || (expr == NULL)) {
    return DRDC_E_NULL;
  }
  if (length > DRDC_UNITS_EXPR_LENGTH_MAX) {
    return DRDC_E_OVERLONG;
  }
  use.unit = NULL;
  use.factors = 0u;
  use.combined = 0u;
  st = parse_levels(text, length, levels, &use, &rounded);
  if (st != DRDC_OK) {
    return st;
  }
  offset.num = 0;
  offset.den = 1;
  if (use.unit != NULL) {
    if ((use.factors != 1u) || (use.combined != 0u)) {
      return DRDC_E_DOMAIN;
    }
    offset = drdc__units_offset(use.unit);
  }
  /* the whole value back into one rational: beyond 2^+-61 it has none */
  if (rat_shift(&levels[0].factor, (int)levels[0].scale, &rounded) != DRDC_OK) {
    return DRDC_E_OVERFLOW;
  }
  for (i = 0u; i < (size_t)DRDC_UNITS_DIMENSIONS; i++) {
    expr->dimension[i] = levels[0].dimension[i];
  }
  expr->factor_num = levels[0].factor.num;
  expr->factor_den = levels[0].factor.den;
  expr->offset_num = offset.num;
  expr->offset_den = offset.den;
  expr->rounded = rounded;
  return DRDC_OK;
}
