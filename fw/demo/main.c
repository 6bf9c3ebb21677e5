/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Demo firmware: a pose node like one of libdrdc's robot controllers.
 *
 * It reads a scripted stream from a GNSS receiver (NMEA GGA and RMC
 * sentences, and HDT or THS true heading from a dual-antenna receiver when
 * it has one; on a board this would be a UART) and from an IMU (attitude
 * quaternions), and for each epoch prints the UTC and GPS time, the global
 * pose {W} (longitude, latitude, height, quaternion), {We} (the same with
 * Z-Y-X Euler angles), the JAUS scaled integers of the position and the
 * body of a JAUS Report Global Pose message (AS6009, little-endian) in
 * hex. All of it integer arithmetic; the same numbers come out of the host
 * tool drdc.
 * Then the UTM pose with the attitude turned to grid north by the
 * meridian convergence ({We-UTM}), the MGRS square to 1 m, and the local
 * pose {l} relative to the first fix (its body frame: x forward, y right,
 * z down).
 */
#include <stddef.h>

#include <drdc/fixed.h>
#include <drdc/geo.h>
#include <drdc/geo_mgrs.h>
#include <drdc/jaus_pose.h>
#include <drdc/jaus_scaled.h>
#include <drdc/nmea.h>
#include <drdc/orient.h>
#include <drdc/geo_pose.h>
#include <drdc/time.h>
#include <drdc/time_iso8601.h>
#include <drdc/time_jaus.h>
#include <drdc/time_scales.h>
#include <drdc/version.h>

#include "drdc_board.h"
#include "console.h"

/* The receiver's stream: one GGA and one RMC per second (RTK fixed, near
 * DRDC Suffield, Alberta), as a u-blox-style receiver sends them, and at
 * some epochs the true heading of a dual-antenna receiver (HDT, or THS
 * with its mode). One sentence a line, as the receiver sends it. */
typedef struct gnss_epoch {
  const char *gga;
  const char *rmc;
  const char *heading; /* HDT or THS, or NULL */
} gnss_epoch_t;

/* clang-format off */
static const gnss_epoch_t gnss[] = {
  {"$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,12,0.7,754.3,M,-16.2,M,1.0,0001*66\r\n",
   "$GNRMC,170000.00,A,5016.20000,N,11110.20000,W,2.57,045.00,221126,,,R*40\r\n",
   NULL},
  {"$GNGGA,170001.00,5016.20050,N,11110.19920,W,4,12,0.7,754.4,M,-16.2,M,1.0,0001*64\r\n",
   "$GNRMC,170001.00,A,5016.20050,N,11110.19920,W,2.57,045.00,221126,,,R*45\r\n",
   "$GNHDT,46.62,T*2D\r\n"},
  {"$GNGGA,170002.00,5016.20100,N,11110.19840,W,4,12,0.7,754.5,M,-16.2,M,1.0,0001*65\r\n",
   "$GNRMC,170002.00,A,5016.20100,N,11110.19840,W,2.57,045.00,221126,,,R*45\r\n",
   NULL},
  {"$GNGGA,170003.00,5016.20150,N,11110.19760,W,4,12,0.7,754.6,M,-16.2,M,1.0,0001*6F\r\n",
   "$GNRMC,170003.00,A,5016.20150,N,11110.19760,W,2.57,045.00,221126,,,R*4C\r\n",
   "$GNTHS,49.41,A*21\r\n"},
};
/* clang-format on */

/* The IMU's attitude at each epoch, body FRD to world NED, Q1.30. */
/* clang-format off */
static const drdc_quat_t imu[] = {
  { 991756660, -15826452, 13727054, 410976062 }, /* yaw 45.0 pitch 2.0 roll -1.0 */
  { 986281899, -15022750, 15980188, 423896769 }, /* yaw 46.5 pitch 2.2 roll -0.8 */
  { 980703000, -12282277, 16069705, 436731086 }, /* yaw 48.0 pitch 2.1 roll -0.5 */
  { 974954420, -10005645, 14990451, 449511465 }, /* yaw 49.5 pitch 1.9 roll -0.3 */
};
/* clang-format on */

#define EPOCHS (sizeof imu / sizeof imu[0])

/* The receiver's geoid separation N (GGA field 11), for ellipsoidal
 * heights in the local tangent plane. */
#define GEOID_SEPARATION   (INT64_C(-162) * 65536 / 10)
#define NAS_PER_DEGREE_INT DRDC_NAS_PER_DEGREE

static size_t length_of(const char *s)
{
  size_t n = 0;

  while (s[n] != '\0') {
    n++;
  }
  return n;
}

/* value * num / den rounded by the library's one rule */
static int64_t scaled(int64_t value, int64_t num, int64_t den)
{
  int64_t out = 0;

  (void)drdc_fx_muldiv_s64(value, num, den, &out);
  return out;
}

/* degrees with 9 decimals of an angle in nano-arcseconds */
static void put_nas(drdc_nas_t a)
{
  console_put_decimal(scaled(a, 1, 3600), 9u);
}

