/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief drdc.nmea's loops: the lines of a buffer found, each parsed with
 *        drdc_nmea_parse_with() into columns, and every sentence with a
 *        time of day dated with drdc_nmea_utc() on the date of the RMC or
 *        ZDA before it (drdc_nmea_parse_date(): those without a fix too).
 *
 * Only python/build_backend.py compiles this file, into the package's
 * libdrdc.so; drdc/_nmea.py declares the prototypes and the column
 * structure. Lines are those of the `drdc` tool's reader: they end at LF,
 * the LF and one CR before it are no part of the sentence, and a last
 * line without LF is a line.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/nmea.h>

/** The output columns, n rows each (drdc/_nmea.py allocates them). Where
 *  a line's status is an error its row is 0 but for the status, type -1
 *  and utc_status. */
typedef struct drdc_batch_nmea_columns {
  int32_t *status;
  int8_t *type; /* drdc_nmea_type_t, -1 where the line is refused */
  /* text columns as numpy's str arrays hold them, one UCS-4 code unit a
   * character, NUL-padded: no conversion of a bytes column afterwards */
  uint32_t *talker; /* 2 a row */
  uint32_t *has;
  uint32_t *beyond;
  int32_t *hour;
  int32_t *minute;
  int32_t *second;
  int32_t *nsec;
  int64_t *latitude;
  int64_t *longitude;
  int64_t *altitude;
  int64_t *separation;
  int32_t *quality;
  int32_t *satellites;
  int32_t *hdop;
  int32_t *pdop;
  int32_t *vdop;
  int32_t *speed;
  uint32_t *course;
  uint32_t *course_magnetic;
  uint32_t *heading;
  uint32_t *mode; /* 8 a row */
  int32_t *fix_type;
  int32_t *system_id;
  uint16_t *satellite_ids; /* DRDC_NMEA_GSA_IDS a row */
  int32_t *year;
  int32_t *month;
  int32_t *day;
  int32_t *zone_hours;
  int32_t *zone_minutes;
  int32_t *rms;
  int32_t *sigma_major;
  int32_t *sigma_minor;
  uint32_t *orientation;
  int32_t *sigma_latitude;
  int32_t *sigma_longitude;
  int32_t *sigma_altitude;
  int64_t *utc_sec;  /* NULL: no dating */
  int32_t *utc_nsec; /* NULL with utc_sec */
  int32_t *utc_status;
} drdc_batch_nmea_columns_t;

/** How many lines `size` bytes hold: one per LF, and one more for text
 *  after the last LF. */
size_t drdc_batch_line_count(const char *buf, size_t size)
{
  size_t count = 0u;
  const char *p = buf;
  const char *end = buf + size;

  while (p < end) {
    const char *lf = memchr(p, '\n', (size_t)(end - p));

    count++;
    if (lf == NULL) {
      break;
    }
    p = lf + 1;
  }
  return count;
}

/** Line i of the first n of buf is buf[starts[i] .. ends[i]), its LF
 *  included when it has one. */
void drdc_batch_line_bounds(const char *buf, size_t size, size_t n,
                            int64_t *starts, int64_t *ends)
{
  size_t i = 0u;
  const char *p = buf;
  const char *end = buf + size;

  while ((i < n) && (p < end)) {
    const char *lf = memchr(p, '\n', (size_t)(end - p));

    starts[i] = (int64_t)(p - buf);
    p = (lf == NULL) ? end : lf + 1;
    ends[i] = (int64_t)(p - buf);
    i++;
  }
}

static void put_record(const drdc_batch_nmea_columns_t *c, size_t i,
                       const drdc_nmea_t *r)
{
  size_t k;

  c->type[i] = (int8_t)r->type;
  c->talker[2u * i] = (uint8_t)r->talker[0];
  c->talker[(2u * i) + 1u] = (uint8_t)r->talker[1];
  c->has[i] = r->has;
  c->beyond[i] = r->beyond;
  c->hour[i] = r->time.hour;
  c->minute[i] = r->time.minute;
  c->second[i] = r->time.second;
  c->nsec[i] = r->time.nsec;
  c->latitude[i] = r->latitude;
  c->longitude[i] = r->longitude;
  c->altitude[i] = r->altitude;
  c->separation[i] = r->separation;
  c->quality[i] = r->quality;
  c->satellites[i] = r->satellites;
  c->hdop[i] = r->hdop;
  c->pdop[i] = r->pdop;
  c->vdop[i] = r->vdop;
  c->speed[i] = r->speed;
  c->course[i] = r->course;
  c->course_magnetic[i] = r->course_magnetic;
  c->heading[i] = r->heading;
  for (k = 0u; k < 8u; k++) {
    c->mode[(8u * i) + k] = (uint8_t)r->mode[k];
  }
  c->fix_type[i] = r->fix_type;
  c->system_id[i] = r->system_id;
  for (k = 0u; k < DRDC_NMEA_GSA_IDS; k++) {
    c->satellite_ids[(DRDC_NMEA_GSA_IDS * i) + k] = r->satellite_ids[k];
  }
  c->year[i] = r->year;
  c->month[i] = r->month;
  c->day[i] = r->day;
  c->zone_hours[i] = r->zone_hours;
  c->zone_minutes[i] = r->zone_minutes;
  c->rms[i] = r->rms;
  c->sigma_major[i] = r->sigma_major;
  c->sigma_minor[i] = r->sigma_minor;
  c->orientation[i] = r->orientation;
  c->sigma_latitude[i] = r->sigma_latitude;
  c->sigma_longitude[i] = r->sigma_longitude;
  c->sigma_altitude[i] = r->sigma_altitude;
}

