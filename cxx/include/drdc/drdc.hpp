/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief C++17 value classes over the C API of libdrdc-fx, header-only.
 *
 * Every computation is a call of the C function that does it; this header
 * only gives the C structs value semantics, operators and names. It needs
 * no heap, no exceptions, no RTTI and no C++ standard library (only the C
 * headers <stdint.h> and <stddef.h>), so it compiles for MCUs with
 * `-fno-exceptions -fno-rtti` as well as on hosts.
 *
 * Errors: a function that can fail returns a drdc::result<T>, a value or a
 * status, checked with ok(); value() gives the value (unspecified after an
 * error, as the C outputs are). Where the compiler has exceptions
 * (`__cpp_exceptions`), value_or_throw() throws drdc::error instead.
 *
 * Literals: `45.5_deg` and `754.3_m` are exact decimals kept in their
 * type; converting one to a value class (drdc::Angle, drdc::GeoAngle,
 * drdc::Length, drdc::LocalLength) rounds it once, to nearest with ties
 * away from zero (docs/conventions.md), while compiling: the result is a
 * constant, out-of-range literals fail to compile, and no floating point
 * exists at any stage.
 *
 *     using namespace drdc::literals;
 *     const drdc::Euler e{46.5_deg, 2.2_deg, -0.8_deg};
 *     const drdc::result<drdc::Quat> q = drdc::to_quat(e);
 *     const drdc::result<drdc::Quat> r = q * q.value().conj();
 *     if (!r.ok()) {
 *       return 1; // r.code() says why: q's error or the product's
 *     }
 */
#ifndef DRDC_HPP
#define DRDC_HPP

#if __cplusplus < 201703L
#error "drdc.hpp needs C++17"
#endif

extern "C" {
#include <drdc/fixed.h>
#include <drdc/geo.h>
#include <drdc/geo_mgrs.h>
#include <drdc/geo_pose.h>
#include <drdc/jaus_pose.h>
#include <drdc/jaus_scaled.h>
#include <drdc/nmea.h>
#include <drdc/orient.h>
#include <drdc/status.h>
#include <drdc/time.h>
#include <drdc/time_iso8601.h>
#include <drdc/time_jaus.h>
#include <drdc/time_scales.h>
}

#include <stddef.h>
#include <stdint.h>

