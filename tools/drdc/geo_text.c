/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Angles and decimals of drdc geo, read and written exactly with
 *        128-bit integers (no floating point between text and the
 *        library's fixed-point values).
 */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "geo_text.h"

__extension__ typedef unsigned __int128 u128;
__extension__ typedef __int128 i128;

/* Significant digits of metres kept when reading (digits * 65536 fits
 * 128 bits); later ones only tell whether the value is exact. */
#define METRE_DIGITS_KEPT 33
/* Largest metres read: GeoConvert reads any, Q47.16 holds 1.4e14 m and
 * no UTM/UPS coordinate is near 1e12 m. */
#define METRE_INTEGER_MAX ((u128)1000000000000u)
/* Fraction digits kept when reading; later ones only tell whether the
 * value is exact and break a tie. */
#define FRACTION_DIGITS_MAX 18
/* Longest token read: GeoConvert has no limit, a coordinate needs far
 * less. */
#define TOKEN_MAX 256

static u128 pow10_u128(int n)
{
  u128 p = 1;
  int i;

  for (i = 0; i < n; i++) {
    p *= 10u;
  }
  return p;
}

/* num / den rounded to nearest, ties to even; `above` says the true
 * numerator is a little more than num (digits that were dropped). */
static u128 divide_round_even(u128 num, u128 den, bool above, bool *exact)
{
  u128 q = num / den;
  u128 r = num % den;

  *exact = (r == 0u) && !above;
  if (((2u * r) > den) || (((2u * r) == den) && (above || ((q & 1u) != 0u)))) {
    q++;
  }
  return q;
}

/* UTF-8 and Latin-1 spellings GeoConvert reads as d ' " + - or drops
 * ('\0'), in its order (longest sequences first where they overlap). */
static const struct {
  const char *text;
  char as;
} aliases[] = {
    {"\xc2\xb0", 'd'},
    {"\xc2\xba", 'd'},
    {"\xe2\x81\xb0", 'd'},
    {"\xcb\x9a", 'd'},
    {"\xe2\x88\x98", 'd'},
    {"\xe2\x80\xb2", '\''},
    {"\xe2\x80\xb5", '\''},
    {"\xc2\xb4", '\''},
    {"\xe2\x80\x98", '\''},
    {"\xe2\x80\x99", '\''},
    {"\xe2\x80\x9b", '\''},
    {"\xca\xb9", '\''},
    {"\xcb\x8a", '\''},
    {"\xcb\x8b", '\''},
    {"\xe2\x80\xb3", '"'},
    {"\xe2\x80\xb6", '"'},
    {"\xcb\x9d", '"'},
    {"\xe2\x80\x9c", '"'},
    {"\xe2\x80\x9d", '"'},
    {"\xe2\x80\x9f", '"'},
    {"\xca\xba", '"'},
    {"\xe2\x9e\x95", '+'},
    {"\xe2\x81\xa4", '+'},
    {"\xe2\x80\x90", '-'},
    {"\xe2\x80\x91", '-'},
    {"\xe2\x80\x93", '-'},
    {"\xe2\x80\x94", '-'},
    {"\xe2\x88\x92", '-'},
    {"\xe2\x9e\x96", '-'},
    {"\xc2\xa0", '\0'},
    {"\xe2\x80\x87", '\0'},
    {"\xe2\x80\x89", '\0'},
    {"\xe2\x80\x8a", '\0'},
    {"\xe2\x80\x8b", '\0'},
    {"\xe2\x80\xaf", '\0'},
    {"\xe2\x81\xa3", '\0'},
    {"\xb0", 'd'},
    {"\xba", 'd'},
    {"*", 'd'},
    {"`", '\''},
    {"\xb4", '\''},
    {"\xa0", '\0'},
    {"''", '"'},
};

/* Replace every occurrence of pat in s (NUL-terminated, edited in place:
 * the replacement is never longer). */
static void replace_all(char *s, const char *pat, char as)
{
  size_t n = strlen(pat);
  char *p;

  while ((p = strstr(s, pat)) != NULL) {
    if (as != '\0') {
      *p = as;
      memmove(p + 1, p + n, strlen(p + n) + 1u);
    } else {
      memmove(p, p + n, strlen(p + n) + 1u);
    }
  }
}

static int hemisphere_of(char c)
{
  switch (toupper((unsigned char)c)) {
  case 'S':
    return -1 * GEO_TEXT_LATITUDE;
  case 'N':
    return GEO_TEXT_LATITUDE;
  case 'W':
    return -1 * GEO_TEXT_LONGITUDE;
  case 'E':
    return GEO_TEXT_LONGITUDE;
  default:
    return 0;
  }
}

static bool is_sign(char c)
{
  return (c == '+') || (c == '-');
}

/* GeoConvert's names of the components in its messages; a fourth ':'
 * component without digits is named by the separators' list. */
static const char *const component_names[4] = {"degrees", "minutes", "seconds",
                                               "D'\":"};
/* Integer digits kept of a component; GeoConvert takes any, drdc refuses
 * angles beyond GEO_TEXT_DEGREES_MAX after every other check. */
#define COMPONENT_MAX INT64_C(1000000000000000)

/* One piece of an angle (no interior sign), GeoConvert's InternalDecode:
 * [hemisphere][sign]components[hemisphere]. On error, `why` gets
 * GeoConvert's message, which quotes the piece without its hemisphere
 * letters and sign (or the whole piece when nothing is left of it). */
static bool read_piece(const char *s, size_t beg, size_t end,
                       geo_text_angle_t *out, char *why, size_t why_size)
{
  size_t piece_beg = beg;
  size_t piece_end = end;
  int sign = 1;
  int h;
  char first_letter = '\0';
  int64_t whole[3] = {0, 0, 0};
  int64_t current = 0;
  u128 frac = 0;
  int frac_digits = 0;
  bool frac_above = false; /* nonzero digits beyond FRACTION_DIGITS_MAX */
  int frac_piece = -1;     /* the component holding the fraction */
  int npiece = 0;
  int ncurrent = 0;
  bool point = false;
  int digcount = 0; /* 0: no point in this component; else 1 + decimals */
  size_t p;
  int64_t units[3] = {GEO_TEXT_NAS_PER_DEGREE, GEO_TEXT_NAS_PER_MINUTE,
                      GEO_TEXT_NAS_PER_SECOND};
  int64_t nas;
  bool exact = true;
  int len;
  int k_check;

  out->hemisphere = GEO_TEXT_NONE;
  if ((end > beg) && ((h = hemisphere_of(s[beg])) != 0)) {
    out->hemisphere = (enum geo_text_hemisphere)((h < 0) ? -h : h);
    sign = (h < 0) ? -1 : 1;
    first_letter = s[beg]; /* quoted as given */
    beg++;
  }
  if ((end > beg) && ((h = hemisphere_of(s[end - 1u])) != 0)) {
    char last_letter = s[end - 1u];

    len = (int)(piece_end - piece_beg);
    if (toupper((unsigned char)first_letter) ==
        toupper((unsigned char)last_letter)) {
      snprintf(why, why_size, "Repeated hemisphere indicators %c in %.*s",
               first_letter, len, s + piece_beg);
      return false;
    }
    if (first_letter != '\0') {
      snprintf(why, why_size,
               "Contradictory hemisphere indicators %c and %c in %.*s",
               first_letter, last_letter, len, s + piece_beg);
      return false;
    }
    out->hemisphere = (enum geo_text_hemisphere)((h < 0) ? -h : h);
    sign = (h < 0) ? -1 : 1;
    end--;
  }
  if ((end > beg) && is_sign(s[beg])) {
    sign *= (s[beg] == '-') ? -1 : 1;
    beg++;
  }
  len = (int)(end - beg);
  if (end == beg) {
    snprintf(why, why_size, "Empty or incomplete DMS string %.*s",
             (int)(piece_end - piece_beg), s + piece_beg);
    return false;
  }
  for (p = beg; p < end; p++) {
    char x = s[p];
    int k;

    if (isdigit((unsigned char)x)) {
      ncurrent++;
      if (digcount > 0) {
        digcount++;
        if (frac_digits < FRACTION_DIGITS_MAX) {
          frac = (frac * 10u) + (u128)(unsigned)(x - '0');
          frac_digits++;
        } else if (x != '0') {
          frac_above = true;
        }
      } else {
        current = (current < COMPONENT_MAX) ? ((current * 10) + (x - '0'))
                                            : COMPONENT_MAX;
      }
      continue;
    }
    if (x == '.') {
      if (point) {
        snprintf(why, why_size, "Multiple decimal points in %.*s", len,
                 s + beg);
        return false;
      }
      point = true;
      digcount = 1;
      continue;
    }
    switch (toupper((unsigned char)x)) {
    case 'D':
      k = 0;
      break;
    case '\'':
      k = 1;
      break;
    case '"':
      k = 2;
      break;
    case ':':
      if ((p + 1u) == end) {
        snprintf(why, why_size, "Illegal for : to appear at the end of %.*s",
                 len, s + beg);
        return false;
      }
      k = npiece;
      break;
    default:
      snprintf(why, why_size, "Illegal character %c in DMS string %.*s", x, len,
               s + beg);
      return false;
    }
    if (k == (npiece - 1)) {
      snprintf(why, why_size, "Repeated %s component in %.*s",
               component_names[k], len, s + beg);
      return false;
    }
    if (k < npiece) {
      snprintf(why, why_size, "%s component follows %s component in %.*s",
               component_names[k], component_names[npiece - 1], len, s + beg);
      return false;
    }
    if (ncurrent == 0) {
      snprintf(why, why_size, "Missing numbers in %s component of %.*s",
               component_names[k], len, s + beg);
      return false;
    }
    if (k > 2) {
      snprintf(why, why_size, "Extra text following seconds in DMS string %.*s",
               len, s + beg);
      return false;
    }
    whole[k] = current;
    if (digcount > 0) {
      frac_piece = k;
    }
    if ((p + 1u) < end) {
      npiece = k + 1;
      current = 0;
      ncurrent = 0;
      digcount = 0;
    }
  }
  if (strchr("Dd'\":", s[end - 1u]) == NULL) {
    if (npiece >= 3) {
      snprintf(why, why_size, "Extra text following seconds in DMS string %.*s",
               len, s + beg);
      return false;
    }
    if (ncurrent == 0) {
      snprintf(why, why_size, "Missing numbers in trailing component of %.*s",
               len, s + beg);
      return false;
    }
    whole[npiece] = current;
    if (digcount > 0) {
      frac_piece = npiece;
    }
  }
  if (point && (digcount == 0)) {
    snprintf(why, why_size, "Decimal point in non-terminal component of %.*s",
             len, s + beg);
    return false;
  }
  for (k_check = 1; k_check < 3; k_check++) {
    if (whole[k_check] >= 60) {
      /* GeoConvert quotes the component with its fraction, to 6
       * significant digits (%g). In nas it fits int64_t up to about 1.5e8
       * minutes or 9.2e9 seconds; a larger component is quoted whole, in
       * its own unit: at 9 digits and more the fraction cannot reach the
       * sixth (a half-way tie aside). */
      char number[32];
      bool ignored;

      if (whole[k_check] > (INT64_MAX / units[k_check]) - 1) {
        geo_text_put_general(number, sizeof number, whole[k_check], 1, false);
      } else {
        int64_t v = whole[k_check] * units[k_check];

        if (frac_piece == k_check) {
          v += (int64_t)divide_round_even(frac * (u128)(uint64_t)units[k_check],
                                          pow10_u128(frac_digits), frac_above,
                                          &ignored);
        }
        geo_text_put_general(number, sizeof number, v, units[k_check], false);
      }
      snprintf(why, why_size, "%s %s not in range [0, 60)",
               (k_check == 1) ? "Minutes" : "Seconds", number);
      return false;
    }
  }
  out->too_large = (whole[0] > GEO_TEXT_DEGREES_MAX);
  if (out->too_large) {
    /* GeoConvert reads it; drdc cannot hold it (the caller says so
     * after GeoConvert's own checks of the other word) */
    whole[0] = 0;
  }
  nas = (whole[0] * units[0]) + (whole[1] * units[1]) + (whole[2] * units[2]);
  if (frac_piece >= 0) {
    nas +=
        (int64_t)divide_round_even(frac * (u128)(uint64_t)units[frac_piece],
                                   pow10_u128(frac_digits), frac_above, &exact);
  }
  out->nas = sign * nas;
  out->negative = (sign < 0);
  out->exact = exact;
  return true;
}

bool geo_text_read_angle(const char *text, geo_text_angle_t *out, char *why,
                         size_t why_size)
{
  char s[TOKEN_MAX + 1];
  size_t i;
  size_t beg = 0;
  size_t end;
  size_t p;
  size_t pb;
  int pieces = 0;
  geo_text_angle_t sum = {0, true, true, GEO_TEXT_NONE, false};

  if (strlen(text) > TOKEN_MAX) {
    snprintf(why, why_size, "angle text longer than %d bytes", TOKEN_MAX);
    return false;
  }
  strcpy(s, text);
  for (i = 0; i < (sizeof aliases / sizeof aliases[0]); i++) {
    replace_all(s, aliases[i].text, aliases[i].as);
  }
  end = strlen(s);
  while ((beg < end) && isspace((unsigned char)s[beg])) {
    beg++;
  }
  while ((beg < end) && isspace((unsigned char)s[end - 1u])) {
    end--;
  }
  for (p = beg; p < end; p = pb, pieces++) {
    size_t pa = p;
    geo_text_angle_t piece;

    if ((pieces == 0) && (hemisphere_of(s[pa]) != 0)) {
      pa++;
    }
    if ((pieces > 0) || ((pa < end) && is_sign(s[pa]))) {
      pa++;
    }
    for (pb = pa; (pb < end) && !is_sign(s[pb]); pb++) {
    }
    if (!read_piece(s, p, pb, &piece, why, why_size)) {
      return false;
    }
    /* each piece and the sum stay within GEO_TEXT_DEGREES_MAX: no
     * overflow here nor when the sum is printed */
    sum.nas += piece.nas;
    if ((sum.nas > (GEO_TEXT_DEGREES_MAX * GEO_TEXT_NAS_PER_DEGREE)) ||
        (sum.nas < -(GEO_TEXT_DEGREES_MAX * GEO_TEXT_NAS_PER_DEGREE)) ||
        piece.too_large) {
      sum.too_large = true;
      sum.nas = 0;
    }
    /* GeoConvert sums from -0.0: the sum is a negative zero only when
     * every piece is one */
    sum.negative = sum.negative && piece.negative;
    sum.exact = sum.exact && piece.exact;
    if (sum.hemisphere == GEO_TEXT_NONE) {
      sum.hemisphere = piece.hemisphere;
    } else if ((piece.hemisphere != GEO_TEXT_NONE) &&
               (piece.hemisphere != sum.hemisphere)) {
      snprintf(why, why_size, "Incompatible hemisphere specifier in %.*s",
               (int)(end - beg), s + beg);
      return false;
    }
  }
  if (pieces == 0) {
    snprintf(why, why_size, "Empty or incomplete DMS string %s", s);
    return false;
  }
  if (sum.nas != 0) {
    sum.negative = (sum.nas < 0);
  }
  *out = sum;
  return true;
}

/* A decimal number as read: (-1)^neg x digits x 10^scale, a little more
 * in magnitude when `above`. */
struct decimal {
  bool neg;
  u128 digits; /* the significant digits kept, as an integer */
  int scale;
  bool above; /* nonzero digits dropped after those kept */
};

/* [+-]digits[.digits][e[+-]digits] -> d; false when text is not that. */
static bool read_decimal(const char *s, struct decimal *d)
{
  int kept = 0; /* significant digits kept */
  bool any = false;
  bool point = false;
  int exponent = 0;

  d->neg = false;
  d->digits = 0;
  d->scale = 0;
  d->above = false;
  if ((*s == '+') || (*s == '-')) {
    d->neg = (*s == '-');
    s++;
  }
  for (; isdigit((unsigned char)*s) || ((*s == '.') && !point); s++) {
    if (*s == '.') {
      point = true;
      continue;
    }
    any = true;
    if ((kept < METRE_DIGITS_KEPT) && ((kept > 0) || (*s != '0'))) {
      d->digits = (d->digits * 10u) + (u128)(unsigned)(*s - '0');
      kept++;
      d->scale -= point ? 1 : 0;
    } else if (kept == METRE_DIGITS_KEPT) {
      d->scale += point ? 0 : 1; /* a dropped integer digit */
      d->above = d->above || (*s != '0');
    } else {
      d->scale -= point ? 1 : 0; /* a leading zero after the point */
    }
  }
  if (!any) {
    return false;
  }
  if ((*s == 'e') || (*s == 'E')) {
    int sign = 1;

    s++;
    if ((*s == '+') || (*s == '-')) {
      sign = (*s == '-') ? -1 : 1;
      s++;
    }
    if (!isdigit((unsigned char)*s)) {
      return false;
    }
    for (; isdigit((unsigned char)*s); s++) {
      exponent = (exponent < 10000) ? ((exponent * 10) + (*s - '0')) : 10000;
    }
    exponent *= sign;
  }
  d->scale += exponent;
  return *s == '\0';
}

/* A number of metres as whole metres and a decimal fraction: whole +
 * (frac + a little when sticky) / 10^k, 0 <= frac < 10^k, k <= 38. */
struct split_metres {
  int64_t whole;
  u128 frac;
  int k;
  bool sticky;
};

/* d + add metres -> *out; false beyond METRE_INTEGER_MAX (|add| is far
 * below it, so whole stays within int64). */
static bool split_metres(const struct decimal *d, int64_t add,
                         struct split_metres *out)
{
  u128 digits = d->digits;
  int k = -d->scale;
  bool sticky = d->above;
  u128 whole;
  u128 frac;

  if (digits == 0u) {
    /* zero, whatever its exponent */
    whole = 0;
    frac = 0;
    k = 0;
  } else if (k <= 0) {
    /* an integer; compared before the product, which could leave 128
     * bits */
    if ((-k > 12) || (digits > (METRE_INTEGER_MAX / pow10_u128(-k)))) {
      return false;
    }
    whole = digits * pow10_u128(-k);
    frac = 0;
    k = 0;
  } else {
    if (k > 38) {
      /* 38 decimals kept (10^38 < 2^127): the digits below only make
       * the fraction a little more */
      if ((k - 38) > 38) {
        sticky = sticky || (digits != 0u);
        digits = 0;
      } else {
        sticky = sticky || ((digits % pow10_u128(k - 38)) != 0u);
        digits /= pow10_u128(k - 38);
      }
      k = 38;
    }
    whole = digits / pow10_u128(k);
    frac = digits % pow10_u128(k);
    if (whole > METRE_INTEGER_MAX) {
      return false;
    }
  }
  if (!d->neg) {
    out->whole = (int64_t)whole;
    out->frac = frac;
  } else if ((frac == 0u) && !sticky) {
    out->whole = -(int64_t)whole;
    out->frac = 0;
  } else {
    /* -(w + (f + s) / 10^k) = -w - 1 + (10^k - f - s) / 10^k, and with
     * 0 < s < 1 the fraction is 10^k - f - 1 and a little more */
    out->whole = -(int64_t)whole - 1;
    out->frac = pow10_u128(k) - frac - (sticky ? 1u : 0u);
  }
  out->whole += add;
  out->k = k;
  out->sticky = sticky;
  return true;
}

bool geo_text_read_metres(const char *s, int64_t *q16, int64_t *rest,
                          bool *exact)
{
  struct decimal d;
  struct split_metres m;
  u128 v;
  u128 den;
  u128 r;
  u128 bits = 0;
  i128 floor48; /* the value in 2^-48 m, rounded down, minus q16 */
  bool below;   /* something lies below the 49 bits of the fraction */
  int i;

  if (!read_decimal(s, &d)) {
    return false;
  }
  if (d.digits == 0u) {
    v = 0;
    *exact = !d.above;
  } else if (d.scale >= 0) {
    /* an integer: at most METRE_INTEGER_MAX */
    /* compared before the product, which could leave 128 bits (33
     * digits times 10^12) */
    if ((d.scale > 12) ||
        (d.digits > METRE_INTEGER_MAX / pow10_u128(d.scale))) {
      return false;
    }
    v = d.digits * pow10_u128(d.scale) * 65536u;
    *exact = !d.above;
  } else if (d.scale < -38) {
    v = 0; /* below 2^-17 m: 10^-38 of 33 digits */
    *exact = false;
  } else {
    v = divide_round_even(d.digits * 65536u, pow10_u128(-d.scale), d.above,
                          exact);
    if (v > (METRE_INTEGER_MAX * 65536u)) {
      return false;
    }
  }
  *q16 = d.neg ? -(int64_t)v : (int64_t)v;
  if (!split_metres(&d, 0, &m)) {
    return false;
  }
  /* the value in units of 2^-48 m: 49 bits of the fraction by long
   * division (2 r < 2 x 10^38 < 2^128), then one rounding to nearest,
   * ties to even */
  den = pow10_u128(m.k);
  r = m.frac;
  for (i = 0; i < 49; i++) {
    r <<= 1;
    bits <<= 1;
    if (r >= den) {
      r -= den;
      bits |= 1u;
    }
  }
  below = (r != 0u) || m.sticky;
  /* |value - q16| <= 2^-17 m: the differences fit 33 bits */
  floor48 = ((i128)m.whole * ((i128)1 << 48)) + (i128)(bits >> 1) -
            ((i128)*q16 * ((i128)1 << 32));
  *rest = (int64_t)floor48;
  if (((bits & 1u) != 0u) && (below || ((bits & 2u) != 0u))) {
    *rest += 1;
  }
  /* a value off q16 by less than half of 2^-48 m keeps its side */
  if ((*rest == 0) && !*exact) {
    *rest = ((floor48 < 0) ? -1 : 1);
  }
  return true;
}

bool geo_text_metres_scaled(const char *text, int64_t add, int decimals,
                            bool down, int64_t *out, bool *negative)
{
  struct decimal d;
  struct split_metres m;
  i128 q;           /* the value times 10^decimals, rounded down */
  int half = 0;     /* what lies below q against one half: -1, 0 (a tie), 1 */
  bool zero = true; /* nothing lies below q */

  if ((decimals < -9) || (decimals > 18) || !read_decimal(text, &d) ||
      !split_metres(&d, add, &m)) {
    return false;
  }
  if (decimals >= 0) {
    q = (i128)m.whole * (i128)pow10_u128(decimals);
    if (decimals >= m.k) {
      q += (i128)(m.frac * pow10_u128(decimals - m.k));
      half = -1;
      zero = !m.sticky;
    } else {
      u128 p = pow10_u128(m.k - decimals);
      u128 r = m.frac % p;

      q += (i128)(m.frac / p);
      zero = (r == 0u) && !m.sticky;
      half = ((2u * r) < p) ? -1 : (((2u * r) == p) && !m.sticky) ? 0 : 1;
    }
  } else {
    int64_t p = (int64_t)pow10_u128(-decimals);
    int64_t quotient = m.whole / p;
    int64_t r = m.whole % p;

    if (r < 0) {
      r += p;
      quotient--;
    }
    q = quotient;
    zero = (r == 0) && (m.frac == 0u) && !m.sticky;
    half = (r < (p / 2))                                     ? -1
           : ((r == (p / 2)) && (m.frac == 0u) && !m.sticky) ? 0
                                                             : 1;
  }
  if (zero) {
    half = -1;
  }
  if (!down && ((half > 0) || ((half == 0) && ((q & 1) != 0)))) {
    q++;
  }
  if ((q > INT64_MAX) || (q < INT64_MIN)) {
    return false;
  }
  *out = (int64_t)q;
  /* a negative zero (no add) is negative, as GeoConvert's double */
  *negative = (m.whole < 0) || (d.neg && (m.whole == 0) && (add == 0));
  return true;
}

/* A string built piece by piece, cut (never overrun) at its size. */
struct text {
  char *out;
  size_t size;
  size_t n;
};

static void put_char(struct text *t, char c)
{
  if ((t->n + 1u) < t->size) {
    t->out[t->n++] = c;
    t->out[t->n] = '\0';
  }
}

static void put_string(struct text *t, const char *s)
{
  while (*s != '\0') {
    put_char(t, *s++);
  }
}

/* v in decimal with at least `digits` digits (zero-filled). */
static void put_uint(struct text *t, u128 v, int digits)
{
  char d[48];
  int n = 0;

  do {
    d[n++] = (char)('0' + (int)(v % 10u));
    v /= 10u;
  } while ((v != 0u) || (n < digits));
  while (n > 0) {
    put_char(t, d[--n]);
  }
}

static void start(struct text *t, char *out, size_t size)
{
  t->out = out;
  t->size = size;
  t->n = 0;
  if (size > 0u) {
    out[0] = '\0';
  }
}

/* |value| * 10^decimals / unit rounded half to even. */
static u128 scaled_magnitude(int64_t value, int64_t unit, int decimals)
{
  u128 mag = (value < 0) ? (u128)(-(value + 1)) + 1u : (u128)value;
  bool exact;

  return divide_round_even(mag * pow10_u128(decimals), (u128)unit, false,
                           &exact);
}

void geo_text_put_fixed(char *out, size_t size, int64_t value, int64_t unit,
                        int decimals, bool negative)
{
  u128 q = scaled_magnitude(value, unit, decimals);
  u128 p = pow10_u128(decimals);
  struct text t;

  start(&t, out, size);
  if ((value < 0) || ((value == 0) && negative)) {
    put_char(&t, '-');
  }
  put_uint(&t, q / p, 1);
  if (decimals > 0) {
    put_char(&t, '.');
    put_uint(&t, q % p, decimals);
  }
}

static int bit_length(u128 v)
{
  int n = 0;

  while (v != 0u) {
    v >>= 1;
    n++;
  }
  return n;
}

/* mag / den (mag, den > 0, the quotient below 2^64) rounded to the
 * nearest double, as *m / 2^*shift with 2^52 <= *m < 2^53: the number
 * GeoConvert holds when it reads the value's text or divides by a power
 * of ten, correctly rounded. mag * 2^shift stays below 2^110 for the
 * quotients drdc geo quotes (>= 1 nas of a degree, 2^-16 m of a km). */
static void nearest_double(u128 mag, u128 den, u128 *m, int *shift)
{
  u128 limit = (u128)1 << 53;
  int s = 52 - (bit_length(mag) - bit_length(den));
  u128 num;
  u128 d;
  u128 q;
  bool exact;

  for (;;) {
    num = (s >= 0) ? (mag << s) : mag;
    d = (s >= 0) ? den : (den << -s);
    q = num / d;
    if (q >= limit) {
      s--;
    } else if (q < (limit >> 1)) {
      s++;
    } else {
      break;
    }
  }
  q = divide_round_even(num, d, false, &exact);
  if (q == limit) {
    q >>= 1;
    s--;
  }
  *m = q;
  *shift = s;
}

void geo_text_put_general(char *out, size_t size, int64_t value, int64_t unit,
                          bool negative)
{
  u128 mag = (value < 0) ? (u128)(-(value + 1)) + 1u : (u128)value;
  u128 den = (u128)unit;
  int shift;
  int exponent = 0; /* 10^exponent <= mag / den < 10^(exponent + 1) */
  u128 q;
  u128 rest;
  bool exact;
  char digits[8];
  int decimals;
  int n;
  struct text t;

  start(&t, out, size);
  if ((value < 0) || ((value == 0) && negative)) {
    put_char(&t, '-');
  }
  if (mag == 0u) {
    put_char(&t, '0');
    return;
  }
  /* printf rounds the double's exact binary value, half to even */
  nearest_double(mag, den, &mag, &shift);
  den = (shift >= 0) ? ((u128)1 << shift) : 1u;
  mag = (shift >= 0) ? mag : (mag << -shift);
  while (mag >= (den * pow10_u128(exponent + 1))) {
    exponent++;
  }
  while ((mag * pow10_u128(-exponent)) < den) {
    exponent--;
  }
  /* the 6 significant digits, rounded half to even from the exact value */
  if (exponent <= 5) {
    q = divide_round_even(mag * pow10_u128(5 - exponent), den, false, &exact);
  } else {
    q = divide_round_even(mag, den * pow10_u128(exponent - 5), false, &exact);
  }
  if (q == 1000000u) {
    q = 100000u;
    exponent++;
  }
  for (n = 5, rest = q; n >= 0; n--) {
    digits[n] = (char)('0' + (int)(rest % 10u));
    rest /= 10u;
  }
  digits[6] = '\0';
  if ((exponent < -4) || (exponent >= 6)) {
    /* d.ddddde+XX without trailing zeros */
    for (n = 6; (n > 1) && (digits[n - 1] == '0'); n--) {
    }
    put_char(&t, digits[0]);
    if (n > 1) {
      put_char(&t, '.');
      for (decimals = 1; decimals < n; decimals++) {
        put_char(&t, digits[decimals]);
      }
    }
    put_char(&t, 'e');
    put_char(&t, (exponent < 0) ? '-' : '+');
    put_uint(&t, (u128)(unsigned)((exponent < 0) ? -exponent : exponent), 2);
    return;
  }
  /* fixed: q / 10^decimals, trailing zeros of the fraction dropped */
  {
    uint64_t whole = (uint64_t)(q / pow10_u128(5 - exponent));
    uint64_t fraction = (uint64_t)(q % pow10_u128(5 - exponent));

    decimals = 5 - exponent;
    while ((decimals > 0) && ((fraction % 10u) == 0u)) {
      fraction /= 10u;
      decimals--;
    }
    put_uint(&t, whole, 1);
    if (decimals > 0) {
      put_char(&t, '.');
      put_uint(&t, fraction, decimals);
    }
  }
}

void geo_text_put_dms(char *out, size_t size, int64_t nas, bool negative,
                      int prec, enum geo_text_hemisphere which, char sep)
{
  /* the last component and its decimals, as DMS::Encode picks them */
  int last = (prec < 2) ? 0 : ((prec < 4) ? 1 : 2);
  int decimals = prec - (2 * last);
  const int64_t units[3] = {GEO_TEXT_NAS_PER_DEGREE, GEO_TEXT_NAS_PER_MINUTE,
                            GEO_TEXT_NAS_PER_SECOND};
  u128 total = scaled_magnitude(nas, units[last], decimals);
  u128 p = pow10_u128(decimals);
  u128 whole = total / p;
  int width = (int)which + 1; /* degree digits: 2 latitude, 3 longitude */
  bool south_or_west = (nas < 0) || ((nas == 0) && negative);
  struct text t;

  start(&t, out, size);
  if (last == 0) {
    put_uint(&t, whole, width);
  } else if (last == 1) {
    put_uint(&t, whole / 60u, width);
    put_char(&t, (sep != '\0') ? sep : 'd');
    put_uint(&t, whole % 60u, 2);
  } else {
    put_uint(&t, whole / 3600u, width);
    put_char(&t, (sep != '\0') ? sep : 'd');
    put_uint(&t, (whole / 60u) % 60u, 2);
    put_char(&t, (sep != '\0') ? sep : '\'');
    put_uint(&t, whole % 60u, 2);
  }
  if (decimals > 0) {
    put_char(&t, '.');
    put_uint(&t, total % p, decimals);
  }
  if ((sep == '\0') && (last > 0)) {
    put_string(&t, (last == 1) ? "'" : "\"");
  }
  if (which == GEO_TEXT_LATITUDE) {
    put_char(&t, south_or_west ? 'S' : 'N');
  } else {
    put_char(&t, south_or_west ? 'W' : 'E');
  }
}
