/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief NMEA 0183: a corpus of sentences against Python's Fraction
 *        reading of the same text, every malformation with its status,
 *        every prefix of every sentence parsed from a buffer that ends
 *        where the text ends (ASan catches any over-read), UTC
 *        stitching across midnight and a leap second, and the dates
 *        drdc_nmea_parse_date() keeps of RMCs without a fix.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/nmea.h>

#include "suites.h"
#include "unity.h"
#include "vectors_nmea.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
#define BUFFER   160u

static void sentinel(drdc_nmea_t *n)
{
  const unsigned char *end = (const unsigned char *)(n + 1);
  unsigned char *p = (unsigned char *)n;

  while (p < end) {
    *p = 0xA5u;
    p++;
  }
}

static int unchanged(const drdc_nmea_t *n)
{
  const unsigned char *end = (const unsigned char *)(n + 1);
  const unsigned char *p = (const unsigned char *)n;

  while (p < end) {
    if (*p != 0xA5u) {
      return 0;
    }
    p++;
  }
  return 1;
}

static void parse_ok(const char *text, size_t length, drdc_nmea_t *n)
{
  sentinel(n);
  TEST_ASSERT_EQUAL_INT_MESSAGE(DRDC_OK, drdc_nmea_parse(text, length, n),
                                text);
}

static void test_corpus_matches_the_fraction_model(void)
{
  size_t i;
  size_t k;

  for (i = 0u; i < COUNT(nmea_vectors); i++) {
    const struct nmea_vector *v = &nmea_vectors[i];
    drdc_nmea_t n;
    drdc_nmea_t strict;

    parse_ok(v->text, v->length, &n);

    TEST_ASSERT_EQUAL_INT_MESSAGE(v->type, n.type, v->text);
    TEST_ASSERT_EQUAL_STRING(v->talker, n.talker);
    TEST_ASSERT_EQUAL_HEX32_MESSAGE(v->has, n.has, v->text);
    TEST_ASSERT_EQUAL_HEX32_MESSAGE(v->beyond, n.beyond, v->text);
    TEST_ASSERT_EQUAL_INT32(v->tod[0], n.time.hour);
    TEST_ASSERT_EQUAL_INT32(v->tod[1], n.time.minute);
    TEST_ASSERT_EQUAL_INT32(v->tod[2], n.time.second);
    TEST_ASSERT_EQUAL_INT32(v->tod[3], n.time.nsec);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(v->latitude, n.latitude, v->text);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(v->longitude, n.longitude, v->text);
    TEST_ASSERT_EQUAL_INT64(v->altitude, n.altitude);
    TEST_ASSERT_EQUAL_INT64(v->separation, n.separation);
    TEST_ASSERT_EQUAL_INT32(v->quality, n.quality);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->satellites, n.satellites, v->text);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->dop[0], n.hdop, v->text);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->dop[1], n.pdop, v->text);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->dop[2], n.vdop, v->text);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->speed, n.speed, v->text);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(v->angle[0], n.course, v->text);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(v->angle[1], n.course_magnetic, v->text);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(v->angle[2], n.heading, v->text);
    TEST_ASSERT_EQUAL_STRING_MESSAGE(v->mode, n.mode, v->text);
    TEST_ASSERT_EQUAL_INT32(v->fix_type, n.fix_type);
    TEST_ASSERT_EQUAL_INT32(v->system_id, n.system_id);
    TEST_ASSERT_EQUAL_UINT16_ARRAY_MESSAGE(v->satellite_ids, n.satellite_ids,
                                           DRDC_NMEA_GSA_IDS, v->text);
    TEST_ASSERT_EQUAL_INT32(v->date[0], n.year);
    TEST_ASSERT_EQUAL_INT32(v->date[1], n.month);
    TEST_ASSERT_EQUAL_INT32(v->date[2], n.day);
    TEST_ASSERT_EQUAL_INT32(v->date[3], n.zone_hours);
    TEST_ASSERT_EQUAL_INT32(v->date[4], n.zone_minutes);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->gst[0], n.rms, v->text);
    TEST_ASSERT_EQUAL_INT32(v->gst[1], n.sigma_major);
    TEST_ASSERT_EQUAL_INT32(v->gst[2], n.sigma_minor);
    TEST_ASSERT_EQUAL_UINT32((uint32_t)v->gst[3], n.orientation);
    TEST_ASSERT_EQUAL_INT32(v->gst[4], n.sigma_latitude);
    TEST_ASSERT_EQUAL_INT32(v->gst[5], n.sigma_longitude);
    TEST_ASSERT_EQUAL_INT32(v->gst[6], n.sigma_altitude);
    for (k = 0u; k < 3u; k++) {
      /* the talker is NUL-terminated within its array */
      TEST_ASSERT_TRUE((k < 2u) || (n.talker[k] == '\0'));
    }
    /* strict mode decodes the same record, or refuses the sentence
     * without touching the output */
    sentinel(&strict);
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        v->strict,
        drdc_nmea_parse_with(v->text, v->length, DRDC_NMEA_STRICT, &strict),
        v->text);
    if (v->strict == DRDC_OK) {
      TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&n, &strict, sizeof n, v->text);
    } else {
      TEST_ASSERT_TRUE(unchanged(&strict));
    }
  }
  TEST_ASSERT_TRUE(COUNT(nmea_vectors) >= 60u);
}

