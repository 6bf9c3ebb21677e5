/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief UTC <-> civil, TAI, GPS, Unix and RTEMS against ERFA, the IERS
 *        leap-second file and Python's datetime: every leap second since
 *        1972, the GPS week rollovers, year and month ends and 10 000
 *        random instants 1972..2100, all exact to the nanosecond; JAUS
 *        time stamps of the same random instants.
 */
#include <drdc/time_jaus.h>
#include <drdc/time_scales.h>

#include "suites.h"
#include "unity.h"
#include "vectors_time.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
#define NS       INT32_C(1000000000)
#define DAY      INT64_C(86400)
/* TAI seconds since 1958 of the GPS epoch (GPS = TAI - 19 s). */
#define GPS_EPOCH_TAI  INT64_C(694656019)
#define UNIX_GPS_EPOCH INT64_C(315964800)

static int64_t floor_div(int64_t a, int64_t b)
{
  return ((a % b) < 0) ? ((a / b) - 1) : (a / b);
}

/* Status every offset-dependent conversion must give on a UTC day. */
static drdc_status_t expected_status(int64_t utc_sec)
{
  return (floor_div(utc_sec, DAY) >= LEAP_ORACLE_EXPIRY_DAY)
             ? DRDC_W_LEAP_EXPIRED
             : DRDC_OK;
}

static void test_builtin_table_is_the_iers_table(void)
{
  const drdc_time_leap_t *l = drdc_time_leap_builtin();
  size_t i;

  TEST_ASSERT_EQUAL_INT32(COUNT(leap_oracle), l->table_count);
  TEST_ASSERT_EQUAL_INT32(0, l->extra_count);
  for (i = 0; i < COUNT(leap_oracle); i++) {
    TEST_ASSERT_EQUAL_INT32(leap_oracle[i][0], l->table[i].day);
    TEST_ASSERT_EQUAL_INT32(leap_oracle[i][1], l->table[i].tai_utc);
  }
  TEST_ASSERT_EQUAL_INT32(LEAP_ORACLE_EXPIRY_DAY, l->expiry_day);
  TEST_ASSERT_EQUAL_INT32(LEAP_ORACLE_EXPIRY_DAY,
                          DRDC_TIME_LEAP_BUILTIN_EXPIRY_DAY);
}

/* Checks one instant both ways through every scale; returns NULL or the
 * name of the first mismatch. */
static const char *check_instant(const drdc_time_civil_t *c, int64_t utc_sec,
                                 int32_t nsec, int64_t tai_sec)
{
  drdc_status_t want = expected_status(utc_sec);
  drdc_time_t t = {0, 0};
  drdc_time_t back = {0, 0};
  drdc_time_civil_t c2;
  drdc_time_count_t k = {0, 0};
  drdc_time_gps_t g = {0, 0, 0};
  int32_t sub = nsec % NS;
  int64_t unix_sec = utc_sec + ((nsec >= NS) ? 1 : 0);

  if ((drdc_time_from_civil(NULL, c, &t) != DRDC_OK) || (t.sec != utc_sec) ||
      (t.nsec != nsec)) {
    return "civil -> utc";
  }
  if ((drdc_time_to_civil(NULL, &t, &c2) != DRDC_OK) || (c2.year != c->year) ||
      (c2.month != c->month) || (c2.day != c->day) || (c2.hour != c->hour) ||
      (c2.minute != c->minute) || (c2.second != c->second) ||
      (c2.nsec != c->nsec)) {
    return "utc -> civil";
  }
  if ((drdc_time_utc_to_tai(NULL, &t, &k) != want) || (k.sec != tai_sec) ||
      (k.nsec != sub)) {
    return "utc -> tai";
  }
  if ((drdc_time_tai_to_utc(NULL, &k, &back) != want) || (back.sec != t.sec) ||
      (back.nsec != t.nsec)) {
    return "tai -> utc";
  }
  if (utc_sec >= UNIX_GPS_EPOCH) {
    int64_t gs = tai_sec - GPS_EPOCH_TAI;

    if ((drdc_time_utc_to_gps(NULL, &t, &g) != want) ||
        (g.week != (int32_t)(gs / 604800)) ||
        (g.tow != (int32_t)(gs % 604800)) || (g.nsec != sub)) {
      return "utc -> gps";
    }
    if ((drdc_time_gps_to_utc(NULL, &g, &back) != want) ||
        (back.sec != t.sec) || (back.nsec != t.nsec)) {
      return "gps -> utc";
    }
  }
  if ((drdc_time_utc_to_unix(NULL, &t, &k) != DRDC_OK) || (k.sec != unix_sec) ||
      (k.nsec != sub)) {
    return "utc -> unix";
  }
  if ((drdc_time_unix_to_utc(&k, &back) != DRDC_OK) || (back.sec != unix_sec) ||
      (back.nsec != sub)) {
    return "unix -> utc";
  }
  if ((drdc_time_utc_to_rtems(NULL, &t, &k) != DRDC_OK) ||
      (k.sec != unix_sec - DRDC_TIME_RTEMS_EPOCH_UNIX) || (k.nsec != sub)) {
    return "utc -> rtems";
  }
  if ((drdc_time_rtems_to_utc(&k, &back) != DRDC_OK) ||
      (back.sec != unix_sec) || (back.nsec != sub)) {
    return "rtems -> utc";
  }
  return NULL;
}