namespace drdc {

/* ------------------------------------------------------------------ */
/* Status and result                                                   */

/** A status of the C API (DRDC_OK, DRDC_E_*, DRDC_W_*). */
using status = drdc_status_t;

#if defined(__cpp_exceptions)
/** Thrown by result::value_or_throw() (only where exceptions exist). Not
 *  derived from std::exception: this header includes no C++ library. */
struct error {
  status code; /**< the status that was not DRDC_OK */
  /** The status's name, e.g. "DRDC_E_RANGE". */
  const char *what() const noexcept
  {
    return drdc_status_name(code);
  }
};
#endif

/**
 * A value of T or the status that kept it from being computed. T is one
 * of this header's value classes (trivially copyable, default
 * constructible). A warning status (DRDC_W_*) carries a value: ok() is
 * true and warning() tells.
 */
template <typename T> class result {
public:
  /** A value: status DRDC_OK. */
  constexpr result(const T &v) : value_(v), status_(DRDC_OK)
  {
  }
  /** A value with the status the C call gave; after an error (not a
   *  warning) the value is what the call left, unspecified. */
  constexpr result(const T &v, status s) : value_(v), status_(s)
  {
  }
  /** An error: no value (a default-constructed T behind it). */
  constexpr result(status s) : value_(), status_(s)
  {
  }
  /** The result of `call(T &out)`, a C call that writes `out` and
   *  returns its status, built in place. */
  template <typename Call> static result of(Call call)
  {
    result r(DRDC_OK);
    r.status_ = call(r.value_);
    return r;
  }

  /** True when the value was written (DRDC_OK or a warning). */
  constexpr bool ok() const
  {
    return !drdc_status_is_error(status_);
  }
  /** ok(), for `if (r)`. */
  constexpr explicit operator bool() const
  {
    return ok();
  }
  /** True for DRDC_W_*: the value is written but worth a look. */
  constexpr bool warning() const
  {
    return drdc_status_is_warning(status_);
  }
  /** The status of the C call. */
  constexpr status code() const
  {
    return status_;
  }
  /** The value; unspecified when !ok(). */
  constexpr const T &value() const
  {
    return value_;
  }
  /** The value, or `fallback` when !ok(). */
  constexpr T value_or(const T &fallback) const
  {
    return ok() ? value_ : fallback;
  }
#if defined(__cpp_exceptions)
  /** The value, or throw drdc::error when !ok(). */
  const T &value_or_throw() const
  {
    if (!ok()) {
      throw error{status_};
    }
    return value_;
  }
#endif

private:
  T value_;
  status status_;
};

/** The result of a C call that wrote `out`: `out` with the call's status
 *  (after an error `out` is what the call left, the unspecified value).
 *  The call is a statement of its own before this one: the order in
 *  which a call's arguments are evaluated is unspecified, so `out` read
 *  in the same argument list might predate the call. */
template <typename T> constexpr result<T> make_result(status s, const T &out)
{
  return result<T>(out, s);
}

/* ------------------------------------------------------------------ */
/* Exact decimal literals                                              */

namespace detail {

/** An unsigned 128-bit integer for constant evaluation: the literals'
 *  products (up to 19 digits times 2^42) exceed 64 bits, and not every
 *  target compiler has __int128. */
struct u128 {
  /** Bits 64..127. */
  uint64_t hi;
  /** Bits 0..63. */
  uint64_t lo;
};

/** The full 128-bit product of two 64-bit factors. */
constexpr u128 mul_64x64(uint64_t a, uint64_t b)
{
  const uint64_t a0 = a & 0xffffffffu;
  const uint64_t a1 = a >> 32;
  const uint64_t b0 = b & 0xffffffffu;
  const uint64_t b1 = b >> 32;
  const uint64_t p00 = a0 * b0;
  const uint64_t p01 = a0 * b1;
  const uint64_t p10 = a1 * b0;
  const uint64_t p11 = a1 * b1;
  const uint64_t middle =
      (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
  return u128{p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32),
              (middle << 32) | (p00 & 0xffffffffu)};
}

/** a < b. */
constexpr bool less(u128 a, u128 b)
{
  return (a.hi < b.hi) || ((a.hi == b.hi) && (a.lo < b.lo));
}

/** a - b (a >= b). */
constexpr u128 minus(u128 a, u128 b)
{
  return u128{a.hi - b.hi - ((a.lo < b.lo) ? 1u : 0u), a.lo - b.lo};
}

/** 2 a + bit. */
constexpr u128 twice_plus(u128 a, unsigned bit)
{
  return u128{(a.hi << 1) | (a.lo >> 63), (a.lo << 1) | bit};
}

/** n / d rounded to nearest, ties away from zero (d > 0): long division
 *  one bit at a time, then the remainder against half the divisor. */
constexpr u128 div_round(u128 n, u128 d)
{
  u128 q{0u, 0u};
  u128 r{0u, 0u};
  for (int i = 127; i >= 0; --i) {
    const uint64_t word = (i >= 64) ? n.hi : n.lo;
    const unsigned bit = static_cast<unsigned>((word >> (i % 64)) & 1u);
    r = twice_plus(r, bit);
    q = twice_plus(q, 0u);
    if (!less(r, d)) {
      r = minus(r, d);
      q.lo |= 1u;
    }
  }
  /* round up when 2 r >= d; r < d, so when r has bit 127 set, 2 r
   * exceeds 128 bits and is certainly >= d (twice_plus would drop that
   * bit and compare a wrong, smaller value) */
  if (((r.hi >> 63) != 0u) || !less(twice_plus(r, 0u), d)) {
    q.lo += 1u;
    if (q.lo == 0u) {
      q.hi += 1u;
    }
  }
  return q;
}

/** A decimal literal: digits / 10^scale, exactly. */
struct decimal {
  uint64_t digits; /**< the literal's digits without the point */
  unsigned scale;  /**< digits after the point */
  bool ok;         /**< digits and '.' only, at most 19 digits */
  bool octal;      /**< a leading 0 followed by a digit before the point */
};

/** The characters of a numeric literal, as the literal operator template
 *  receives them: decimal digits, one '.', digit separators. Hexadecimal
 *  prefixes and exponents are refused, and so is a leading 0 followed by
 *  a digit before the point: C++ reads `010` as octal 8 but `010.5` as
 *  decimal, so a reader of `010_m` cannot tell whether 8 m or 10 m is
 *  meant; refusing both spares the reader the rule. */
template <char... C> constexpr decimal parse()
{
  const char text[] = {C..., '\0'};
  decimal d{0u, 0u, true, false};
  bool point = false;
  unsigned count = 0u;
  /* the first character after a leading '0' (separators skipped) */
  if (text[0] == '0') {
    const char *p = text + 1;
    while (*p == '\'') {
      ++p;
    }
    d.octal = (*p >= '0') && (*p <= '9');
  }
  for (const char *p = text; *p != '\0'; ++p) {
    if (*p == '\'') {
      continue;
    }
    if ((*p == '.') && !point) {
      point = true;
      continue;
    }
    if ((*p < '0') || (*p > '9') || (count == 19u)) {
      d.ok = false;
      return d;
    }
    d.digits = (d.digits * 10u) + static_cast<uint64_t>(*p - '0');
    count++;
    if (point) {
      d.scale++;
    }
  }
  return d;
}

/** 10^n (n <= 19). */
constexpr uint64_t pow10(unsigned n)
{
  uint64_t p = 1u;
  for (unsigned k = 0u; k < n; ++k) {
    p *= 10u;
  }
  return p;
}

/** |value| * num / (10^scale * den), rounded: the literal in units of
 *  1 / (num / den) of its own unit. */
constexpr u128 convert(decimal d, uint64_t num, uint64_t den)
{
  return div_round(mul_64x64(d.digits, num), mul_64x64(pow10(d.scale), den));
}

/** A signed result that fits int64_t (magnitude up to 2^63 when negative). */
constexpr bool fits_i64(u128 m, bool negative)
{
  return (m.hi == 0u) && (m.lo <= (negative ? (uint64_t{1} << 63) : INT64_MAX));
}

/** The signed value of a magnitude that fits_i64() accepts. */
constexpr int64_t to_i64(u128 m, bool negative)
{
  /* two's complement of the magnitude, in unsigned arithmetic */
  return negative ? static_cast<int64_t>(~m.lo + 1u)
                  : static_cast<int64_t>(m.lo);
}

struct degree_unit {};
struct metre_unit {};

} // namespace detail

/**
 * A decimal literal of unit U kept exactly in its type (its characters
 * are the template arguments), so that every conversion is a constant.
 */
template <typename U, bool Negative, char... C> struct literal {
  /** The decimal, parsed while compiling. */
  static constexpr detail::decimal value = detail::parse<C...>();
  static_assert(value.ok, "drdc literal: decimal digits and one '.' only, "
                          "at most 19 digits, no exponent");
  static_assert(!value.octal, "drdc literal: no leading 0 before a digit "
                              "(C++ reads 010 as octal 8)");
  /** The same literal negated: `-1.5_m`. */
  constexpr literal<U, !Negative, C...> operator-() const
  {
    return {};
  }
};

namespace literals {
/** An angle in degrees: `46.5_deg`, converted to drdc::Angle or
 *  drdc::GeoAngle. */
template <char... C>
constexpr literal<detail::degree_unit, false, C...> operator""_deg()
{
  return {};
}
/** A length in metres: `754.3_m`, converted to drdc::Length or
 *  drdc::LocalLength. */
template <char... C>
constexpr literal<detail::metre_unit, false, C...> operator""_m()
{
  return {};
}
} // namespace literals

/* ------------------------------------------------------------------ */
/* Scalar value classes                                                */

/** An attitude angle: a binary angle, 2^32 per turn (drdc_bam32_t), which
 *  wraps modulo one turn as the C type does. */
class Angle {
public:
  constexpr Angle() : bam_(0u)
  {
  }
  /** From the C representation. */
  static constexpr Angle from_bam(drdc_bam32_t b)
  {
    return Angle(b);
  }
  /** From a degree literal: `Angle a = 46.5_deg;` rounded to 2^-32 turn
   *  while compiling, wrapped into one turn. */
  template <bool N, char... C>
  constexpr Angle(literal<detail::degree_unit, N, C...>)
      : bam_(bam_of<N, C...>::value)
  {
  }
  /** The binary angle, 2^32 per turn. */
  constexpr drdc_bam32_t bam() const
  {
    return bam_;
  }
  /** Sum modulo one turn. */
  constexpr Angle operator+(Angle o) const
  {
    return Angle(static_cast<drdc_bam32_t>(bam_ + o.bam_));
  }
  /** Difference modulo one turn. */
  constexpr Angle operator-(Angle o) const
  {
    return Angle(static_cast<drdc_bam32_t>(bam_ - o.bam_));
  }
  /** Equal in every field. */
  constexpr bool operator==(Angle o) const
  {
    return bam_ == o.bam_;
  }
  /** Not equal in some field. */
  constexpr bool operator!=(Angle o) const
  {
    return bam_ != o.bam_;
  }

private:
  template <bool N, char... C> struct bam_of {
    static constexpr uint32_t magnitude = static_cast<uint32_t>(
        detail::convert(detail::parse<C...>(), uint64_t{1} << 32, 360u).lo);
    static constexpr drdc_bam32_t value =
        N ? static_cast<drdc_bam32_t>(0u - magnitude) : magnitude;
  };
  constexpr explicit Angle(drdc_bam32_t b) : bam_(b)
  {
  }
  drdc_bam32_t bam_;
};

/** A latitude or longitude: nano-arcseconds (drdc_nas_t). */
class GeoAngle {
public:
  constexpr GeoAngle() : nas_(0)
  {
  }
  /** From nano-arcseconds. */
  static constexpr GeoAngle from_nas(drdc_nas_t n)
  {
    return GeoAngle(n);
  }
  /** From a degree literal: `GeoAngle lat = 50.27_deg;` rounded to 1 nas
   *  while compiling (degree text to 12 decimals is exact). */
  template <bool N, char... C>
  constexpr GeoAngle(literal<detail::degree_unit, N, C...>)
      : nas_(nas_of<N, C...>::value)
  {
  }
  /** Nano-arcseconds. */
  constexpr drdc_nas_t nas() const
  {
    return nas_;
  }
  /** Equal in every field. */
  constexpr bool operator==(GeoAngle o) const
  {
    return nas_ == o.nas_;
  }
  /** Not equal in some field. */
  constexpr bool operator!=(GeoAngle o) const
  {
    return nas_ != o.nas_;
  }
  /** Smaller raw value. */
  constexpr bool operator<(GeoAngle o) const
  {
    return nas_ < o.nas_;
  }

private:
  template <bool N, char... C> struct nas_of {
    static constexpr detail::u128 magnitude = detail::convert(
        detail::parse<C...>(), uint64_t{DRDC_NAS_PER_DEGREE}, 1u);
    static_assert(detail::fits_i64(magnitude, N),
                  "drdc literal: beyond the range of drdc_nas_t");
    static constexpr drdc_nas_t value = detail::to_i64(magnitude, N);
  };
  constexpr explicit GeoAngle(drdc_nas_t n) : nas_(n)
  {
  }
  drdc_nas_t nas_;
};

/** A global length (UTM, heights): Q47.16 metres (drdc_q47_16_t). */
class Length {
public:
  constexpr Length() : raw_(0)
  {
  }
  /** From Q47.16 metres. */
  static constexpr Length from_q47_16(drdc_q47_16_t r)
  {
    return Length(r);
  }
  /** From a metre literal: `Length h = 754.3_m;` rounded to 2^-16 m. */
  template <bool N, char... C>
  constexpr Length(literal<detail::metre_unit, N, C...>)
      : raw_(raw_of<N, C...>::value)
  {
  }
  /** Q47.16 metres. */
  constexpr drdc_q47_16_t q47_16() const
  {
    return raw_;
  }
  /** Equal in every field. */
  constexpr bool operator==(Length o) const
  {
    return raw_ == o.raw_;
  }
  /** Not equal in some field. */
  constexpr bool operator!=(Length o) const
  {
    return raw_ != o.raw_;
  }
  /** Smaller raw value. */
  constexpr bool operator<(Length o) const
  {
    return raw_ < o.raw_;
  }

private:
  template <bool N, char... C> struct raw_of {
    static constexpr detail::u128 magnitude =
        detail::convert(detail::parse<C...>(), uint64_t{1} << 16, 1u);
    static_assert(detail::fits_i64(magnitude, N),
                  "drdc literal: beyond the range of Q47.16");
    static constexpr drdc_q47_16_t value = detail::to_i64(magnitude, N);
  };
  constexpr explicit Length(drdc_q47_16_t r) : raw_(r)
  {
  }
  drdc_q47_16_t raw_;
};

/** A local length (local pose, offsets): Q15.16 metres, +-32 km. */
class LocalLength {
public:
  constexpr LocalLength() : raw_(0)
  {
  }
  /** From Q15.16 metres. */
  static constexpr LocalLength from_q15_16(drdc_q15_16_t r)
  {
    return LocalLength(r);
  }
  /** From a metre literal: `LocalLength x = 1.33_m;` rounded to 2^-16 m;
   *  beyond +-32 768 m it does not compile. */
  template <bool N, char... C>
  constexpr LocalLength(literal<detail::metre_unit, N, C...>)
      : raw_(raw_of<N, C...>::value)
  {
  }
  /** Q15.16 metres. */
  constexpr drdc_q15_16_t q15_16() const
  {
    return raw_;
  }
  /** The same length as a global one: exact. */
  constexpr Length global() const
  {
    return Length::from_q47_16(static_cast<drdc_q47_16_t>(raw_));
  }
  /** Equal in every field. */
  constexpr bool operator==(LocalLength o) const
  {
    return raw_ == o.raw_;
  }
  /** Not equal in some field. */
  constexpr bool operator!=(LocalLength o) const
  {
    return raw_ != o.raw_;
  }
  /** Smaller raw value. */
  constexpr bool operator<(LocalLength o) const
  {
    return raw_ < o.raw_;
  }

private:
  template <bool N, char... C> struct raw_of {
    static constexpr detail::u128 magnitude =
        detail::convert(detail::parse<C...>(), uint64_t{1} << 16, 1u);
    static_assert((magnitude.hi == 0u) &&
                      (magnitude.lo <=
                       (N ? (uint64_t{1} << 31) : uint64_t{INT32_MAX})),
                  "drdc literal: beyond the range of Q15.16");
    static constexpr drdc_q15_16_t value =
        static_cast<drdc_q15_16_t>(detail::to_i64(magnitude, N));
  };
  constexpr explicit LocalLength(drdc_q15_16_t r) : raw_(r)
  {
  }
  drdc_q15_16_t raw_;
};

/** A global length as a local one: DRDC_E_OVERFLOW beyond Q15.16. */
inline result<LocalLength> to_local(Length l)
{
  drdc_q15_16_t out = 0;
  const status s = drdc_fx_q15_16_from_q47_16(l.q47_16(), &out);
  return make_result(s, LocalLength::from_q15_16(out));
}

/* ------------------------------------------------------------------ */
/* Orientation                                                         */

/** Z-Y-X Euler angles: yaw, pitch, roll (drdc_euler_t). */
struct Euler {
  Angle yaw;   /**< Psi, about z (down): positive turns right */
  Angle pitch; /**< Theta: positive nose up */
  Angle roll;  /**< Phi: positive right wing down */