/* Every malformation gives its own status and leaves the output as it
 * was; the test names every status drdc_nmea_parse() documents. */
static void test_drdc_nmea_parse_malformations(void)
{
  static const drdc_status_t documented[] = {
      DRDC_E_SYNTAX,        DRDC_E_CHARACTER, DRDC_E_TRUNCATED, DRDC_E_OVERLONG,
      DRDC_E_TRAILING,      DRDC_E_CHECKSUM,  DRDC_E_SENTENCE,  DRDC_E_NO_FIX,
      DRDC_E_MISSING_FIELD, DRDC_E_HOUR,      DRDC_E_MINUTE,    DRDC_E_SECOND,
      DRDC_E_DAY,           DRDC_E_MONTH,     DRDC_E_YEAR,      DRDC_E_RANGE,
  };
  size_t i;
  size_t k;

  for (i = 0u; i < COUNT(nmea_bad_vectors); i++) {
    const struct nmea_bad_vector *v = &nmea_bad_vectors[i];
    drdc_nmea_t n;

    sentinel(&n);
    if (v->flags == 0u) {
      TEST_ASSERT_EQUAL_INT_MESSAGE(
          v->status, drdc_nmea_parse(v->text, v->length, &n), v->text);
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        v->status, drdc_nmea_parse_with(v->text, v->length, v->flags, &n),
        v->text);
    TEST_ASSERT_TRUE(unchanged(&n));
  }
  for (k = 0u; k < COUNT(documented); k++) {
    int seen = 0;

    for (i = 0u; i < COUNT(nmea_bad_vectors); i++) {
      if (nmea_bad_vectors[i].status == documented[k]) {
        seen = 1;
      }
    }
    TEST_ASSERT_TRUE_MESSAGE(seen, drdc_status_name(documented[k]));
  }
}

static void test_drdc_nmea_parse_null(void)
{
  drdc_nmea_t n;

  sentinel(&n);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_nmea_parse(NULL, 10u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_nmea_parse(nmea_vectors[0].text, nmea_vectors[0].length, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_nmea_parse_with(NULL, 10u, DRDC_NMEA_STRICT, &n));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_nmea_parse_with(nmea_vectors[0].text,
                                             nmea_vectors[0].length, 0u, NULL));
  TEST_ASSERT_TRUE(unchanged(&n));
}

/* Parse every prefix of `text` from the end of a buffer, so that a read
 * at or past `length` leaves the object (ASan reports it on host-asan). */
static void parse_every_prefix(const char *text, size_t length)
{
  char buffer[BUFFER];
  size_t n;
  size_t i;

  TEST_ASSERT_TRUE(length <= BUFFER);
  for (n = 0u; n <= length; n++) {
    drdc_nmea_t out;
    drdc_status_t st;
    char *start = &buffer[BUFFER - n];

    for (i = 0u; i < n; i++) {
      start[i] = text[i];
    }
    sentinel(&out);
    st = drdc_nmea_parse(start, n, &out);
    if (st != DRDC_OK) {
      TEST_ASSERT_TRUE(unchanged(&out));
    }
  }
}

