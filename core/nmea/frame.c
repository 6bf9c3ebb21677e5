/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief NMEA 0183 framing: `$`, printable ASCII, `*hh` checksum, length,
 *        address; fields split in place, never reading past `length`.
 */
#include "nmea_impl.h"

/* Value of a hex digit, or -1. */
static int hex_value(char c)
{
  int v = -1;

  if ((c >= '0') && (c <= '9')) {
    v = (int)c - (int)'0';
  } else if ((c >= 'A') && (c <= 'F')) {
    v = ((int)c - (int)'A') + 10;
  } else if ((c >= 'a') && (c <= 'f')) {
    v = ((int)c - (int)'a') + 10;
  } else {
    v = -1;
  }
  return v;
}

static int is_upper(char c)
{
  return ((c >= 'A') && (c <= 'Z')) ? 1 : 0;
}

/* A sentence formatter and its type. */
typedef struct nmea_formatter {
  char name[3];
  drdc_nmea_type_t type;
} nmea_formatter_t;

/* The sentence formatter of the address, or DRDC_E_SENTENCE. */
static drdc_status_t formatter(const char *a, drdc_nmea_type_t *type)
{
  static const nmea_formatter_t formatters[] = {
      {{'G', 'G', 'A'}, DRDC_NMEA_GGA}, {{'R', 'M', 'C'}, DRDC_NMEA_RMC},
      {{'G', 'N', 'S'}, DRDC_NMEA_GNS}, {{'Z', 'D', 'A'}, DRDC_NMEA_ZDA},
      {{'G', 'S', 'T'}, DRDC_NMEA_GST}, {{'G', 'L', 'L'}, DRDC_NMEA_GLL},
      {{'V', 'T', 'G'}, DRDC_NMEA_VTG}, {{'H', 'D', 'T'}, DRDC_NMEA_HDT},
      {{'T', 'H', 'S'}, DRDC_NMEA_THS}, {{'G', 'S', 'A'}, DRDC_NMEA_GSA},
  };
  size_t i;

  for (i = 0u; i < (sizeof(formatters) / sizeof(formatters[0])); i++) {
    const char *name = formatters[i].name;

    if ((a[0] == name[0]) && (a[1] == name[1]) && (a[2] == name[2])) {
      *type = formatters[i].type;
      return DRDC_OK;
    }
  }
  return DRDC_E_SENTENCE;
}

/* Whether the rest of the text after the checksum is empty or a line
 * end (CR LF, LF or CR). */
static int line_end_only(const char *rest, size_t n)
{
  int ok = 0;
  char c0 = '\0';
  char c1 = '\0';

  if (n >= 1u) {
    c0 = rest[0];
  }
  if (n >= 2u) {
    c1 = rest[1];
  }
  if (n == 0u) {
    ok = 1;
  } else if ((n == 1u) && ((c0 == '\r') || (c0 == '\n'))) {
    ok = 1;
  } else if ((n == 2u) && (c0 == '\r') && (c1 == '\n')) {
    ok = 1;
  } else {
    ok = 0;
  }
  return ok;
}

drdc_status_t drdc__nmea_frame(const char *text, size_t length, uint32_t flags,
                               nmea_frame_t *fr)
{
  size_t body_max = NMEA_BODY_MAX;
  size_t i = 1u;
  size_t star = 0u;
  unsigned sum = 0u;
  int hi;
  int lo;
  size_t k;

  if ((flags & DRDC_NMEA_STRICT) != 0u) {
    body_max = NMEA_0183_BODY_MAX;
  }
  if ((length == 0u) || (text[0] != '$')) {
    return DRDC_E_SYNTAX;
  }
  /* scan to '*': printable ASCII only; a line end before it truncates */
  while ((i < length) && (star == 0u)) {
    unsigned char c = (unsigned char)text[i];

    if (c == (unsigned char)'*') {
      star = i;
    } else if ((c == (unsigned char)'\r') || (c == (unsigned char)'\n')) {
      return (i > body_max) ? DRDC_E_OVERLONG : DRDC_E_TRUNCATED;
    } else if ((c < 0x20u) || (c > 0x7Eu)) {
      return DRDC_E_CHARACTER;
    } else {
      sum ^= (unsigned)c;
      i++;
    }
  }
  if (star == 0u) {
    return (length > body_max) ? DRDC_E_OVERLONG : DRDC_E_TRUNCATED;
  }
  if ((star + 3u) > body_max) {
    return DRDC_E_OVERLONG;
  }
  if ((star + 3u) > length) {
    return DRDC_E_TRUNCATED;
  }
  hi = hex_value(text[star + 1u]);
  lo = hex_value(text[star + 2u]);
  if ((hi < 0) || (lo < 0)) {
    return DRDC_E_SYNTAX;
  }
  if (line_end_only(&text[star + 3u], length - (star + 3u)) == 0) {
    return DRDC_E_TRAILING;
  }
  if (sum != (((unsigned)hi * 16u) + (unsigned)lo)) {
    return DRDC_E_CHECKSUM;
  }
  /* address: two-letter talker and a three-letter formatter, then ','.
   * An address starting with P is proprietary (P and a manufacturer's
   * code: Quectel's $PQGSA is not a GSA from talker "PQ"); no talker
   * starts with P. */
  if ((star < 7u) || (text[6] != ',') || (is_upper(text[1]) == 0) ||
      (is_upper(text[2]) == 0) || (text[1] == 'P')) {
    return DRDC_E_SENTENCE;
  }
  if (formatter(&text[3], &fr->type) != DRDC_OK) {
    return DRDC_E_SENTENCE;
  }
  fr->text = text;
  fr->strict = ((flags & DRDC_NMEA_STRICT) != 0u) ? 1u : 0u;
  /* fields between the address and '*'; every offset is at most
   * star + 1 <= NMEA_BODY_MAX - 2 = 124, so it fits uint8_t */
  fr->count = 0u;
  fr->start[0] = 7u;
  for (k = 7u; k <= star; k++) {
    if (((k == star) || (text[k] == ',')) && (fr->count < NMEA_FIELDS_MAX)) {
      fr->count++;
      fr->start[fr->count] = (uint8_t)(k + 1u);
    }
  }
  return DRDC_OK;
}