  /** The C struct of the same value. */
  constexpr drdc_euler_t c() const
  {
    return drdc_euler_t{yaw.bam(), pitch.bam(), roll.bam()};
  }
  /** From the C struct. */
  static constexpr Euler from_c(const drdc_euler_t &e)
  {
    return Euler{Angle::from_bam(e.yaw), Angle::from_bam(e.pitch),
                 Angle::from_bam(e.roll)};
  }
  /** Equal in every field. */
  constexpr bool operator==(const Euler &o) const
  {
    return (yaw == o.yaw) && (pitch == o.pitch) && (roll == o.roll);
  }
  /** Not equal in some field. */
  constexpr bool operator!=(const Euler &o) const
  {
    return !(*this == o);
  }
};

/**
 * A quaternion, scalar first, Q1.30 (drdc_quat_t). `a * b` is the
 * Hamilton product drdc_quat_mul(): a result, since a product of
 * non-unit quaternions may overflow Q1.30 (DRDC_E_OVERFLOW); products
 * chain (`a * b * c`), the first error passing through.
 */
class Quat {
public:
  /** The identity: q = [1, 0, 0, 0]. */
  constexpr Quat() : q_{DRDC_Q1_30_ONE, 0, 0, 0}
  {
  }
  /** From the C struct. */
  constexpr explicit Quat(const drdc_quat_t &q) : q_(q)
  {
  }
  /** From the four Q1.30 integers, scalar first. */
  constexpr Quat(drdc_q1_30_t s, drdc_q1_30_t x, drdc_q1_30_t y, drdc_q1_30_t z)
      : q_{s, x, y, z}
  {
  }
  /** The C struct of the same value. */
  constexpr const drdc_quat_t &c() const
  {
    return q_;
  }
  /** Scalar part, Q1.30. */
  constexpr drdc_q1_30_t s() const
  {
    return q_.s;
  }
  /** x part, Q1.30. */
  constexpr drdc_q1_30_t x() const
  {
    return q_.x;
  }
  /** y part, Q1.30. */
  constexpr drdc_q1_30_t y() const
  {
    return q_.y;
  }
  /** z part, Q1.30. */
  constexpr drdc_q1_30_t z() const
  {
    return q_.z;
  }