static void test_never_reads_past_the_buffer(void)
{
  size_t i;

  for (i = 0u; i < COUNT(nmea_vectors); i++) {
    parse_every_prefix(nmea_vectors[i].text, nmea_vectors[i].length);
  }
  for (i = 0u; i < COUNT(nmea_bad_vectors); i++) {
    parse_every_prefix(nmea_bad_vectors[i].text, nmea_bad_vectors[i].length);
  }
}

static void parse_text(const char *text, drdc_nmea_t *out)
{
  size_t n = 0u;

  while (text[n] != '\0') {
    n++;
  }
  parse_ok(text, n, out);
}

/* Named cases: the header's example, a GGA after midnight on the date of
 * an RMC before it, a leap second dated by ZDA, an RMC dating itself. */
static void test_drdc_nmea_utc_stitching(void)
{
  drdc_nmea_t rmc;
  drdc_nmea_t gga;
  drdc_nmea_t zda;
  drdc_nmea_t leap;
  drdc_time_t t = {0, 0};

  parse_text("$GPRMC,235959.00,A,4807.038,N,01131.000,E,22.4,84.4,311216,3.1,W,"
             "A*2C\r\n",
             &rmc);
  parse_text(
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n",
      &gga);

  TEST_ASSERT_EQUAL_INT64(INT64_C(173222280000000), gga.latitude);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_nmea_utc(NULL, &rmc, &rmc, &t));
  TEST_ASSERT_EQUAL_INT64(INT64_C(1483228799),
                          t.sec); /* 2016-12-31T23:59:59Z */
  TEST_ASSERT_EQUAL_INT32(0, t.nsec);
  gga.time.hour = 0;
  gga.time.minute = 0;
  gga.time.second = 1;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_nmea_utc(NULL, &rmc, &gga, &t));
  TEST_ASSERT_EQUAL_INT64(INT64_C(1483228801),
                          t.sec); /* 2017-01-01T00:00:01Z */
  parse_text("$GPZDA,235960.50,31,12,2016,-05,30*47\r\n", &zda);
  TEST_ASSERT_EQUAL_INT32(-5, zda.zone_hours);
  TEST_ASSERT_EQUAL_INT32(30, zda.zone_minutes);
  parse_text("$GPGGA,235960.50,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"
             "*6A\r\n",
             &leap);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_nmea_utc(NULL, &zda, &leap, &t));
  TEST_ASSERT_EQUAL_INT64(INT64_C(1483228799), t.sec);
  TEST_ASSERT_EQUAL_INT32(1500000000, t.nsec);
  /* a GGA late in the day before the RMC's date */
  rmc.time.hour = 0;
  gga.time.hour = 23;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_nmea_utc(NULL, &rmc, &gga, &t));
  TEST_ASSERT_EQUAL_INT64(INT64_C(1483138801),
                          t.sec); /* 2016-12-30T23:00:01Z */
}

static void test_drdc_nmea_utc_bad_input(void)
{
  drdc_nmea_t zda;
  drdc_nmea_t gga;
  drdc_time_t t = {7, 7};

  parse_text("$GPZDA,235959.00,31,12,9999,,*66\r\n", &zda);
  parse_text(
      "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n",
      &gga);

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_nmea_utc(NULL, NULL, &gga, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_nmea_utc(NULL, &zda, NULL, &t));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_nmea_utc(NULL, &zda, &gga, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MISSING_FIELD,
                        drdc_nmea_utc(NULL, &gga, &gga, &t));
  /* 00:00:01 after 9999-12-31T23:59:59 is past the calendar */
  gga.time.hour = 0;
  gga.time.minute = 0;
  gga.time.second = 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_nmea_utc(NULL, &zda, &gga, &t));
  /* 30 February */
  zda.year = 2024;
  zda.month = 2;
  zda.day = 30;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, drdc_nmea_utc(NULL, &zda, &zda, &t));
  /* second 60 on a day without a leap second */
  zda.day = 28;
  zda.time.second = 60;
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, drdc_nmea_utc(NULL, &zda, &zda, &t));
  TEST_ASSERT_EQUAL_INT64(7, t.sec);
  TEST_ASSERT_EQUAL_INT32(7, t.nsec);
}

