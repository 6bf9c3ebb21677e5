/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief std::ostream printing of drdc.hpp's value classes, for hosts.
 *
 * Optional and separate: drdc.hpp itself needs no iostreams. Every number
 * is written by the library's own exact formatter (drdc_fx_format), so a
 * host prints the digits firmware prints with drdc_fx_format:
 * lengths in metres with 3 decimals, angles in degrees with 9 (latitude,
 * longitude) or 8 (attitude) decimals, quaternion parts with 9, UTC in
 * ISO 8601 with nanoseconds, and a status by its name.
 */
#ifndef DRDC_OSTREAM_HPP
#define DRDC_OSTREAM_HPP

#include <ostream>

#include <drdc/drdc.hpp>

namespace drdc {

namespace detail {

/** value / 2^frac_bits with `decimals` digits, or the status's name. */
inline std::ostream &put_fixed(std::ostream &os, int64_t value,
                               uint32_t frac_bits, uint32_t decimals)
{
  char text[DRDC_FX_FORMAT_MAX];
  const status s =
      drdc_fx_format(value, frac_bits, decimals, text, sizeof text, nullptr);
  return os << (s == DRDC_OK ? text : drdc_status_name(s));
}

/** `scaled` (a count of 10^-decimals units) as a decimal number. */
inline std::ostream &put_scaled(std::ostream &os, const result<int64_t> &r,
                                uint32_t decimals)
{
  if (!r.ok()) {
    return os << drdc_status_name(r.code());
  }
  /* a count of 10^-decimals with 0 fraction bits: print it and move the
   * point, which drdc_fx_format cannot do for a decimal scale */
  char digits[DRDC_FX_FORMAT_MAX];
  const int64_t v = r.value();
  const uint64_t magnitude =
      (v < 0) ? (0u - static_cast<uint64_t>(v)) : static_cast<uint64_t>(v);
  size_t n = 0u;
  uint64_t rest = magnitude;
  do {
    digits[n++] = static_cast<char>('0' + static_cast<int>(rest % 10u));
    rest /= 10u;
  } while ((rest != 0u) || (n <= decimals));
  if (v < 0) {
    os << '-';
  }
  while (n > 0u) {
    os << digits[--n];
    if ((n == decimals) && (decimals != 0u)) {
      os << '.';
    }
  }
  return os;
}

} // namespace detail

/** The status by its name. */
inline std::ostream &operator<<(std::ostream &os, status s)
{
  return os << drdc_status_name(s);
}

/** Metres, 3 decimals. */
inline std::ostream &operator<<(std::ostream &os, Length l)
{
  return detail::put_fixed(os, l.q47_16(), 16u, 3u);
}

/** Metres, 3 decimals. */
inline std::ostream &operator<<(std::ostream &os, LocalLength l)
{
  return detail::put_fixed(os, l.q15_16(), 16u, 3u);
}

/** Degrees, 9 decimals (nas / 3600 is 1e-9 degree). */
inline std::ostream &operator<<(std::ostream &os, GeoAngle a)
{
  return detail::put_scaled(os, muldiv(a.nas(), 1, 3600), 9u);
}

/** Degrees in (-180, 180], 8 decimals (360e8 / 2^32 = 140625000 / 2^24). */
inline std::ostream &operator<<(std::ostream &os, Angle a)
{
  const int32_t signed_bam = static_cast<int32_t>(a.bam());
  return detail::put_scaled(os, muldiv(signed_bam, 140625000, INT64_C(1) << 24),
                            8u);
}

/** [s x y z], 9 decimals each. */
inline std::ostream &operator<<(std::ostream &os, const Quat &q)
{
  os << '[';
  detail::put_fixed(os, q.s(), 30u, 9u) << ' ';
  detail::put_fixed(os, q.x(), 30u, 9u) << ' ';
  detail::put_fixed(os, q.y(), 30u, 9u) << ' ';
  return detail::put_fixed(os, q.z(), 30u, 9u) << ']';
}

/** yaw, pitch, roll in degrees. */
inline std::ostream &operator<<(std::ostream &os, const Euler &e)
{
  return os << "yaw " << e.yaw << " pitch " << e.pitch << " roll " << e.roll;
}

/** ISO 8601 with nanoseconds. */
inline std::ostream &operator<<(std::ostream &os, const UtcTime &t)
{
  char text[DRDC_TIME_ISO8601_SIZE];
  const status s = t.format(text, sizeof text, 9);
  return os << (s == DRDC_OK ? text : drdc_status_name(s));
}

/** Week and time of week with nanoseconds. */
inline std::ostream &operator<<(std::ostream &os, const GpsTime &g)
{
  /* under 604 800 s: the nanoseconds of the week fit int64_t */
  os << "week " << g.week() << " tow ";
  return detail::put_scaled(
      os, result<int64_t>((int64_t{g.tow()} * 1000000000) + g.nsec()), 9u);
}

/** Seconds with 9 decimals. */
inline std::ostream &operator<<(std::ostream &os, const Duration &d)
{
  const result<int64_t> whole = muldiv(d.sec(), 1000000000, 1);
  if (!whole.ok() || (whole.value() > (INT64_MAX - d.nsec()))) {
    return os << DRDC_E_OVERFLOW;
  }
  return detail::put_scaled(os, result<int64_t>(whole.value() + d.nsec()), 9u);
}

/** Longitude, latitude, height and quaternion. */
inline std::ostream &operator<<(std::ostream &os, const WPose &w)
{
  return os << "lon " << w.longitude << " lat " << w.latitude << " h "
            << w.height << " q " << w.q;
}

/** Zone, hemisphere, easting and northing (m, 3 decimals). */
inline std::ostream &operator<<(std::ostream &os, const Utm &u)
{
  return os << u.zone() << (u.north() ? 'n' : 's') << ' ' << u.easting() << ' '
            << u.northing();
}

/** The MGRS text. */
inline std::ostream &operator<<(std::ostream &os, const Mgrs &m)
{
  return os << m.c_str();
}

/** The value, or the status's name. */
template <typename T>
std::ostream &operator<<(std::ostream &os, const result<T> &r)
{
  if (!r.ok()) {
    return os << r.code();
  }
  return os << r.value();
}

} // namespace drdc

#endif /* DRDC_OSTREAM_HPP */
