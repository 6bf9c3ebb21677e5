/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Array loops of the time functions beyond batch.c's: civil time
 *        both ways, ISO 8601 text both ways and JAUS time stamps, one
 *        public function call per element, the built-in leap table.
 *
 * Only python/build_backend.py compiles this file; drdc/_lib.py declares
 * the prototypes. Outputs of an element whose status is an error are 0
 * (text: all NUL).
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/time.h>
#include <drdc/time_iso8601.h>
#include <drdc/time_jaus.h>

/* civil[7 * i ..]: year, month, day, hour, minute, second, nsec */
void drdc_batch_time_from_civil(size_t n, const int32_t *civil, int64_t *sec,
                                int32_t *nsec, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    const int32_t *f = &civil[7u * i];
    drdc_time_civil_t c;
    drdc_time_t t = {0, 0};

    c.year = f[0];
    c.month = f[1];
    c.day = f[2];
    c.hour = f[3];
    c.minute = f[4];
    c.second = f[5];
    c.nsec = f[6];
    status[i] = (int32_t)drdc_time_from_civil(NULL, &c, &t);
    sec[i] = t.sec;
    nsec[i] = t.nsec;
  }
}

void drdc_batch_time_to_civil(size_t n, const int64_t *sec, const int32_t *nsec,
                              int32_t *civil, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int32_t *f = &civil[7u * i];
    drdc_time_t t;
    drdc_time_civil_t c = {0, 0, 0, 0, 0, 0, 0};

    t.sec = sec[i];
    t.nsec = nsec[i];
    status[i] = (int32_t)drdc_time_to_civil(NULL, &t, &c);
    f[0] = c.year;
    f[1] = c.month;
    f[2] = c.day;
    f[3] = c.hour;
    f[4] = c.minute;
    f[5] = c.second;
    f[6] = c.nsec;
  }
}

/* DRDC_TIME_ISO8601_SIZE bytes a row: the text and its NUL, zero-padded */
void drdc_batch_time_iso8601_format(size_t n, const int64_t *sec,
                                    const int32_t *nsec, int32_t digits,
                                    char *text, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    char *row = &text[i * (size_t)DRDC_TIME_ISO8601_SIZE];
    drdc_time_t t;
    drdc_status_t st;

    t.sec = sec[i];
    t.nsec = nsec[i];
    memset(row, 0, (size_t)DRDC_TIME_ISO8601_SIZE);
    st = drdc_time_iso8601_format(NULL, &t, digits, row,
                                  (size_t)DRDC_TIME_ISO8601_SIZE);
    status[i] = (int32_t)st;
    if (drdc_status_is_error(st)) {
      memset(row, 0, (size_t)DRDC_TIME_ISO8601_SIZE);
    }
  }
}

/* `width` bytes a row, NUL-padded; `scratch` width + 1 bytes */
void drdc_batch_time_iso8601_parse(size_t n, const char *text, size_t width,
                                   char *scratch, int64_t *sec, int32_t *nsec,
                                   int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_time_t t = {0, 0};

    memcpy(scratch, &text[i * width], width);
    scratch[width] = '\0';
    status[i] = (int32_t)drdc_time_iso8601_parse(NULL, scratch, &t);
    sec[i] = t.sec;
    nsec[i] = t.nsec;
  }
}

void drdc_batch_time_jaus_pack(size_t n, const int64_t *sec,
                               const int32_t *nsec, uint32_t *stamp,
                               int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_time_t t;
    uint32_t s = 0u;

    t.sec = sec[i];
    t.nsec = nsec[i];
    status[i] = (int32_t)drdc_time_jaus_pack(NULL, &t, &s);
    stamp[i] = s;
  }
}

void drdc_batch_time_jaus_to_utc(size_t n, const uint32_t *stamp,
                                 const int64_t *ref_sec,
                                 const int32_t *ref_nsec, int64_t *sec,
                                 int32_t *nsec, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_time_t ref;
    drdc_time_t t = {0, 0};

    ref.sec = ref_sec[i];
    ref.nsec = ref_nsec[i];
    status[i] = (int32_t)drdc_time_jaus_to_utc(NULL, stamp[i], &ref, &t);
    sec[i] = t.sec;
    nsec[i] = t.nsec;
  }
}