static void test_nmea_utc_extreme_time_fields_do_not_overflow(void)
{
  /* Regression: the seconds of the day of a sentence's time fields were
   * summed in int32_t before any check (undefined behaviour, caught by
   * UBSan: utc.c seconds_of_day(), hour INT32_MIN times 60). Hand-filled
   * fields at the ends of int32_t now wrap modulo 2^32 and reach
   * drdc_time_from_civil(), which refuses them; utc unchanged. */
  static const int32_t far[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX};
  drdc_nmea_t rmc;
  size_t i;

  parse_text("$GPRMC,161229.487,A,3723.2475,N,12158.3416,W,0.13,309.62,"
             "120598,,*10\r\n",
             &rmc);
  for (i = 0; i < COUNT(far); i++) {
    drdc_nmea_t s = rmc;
    drdc_time_t t;

    memset(&t, 0x5A, sizeof t);
    s.time.hour = far[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_HOUR, drdc_nmea_utc(NULL, &rmc, &s, &t));
    s = rmc;
    s.time.minute = far[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE, drdc_nmea_utc(NULL, &rmc, &s, &t));
    s = rmc;
    s.time.second = far[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, drdc_nmea_utc(NULL, &rmc, &s, &t));
    s = rmc;
    s.time.nsec = far[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND, drdc_nmea_utc(NULL, &rmc, &s, &t));
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &t, sizeof t);
  }
}

static void test_nmea_utc_dated_time_out_of_range_is_refused(void)
{
  /* Contract fix: `dated`'s time of day only chooses the day of `s`'s, and
   * was never checked, so a hand-filled hour of 24 or 100 gave DRDC_OK with
   * a day moved by it. Each field just outside its range and at the ends of
   * int32_t now gives the status drdc_time_from_civil() gives for `s`'s,
   * and utc is unchanged. */
  static const int32_t hours[] = {-1, 24, 100, INT32_MIN, INT32_MAX};
  static const int32_t minutes[] = {-1, 60, INT32_MIN, INT32_MAX};
  static const int32_t seconds[] = {-1, 61, INT32_MIN, INT32_MAX};
  static const int32_t nsecs[] = {-1, 1000000000, INT32_MIN, INT32_MAX};
  drdc_nmea_t rmc;
  drdc_nmea_t gga;
  drdc_nmea_t dated;
  drdc_time_t t;
  size_t i;

  parse_text("$GPRMC,161229.487,A,3723.2475,N,12158.3416,W,0.13,309.62,"
             "120598,,*10\r\n",
             &rmc);
  parse_text("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,"
             "M,,*47\r\n",
             &gga);
  memset(&t, 0x5A, sizeof t);
  for (i = 0; i < COUNT(hours); i++) {
    dated = rmc;
    dated.time.hour = hours[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_HOUR, drdc_nmea_utc(NULL, &dated, &gga, &t));
  }
  for (i = 0; i < COUNT(minutes); i++) {
    dated = rmc;
    dated.time.minute = minutes[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE, drdc_nmea_utc(NULL, &dated, &gga, &t));
  }
  for (i = 0; i < COUNT(seconds); i++) {
    dated = rmc;
    dated.time.second = seconds[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, drdc_nmea_utc(NULL, &dated, &gga, &t));
  }
  for (i = 0; i < COUNT(nsecs); i++) {
    dated = rmc;
    dated.time.nsec = nsecs[i];
    TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                          drdc_nmea_utc(NULL, &dated, &gga, &t));
    /* the same field of s, refused by drdc_time_from_civil() */
    TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                          drdc_nmea_utc(NULL, &rmc, &dated, &t));
  }
  TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, &t, sizeof t);
  /* the edges of the ranges are accepted */
  dated = rmc;
  dated.time.hour = 23;
  dated.time.minute = 59;
  dated.time.second = 59;
  dated.time.nsec = 999999999;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_nmea_utc(NULL, &dated, &gga, &t));
}

/* Every field other than the type, talker, time of day and date (and a
 * ZDA's zone) is 0 in a record of drdc_nmea_parse_date(). */