  /** Hamilton product (drdc_quat_mul). */
  result<Quat> operator*(const Quat &b) const
  {
    /* the C function writes straight into the returned object: the hot
     * path costs what the C call costs (fw/bench-cxx) */
    return result<Quat>::of(
        [&](Quat &out) { return drdc_quat_mul(&q_, &b.q_, &out.q_); });
  }
  /** Conjugate (drdc_quat_conj): the inverse of a unit quaternion;
   *  DRDC_E_OVERFLOW when a vector part is INT32_MIN, whose negation does
   *  not fit Q1.30. */
  result<Quat> conj() const
  {
    Quat out;
    const status s = drdc_quat_conj(&q_, &out.q_);
    return make_result(s, out);
  }
  /** Unit length again (drdc_quat_normalize); DRDC_E_DOMAIN for zero. */
  result<Quat> normalized() const
  {
    Quat out;
    const status s = drdc_quat_normalize(&q_, &out.q_);
    return make_result(s, out);
  }
  /** Bits equal (q and -q are the same rotation but not equal here). */
  constexpr bool operator==(const Quat &o) const
  {
    return (q_.s == o.q_.s) && (q_.x == o.q_.x) && (q_.y == o.q_.y) &&
           (q_.z == o.q_.z);
  }
  /** Not equal in some field. */
  constexpr bool operator!=(const Quat &o) const
  {
    return !(*this == o);
  }

private:
  drdc_quat_t q_;
};

/** A product whose left factor may be an error: the error, or the
 *  product. */
inline result<Quat> operator*(const result<Quat> &a, const Quat &b)
{
  return a.ok() ? a.value() * b : a;
}

/** A product with a result factor: its error, or the product. */
inline result<Quat> operator*(const result<Quat> &a, const result<Quat> &b)
{
  return b.ok() ? a * b.value() : b;
}

/** A product with a result factor: its error, or the product. */
inline result<Quat> operator*(const Quat &a, const result<Quat> &b)
{
  return b.ok() ? a * b.value() : b;
}

/** Euler angles -> quaternion (drdc_quat_from_euler). */
inline result<Quat> to_quat(const Euler &e)
{
  const drdc_euler_t in = e.c();
  drdc_quat_t out{0, 0, 0, 0};
  const status s = drdc_quat_from_euler(&in, &out);
  return make_result(s, Quat(out));
}

/** Quaternion -> Euler angles (drdc_euler_from_quat). */
inline result<Euler> to_euler(const Quat &q)
{
  drdc_euler_t out{0u, 0u, 0u};
  const status s = drdc_euler_from_quat(&q.c(), &out);
  return make_result(s, Euler::from_c(out));
}

/** A local position: x, y, z in Q15.16 metres. */
struct LocalVec {
  LocalLength x; /**< forward (body) or north */
  LocalLength y; /**< right or east */
  LocalLength z; /**< down */

