/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the NMEA 0183 parser: any bytes, in a heap block of
 *        exactly their length (ASan reports any read past it). A sentence
 *        accepted must carry a matching checksum, and its values must lie
 *        in their documented ranges; a rejected one leaves the output
 *        alone. drdc_nmea_parse_date() likewise, on the same bytes. Host
 *        only.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/nmea.h>

static int checksum_matches(const char *s, size_t n)
{
  unsigned sum = 0;
  size_t i = 1;
  char hex[3];

  while (i < n && s[i] != '*') {
    sum ^= (unsigned char)s[i];
    i++;
  }
  if (i + 2 >= n) {
    return 0; /* no two checksum digits */
  }
  hex[0] = "0123456789ABCDEF"[sum >> 4];
  hex[1] = "0123456789ABCDEF"[sum & 15u];
  hex[2] = '\0';
  return (s[i + 1] == hex[0] || s[i + 1] == (char)(hex[0] | 0x20)) &&
         (s[i + 2] == hex[1] || s[i + 2] == (char)(hex[1] | 0x20));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  char *text = malloc(size ? size : 1);
  drdc_nmea_t n;
  drdc_status_t st;

  if (text == NULL) {
    return 0;
  }
  if (size) {
    memcpy(text, data, size);
  }
  memset(&n, 0xA5, sizeof n);
  st = drdc_nmea_parse(text, size, &n);
  if (st == DRDC_OK) {
    const int64_t deg = DRDC_NAS_PER_DEGREE;

    if (size > DRDC_NMEA_LENGTH_MAX || !checksum_matches(text, size) ||
        n.latitude > 90 * deg || n.latitude < -90 * deg ||
        n.longitude > 180 * deg || n.longitude < -180 * deg ||
        n.time.hour < 0 || n.time.hour > 23 || n.time.minute < 0 ||
        n.time.minute > 59 || n.time.second < 0 || n.time.second > 60 ||
        n.time.nsec < 0 || n.time.nsec > 999999999 || n.talker[2] != '\0') {
      abort();
    }
  } else {
    const unsigned char *p = (const unsigned char *)&n;
    size_t i;

    for (i = 0; i < sizeof n; i++) {
      if (p[i] != 0xA5) {
        abort(); /* an error must leave the output alone */
      }
    }
  }
  /* the date of an RMC or ZDA, whatever its fix: in range, and the
   * same as the full parse's wherever that decodes the sentence */
  {
    drdc_nmea_t d;
    const unsigned char *p = (const unsigned char *)&d;
    size_t i;

    memset(&d, 0xA5, sizeof d);
    if (drdc_nmea_parse_date(text, size, 0u, &d) == DRDC_OK) {
      if ((d.type != DRDC_NMEA_RMC && d.type != DRDC_NMEA_ZDA) ||
          !checksum_matches(text, size) || d.month < 1 || d.month > 12 ||
          d.day < 1 || d.day > 31 || d.time.hour < 0 || d.time.hour > 23 ||
          d.time.second > 60 ||
          (st == DRDC_OK &&
           (d.year != n.year || d.month != n.month || d.day != n.day ||
            memcmp(&d.time, &n.time, sizeof d.time) != 0))) {
        abort();
      }
    } else {
      for (i = 0; i < sizeof d; i++) {
        if (p[i] != 0xA5) {
          abort();
        }
      }
    }
  }
  free(text);
  return 0;
}