static void assert_date_only(const drdc_nmea_t *n, const char *text)
{
  size_t k;

  TEST_ASSERT_EQUAL_INT64_MESSAGE(0, n->latitude, text);
  TEST_ASSERT_EQUAL_INT64_MESSAGE(0, n->longitude, text);
  TEST_ASSERT_EQUAL_INT64(0, n->altitude);
  TEST_ASSERT_EQUAL_INT64(0, n->separation);
  TEST_ASSERT_EQUAL_INT32(0, n->quality);
  TEST_ASSERT_EQUAL_INT32(0, n->satellites);
  TEST_ASSERT_EQUAL_INT32(0, n->hdop);
  TEST_ASSERT_EQUAL_INT32(0, n->speed);
  TEST_ASSERT_EQUAL_UINT32(0u, n->course);
  TEST_ASSERT_EQUAL_UINT32(0u, n->heading);
  TEST_ASSERT_EQUAL_UINT32(0u, n->beyond);
  for (k = 0u; k < sizeof(n->mode); k++) {
    TEST_ASSERT_EQUAL_CHAR_MESSAGE('\0', n->mode[k], text);
  }
}

/* The time of day and date of RMCs without a fix (status V, mode N), of
 * valid RMCs and of ZDAs, against pynmeagps's reading of the text. */
static void test_drdc_nmea_parse_date_keeps_the_date(void)
{
  size_t i;

  for (i = 0u; i < COUNT(nmea_date_vectors); i++) {
    const struct nmea_date_vector *v = &nmea_date_vectors[i];
    drdc_nmea_t n;
    drdc_nmea_t full;

    sentinel(&n);
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        DRDC_OK, drdc_nmea_parse_date(v->text, v->length, v->flags, &n),
        v->text);
    TEST_ASSERT_EQUAL_INT_MESSAGE(v->type, n.type, v->text);
    TEST_ASSERT_EQUAL_STRING(v->talker, n.talker);
    TEST_ASSERT_EQUAL_HEX32_MESSAGE(v->has, n.has, v->text);
    TEST_ASSERT_EQUAL_INT32(v->tod[0], n.time.hour);
    TEST_ASSERT_EQUAL_INT32(v->tod[1], n.time.minute);
    TEST_ASSERT_EQUAL_INT32(v->tod[2], n.time.second);
    TEST_ASSERT_EQUAL_INT32(v->tod[3], n.time.nsec);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(v->date[0], n.year, v->text);
    TEST_ASSERT_EQUAL_INT32(v->date[1], n.month);
    TEST_ASSERT_EQUAL_INT32(v->date[2], n.day);
    TEST_ASSERT_EQUAL_INT32(v->date[3], n.zone_hours);
    TEST_ASSERT_EQUAL_INT32(v->date[4], n.zone_minutes);
    assert_date_only(&n, v->text);
    /* a ZDA is all date: the same record as drdc_nmea_parse()'s; an RMC
     * with a fix has that record's time and date */
    sentinel(&full);
    if (drdc_nmea_parse_with(v->text, v->length, v->flags, &full) == DRDC_OK) {
      if (v->type == DRDC_NMEA_ZDA) {
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&full, &n, sizeof n, v->text);
      }
      TEST_ASSERT_EQUAL_MEMORY(&full.time, &n.time, sizeof n.time);
      TEST_ASSERT_EQUAL_INT32(full.year, n.year);
      TEST_ASSERT_EQUAL_INT32(full.month, n.month);
      TEST_ASSERT_EQUAL_INT32(full.day, n.day);
    } else {
      /* only an RMC without a fix is refused by the full parse */
      TEST_ASSERT_EQUAL_INT_MESSAGE(
          DRDC_E_NO_FIX,
          drdc_nmea_parse_with(v->text, v->length, v->flags, &full), v->text);
    }
  }
}

/* Every refusal of drdc_nmea_parse_date() gives its status and leaves
 * the output as it was; the test names every status it documents. */
