/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Array loops of the Python package's *_array functions: each calls
 *        one public function of the library per element, so that Python
 *        pays one ctypes call per array instead of one per element.
 *
 * Only python/build_backend.py compiles this file, into the package's
 * libdrdc.so (never into libdrdc.a); drdc/_lib.py declares the
 * prototypes. The caller passes contiguous arrays of n elements of the
 * types below (drdc/_check.py converts them). Where an element's status
 * is an error its outputs are 0 (the library leaves them unchanged, so
 * they are cleared first); DRDC_OK and the warnings have them written.
 */
#include <stddef.h>
#include <stdint.h>

#include <drdc/geo.h>
#include <drdc/orient.h>
#include <drdc/time_scales.h>
#include <drdc/units.h>

void drdc_batch_geo_to_utm(size_t n, const int64_t *lat, const int64_t *lon,
                           const int32_t *zone, int32_t *out_zone,
                           uint8_t *north, int64_t *easting, int64_t *northing,
                           int64_t *convergence, int64_t *scale,
                           int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_geo_utm_t u = {0, false, 0, 0};
    drdc_nas_t c = 0;
    drdc_q5_58_t k = 0;

    status[i] = (int32_t)drdc_geo_to_utm(lat[i], lon[i], zone[i], &u, &c, &k);
    out_zone[i] = u.zone;
    north[i] = u.north ? 1u : 0u;
    easting[i] = u.easting;
    northing[i] = u.northing;
    convergence[i] = c;
    scale[i] = k;
  }
}

/* convergence and scale NULL: the library then skips computing them (a
 * third of the reverse projection's time) */
void drdc_batch_geo_from_utm(size_t n, const int32_t *zone,
                             const int32_t *north, const int64_t *easting,
                             const int64_t *northing, int64_t *lat,
                             int64_t *lon, int64_t *convergence, int64_t *scale,
                             int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_geo_utm_t u;
    drdc_nas_t la = 0;
    drdc_nas_t lo = 0;
    drdc_nas_t c = 0;
    drdc_q5_58_t k = 0;

    u.zone = zone[i];
    u.north = (north[i] != 0);
    u.easting = easting[i];
    u.northing = northing[i];
    status[i] = (int32_t)drdc_geo_from_utm(&u, &la, &lo,
                                           (convergence != NULL) ? &c : NULL,
                                           (scale != NULL) ? &k : NULL);
    lat[i] = la;
    lon[i] = lo;
    if (convergence != NULL) {
      convergence[i] = c;
    }
    if (scale != NULL) {
      scale[i] = k;
    }
  }
}

void drdc_batch_time_utc_to_gps(size_t n, const int64_t *sec,
                                const int32_t *nsec, int32_t *week,
                                int32_t *tow, int32_t *out_nsec,
                                int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_time_t t;
    drdc_time_gps_t g = {0, 0, 0};

    t.sec = sec[i];
    t.nsec = nsec[i];
    status[i] = (int32_t)drdc_time_utc_to_gps(NULL, &t, &g);
    week[i] = g.week;
    tow[i] = g.tow;
    out_nsec[i] = g.nsec;
  }
}

void drdc_batch_time_gps_to_utc(size_t n, const int32_t *week,
                                const int32_t *tow, const int32_t *nsec,
                                int64_t *sec, int32_t *out_nsec,
                                int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_time_gps_t g;
    drdc_time_t t = {0, 0};

    g.week = week[i];
    g.tow = tow[i];
    g.nsec = nsec[i];
    status[i] = (int32_t)drdc_time_gps_to_utc(NULL, &g, &t);
    sec[i] = t.sec;
    out_nsec[i] = t.nsec;
  }
}

/* The conversions between two (seconds, nanoseconds) scales, by number:
 * the Python side names them in the same order. */
enum batch_count_conversion {
  BATCH_UTC_TO_TAI = 0,
  BATCH_TAI_TO_UTC = 1,
  BATCH_UTC_TO_UNIX = 2,
  BATCH_UNIX_TO_UTC = 3
};