/* degrees with 8 decimals of a binary angle, in (-180, 180] */
static void put_bam(drdc_bam32_t a)
{
  /* 360e8 / 2^32 = 140625000 / 2^24 */
  console_put_decimal(scaled((int32_t)a, 140625000, INT64_C(1) << 24), 8u);
}

static void put_q1_30(drdc_q1_30_t v)
{
  console_put_decimal(scaled(v, 10000000, INT64_C(1) << 30), 7u);
}

/* bytes as lowercase hex, two digits each */
static void put_hex(const uint8_t *p, size_t n)
{
  static const char digits[] = "0123456789abcdef";
  size_t k;

  for (k = 0u; k < n; k++) {
    bsp_putc(digits[p[k] >> 4]);
    bsp_putc(digits[p[k] & 15u]);
  }
}

/* The JAUS Report Global Pose body of an epoch: position (MSL height),
 * attitude and time stamp; no RMS values (the receiver sends no GST). */
static drdc_status_t jaus_body(const drdc_nmea_t *gga, const drdc_euler_t *e,
                               const drdc_time_t *utc, uint8_t *buf,
                               size_t *length)
{
  drdc_jaus_global_pose_t b;
  drdc_status_t st;

  b.presence = DRDC_JAUS_PV_LATITUDE | DRDC_JAUS_PV_LONGITUDE |
               DRDC_JAUS_PV_ALTITUDE | DRDC_JAUS_PV_ROLL | DRDC_JAUS_PV_PITCH |
               DRDC_JAUS_PV_YAW | DRDC_JAUS_PV_TIME_STAMP;
  b.pose.latitude = gga->latitude;
  b.pose.longitude = gga->longitude;
  b.pose.height = gga->altitude;
  b.pose.e = *e;
  b.position_rms = 0;
  b.attitude_rms = 0u;
  st = drdc_time_jaus_pack(NULL, utc, &b.time_stamp);
  if (st == DRDC_OK) {
    st = drdc_jaus_global_pose_pack(&b, DRDC_JAUS_FORM_AS6009, buf,
                                    DRDC_JAUS_POSE_BODY_MAX, length);
  }
  return st;
}

static void put_status(drdc_status_t st)
{
  bsp_puts("  ERROR ");
  bsp_puts(drdc_status_name(st));
  bsp_putc('\n');
}

/* metres with 3 decimals of a Q47.16 length */
static void put_metres(drdc_q47_16_t m)
{
  console_put_decimal(scaled(m, 1000, 65536), 3u);
}

/* UTM, grid attitude, MGRS and the local pose of one epoch */
static drdc_status_t grid_and_local(const drdc_WPose_t *w,
                                    const drdc_WPose_t *first)
{
  drdc_WUTMPose_t u;
  drdc_euler_t grid = {0u, 0u, 0u};
  drdc_euler_t truth = {0u, 0u, 0u};
  drdc_lPose_t l;
  char mgrs[DRDC_GEO_MGRS_SIZE];
  drdc_status_t st;

  st = drdc_pose_wutm_from_w(w, DRDC_GEO_ZONE_STANDARD, &u);
  if (st == DRDC_OK) {
    st = drdc_euler_from_quat(&u.q, &grid);
  }
  if (st == DRDC_OK) {
    st = drdc_euler_from_quat(&w->q, &truth);
  }
  if (st == DRDC_OK) {
    st = drdc_geo_mgrs_from_utm(&u.utm, 5, mgrs, sizeof mgrs);
  }
  if (st == DRDC_OK) {
    st = drdc_pose_l_from_w(first, GEOID_SEPARATION, w, &l);
  }
  if (st != DRDC_OK) {
    return st;
  }
  bsp_puts("  UTM   ");
  console_put_i64(u.utm.zone);
  bsp_putc(u.utm.north ? 'n' : 's');
  bsp_putc(' ');
  put_metres(u.utm.easting);
  bsp_putc(' ');
  put_metres(u.utm.northing);
  bsp_puts(" m  convergence ");
  put_bam(truth.yaw - grid.yaw);
  bsp_puts(" deg  grid yaw ");
  put_bam(grid.yaw);
  bsp_puts("\n  MGRS  ");
  bsp_puts(mgrs);
  bsp_puts("\n  {l}   x ");
  put_metres(l.p.x);
  bsp_puts(" y ");
  put_metres(l.p.y);
  bsp_puts(" z ");
  put_metres(l.p.z);
  bsp_puts(" m from the first fix\n");
  return DRDC_OK;
}

/* The GNSS true heading beside the IMU's yaw: a pose node watches the
 * difference for drift of the IMU's heading. */
static void put_heading(const drdc_nmea_t *h, drdc_bam32_t imu_yaw)
{
  bsp_puts("  GNSS  heading ");
  put_bam(h->heading);
  bsp_puts(" deg true (");
  bsp_puts(h->talker);
  bsp_puts((h->type == DRDC_NMEA_HDT) ? "HDT" : "THS");
  bsp_puts("), IMU yaw - heading ");
  put_bam(imu_yaw - h->heading);
  bsp_puts(" deg\n");
}