  /** The C struct of the same value. */
  constexpr drdc_vec3_q15_16_t c() const
  {
    return drdc_vec3_q15_16_t{x.q15_16(), y.q15_16(), z.q15_16()};
  }
  /** From the C struct. */
  static constexpr LocalVec from_c(const drdc_vec3_q15_16_t &v)
  {
    return LocalVec{LocalLength::from_q15_16(v.x),
                    LocalLength::from_q15_16(v.y),
                    LocalLength::from_q15_16(v.z)};
  }
};

/** v rotated by q (drdc_quat_rotate_q15_16). */
inline result<LocalVec> rotate(const Quat &q, const LocalVec &v)
{
  const drdc_vec3_q15_16_t in = v.c();
  drdc_vec3_q15_16_t out{0, 0, 0};
  const status s = drdc_quat_rotate_q15_16(&q.c(), &in, &out);
  return make_result(s, LocalVec::from_c(out));
}

/* ------------------------------------------------------------------ */
/* Time                                                                */

/**
 * A span of time: whole seconds (floor) and nanoseconds 0..999 999 999,
 * so a negative span has negative seconds, as drdc_time_count_t. Sums,
 * differences and negation return a result: DRDC_E_OVERFLOW where the
 * seconds would leave int64_t, never a wrapped value.
 */
class Duration {
public:
  /** Zero. */
  constexpr Duration() : sec_(0), nsec_(0)
  {
  }
  /** A whole number of seconds. */
  static constexpr Duration seconds(int64_t s)
  {
    return Duration(s, 0);
  }
  /** A number of nanoseconds, any int64_t: the floor of ns / 1e9 and the
   *  remainder (truncating division, then the negative remainder moved
   *  up, so that nothing can overflow). */
  static constexpr Duration nanoseconds(int64_t ns)
  {
    const int64_t whole = ns / ns_per_second;
    const int64_t rest = ns % ns_per_second;
    return (rest < 0) ? Duration(whole - 1, rest + ns_per_second)
                      : Duration(whole, rest);
  }
  /** Seconds and nanoseconds; DRDC_E_NANOSECOND outside 0..999 999 999. */
  static result<Duration> of(int64_t sec, int32_t nsec)
  {
    if ((nsec < 0) || (nsec >= ns_per_second)) {
      return result<Duration>(DRDC_E_NANOSECOND);
    }
    return Duration(sec, nsec);
  }
  /** Whole seconds (floor). */
  constexpr int64_t sec() const
  {
    return sec_;
  }
  /** Nanoseconds, 0..999 999 999. */
  constexpr int32_t nsec() const
  {
    return static_cast<int32_t>(nsec_);
  }
  /** The sum; DRDC_E_OVERFLOW beyond int64_t seconds. */
  result<Duration> operator+(Duration o) const
  {
    const int64_t ns = nsec_ + o.nsec_; /* < 2e9 */
    const int64_t carry = (ns >= ns_per_second) ? 1 : 0;
    int64_t sec = 0;
    if (!add(sec_, o.sec_, &sec) || !add(sec, carry, &sec)) {
      return result<Duration>(DRDC_E_OVERFLOW);
    }
    return Duration(sec, ns - (carry * ns_per_second));
  }
  /** The difference; DRDC_E_OVERFLOW beyond int64_t seconds. */
  result<Duration> operator-(Duration o) const
  {
    /* subtracted directly: -o overflows for INT64_MIN s although the
     * difference may fit */
    const bool borrow = nsec_ < o.nsec_;
    int64_t sec = 0;
    bool fits = false;
    if (!borrow) {
      fits = sub(sec_, o.sec_, &sec);
    } else if (sec_ > o.sec_) {
      /* sec_ > INT64_MIN, so sec_ - 1 fits; the difference is >= 0 and
       * might only fit with the borrow taken first */
      fits = sub(sec_ - 1, o.sec_, &sec);
    } else {
      /* the difference is <= 0: if it overflows, one less does too */
      fits = sub(sec_, o.sec_, &sec) && sub(sec, 1, &sec);
    }
    if (!fits) {
      return result<Duration>(DRDC_E_OVERFLOW);
    }
    return Duration(sec, nsec_ - o.nsec_ + (borrow ? ns_per_second : 0));
  }
  /** The negated span; DRDC_E_OVERFLOW for INT64_MIN whole seconds. */
  result<Duration> operator-() const
  {
    if (nsec_ != 0) {
      /* -(s + n) = (-s - 1) + (1 - n): -s - 1 is ~s, which always fits */
      return Duration(~sec_, ns_per_second - nsec_);
    }
    if (sec_ == INT64_MIN) {
      return result<Duration>(DRDC_E_OVERFLOW);
    }
    return Duration(-sec_, 0);
  }
  /** Equal in every field. */
  constexpr bool operator==(Duration o) const
  {
    return (sec_ == o.sec_) && (nsec_ == o.nsec_);
  }
  /** Not equal in some field. */
  constexpr bool operator!=(Duration o) const
  {
    return !(*this == o);
  }
  /** Shorter. */
  constexpr bool operator<(Duration o) const
  {
    return (sec_ < o.sec_) || ((sec_ == o.sec_) && (nsec_ < o.nsec_));
  }
  /** Longer. */
  constexpr bool operator>(Duration o) const
  {
    return o < *this;
  }
  /** Not longer. */
  constexpr bool operator<=(Duration o) const
  {
    return !(o < *this);
  }
  /** Not shorter. */
  constexpr bool operator>=(Duration o) const
  {
    return !(*this < o);
  }

private:
  static constexpr int64_t ns_per_second = 1000000000;
  /* a + b into *out when it fits int64_t */
  static bool add(int64_t a, int64_t b, int64_t *out)
  {
    if (((b > 0) && (a > (INT64_MAX - b))) ||
        ((b < 0) && (a < (INT64_MIN - b)))) {
      return false;
    }
    *out = a + b;
    return true;
  }
  /* a - b into *out when it fits int64_t */
  static bool sub(int64_t a, int64_t b, int64_t *out)
  {
    if (((b < 0) && (a > (INT64_MAX + b))) ||
        ((b > 0) && (a < (INT64_MIN + b)))) {
      return false;
    }
    *out = a - b;
    return true;
  }
  constexpr Duration(int64_t s, int64_t ns) : sec_(s), nsec_(ns)
  {
  }
  int64_t sec_;
  int64_t nsec_;
};

/** A sum whose left term may be an error: the error, or the sum. */
inline result<Duration> operator+(const result<Duration> &a, Duration b)
{
  return a.ok() ? a.value() + b : a;
}

/** A difference whose left term may be an error: the error, or it. */
inline result<Duration> operator-(const result<Duration> &a, Duration b)
{
  return a.ok() ? a.value() - b : a;
}

/**
 * A UTC instant (drdc_time_t): seconds since 1970 at 86 400 a day and
 * nanoseconds, the leap second 23:59:60 as nanoseconds >= 1e9 of
 * 23:59:59. Instants compare in time order. Adding a duration goes
 * through TAI (drdc_time_utc_to_tai, drdc_time_tai_to_utc), so it counts
 * leap seconds; `leap` NULL means the built-in table.
 */
class UtcTime {
public:
  constexpr UtcTime() : t_{0, 0}
  {
  }
  /** From the C struct. */
  constexpr explicit UtcTime(const drdc_time_t &t) : t_(t)
  {
  }
  /** The C struct of the same value. */
  constexpr const drdc_time_t &c() const
  {
    return t_;
  }

