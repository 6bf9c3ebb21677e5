/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The pose-node demo of fw/demo written in C++ with drdc.hpp.
 *
 * The same scripted NMEA sentences and IMU quaternions in, the same text
 * out, byte for byte (tests/integration/test_cxx.py compares them on every
 * target that builds it): UTC and GPS time, {W}, {We}, the JAUS scaled position
 * and Report Global Pose body, the GNSS heading, {We-UTM}, MGRS and {l}.
 * Value classes and drdc::result instead of structs and status checks; no
 * heap, exceptions or RTTI, so it builds for a Cortex-M3 with
 * -fno-exceptions -fno-rtti.
 */
#include <drdc/drdc.hpp>
#include <drdc/version.h>

extern "C" {
#include "console.h"
#include "drdc_board.h"
}

using namespace drdc::literals;

namespace {

/* The receiver's stream: one GGA and one RMC per second (RTK fixed, near
 * DRDC Suffield, Alberta) and at some epochs the true heading of a
 * dual-antenna receiver (HDT, or THS with its mode). */
struct GnssEpoch {
  const char *gga;
  const char *rmc;
  const char *heading; /* HDT or THS, or nullptr */
};

/* clang-format off */
const GnssEpoch gnss[] = {
  {"$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,12,0.7,754.3,M,-16.2,M,1.0,0001*66\r\n",
   "$GNRMC,170000.00,A,5016.20000,N,11110.20000,W,2.57,045.00,221126,,,R*40\r\n",
   nullptr},
  {"$GNGGA,170001.00,5016.20050,N,11110.19920,W,4,12,0.7,754.4,M,-16.2,M,1.0,0001*64\r\n",
   "$GNRMC,170001.00,A,5016.20050,N,11110.19920,W,2.57,045.00,221126,,,R*45\r\n",
   "$GNHDT,46.62,T*2D\r\n"},
  {"$GNGGA,170002.00,5016.20100,N,11110.19840,W,4,12,0.7,754.5,M,-16.2,M,1.0,0001*65\r\n",
   "$GNRMC,170002.00,A,5016.20100,N,11110.19840,W,2.57,045.00,221126,,,R*45\r\n",
   nullptr},
  {"$GNGGA,170003.00,5016.20150,N,11110.19760,W,4,12,0.7,754.6,M,-16.2,M,1.0,0001*6F\r\n",
   "$GNRMC,170003.00,A,5016.20150,N,11110.19760,W,2.57,045.00,221126,,,R*4C\r\n",
   "$GNTHS,49.41,A*21\r\n"},
};

/* The IMU's attitude at each epoch, body FRD to world NED, Q1.30. */
const drdc::Quat imu[] = {
  {991756660, -15826452, 13727054, 410976062}, /* yaw 45.0 pitch 2.0 roll -1.0 */
  {986281899, -15022750, 15980188, 423896769}, /* yaw 46.5 pitch 2.2 roll -0.8 */
  {980703000, -12282277, 16069705, 436731086}, /* yaw 48.0 pitch 2.1 roll -0.5 */
  {974954420, -10005645, 14990451, 449511465}, /* yaw 49.5 pitch 1.9 roll -0.3 */
};
/* clang-format on */

/* The receiver's geoid separation N (GGA field 11), for ellipsoidal
 * heights in the local tangent plane. */
constexpr drdc::Length geoid_separation = -16.2_m;

/* The JAUS RA 3.x ranges of latitude and longitude, nas. */
constexpr drdc::GeoAngle lat_min = -90_deg;
constexpr drdc::GeoAngle lat_max = 90_deg;
constexpr drdc::GeoAngle lon_min = -180_deg;
constexpr drdc::GeoAngle lon_max = 180_deg;

size_t length_of(const char *s)
{
  size_t n = 0u;
  while (s[n] != '\0') {
    n++;
  }
  return n;
}

/* A value rounded to a decimal scale, printed with that many decimals;
 * as in fw/demo, a value beyond int64_t prints as 0 (none here can be). */
void put_scaled(int64_t value, int64_t num, int64_t den, unsigned decimals)
{
  console_put_decimal(drdc::muldiv(value, num, den).value_or(0), decimals);
}

void put(drdc::GeoAngle a)
{
  put_scaled(a.nas(), 1, 3600, 9u);
}

/* degrees in (-180, 180]: 360e8 / 2^32 = 140625000 / 2^24 */
void put(drdc::Angle a)
{
  put_scaled(static_cast<int32_t>(a.bam()), 140625000, INT64_C(1) << 24, 8u);
}

void put(drdc::Length m)
{
  put_scaled(m.q47_16(), 1000, 65536, 3u);
}

void put(drdc::LocalLength m)
{
  put(m.global());
}

void put_q1_30(drdc_q1_30_t v)
{
  put_scaled(v, 10000000, INT64_C(1) << 30, 7u);
}

void put_hex(const drdc::JausBody &body)
{
  static const char digits[] = "0123456789abcdef";
  for (size_t k = 0u; k < body.length; k++) {
    bsp_putc(digits[body.bytes[k] >> 4]);
    bsp_putc(digits[body.bytes[k] & 15u]);
  }
}

void put_status(drdc::status st)
{
  bsp_puts("  ERROR ");
  bsp_puts(drdc_status_name(st));
  bsp_putc('\n');
}

/* The JAUS Report Global Pose body of an epoch: position (MSL height),
 * attitude and time stamp; no RMS values (the receiver sends no GST). */
drdc::result<drdc::JausBody>
jaus_body(const drdc::Nmea &gga, const drdc::Euler &e, const drdc::UtcTime &utc)
{
  const drdc::result<uint32_t> stamp = drdc::jaus_stamp(utc);
  if (!stamp.ok()) {
    return stamp.code();
  }
  const drdc::WePose pose{gga.longitude(), gga.latitude(), gga.altitude(), e};
  drdc_jaus_global_pose_t b{};
  b.presence = DRDC_JAUS_PV_LATITUDE | DRDC_JAUS_PV_LONGITUDE |
               DRDC_JAUS_PV_ALTITUDE | DRDC_JAUS_PV_ROLL | DRDC_JAUS_PV_PITCH |
               DRDC_JAUS_PV_YAW | DRDC_JAUS_PV_TIME_STAMP;
  b.pose = pose.c();
  b.time_stamp = stamp.value();
  return drdc::jaus_pack(b, DRDC_JAUS_FORM_AS6009);
}

/* UTM, grid attitude, MGRS and the local pose of one epoch */
drdc::status grid_and_local(const drdc::WPose &w, const drdc::WPose &first)
{
  const drdc::result<drdc::WUTMPose> u = drdc::to_utm(w);
  if (!u.ok()) {
    return u.code();
  }
  const drdc::result<drdc::Euler> grid = drdc::to_euler(u.value().q);
  const drdc::result<drdc::Euler> truth = drdc::to_euler(w.q);
  const drdc::result<drdc::Mgrs> mgrs = drdc::Mgrs::from_utm(u.value().utm, 5);
  const drdc::result<drdc::LPose> l =
      drdc::to_local(first, geoid_separation, w);
  const drdc::status statuses[] = {grid.code(), truth.code(), mgrs.code(),
                                   l.code()};
  for (drdc::status st : statuses) {
    if (st != DRDC_OK) {
      return st;
    }
  }
  const drdc::Utm &utm = u.value().utm;
  bsp_puts("  UTM   ");
  console_put_i64(utm.zone());
  bsp_putc(utm.north() ? 'n' : 's');
  bsp_putc(' ');
  put(utm.easting());
  bsp_putc(' ');
  put(utm.northing());
  bsp_puts(" m  convergence ");
  put(truth.value().yaw - grid.value().yaw);
  bsp_puts(" deg  grid yaw ");
  put(grid.value().yaw);
  bsp_puts("\n  MGRS  ");
  bsp_puts(mgrs.value().c_str());
  bsp_puts("\n  {l}   x ");
  put(l.value().p.x);
  bsp_puts(" y ");
  put(l.value().p.y);
  bsp_puts(" z ");
  put(l.value().p.z);
  bsp_puts(" m from the first fix\n");
  return DRDC_OK;
}

/* The GNSS true heading beside the IMU's yaw: a pose node watches the
 * difference for drift of the IMU's heading. */
void put_heading(const drdc::Nmea &h, drdc::Angle imu_yaw)
{
  bsp_puts("  GNSS  heading ");
  put(h.heading());
  bsp_puts(" deg true (");
  bsp_puts(h.c.talker);
  bsp_puts((h.c.type == DRDC_NMEA_HDT) ? "HDT" : "THS");
  bsp_puts("), IMU yaw - heading ");
  put(imu_yaw - h.heading());
  bsp_puts(" deg\n");
}

void epoch(unsigned k, const drdc::Nmea &gga, const drdc::Nmea &rmc,
           const drdc::Nmea *heading, drdc::WPose &first)
{
  const drdc::result<drdc::UtcTime> utc = gga.utc(rmc);
  char iso[DRDC_TIME_ISO8601_SIZE];
  drdc::status st = utc.code();
  if (st == DRDC_OK) {
    st = utc.value().format(iso, sizeof iso, 3);
  }
  if (st != DRDC_OK) {
    put_status(st);
    return;
  }
  const drdc::result<drdc::GpsTime> gps = drdc::GpsTime::from_utc(utc.value());
  const drdc::result<drdc::Euler> e = drdc::to_euler(imu[k]);
  const drdc::result<int64_t> jaus_lat =
      drdc::jaus_scaled(gga.latitude().nas(), lat_min.nas(), lat_max.nas(),
                        DRDC_JAUS_INT32, DRDC_JAUS_FORM_RA3);
  const drdc::result<int64_t> jaus_lon =
      drdc::jaus_scaled(gga.longitude().nas(), lon_min.nas(), lon_max.nas(),
                        DRDC_JAUS_INT32, DRDC_JAUS_FORM_RA3);
  const drdc::result<drdc::JausBody> body =
      e.ok() ? jaus_body(gga, e.value(), utc.value())
             : drdc::result<drdc::JausBody>(e.code());
  const drdc::status statuses[] = {gps.code(), e.code(), jaus_lat.code(),
                                   jaus_lon.code(), body.code()};
  for (drdc::status s : statuses) {
    if (s != DRDC_OK) {
      put_status(s);
      return;
    }
  }
  bsp_puts("epoch ");
  console_put_u64(k + 1u);
  bsp_puts("  fix quality ");
  console_put_i64(gga.c.quality);
  bsp_puts(", ");
  console_put_i64(gga.c.satellites);
  bsp_puts(" satellites\n  UTC   ");
  bsp_puts(iso);
  bsp_puts("   GPS week ");
  console_put_i64(gps.value().week());
  bsp_puts(" TOW ");
  console_put_i64(gps.value().tow());
  bsp_puts("\n  {W}   lon ");
  put(gga.longitude());
  bsp_puts(" lat ");
  put(gga.latitude());
  bsp_puts(" deg  h ");
  put(gga.altitude());
  bsp_puts(" m MSL  q [");
  put_q1_30(imu[k].s());
  bsp_putc(' ');
  put_q1_30(imu[k].x());
  bsp_putc(' ');
  put_q1_30(imu[k].y());
  bsp_putc(' ');
  put_q1_30(imu[k].z());
  bsp_puts("]\n  {We}  yaw ");
  put(e.value().yaw);
  bsp_puts(" pitch ");
  put(e.value().pitch);
  bsp_puts(" roll ");
  put(e.value().roll);
  bsp_puts(" deg\n  JAUS  latitude ");
  console_put_i64(jaus_lat.value());
  bsp_puts(" longitude ");
  console_put_i64(jaus_lon.value());
  bsp_puts(
      " (int32, RA 3.x scaled)\n  JAUS  Report Global Pose body (AS6009) ");
  put_hex(body.value());
  bsp_putc('\n');
  if (heading != nullptr) {
    put_heading(*heading, e.value().yaw);
  }

  const drdc::WPose w{gga.longitude(), gga.latitude(), gga.altitude(), imu[k]};
  if (k == 0u) {
    first = w;
  }
  st = grid_and_local(w, first);
  if (st != DRDC_OK) {
    put_status(st);
  }
}

} // namespace

