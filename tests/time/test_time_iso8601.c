/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief ISO 8601 text in and out: reference text from datetime and ERFA
 *        (every leap second), digits and buffer sizes, and the bad-text
 *        catalogue with its statuses.
 */
#include <drdc/time_iso8601.h>

#include "suites.h"
#include "unity.h"
#include "vectors_iso8601.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static void test_format_and_parse_match_the_reference(void)
{
  size_t i;

  for (i = 0; i < COUNT(iso8601_vectors); i++) {
    const struct iso8601_vector *v = &iso8601_vectors[i];
    drdc_time_t t = {v->sec, v->nsec};
    drdc_time_t back = {0, 0};
    char text[DRDC_TIME_ISO8601_SIZE];

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_time_iso8601_format(NULL, &t, 9, text, sizeof text));
    TEST_ASSERT_EQUAL_STRING(v->text, text);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_time_iso8601_parse(NULL, v->text, &back));
    TEST_ASSERT_EQUAL_INT64(v->sec, back.sec);
    TEST_ASSERT_EQUAL_INT32(v->nsec, back.nsec);
  }
}

static void test_fraction_digits_and_buffer(void)
{
  drdc_time_t t = {INT64_C(1483228799), 1987654321}; /* 23:59:60.987654321 */
  char text[DRDC_TIME_ISO8601_SIZE] = "unchanged";
  drdc_time_t back = {0, 0};

  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_iso8601_format(NULL, &t, 0, text, 21));
  TEST_ASSERT_EQUAL_STRING("2016-12-31T23:59:60Z", text);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_time_iso8601_format(NULL, &t, 3, text, 25));
  TEST_ASSERT_EQUAL_STRING("2016-12-31T23:59:60.987Z", text); /* truncated */
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        drdc_time_iso8601_format(NULL, &t, 3, text, 24));
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        drdc_time_iso8601_format(NULL, &t, 9, text, 30));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_iso8601_format(NULL, &t, 10, text, 31));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        drdc_time_iso8601_format(NULL, &t, -1, text, 31));
  TEST_ASSERT_EQUAL_STRING("2016-12-31T23:59:60.987Z", text);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_time_iso8601_format(NULL, &t, 3, NULL, 31));
  t.sec -= 86400; /* 2016-12-30 has no leap second */
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND,
                        drdc_time_iso8601_format(NULL, &t, 3, text, 31));
  /* short fractions scale up; both calendar ends */
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_time_iso8601_parse(NULL, "0001-01-01T00:00:00.5Z", &back));
  TEST_ASSERT_EQUAL_INT64(INT64_C(-62135596800), back.sec);
  TEST_ASSERT_EQUAL_INT32(500000000, back.nsec);
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK, drdc_time_iso8601_parse(NULL, "9999-12-31T23:59:59Z", &back));
  TEST_ASSERT_EQUAL_INT64(INT64_C(253402300799), back.sec);
  TEST_ASSERT_EQUAL_INT32(0, back.nsec);
}

static void test_bad_text_gives_its_status(void)
{
  static const struct {
    const char *text;
    drdc_status_t status;
  } bad[] = {
      {"2024-01-01T00:00:00ZX", DRDC_E_TRAILING}, /* trailing garbage */
      {"2024-01-01T00:00:00Z ", DRDC_E_TRAILING},
      {"2024-01-01T00:00:00Z\n", DRDC_E_TRAILING},
      {"2024-01-01T00:00:00.5Z0", DRDC_E_TRAILING},
      {"", DRDC_E_SYNTAX},
      {"2024", DRDC_E_SYNTAX},
      {"2024-01-01", DRDC_E_SYNTAX},
      {"2024-01-01T00:00:00", DRDC_E_SYNTAX},  /* no Z */
      {"2024-01-01 00:00:00Z", DRDC_E_SYNTAX}, /* space for T */
      {"2024-01-01t00:00:00z", DRDC_E_SYNTAX},
      {"2024-1-01T00:00:00Z", DRDC_E_SYNTAX},
      {"+2024-01-01T00:00:00Z", DRDC_E_SYNTAX},
      {"2024-01-01T00:00:00+00:00", DRDC_E_SYNTAX},
      {"2024-01-01T00:00:00.Z", DRDC_E_SYNTAX}, /* no fraction digit */
      {"2024-01-01T00:00:00.1234567890Z", DRDC_E_SYNTAX}, /* 10 digits */
      {"2024-01-01T00:00:0aZ", DRDC_E_SYNTAX},
      {"2024-13-01T00:00:00Z", DRDC_E_MONTH}, /* month 13 */
      {"2024-00-01T00:00:00Z", DRDC_E_MONTH},
      {"2024-01-00T00:00:00Z", DRDC_E_DAY},  /* day 0 */
      {"2023-02-29T00:00:00Z", DRDC_E_DAY},  /* Feb 29, common year */
      {"0000-01-01T00:00:00Z", DRDC_E_YEAR}, /* out-of-range year */
      {"2024-01-01T24:00:00Z", DRDC_E_HOUR},
      {"2024-01-01T00:60:00Z", DRDC_E_MINUTE},
      {"2024-01-01T00:00:61Z", DRDC_E_SECOND},
      {"2015-12-31T23:59:60Z", DRDC_E_SECOND},     /* no leap second */
      {"2016-12-31T23:59:60.999999999Z", DRDC_OK}, /* but here there is */
  };
  size_t i;

  for (i = 0; i < COUNT(bad); i++) {
    drdc_time_t t = {7, 7};

    TEST_ASSERT_EQUAL_INT_MESSAGE(
        bad[i].status, drdc_time_iso8601_parse(NULL, bad[i].text, &t),
        bad[i].text);
    if (bad[i].status != DRDC_OK) {
      TEST_ASSERT_EQUAL_INT64(7, t.sec);
      TEST_ASSERT_EQUAL_INT32(7, t.nsec);
    }
  }
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_time_iso8601_parse(NULL, NULL, NULL));
}

void suite_time_iso8601(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_format_and_parse_match_the_reference);
  RUN_TEST(test_fraction_digits_and_buffer);
  RUN_TEST(test_bad_text_gives_its_status);
}