  /** From civil fields (drdc_time_from_civil). */
  static result<UtcTime> from_civil(const drdc_time_civil_t &civil,
                                    const drdc_time_leap_t *leap = nullptr)
  {
    drdc_time_t out{0, 0};
    const status s = drdc_time_from_civil(leap, &civil, &out);
    return make_result(s, UtcTime(out));
  }
  /** From ISO 8601 text (drdc_time_iso8601_parse). */
  static result<UtcTime> parse(const char *text,
                               const drdc_time_leap_t *leap = nullptr)
  {
    drdc_time_t out{0, 0};
    const status s = drdc_time_iso8601_parse(leap, text, &out);
    return make_result(s, UtcTime(out));
  }
  /** ISO 8601 text with `digits` decimals of a second into buf
   *  (drdc_time_iso8601_format; DRDC_TIME_ISO8601_SIZE bytes suffice). */
  status format(char *buf, size_t size, int32_t digits,
                const drdc_time_leap_t *leap = nullptr) const
  {
    return drdc_time_iso8601_format(leap, &t_, digits, buf, size);
  }
  /** TAI seconds and nanoseconds since 1958 (drdc_time_utc_to_tai). */
  result<Duration> tai(const drdc_time_leap_t *leap = nullptr) const
  {
    drdc_time_count_t out{0, 0};
    const status s = drdc_time_utc_to_tai(leap, &t_, &out);
    /* the C count's nanoseconds are 0..999 999 999, so of() takes them */
    const result<Duration> d = Duration::of(out.sec, out.nsec);
    return make_result(s, d.value());
  }
  /** The instant `d` later on the TAI time line. */
  result<UtcTime> plus(Duration d, const drdc_time_leap_t *leap = nullptr) const
  {
    const result<Duration> tai_now = tai(leap);
    if (!tai_now.ok()) {
      return result<UtcTime>(tai_now.code());
    }
    const result<Duration> later = tai_now.value() + d;
    if (!later.ok()) {
      return result<UtcTime>(later.code());
    }
    const drdc_time_count_t in{later.value().sec(), later.value().nsec()};
    drdc_time_t out{0, 0};
    const status s = drdc_time_tai_to_utc(leap, &in, &out);
    /* the result rests on this instant's TAI-UTC too: its warning
     * (DRDC_W_LEAP_EXPIRED) holds when the way back reports none */
    return make_result((s == DRDC_OK) ? tai_now.code() : s, UtcTime(out));
  }
  /** plus(d) with the built-in leap-second table. */
  result<UtcTime> operator+(Duration d) const
  {
    return plus(d);
  }
  /** plus(-d) with the built-in leap-second table. */
  result<UtcTime> operator-(Duration d) const
  {
    const result<Duration> minus_d = -d;
    if (!minus_d.ok()) {
      return result<UtcTime>(minus_d.code());
    }
    return plus(minus_d.value());
  }
  /** Elapsed time from `o` to this instant, leap seconds counted. */
  result<Duration> operator-(const UtcTime &o) const
  {
    const result<Duration> a = tai();
    const result<Duration> b = o.tai();
    if (!a.ok()) {
      return a;
    }
    if (!b.ok()) {
      return b;
    }
    const result<Duration> d = a.value() - b.value();
    if (!d.ok()) {
      return d;
    }
    /* the span rests on both instants' TAI-UTC: a warning on either one
     * (DRDC_W_LEAP_EXPIRED) holds for it */
    return result<Duration>(d.value(), a.warning() ? a.code() : b.code());
  }
  /** Equal in every field. */
  constexpr bool operator==(const UtcTime &o) const
  {
    return (t_.sec == o.t_.sec) && (t_.nsec == o.t_.nsec);
  }
  /** Not equal in some field. */
  constexpr bool operator!=(const UtcTime &o) const
  {
    return !(*this == o);
  }
  /** Time order: a leap second's nanoseconds >= 1e9 sort after 23:59:59
   *  and before the next day's 00:00:00. */
  constexpr bool operator<(const UtcTime &o) const
  {
    return (t_.sec < o.t_.sec) ||
           ((t_.sec == o.t_.sec) && (t_.nsec < o.t_.nsec));
  }
  /** Later in time. */
  constexpr bool operator>(const UtcTime &o) const
  {
    return o < *this;
  }
  /** Not later. */
  constexpr bool operator<=(const UtcTime &o) const
  {
    return !(o < *this);
  }
  /** Not earlier. */
  constexpr bool operator>=(const UtcTime &o) const
  {
    return !(*this < o);
  }

private:
  drdc_time_t t_;
};

/** A GPS time: week, time of week, nanoseconds (drdc_time_gps_t). */
class GpsTime {
public:
  constexpr GpsTime() : g_{0, 0, 0}
  {
  }
  /** From the C struct. */
  constexpr explicit GpsTime(const drdc_time_gps_t &g) : g_(g)
  {
  }
  /** The C struct of the same value. */
  constexpr const drdc_time_gps_t &c() const
  {
    return g_;
  }
  /** Full GPS week since 1980-01-06. */
  constexpr int32_t week() const
  {
    return g_.week;
  }
  /** Seconds of the week, 0..604 799. */
  constexpr int32_t tow() const
  {
    return g_.tow;
  }
  /** Nanoseconds, 0..999 999 999. */
  constexpr int32_t nsec() const
  {
    return g_.nsec;
  }
  /** UTC -> GPS (drdc_time_utc_to_gps). */
  static result<GpsTime> from_utc(const UtcTime &u,
                                  const drdc_time_leap_t *leap = nullptr)
  {
    drdc_time_gps_t out{0, 0, 0};
    const status s = drdc_time_utc_to_gps(leap, &u.c(), &out);
    return make_result(s, GpsTime(out));
  }
  /** GPS -> UTC (drdc_time_gps_to_utc). */
  result<UtcTime> utc(const drdc_time_leap_t *leap = nullptr) const
  {
    drdc_time_t out{0, 0};
    const status s = drdc_time_gps_to_utc(leap, &g_, &out);
    return make_result(s, UtcTime(out));
  }
  /** The GPS time `d` later, through UTC and TAI. */
  result<GpsTime> operator+(Duration d) const
  {
    const result<UtcTime> u = utc();
    if (!u.ok()) {
      return result<GpsTime>(u.code());
    }
    const result<UtcTime> later = u.value() + d;
    if (!later.ok()) {
      return result<GpsTime>(later.code());
    }
    return from_utc(later.value());
  }
  /** The GPS time `d` earlier. */
  result<GpsTime> operator-(Duration d) const
  {
    const result<Duration> minus_d = -d;
    if (!minus_d.ok()) {
      return result<GpsTime>(minus_d.code());
    }
    return *this + minus_d.value();
  }
  /** Equal in every field. */
  constexpr bool operator==(const GpsTime &o) const
  {
    return (g_.week == o.g_.week) && (g_.tow == o.g_.tow) &&
           (g_.nsec == o.g_.nsec);
  }
  /** Not equal in some field. */
  constexpr bool operator!=(const GpsTime &o) const
  {
    return !(*this == o);
  }
  /** Earlier in time. */
  constexpr bool operator<(const GpsTime &o) const
  {
    return (g_.week < o.g_.week) ||
           ((g_.week == o.g_.week) &&
            ((g_.tow < o.g_.tow) ||
             ((g_.tow == o.g_.tow) && (g_.nsec < o.g_.nsec))));
  }
  /** Later in time. */
  constexpr bool operator>(const GpsTime &o) const
  {
    return o < *this;
  }
  /** Not later. */
  constexpr bool operator<=(const GpsTime &o) const
  {
    return !(o < *this);
  }
  /** Not earlier. */
  constexpr bool operator>=(const GpsTime &o) const
  {
    return !(*this < o);
  }

private:
  drdc_time_gps_t g_;
};

/* ------------------------------------------------------------------ */
/* Geodesy and poses                                                   */

/** A UTM/UPS position (drdc_geo_utm_t). */
struct Utm {
  drdc_geo_utm_t c; /**< zone, hemisphere, easting, northing */

  /** UTM zone 1..60, or 0 for UPS. */
  constexpr int32_t zone() const
  {
    return c.zone;
  }
  /** True in the northern hemisphere. */
  constexpr bool north() const
  {
    return c.north;
  }
  /** Easting, Q47.16 m. */
  constexpr Length easting() const
  {
    return Length::from_q47_16(c.easting);
  }
  /** Northing, Q47.16 m. */
  constexpr Length northing() const
  {
    return Length::from_q47_16(c.northing);
  }
  /** UTM of a latitude and longitude in its standard zone (or `zone`;
   *  drdc_geo_to_utm). */
  static result<Utm> from_geo(GeoAngle lat, GeoAngle lon,
                              int32_t zone = DRDC_GEO_ZONE_STANDARD)
  {
    Utm out{};
    const status s =
        drdc_geo_to_utm(lat.nas(), lon.nas(), zone, &out.c, nullptr, nullptr);
    return make_result(s, out);
  }
};

namespace detail {
/** The MGRS text buffers of the C and C++ types, both
 *  DRDC_GEO_MGRS_SIZE bytes. */
inline void copy_text(char (&to)[DRDC_GEO_MGRS_SIZE],
                      const char (&from)[DRDC_GEO_MGRS_SIZE])
{
  for (size_t k = 0u; k < DRDC_GEO_MGRS_SIZE; ++k) {
    to[k] = from[k];
  }
}
} // namespace detail

/** An MGRS reference: NUL-terminated text, no heap. */
struct Mgrs {
  char text[DRDC_GEO_MGRS_SIZE]; /**< e.g. "12UVA8788568665" */

  /** MGRS of a UTM position with `prec` digit pairs
   *  (drdc_geo_mgrs_from_utm). */
  static result<Mgrs> from_utm(const Utm &u, int32_t prec)
  {
    Mgrs out{};
    const status s =
        drdc_geo_mgrs_from_utm(&u.c, prec, out.text, sizeof out.text);
    return make_result(s, out);
  }
  /** The NUL-terminated text. */
  const char *c_str() const
  {
    return text;
  }
};

/** Global pose {W}: longitude, latitude, height MSL, true-north attitude. */
struct WPose {
  GeoAngle longitude; /**< east positive */
  GeoAngle latitude;  /**< north positive */
  Length height;      /**< above mean sea level */
  Quat q;             /**< body FRD to NED */