static drdc_status_t convert_count(int32_t which, int64_t sec, int32_t nsec,
                                   int64_t *out_sec, int32_t *out_nsec)
{
  drdc_status_t st;
  drdc_time_t utc = {sec, nsec};
  drdc_time_count_t count = {sec, nsec};
  drdc_time_t utc_out = {0, 0};
  drdc_time_count_t count_out = {0, 0};

  /* 0 outputs on every error, an unknown `which` too */
  *out_sec = 0;
  *out_nsec = 0;
  switch (which) {
  case BATCH_UTC_TO_TAI:
    st = drdc_time_utc_to_tai(NULL, &utc, &count_out);
    break;
  case BATCH_TAI_TO_UTC:
    st = drdc_time_tai_to_utc(NULL, &count, &utc_out);
    break;
  case BATCH_UTC_TO_UNIX:
    st = drdc_time_utc_to_unix(NULL, &utc, &count_out);
    break;
  case BATCH_UNIX_TO_UTC:
    st = drdc_time_unix_to_utc(&count, &utc_out);
    break;
  default:
    return DRDC_E_RANGE;
  }
  if ((which == BATCH_TAI_TO_UTC) || (which == BATCH_UNIX_TO_UTC)) {
    *out_sec = utc_out.sec;
    *out_nsec = utc_out.nsec;
  } else {
    *out_sec = count_out.sec;
    *out_nsec = count_out.nsec;
  }
  return st;
}

void drdc_batch_time_count(int32_t which, size_t n, const int64_t *sec,
                           const int32_t *nsec, int64_t *out_sec,
                           int32_t *out_nsec, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    status[i] = (int32_t)convert_count(which, sec[i], nsec[i], &out_sec[i],
                                       &out_nsec[i]);
  }
}

void drdc_batch_quat_from_euler(size_t n, const uint32_t *yaw,
                                const uint32_t *pitch, const uint32_t *roll,
                                int32_t *s, int32_t *x, int32_t *y, int32_t *z,
                                int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_euler_t e;
    drdc_quat_t q = {0, 0, 0, 0};

    e.yaw = yaw[i];
    e.pitch = pitch[i];
    e.roll = roll[i];
    status[i] = (int32_t)drdc_quat_from_euler(&e, &q);
    s[i] = q.s;
    x[i] = q.x;
    y[i] = q.y;
    z[i] = q.z;
  }
}

void drdc_batch_euler_from_quat(size_t n, const int32_t *s, const int32_t *x,
                                const int32_t *y, const int32_t *z,
                                uint32_t *yaw, uint32_t *pitch, uint32_t *roll,
                                int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    drdc_quat_t q;
    drdc_euler_t e = {0u, 0u, 0u};

    q.s = s[i];
    q.x = x[i];
    q.y = y[i];
    q.z = z[i];
    status[i] = (int32_t)drdc_euler_from_quat(&q, &e);
    yaw[i] = e.yaw;
    pitch[i] = e.pitch;
    roll[i] = e.roll;
  }
}

void drdc_batch_units_convert(size_t n, const int64_t *raw, unsigned from_frac,
                              const drdc_unit_t *from, unsigned to_frac,
                              const drdc_unit_t *to, int64_t *out,
                              int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int64_t v = 0;

    status[i] =
        (int32_t)drdc_units_convert(raw[i], from_frac, from, to_frac, to, &v);
    out[i] = v;
  }
}

void drdc_batch_units_convert_expr(size_t n, const int64_t *raw,
                                   unsigned from_frac,
                                   const drdc_units_expr_t *from,
                                   unsigned to_frac,
                                   const drdc_units_expr_t *to, int64_t *out,
                                   int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int64_t v = 0;

    status[i] = (int32_t)drdc_units_convert_expr(raw[i], from_frac, from,
                                                 to_frac, to, &v);
    out[i] = v;
  }
}
