/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief drdc.hpp from a host program: one NMEA fix in; UTC, GPS time,
 * the attitude, UTM, MGRS and a local offset out, printed with
 * drdc_ostream.hpp.
 */
#include <cstring>
#include <iostream>

#include <drdc/drdc.hpp>
#include <drdc/drdc_ostream.hpp>

using namespace drdc::literals;

int main()
{
  const char gga[] = "$GNGGA,170000.00,5016.20000,N,11110.20000,W,4,12,0.7,"
                     "754.3,M,-16.2,M,1.0,0001*66\r\n";
  const char rmc[] = "$GNRMC,170000.00,A,5016.20000,N,11110.20000,W,2.57,"
                     "045.00,221126,,,R*40\r\n";
  const drdc::result<drdc::Nmea> fix = drdc::Nmea::parse(gga, strlen(gga));
  const drdc::result<drdc::Nmea> date = drdc::Nmea::parse(rmc, strlen(rmc));
  if (!fix || !date) {
    std::cerr << "NMEA: " << (fix ? date.code() : fix.code()) << '\n';
    return 1;
  }
  const drdc::result<drdc::UtcTime> utc = fix.value().utc(date.value());
  std::cout << "UTC " << utc << '\n';
  if (utc) {
    std::cout << "GPS " << drdc::GpsTime::from_utc(utc.value()) << '\n';
  }

  // attitude from literals, rounded while compiling
  const drdc::Euler attitude{46.5_deg, 2.2_deg, -0.8_deg};
  const drdc::result<drdc::Quat> q = drdc::to_quat(attitude);
  std::cout << "q " << q << '\n';

  const drdc::WPose w{fix.value().longitude(), fix.value().latitude(),
                      fix.value().altitude(), q.value_or(drdc::Quat())};
  const drdc::result<drdc::WUTMPose> u = drdc::to_utm(w);
  if (!u) {
    std::cerr << "UTM: " << u.code() << '\n';
    return 1;
  }
  std::cout << "UTM " << u.value().utm << '\n';
  std::cout << "MGRS " << drdc::Mgrs::from_utm(u.value().utm, 5) << '\n';

  // 10 m ahead of the vehicle, then back to {W}
  const drdc::LPose ahead{{10_m, 0_m, 0_m}, drdc::Quat()};
  const drdc::result<drdc::WPose> there = drdc::to_global(w, -16.2_m, ahead);
  std::cout << "10 m ahead " << there << '\n';
  return there ? 0 : 1;
}