  /** The C struct of the same value. */
  drdc_WPose_t c() const
  {
    return drdc_WPose_t{longitude.nas(), latitude.nas(), height.q47_16(),
                        q.c()};
  }
  /** From the C struct. */
  static WPose from_c(const drdc_WPose_t &w)
  {
    return WPose{GeoAngle::from_nas(w.longitude),
                 GeoAngle::from_nas(w.latitude), Length::from_q47_16(w.height),
                 Quat(w.q)};
  }
};

/** {We}: {W} with Euler angles. */
struct WePose {
  GeoAngle longitude; /**< east positive */
  GeoAngle latitude;  /**< north positive */
  Length height;      /**< above mean sea level */
  Euler e;            /**< yaw from true north */

  /** The C struct of the same value. */
  drdc_WePose_t c() const
  {
    return drdc_WePose_t{longitude.nas(), latitude.nas(), height.q47_16(),
                         e.c()};
  }
  /** From the C struct. */
  static WePose from_c(const drdc_WePose_t &w)
  {
    return WePose{GeoAngle::from_nas(w.longitude),
                  GeoAngle::from_nas(w.latitude), Length::from_q47_16(w.height),
                  Euler::from_c(w.e)};
  }
};

/** {W-UTM}: UTM position, height MSL, grid-north attitude. */
struct WUTMPose {
  Utm utm;       /**< zone, hemisphere, easting, northing */
  Length height; /**< above mean sea level */
  Quat q;        /**< grid north */

  /** The C struct of the same value. */
  drdc_WUTMPose_t c() const
  {
    return drdc_WUTMPose_t{utm.c, height.q47_16(), q.c()};
  }
  /** From the C struct. */
  static WUTMPose from_c(const drdc_WUTMPose_t &u)
  {
    return WUTMPose{Utm{u.utm}, Length::from_q47_16(u.height), Quat(u.q)};
  }
};

/** {We-UTM}: {W-UTM} with Euler angles. */
struct WeUTMPose {
  Utm utm;       /**< zone, hemisphere, easting, northing */
  Length height; /**< above mean sea level */
  Euler e;       /**< yaw from grid north */

  /** The C struct of the same value. */
  drdc_WeUTMPose_t c() const
  {
    return drdc_WeUTMPose_t{utm.c, height.q47_16(), e.c()};
  }
  /** From the C struct. */
  static WeUTMPose from_c(const drdc_WeUTMPose_t &u)
  {
    return WeUTMPose{Utm{u.utm}, Length::from_q47_16(u.height),
                     Euler::from_c(u.e)};
  }
};

/** {W-MGRS}: MGRS text, height MSL, grid-north attitude. */
struct WMGRSPose {
  Mgrs mgrs;     /**< the square */
  Length height; /**< above mean sea level */
  Quat q;        /**< grid north */

  /** The C struct of the same value. */
  drdc_WMGRSPose_t c() const
  {
    drdc_WMGRSPose_t out{};
    detail::copy_text(out.mgrs, mgrs.text);
    out.height = height.q47_16();
    out.q = q.c();
    return out;
  }
  /** From the C struct. */
  static WMGRSPose from_c(const drdc_WMGRSPose_t &m)
  {
    WMGRSPose out{};
    detail::copy_text(out.mgrs.text, m.mgrs);
    out.height = Length::from_q47_16(m.height);
    out.q = Quat(m.q);
    return out;
  }
};

/** {We-MGRS}: {W-MGRS} with Euler angles. */
struct WeMGRSPose {
  Mgrs mgrs;     /**< the square */
  Length height; /**< above mean sea level */
  Euler e;       /**< yaw from grid north */

  /** The C struct of the same value. */
  drdc_WeMGRSPose_t c() const
  {
    drdc_WeMGRSPose_t out{};
    detail::copy_text(out.mgrs, mgrs.text);
    out.height = height.q47_16();
    out.e = e.c();
    return out;
  }
  /** From the C struct. */
  static WeMGRSPose from_c(const drdc_WeMGRSPose_t &m)
  {
    WeMGRSPose out{};
    detail::copy_text(out.mgrs.text, m.mgrs);
    out.height = Length::from_q47_16(m.height);
    out.e = Euler::from_c(m.e);
    return out;
  }
};

/** Local pose {l}: x forward, y right, z down, attitude. */
struct LPose {
  LocalVec p; /**< position */
  Quat q;     /**< attitude */

  /** The C struct of the same value. */
  drdc_lPose_t c() const
  {
    return drdc_lPose_t{p.c(), q.c()};
  }
  /** From the C struct. */
  static LPose from_c(const drdc_lPose_t &l)
  {
    return LPose{LocalVec::from_c(l.p), Quat(l.q)};
  }
};

/** {le}: {l} with Euler angles. */
struct LePose {
  LocalVec p; /**< position */
  Euler e;    /**< attitude */