/* The time of day of row i as the record drdc_nmea_utc() reads. */
static void time_of_row(const drdc_batch_nmea_columns_t *c, size_t i,
                        drdc_nmea_t *s)
{
  s->has = c->has[i];
  s->time.hour = c->hour[i];
  s->time.minute = c->minute[i];
  s->time.second = c->second[i];
  s->time.nsec = c->nsec[i];
}

static void put_utc(const drdc_batch_nmea_columns_t *c, size_t i,
                    const drdc_nmea_t *dated, const drdc_nmea_t *s)
{
  drdc_time_t t = {0, 0};
  drdc_status_t st = drdc_nmea_utc(NULL, dated, s, &t);

  c->utc_status[i] = (int32_t)st;
  c->utc_sec[i] = drdc_status_is_error(st) ? 0 : t.sec;
  c->utc_nsec[i] = drdc_status_is_error(st) ? 0 : t.nsec;
}

/* The sentence of a line of buf[start .. end): without one LF at its end
 * and one CR before that, as the tool's reader takes them off. */
static size_t line_length(const char *text, int64_t start, int64_t end)
{
  size_t length = (size_t)(end - start);

  if ((length > 0u) && (text[length - 1u] == '\n')) {
    length--;
  }
  if ((length > 0u) && (text[length - 1u] == '\r')) {
    length--;
  }
  return length;
}

/* An RMC or ZDA by its address, so that the date-only parse runs only on
 * lines that may carry a date. */
static int may_be_dated(const char *text, size_t length)
{
  return (length >= 6u) && (text[0] == '$') &&
         ((memcmp(&text[3], "RMC", 3u) == 0) ||
          (memcmp(&text[3], "ZDA", 3u) == 0));
}

/**
 * Parse the n lines buf[starts[i] .. ends[i]) (one LF at the end and one
 * CR before it dropped) with drdc_nmea_parse_with(flags) into the
 * columns. With c->utc_sec not NULL, each decoded sentence with a time of
 * day gets the UTC instant drdc_nmea_utc() gives on the date of the last
 * RMC or ZDA before it in the lines (with a fix or not); sentences before
 * the first date get the first one's. utc_status: that call's status, the
 * line's own where it was refused, DRDC_E_MISSING_FIELD where the
 * sentence has no time of day or the lines no date.
 */
void drdc_batch_nmea_parse(const char *buf, size_t n, const int64_t *starts,
                           const int64_t *ends, uint32_t flags,
                           const drdc_batch_nmea_columns_t *c)
{
  drdc_nmea_t date;
  drdc_nmea_t r;
  size_t i;
  size_t first_dated = n;
  int dated = 0;
  int stitch = (c->utc_sec != NULL);

  memset(&date, 0, sizeof date);
  for (i = 0u; i < n; i++) {
    const char *text = buf + starts[i];
    size_t length = line_length(text, starts[i], ends[i]);
    drdc_status_t st;

    st = drdc_nmea_parse_with(text, length, flags, &r);
    c->status[i] = (int32_t)st;
    if (st != DRDC_OK) {
      c->type[i] = -1;
      if (stitch) {
        c->utc_status[i] = (int32_t)st;
      }
    } else {
      put_record(c, i, &r);
    }
    if (!stitch) {
      continue;
    }
    if ((st == DRDC_OK) && ((r.has & DRDC_NMEA_HAS_DATE) != 0u)) {
      date = r;
      dated = 1;
    } else if ((st == DRDC_E_NO_FIX) && may_be_dated(text, length) &&
               (drdc_nmea_parse_date(text, length, flags, &r) == DRDC_OK)) {
      date = r;
      dated = 1;
    } else {
      /* no date on this line */
    }
    if (dated && (first_dated == n)) {
      first_dated = i;
    }
    if (st != DRDC_OK) {
      continue;
    }
    if ((c->has[i] & DRDC_NMEA_HAS_TIME) == 0u) {
      c->utc_status[i] = (int32_t)DRDC_E_MISSING_FIELD;
    } else if (dated) {
      time_of_row(c, i, &r);
      put_utc(c, i, &date, &r);
    } else {
      /* dated below, once the first date is known */
      c->utc_status[i] = (int32_t)DRDC_E_MISSING_FIELD;
    }
  }
  if (!stitch || (first_dated == n)) {
    return;
  }
  /* the sentences before the first date: that date, found again */
  for (i = first_dated; i < n; i++) {
    const char *text = buf + starts[i];
    size_t length = line_length(text, starts[i], ends[i]);

    if (drdc_nmea_parse_date(text, length, flags, &date) == DRDC_OK) {
      break;
    }
  }
  for (i = 0u; i < first_dated; i++) {
    if ((c->status[i] == (int32_t)DRDC_OK) &&
        ((c->has[i] & DRDC_NMEA_HAS_TIME) != 0u)) {
      time_of_row(c, i, &r);
      put_utc(c, i, &date, &r);
    }
  }
}
