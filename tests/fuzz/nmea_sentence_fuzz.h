/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Body of the per-sentence NMEA fuzzers (fuzz_nmea_gll.c, ...):
 *        the input is a talker selector and the fields' text of one
 *        sentence formatter (FUZZ_FORMATTER); the fuzzer frames it with a
 *        correct checksum, so that every input reaches the sentence's
 *        decoder instead of stopping at the checksum. Both modes are
 *        parsed, in a heap block of exactly the sentence's length (ASan
 *        reports any read past it). A decoded record must hold only
 *        documented values; strict mode accepts only what the default
 *        mode accepts, into the same record; a refusal leaves the output
 *        alone. Host only.
 */
#ifndef NMEA_SENTENCE_FUZZ_H
#define NMEA_SENTENCE_FUZZ_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/nmea.h>

/* documented bits of drdc_nmea_t::has and ::beyond */
#define HAS_ALL    UINT32_C(0x7FFFF)
#define BEYOND_ALL UINT32_C(0x3FF)

static const char *const talkers[] = {"GP", "GN", "GL", "GA", "GB",
                                      "BD", "GQ", "HE", "IN", "gp"};

static void fuzz_abort_unless(int ok)
{
  if (!ok) {
    abort();
  }
}

static int untouched(const drdc_nmea_t *n)
{
  const unsigned char *p = (const unsigned char *)n;
  size_t i;

  for (i = 0; i < sizeof *n; i++) {
    if (p[i] != 0xA5) {
      return 0;
    }
  }
  return 1;
}

static void check_record(const drdc_nmea_t *n, drdc_nmea_type_t type)
{
  const int64_t deg = DRDC_NAS_PER_DEGREE;
  size_t k;

  fuzz_abort_unless(n->type == type && n->talker[2] == '\0');
  fuzz_abort_unless((n->has & ~HAS_ALL) == 0 && (n->beyond & ~BEYOND_ALL) == 0);
  fuzz_abort_unless(n->latitude <= 90 * deg && n->latitude >= -90 * deg);
  fuzz_abort_unless(n->longitude <= 180 * deg && n->longitude >= -180 * deg);
  fuzz_abort_unless(n->time.hour >= 0 && n->time.hour <= 23 &&
                    n->time.minute >= 0 && n->time.minute <= 59 &&
                    n->time.second >= 0 && n->time.second <= 60 &&
                    n->time.nsec >= 0 && n->time.nsec <= 999999999);
  fuzz_abort_unless(memchr(n->mode, '\0', sizeof n->mode) != NULL);
  fuzz_abort_unless(n->satellites >= 0 && n->satellites <= 99);
  if (type == DRDC_NMEA_GSA) {
    fuzz_abort_unless(n->satellites <= (int32_t)DRDC_NMEA_GSA_IDS);
    fuzz_abort_unless(n->fix_type == 2 || n->fix_type == 3);
    fuzz_abort_unless(n->system_id >= 0 && n->system_id <= 15);
    for (k = 0; k < DRDC_NMEA_GSA_IDS; k++) {
      fuzz_abort_unless(n->satellite_ids[k] <= 999);
      fuzz_abort_unless((int32_t)k < n->satellites || n->satellite_ids[k] == 0);
    }
  }
  if ((n->has & DRDC_NMEA_HAS_TIME) == 0) {
    fuzz_abort_unless(n->time.hour == 0 && n->time.nsec == 0);
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static const char formatter[] = FUZZ_FORMATTER;
  const char *talker;
  size_t fields = 0;
  size_t length;
  size_t i;
  unsigned sum = 0;
  char *text;
  drdc_nmea_t n;
  drdc_nmea_t strict;
  drdc_status_t st;
  drdc_status_t st_strict;

  if (size == 0 || size > 1024) {
    return 0;
  }
  talker = talkers[data[0] % (sizeof talkers / sizeof talkers[0])];
  fields = size - 1;
  /* "$" talker formatter "," fields "*hh\r\n" */
  length = 1 + 2 + 3 + 1 + fields + 5;
  text = malloc(length);
  if (text == NULL) {
    return 0;
  }
  text[0] = '$';
  memcpy(&text[1], talker, 2);
  memcpy(&text[3], formatter, 3);
  text[6] = ',';
  memcpy(&text[7], &data[1], fields);
  for (i = 1; i < 7 + fields; i++) {
    sum ^= (unsigned char)text[i];
  }
  text[7 + fields] = '*';
  text[8 + fields] = "0123456789ABCDEF"[(sum >> 4) & 15u];
  text[9 + fields] = "0123456789ABCDEF"[sum & 15u];
  text[10 + fields] = '\r';
  text[11 + fields] = '\n';

  memset(&n, 0xA5, sizeof n);
  memset(&strict, 0xA5, sizeof strict);
  st = drdc_nmea_parse(text, length, &n);
  st_strict = drdc_nmea_parse_with(text, length, DRDC_NMEA_STRICT, &strict);
  if (st == DRDC_OK) {
    fuzz_abort_unless(length <= DRDC_NMEA_LENGTH_MAX);
    check_record(&n, FUZZ_TYPE);
  } else {
    fuzz_abort_unless(untouched(&n));
  }
  if (st_strict == DRDC_OK) {
    /* strict mode accepts a subset, into the same record */
    fuzz_abort_unless(st == DRDC_OK && length <= DRDC_NMEA_0183_LENGTH_MAX);
    fuzz_abort_unless(memcmp(&n, &strict, sizeof n) == 0);
  } else {
    fuzz_abort_unless(untouched(&strict));
  }
  free(text);
  return 0;
}

#endif /* NMEA_SENTENCE_FUZZ_H */