int main()
{
  drdc::WPose first{};

  bsp_puts("libdrdc-fx " DRDC_VERSION_STRING " pose-node demo on ");
  bsp_puts(bsp_name);
  bsp_puts(": GNSS (NMEA) + IMU -> UTC, GPS time, {W}, {We}, JAUS,"
           " {We-UTM}, MGRS, {l}\n");
  unsigned k = 0u;
  for (const GnssEpoch &g : gnss) {
    const drdc::result<drdc::Nmea> gga =
        drdc::Nmea::parse(g.gga, length_of(g.gga));
    const drdc::result<drdc::Nmea> rmc =
        drdc::Nmea::parse(g.rmc, length_of(g.rmc));
    const drdc::result<drdc::Nmea> heading =
        (g.heading != nullptr)
            ? drdc::Nmea::parse(g.heading, length_of(g.heading))
            : drdc::result<drdc::Nmea>(drdc::Nmea{});
    if (!gga.ok() || !rmc.ok() || !heading.ok()) {
      put_status(!gga.ok() ? gga.code()
                           : (!rmc.ok() ? rmc.code() : heading.code()));
    } else {
      epoch(k, gga.value(), rmc.value(),
            (g.heading != nullptr) ? &heading.value() : nullptr, first);
    }
    k++;
  }
  return 0;
}