static void epoch(unsigned k, const drdc_nmea_t *gga, const drdc_nmea_t *rmc,
                  const drdc_nmea_t *heading, drdc_WPose_t *first)
{
  drdc_WPose_t w;
  drdc_time_t utc = {0, 0};
  drdc_time_gps_t gps = {0, 0, 0};
  drdc_euler_t e = {0u, 0u, 0u};
  char iso[DRDC_TIME_ISO8601_SIZE];
  int64_t jaus_lat = 0;
  int64_t jaus_lon = 0;
  uint8_t body[DRDC_JAUS_POSE_BODY_MAX];
  size_t body_length = 0u;
  drdc_status_t st;

  st = drdc_nmea_utc(NULL, rmc, gga, &utc);
  if (st == DRDC_OK) {
    st = drdc_time_iso8601_format(NULL, &utc, 3, iso, sizeof iso);
  }
  if (st == DRDC_OK) {
    st = drdc_time_utc_to_gps(NULL, &utc, &gps);
  }
  if (st == DRDC_OK) {
    st = drdc_euler_from_quat(&imu[k], &e);
  }
  if (st == DRDC_OK) {
    st = drdc_jaus_scaled_encode(gga->latitude, -90 * NAS_PER_DEGREE_INT,
                                 90 * NAS_PER_DEGREE_INT, DRDC_JAUS_INT32,
                                 DRDC_JAUS_FORM_RA3, &jaus_lat);
  }
  if (st == DRDC_OK) {
    st = drdc_jaus_scaled_encode(gga->longitude, -180 * NAS_PER_DEGREE_INT,
                                 180 * NAS_PER_DEGREE_INT, DRDC_JAUS_INT32,
                                 DRDC_JAUS_FORM_RA3, &jaus_lon);
  }
  if (st == DRDC_OK) {
    st = jaus_body(gga, &e, &utc, body, &body_length);
  }
  if (st != DRDC_OK) {
    put_status(st);
    return;
  }
  bsp_puts("epoch ");
  console_put_u64(k + 1u);
  bsp_puts("  fix quality ");
  console_put_i64(gga->quality);
  bsp_puts(", ");
  console_put_i64(gga->satellites);
  bsp_puts(" satellites\n  UTC   ");
  bsp_puts(iso);
  bsp_puts("   GPS week ");
  console_put_i64(gps.week);
  bsp_puts(" TOW ");
  console_put_i64(gps.tow);
  bsp_puts("\n  {W}   lon ");
  put_nas(gga->longitude);
  bsp_puts(" lat ");
  put_nas(gga->latitude);
  bsp_puts(" deg  h ");
  console_put_decimal(scaled(gga->altitude, 1000, 65536), 3u);
  bsp_puts(" m MSL  q [");
  put_q1_30(imu[k].s);
  bsp_putc(' ');
  put_q1_30(imu[k].x);
  bsp_putc(' ');
  put_q1_30(imu[k].y);
  bsp_putc(' ');
  put_q1_30(imu[k].z);
  bsp_puts("]\n  {We}  yaw ");
  put_bam(e.yaw);
  bsp_puts(" pitch ");
  put_bam(e.pitch);
  bsp_puts(" roll ");
  put_bam(e.roll);
  bsp_puts(" deg\n  JAUS  latitude ");
  console_put_i64(jaus_lat);
  bsp_puts(" longitude ");
  console_put_i64(jaus_lon);
  bsp_puts(
      " (int32, RA 3.x scaled)\n  JAUS  Report Global Pose body (AS6009) ");
  put_hex(body, body_length);
  bsp_putc('\n');
  if (heading != NULL) {
    put_heading(heading, e.yaw);
  }

  w.longitude = gga->longitude;
  w.latitude = gga->latitude;
  w.height = gga->altitude;
  w.q = imu[k];
  if (k == 0u) {
    *first = w;
  }
  st = grid_and_local(&w, first);
  if (st != DRDC_OK) {
    put_status(st);
  }
}

int main(void)
{
  unsigned k;
  drdc_WPose_t first;

  bsp_puts("libdrdc-fx " DRDC_VERSION_STRING " pose-node demo on ");
  bsp_puts(bsp_name);
  bsp_puts(": GNSS (NMEA) + IMU -> UTC, GPS time, {W}, {We}, JAUS,"
           " {We-UTM}, MGRS, {l}\n");
  for (k = 0u; k < EPOCHS; k++) {
    const gnss_epoch_t *g = &gnss[k];
    drdc_nmea_t gga;
    drdc_nmea_t rmc;
    drdc_nmea_t heading;
    const drdc_nmea_t *has_heading = NULL;
    drdc_status_t st;

    st = drdc_nmea_parse(g->gga, length_of(g->gga), &gga);
    if (st == DRDC_OK) {
      st = drdc_nmea_parse(g->rmc, length_of(g->rmc), &rmc);
    }
    if ((st == DRDC_OK) && (g->heading != NULL)) {
      st = drdc_nmea_parse(g->heading, length_of(g->heading), &heading);
      has_heading = &heading;
    }
    if (st != DRDC_OK) {
      put_status(st);
      continue;
    }
    epoch(k, &gga, &rmc, has_heading, &first);
  }
  return 0;
}