static void test_drdc_nmea_parse_date_bad_input(void)
{
  static const drdc_status_t documented[] = {
      DRDC_E_RANGE,         DRDC_E_SYNTAX,   DRDC_E_CHARACTER, DRDC_E_TRUNCATED,
      DRDC_E_OVERLONG,      DRDC_E_TRAILING, DRDC_E_CHECKSUM,  DRDC_E_SENTENCE,
      DRDC_E_MISSING_FIELD, DRDC_E_HOUR,     DRDC_E_MINUTE,    DRDC_E_SECOND,
      DRDC_E_DAY,           DRDC_E_MONTH,    DRDC_E_YEAR,
  };
  drdc_nmea_t n;
  size_t i;
  size_t k;

  for (i = 0u; i < COUNT(nmea_bad_date_vectors); i++) {
    const struct nmea_bad_vector *v = &nmea_bad_date_vectors[i];

    sentinel(&n);
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        v->status, drdc_nmea_parse_date(v->text, v->length, v->flags, &n),
        v->text);
    TEST_ASSERT_TRUE(unchanged(&n));
  }
  for (k = 0u; k < COUNT(documented); k++) {
    int seen = 0;

    for (i = 0u; i < COUNT(nmea_bad_date_vectors); i++) {
      if (nmea_bad_date_vectors[i].status == documented[k]) {
        seen = 1;
      }
    }
    TEST_ASSERT_TRUE_MESSAGE(seen, drdc_status_name(documented[k]));
  }
  sentinel(&n);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_nmea_parse_date(NULL, 10u, 0u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL, drdc_nmea_parse_date(nmea_date_vectors[0].text,
                                        nmea_date_vectors[0].length, 0u, NULL));
  TEST_ASSERT_TRUE(unchanged(&n));
  /* every prefix from the end of a buffer: no read past `length` */
  for (i = 0u; i < COUNT(nmea_date_vectors); i++) {
    const struct nmea_date_vector *v = &nmea_date_vectors[i];
    char buffer[BUFFER];
    size_t len;

    for (len = 0u; len <= v->length; len++) {
      char *start = &buffer[BUFFER - len];

      for (k = 0u; k < len; k++) {
        start[k] = v->text[k];
      }
      sentinel(&n);
      if (drdc_nmea_parse_date(start, len, 0u, &n) != DRDC_OK) {
        TEST_ASSERT_TRUE(unchanged(&n));
      }
    }
  }
}

/* A fix dated by an RMC without a fix or a ZDA, across midnight both
 * ways and half a day apart, against Python's calendar. */
static void test_nmea_utc_on_the_date_of_an_rmc_without_a_fix(void)
{
  size_t i;

  for (i = 0u; i < COUNT(nmea_stitch_vectors); i++) {
    const struct nmea_stitch_vector *v = &nmea_stitch_vectors[i];
    drdc_nmea_t dated;
    drdc_nmea_t fix;
    drdc_time_t t = {0, 0};

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_nmea_parse_date(v->dated, v->dated_length, 0u, &dated));
    parse_ok(v->text, v->length, &fix);
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        DRDC_OK, drdc_nmea_utc(NULL, &dated, &fix, &t), v->text);
    TEST_ASSERT_EQUAL_INT64_MESSAGE(v->sec, t.sec, v->text);
    TEST_ASSERT_EQUAL_INT32(v->nsec, t.nsec);
  }
}

/* Every decoder, in the order of drdc_nmea_type_t. */
static const drdc_nmea_decoder_t *const every_decoder[] = {
    &drdc_nmea_gga_decoder, &drdc_nmea_rmc_decoder, &drdc_nmea_gns_decoder,
    &drdc_nmea_zda_decoder, &drdc_nmea_gst_decoder, &drdc_nmea_gll_decoder,
    &drdc_nmea_vtg_decoder, &drdc_nmea_hdt_decoder, &drdc_nmea_ths_decoder,
    &drdc_nmea_gsa_decoder};

/* drdc_nmea_parse_some() with every decoder, or with the corpus entry's
 * own alone, gives what drdc_nmea_parse() gives (the corpus checks that
 * against the fraction model), in both modes; without the entry's own it
 * refuses a sentence that frames, or gives the framing's fault, and
 * leaves the output as it was. */