static void test_special_instants_match_erfa(void)
{
  size_t i;

  for (i = 0; i < COUNT(time_specials); i++) {
    const struct time_special *v = &time_specials[i];
    drdc_time_civil_t c;
    const char *what;

    c.year = v->year;
    c.month = v->month;
    c.day = v->day;
    c.hour = v->hour;
    c.minute = v->minute;
    c.second = v->second;
    c.nsec = v->nsec % NS;
    what = check_instant(&c, (int64_t)v->utc_sec, v->nsec,
                         (int64_t)v->utc_sec + DRDC_TIME_TAI_EPOCH_TO_UNIX +
                             v->tai_excess);
    if (what != NULL) {
      UnityPrint("special instant ");
      UnityPrintNumber((UNITY_INT)i);
      TEST_FAIL_MESSAGE(what);
      return;
    }
  }
}

static uint32_t lcg_next(uint64_t *state)
{
  *state = (*state * LCG_MUL) + LCG_ADD;
  return (uint32_t)(*state >> 32);
}

static void test_random_instants_match_erfa(void)
{
  uint64_t state = RANDOM_SEED;
  size_t i;

  for (i = 0; i < COUNT(random_dates); i++) {
    uint32_t a = lcg_next(&state);
    uint32_t b = lcg_next(&state);
    int64_t sec = RANDOM_START + (int64_t)(((uint64_t)a * RANDOM_SPAN) >> 32);
    int32_t nsec = (int32_t)(((uint64_t)b * (uint64_t)NS) >> 32);
    int32_t sod = (int32_t)(sec % DAY);
    uint16_t date = random_dates[i];
    drdc_time_civil_t c;
    const char *what;

    c.year = 1972 + (date >> 9);
    c.month = (date >> 5) & 15;
    c.day = date & 31;
    c.hour = sod / 3600;
    c.minute = (sod / 60) % 60;
    c.second = sod % 60;
    c.nsec = nsec;
    /* the expected status comes from the table's flag, cross-checked */
    if (((random_tai_utc[i] & 0x80) != 0) !=
        (expected_status(sec) == DRDC_W_LEAP_EXPIRED)) {
      TEST_FAIL_MESSAGE("expiry flag of the vector disagrees");
      return;
    }
    what = check_instant(&c, sec, nsec,
                         sec + DRDC_TIME_TAI_EPOCH_TO_UNIX +
                             (random_tai_utc[i] & 0x7f));
    if (what != NULL) {
      UnityPrint("random instant ");
      UnityPrintNumber((UNITY_INT)i);
      TEST_FAIL_MESSAGE(what);
      return;
    }
  }
}

/* JAUS stamps of the random instants: the expected stamp is made of the
 * oracle's fields, and the stamp resolves back by a reference less than
 * 14 days (half the shortest month) away on either side. */
static void test_random_instants_jaus_stamps(void)
{
  uint64_t state = RANDOM_SEED;
  size_t i;

  for (i = 0; i < COUNT(random_dates); i++) {
    uint32_t a = lcg_next(&state);
    uint32_t b = lcg_next(&state);
    int64_t sec = RANDOM_START + (int64_t)(((uint64_t)a * RANDOM_SPAN) >> 32);
    int32_t nsec = (int32_t)(((uint64_t)b * (uint64_t)NS) >> 32);
    uint32_t sod = (uint32_t)(sec % DAY);
    uint32_t want = ((uint32_t)(random_dates[i] & 31) << 27) |
                    ((sod / 3600) << 22) | (((sod / 60) % 60) << 16) |
                    ((sod % 60) << 10) | (uint32_t)(nsec / 1000000);
    /* reference: within 14 days - 1 s, from bits already drawn */
    int64_t shift = (int64_t)((a ^ b) % (28u * 86400u - 1u)) - (14 * DAY - 1);
    drdc_time_t t = {sec, nsec};
    drdc_time_t ref = {sec + shift, (int32_t)(b % (uint32_t)NS)};
    drdc_time_t back = {0, 0};
    uint32_t stamp = 0;

    if ((drdc_time_jaus_pack(NULL, &t, &stamp) != DRDC_OK) || (stamp != want)) {
      UnityPrintNumber((UNITY_INT)i);
      TEST_FAIL_MESSAGE("jaus pack");
      return;
    }
    if ((drdc_time_jaus_to_utc(NULL, stamp, &ref, &back) != DRDC_OK) ||
        (back.sec != sec) || (back.nsec != (nsec / 1000000) * 1000000)) {
      UnityPrintNumber((UNITY_INT)i);
      TEST_FAIL_MESSAGE("jaus to utc");
      return;
    }
  }
}

void suite_time_scales(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_builtin_table_is_the_iers_table);
  RUN_TEST(test_special_instants_match_erfa);
  RUN_TEST(test_random_instants_match_erfa);
  RUN_TEST(test_random_instants_jaus_stamps);
}