  /** The C struct of the same value. */
  drdc_lePose_t c() const
  {
    return drdc_lePose_t{p.c(), e.c()};
  }
  /** From the C struct. */
  static LePose from_c(const drdc_lePose_t &l)
  {
    return LePose{LocalVec::from_c(l.p), Euler::from_c(l.e)};
  }
};

/** {W} -> {W-UTM} in the standard zone or `zone` (drdc_pose_wutm_from_w). */
inline result<WUTMPose> to_utm(const WPose &w,
                               int32_t zone = DRDC_GEO_ZONE_STANDARD)
{
  const drdc_WPose_t in = w.c();
  drdc_WUTMPose_t out{};
  const status s = drdc_pose_wutm_from_w(&in, zone, &out);
  return make_result(s, WUTMPose::from_c(out));
}

/** {W-UTM} -> {W} (drdc_pose_w_from_wutm). */
inline result<WPose> to_w(const WUTMPose &u)
{
  const drdc_WUTMPose_t in = u.c();
  drdc_WPose_t out{};
  const status s = drdc_pose_w_from_wutm(&in, &out);
  return make_result(s, WPose::from_c(out));
}

/** {We} -> {We-UTM} (drdc_pose_weutm_from_we). */
inline result<WeUTMPose> to_utm(const WePose &w,
                                int32_t zone = DRDC_GEO_ZONE_STANDARD)
{
  const drdc_WePose_t in = w.c();
  drdc_WeUTMPose_t out{};
  const status s = drdc_pose_weutm_from_we(&in, zone, &out);
  return make_result(s, WeUTMPose::from_c(out));
}

/** {W} -> {W-MGRS} with `prec` digit pairs (drdc_pose_wmgrs_from_w). */
inline result<WMGRSPose> to_mgrs(const WPose &w, int32_t prec)
{
  const drdc_WPose_t in = w.c();
  drdc_WMGRSPose_t out{};
  const status s = drdc_pose_wmgrs_from_w(&in, prec, &out);
  return make_result(s, WMGRSPose::from_c(out));
}

/** {We} -> {We-MGRS} with `prec` digit pairs (drdc_pose_wemgrs_from_we). */
inline result<WeMGRSPose> to_mgrs(const WePose &w, int32_t prec)
{
  const drdc_WePose_t in = w.c();
  drdc_WeMGRSPose_t out{};
  const status s = drdc_pose_wemgrs_from_we(&in, prec, &out);
  return make_result(s, WeMGRSPose::from_c(out));
}

/** {W-MGRS} -> {W} at the square's centre (drdc_pose_w_from_wmgrs). */
inline result<WPose> to_w(const WMGRSPose &m)
{
  const drdc_WMGRSPose_t in = m.c();
  drdc_WPose_t out{};
  const status s = drdc_pose_w_from_wmgrs(&in, &out);
  return make_result(s, WPose::from_c(out));
}

/** {We-UTM} -> {We} (drdc_pose_we_from_weutm). */
inline result<WePose> to_we(const WeUTMPose &u)
{
  const drdc_WeUTMPose_t in = u.c();
  drdc_WePose_t out{};
  const status s = drdc_pose_we_from_weutm(&in, &out);
  return make_result(s, WePose::from_c(out));
}

/** {We-MGRS} -> {We} at the square's centre (drdc_pose_we_from_wemgrs). */
inline result<WePose> to_we(const WeMGRSPose &m)
{
  const drdc_WeMGRSPose_t in = m.c();
  drdc_WePose_t out{};
  const status s = drdc_pose_we_from_wemgrs(&in, &out);
  return make_result(s, WePose::from_c(out));
}

/** {W} -> {l} relative to `ref`, with the geoid separation N
 *  (drdc_pose_l_from_w). */
inline result<LPose> to_local(const WPose &ref, Length geoid_separation,
                              const WPose &w)
{
  const drdc_WPose_t r = ref.c();
  const drdc_WPose_t in = w.c();
  drdc_lPose_t out{};
  const status s = drdc_pose_l_from_w(&r, geoid_separation.q47_16(), &in, &out);
  return make_result(s, LPose::from_c(out));
}

/** {l} relative to `ref` -> {W} (drdc_pose_w_from_l). */
inline result<WPose> to_global(const WPose &ref, Length geoid_separation,
                               const LPose &l)
{
  const drdc_WPose_t r = ref.c();
  const drdc_lPose_t in = l.c();
  drdc_WPose_t out{};
  const status s = drdc_pose_w_from_l(&r, geoid_separation.q47_16(), &in, &out);
  return make_result(s, WPose::from_c(out));
}

/** {le} relative to `ref` -> {We} (drdc_pose_we_from_le). */
inline result<WePose> to_global(const WePose &ref, Length geoid_separation,
                                const LePose &le)
{
  const drdc_WePose_t r = ref.c();
  const drdc_lePose_t in = le.c();
  drdc_WePose_t out{};
  const status s =
      drdc_pose_we_from_le(&r, geoid_separation.q47_16(), &in, &out);
  return make_result(s, WePose::from_c(out));
}

/** {We} -> {le} relative to `ref` (drdc_pose_le_from_we). */
inline result<LePose> to_local(const WePose &ref, Length geoid_separation,
                               const WePose &we)
{
  const drdc_WePose_t r = ref.c();
  const drdc_WePose_t in = we.c();
  drdc_lePose_t out{};
  const status s =
      drdc_pose_le_from_we(&r, geoid_separation.q47_16(), &in, &out);
  return make_result(s, LePose::from_c(out));
}

/** {le} -> {l} (drdc_pose_l_from_le). */
inline result<LPose> to_quat(const LePose &le)
{
  const drdc_lePose_t in = le.c();
  drdc_lPose_t out{};
  const status s = drdc_pose_l_from_le(&in, &out);
  return make_result(s, LPose::from_c(out));
}

/** {l} -> {le} (drdc_pose_le_from_l). */
inline result<LePose> to_euler(const LPose &l)
{
  const drdc_lPose_t in = l.c();
  drdc_lePose_t out{};
  const status s = drdc_pose_le_from_l(&in, &out);
  return make_result(s, LePose::from_c(out));
}

/* ------------------------------------------------------------------ */
/* NMEA in, JAUS out                                                   */

/** One decoded NMEA 0183 sentence (drdc_nmea_t). */
struct Nmea {
  drdc_nmea_t c; /**< every field, as nmea.h documents */

  /** Parse one sentence of `length` bytes (drdc_nmea_parse). */
  static result<Nmea> parse(const char *text, size_t length)
  {
    Nmea out{};
    const status s = drdc_nmea_parse(text, length, &out.c);
    return make_result(s, out);
  }
  /** UTC of this sentence's time on the date of `dated` (RMC or ZDA;
   *  drdc_nmea_utc). */
  result<UtcTime> utc(const Nmea &dated,
                      const drdc_time_leap_t *leap = nullptr) const
  {
    drdc_time_t out{0, 0};
    const status s = drdc_nmea_utc(leap, &dated.c, &c, &out);
    return make_result(s, UtcTime(out));
  }
  /** Latitude, nas (GGA, RMC, GNS, GLL). */
  constexpr GeoAngle latitude() const
  {
    return GeoAngle::from_nas(c.latitude);
  }
  /** Longitude, nas (GGA, RMC, GNS, GLL). */
  constexpr GeoAngle longitude() const
  {
    return GeoAngle::from_nas(c.longitude);
  }
  /** Height above mean sea level, Q47.16 m (GGA, GNS). */
  constexpr Length altitude() const
  {
    return Length::from_q47_16(c.altitude);
  }
  /** True heading (HDT, THS). */
  constexpr Angle heading() const
  {
    return Angle::from_bam(c.heading);
  }
};

/** A value as a JAUS scaled integer (drdc_jaus_scaled_encode). */
inline result<int64_t> jaus_scaled(int64_t value, int64_t min, int64_t max,
                                   drdc_jaus_type_t type, drdc_jaus_form_t form)
{
  int64_t out = 0;
  const status s = drdc_jaus_scaled_encode(value, min, max, type, form, &out);
  return make_result(s, out);
}

/** A packed JAUS message body: bytes in a fixed buffer, no heap. */
struct JausBody {
  uint8_t bytes[DRDC_JAUS_POSE_BODY_MAX]; /**< the body, little-endian */
  size_t length;                          /**< bytes used */
};

/** Report Global Pose (4402h) body (drdc_jaus_global_pose_pack). */
inline result<JausBody> jaus_pack(const drdc_jaus_global_pose_t &body,
                                  drdc_jaus_form_t form)
{
  JausBody out{};
  const status s = drdc_jaus_global_pose_pack(&body, form, out.bytes,
                                              sizeof out.bytes, &out.length);
  return make_result(s, out);
}

/** A JAUS time stamp of a UTC instant (drdc_time_jaus_pack). */
inline result<uint32_t> jaus_stamp(const UtcTime &u,
                                   const drdc_time_leap_t *leap = nullptr)
{
  uint32_t out = 0u;
  const status s = drdc_time_jaus_pack(leap, &u.c(), &out);
  return make_result(s, out);
}

/** value * num / den, rounded by the library's rule
 *  (drdc_fx_muldiv_s64). */
inline result<int64_t> muldiv(int64_t value, int64_t num, int64_t den)
{
  int64_t out = 0;
  const status s = drdc_fx_muldiv_s64(value, num, den, &out);
  return make_result(s, out);
}

} // namespace drdc

#endif /* DRDC_HPP */