static void test_drdc_nmea_parse_some_decodes_as_parse(void)
{
  size_t i;
  size_t k;

  TEST_ASSERT_EQUAL_size_t(10u, COUNT(every_decoder));
  for (i = 0u; i < COUNT(nmea_vectors); i++) {
    const struct nmea_vector *v = &nmea_vectors[i];
    const drdc_nmea_decoder_t *others[9];
    const drdc_nmea_decoder_t *const *own = &every_decoder[v->type];
    uint32_t flags;
    size_t n_others = 0u;

    for (k = 0u; k < COUNT(every_decoder); k++) {
      if (k != (size_t)v->type) {
        others[n_others] = every_decoder[k];
        n_others++;
      }
    }
    for (flags = 0u; flags <= DRDC_NMEA_STRICT; flags++) {
      drdc_nmea_t want;
      drdc_nmea_t got;
      drdc_status_t st;
      drdc_status_t without;

      sentinel(&want);
      st = drdc_nmea_parse_with(v->text, v->length, flags, &want);
      sentinel(&got);
      TEST_ASSERT_EQUAL_INT_MESSAGE(
          st,
          drdc_nmea_parse_some(v->text, v->length, flags, every_decoder,
                               COUNT(every_decoder), &got),
          v->text);
      TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&want, &got, sizeof got, v->text);
      sentinel(&got);
      TEST_ASSERT_EQUAL_INT_MESSAGE(
          st, drdc_nmea_parse_some(v->text, v->length, flags, own, 1u, &got),
          v->text);
      TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&want, &got, sizeof got, v->text);
      sentinel(&got);
      without = drdc_nmea_parse_some(v->text, v->length, flags, others,
                                     n_others, &got);
      TEST_ASSERT_TRUE_MESSAGE((without == DRDC_E_SENTENCE) ||
                                   ((st != DRDC_OK) && (without == st)),
                               v->text);
      TEST_ASSERT_TRUE(unchanged(&got));
    }
  }
}

/* The statuses drdc_nmea_parse_some() adds to drdc_nmea_parse_with()'s,
 * each leaving the output as it was. */
static void test_drdc_nmea_parse_some_bad_input(void)
{
  static const char gga[] = "$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,"
                            "12,0.7,754.3,M,-16.2,M,1.0,0001*66\r\n";
  static const char vtg[] = "$GPVTG,045.0,T,,M,2.57,N,4.76,K,A*09\r\n";
  const drdc_nmea_decoder_t *const gga_only[] = {&drdc_nmea_gga_decoder};
  const drdc_nmea_decoder_t *const with_null[] = {&drdc_nmea_gga_decoder, NULL};
  drdc_nmea_t n;

  sentinel(&n);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_nmea_parse_some(NULL, 10u, 0u, gga_only, 1u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_nmea_parse_some(gga, sizeof gga - 1u, 0u, gga_only, 1u, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_nmea_parse_some(gga, sizeof gga - 1u,
                                                          0u, NULL, 1u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_nmea_parse_some(gga, sizeof gga - 1u, 0u, with_null, 2u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      drdc_nmea_parse_some(gga, sizeof gga - 1u, 2u, gga_only, 1u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_SENTENCE,
      drdc_nmea_parse_some(vtg, sizeof vtg - 1u, 0u, gga_only, 1u, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_SENTENCE,
      drdc_nmea_parse_some(gga, sizeof gga - 1u, 0u, NULL, 0u, &n));
  TEST_ASSERT_TRUE(unchanged(&n));
  TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_nmea_parse_some(gga, sizeof gga - 1u, 0u,
                                                      gga_only, 1u, &n));
  TEST_ASSERT_EQUAL_INT(DRDC_NMEA_GGA, n.type);
}

void suite_nmea(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_corpus_matches_the_fraction_model);
  RUN_TEST(test_drdc_nmea_parse_malformations);
  RUN_TEST(test_drdc_nmea_parse_null);
  RUN_TEST(test_never_reads_past_the_buffer);
  RUN_TEST(test_drdc_nmea_utc_stitching);
  RUN_TEST(test_drdc_nmea_utc_bad_input);
  RUN_TEST(test_nmea_utc_extreme_time_fields_do_not_overflow);
  RUN_TEST(test_nmea_utc_dated_time_out_of_range_is_refused);
  RUN_TEST(test_drdc_nmea_parse_date_keeps_the_date);
  RUN_TEST(test_drdc_nmea_parse_date_bad_input);
  RUN_TEST(test_nmea_utc_on_the_date_of_an_rmc_without_a_fix);
  RUN_TEST(test_drdc_nmea_parse_some_decodes_as_parse);
  RUN_TEST(test_drdc_nmea_parse_some_bad_input);
}
