/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief NMEA 0183 input: GGA, RMC, GNS, ZDA and GST sentences from any
 *        talker, checksum verified, parsed with integers only into the
 *        library's representations, and UTC stitched from RMC/ZDA dates.
 */
#ifndef DRDC_NMEA_H
#define DRDC_NMEA_H

#include <stddef.h>
#include <stdint.h>

#include <drdc/fixed_types.h>
#include <drdc/status.h>
#include <drdc/time.h>
#include <drdc/types.h>

/**
 * @defgroup drdc_nmea NMEA 0183 sentences
 *
 * **Framing** (NMEA 0183 v4.10): `$` + address (two-letter talker, GP,
 * GN, GL, GA, GB, BD, ..., and the sentence formatter) + `,`-separated
 * fields + `*hh` + optional CR LF. At most 82 characters from `$` to LF
 * inclusive (DRDC_NMEA_LENGTH_MAX), so at most 80 up to the checksum.
 * Every character between `$` and `*` must be printable ASCII (0x20 to
 * 0x7E). The checksum is the XOR of the characters between `$` and `*`,
 * two hex digits (upper or lower case). Fields after the ones defined
 * for a sentence (newer versions of the standard add some) are ignored.
 *
 * **Representations**: latitude and longitude are drdc_nas_t
 * (nano-arcseconds), exact for every `ddmm.mmmmmmmmmm` field with up to
 * 10 decimals of minutes (1e-10 minute = 6 nas): every digit the receiver
 * sent is kept; more decimals are refused (DRDC_E_SYNTAX) rather than
 * rounded. North and east are positive. Heights and GST deviations are
 * Q47.16 / Q15.16 metres, HDOP Q15.16, speed Q15.16 m/s (from knots,
 * x 1852/3600), course and GST orientation drdc_bam32_t (from degrees);
 * each of those is the decimal text rounded once to nearest, ties away
 * from zero (<= 0.5 LSB). Time of day: hour, minute, second (60 in a leap
 * second) and nanoseconds, exact for up to 9 decimals.
 *
 * **Order of checks** (each malformation has its own status):
 * `$` missing (DRDC_E_SYNTAX); a character outside printable ASCII
 * (DRDC_E_CHARACTER); no `*hh` before the text ends (DRDC_E_OVERLONG if
 * already longer than 80 characters, else DRDC_E_TRUNCATED); longer than
 * 80 characters up to the checksum (DRDC_E_OVERLONG); text after the
 * checksum other than CR LF (DRDC_E_TRAILING); wrong checksum
 * (DRDC_E_CHECKSUM); not one of the five sentences or not a two-letter
 * talker (DRDC_E_SENTENCE); the receiver reports no fix (GGA quality 0,
 * RMC status V, GNS mode N in every position: DRDC_E_NO_FIX); a required
 * field empty or absent (DRDC_E_MISSING_FIELD); a malformed number or
 * hemisphere (DRDC_E_SYNTAX); out-of-range values (DRDC_E_HOUR,
 * DRDC_E_MINUTE for minutes of time or of an angle >= 60, DRDC_E_SECOND,
 * DRDC_E_DAY, DRDC_E_MONTH, DRDC_E_YEAR, DRDC_E_RANGE for a latitude
 * beyond 90 or longitude beyond 180 degrees).
 *
 * The parser reads exactly `length` characters and never past them; it
 * needs no NUL terminator, keeps no state and allocates nothing.
 * @{
 */

/** Longest sentence, `$` to LF inclusive (NMEA 0183). */
#define DRDC_NMEA_LENGTH_MAX 82u

/** Sentence formatters decoded. */
typedef enum drdc_nmea_type {
  DRDC_NMEA_GGA = 0, /**< fix: time, position, quality, satellites, HDOP,
                          altitude */
  DRDC_NMEA_RMC = 1, /**< recommended minimum: time, status, position,
                          speed, course, date */
  DRDC_NMEA_GNS = 2, /**< GNSS fix (multi-constellation GGA) */
  DRDC_NMEA_ZDA = 3, /**< time and date */
  DRDC_NMEA_GST = 4  /**< pseudorange error statistics */
} drdc_nmea_type_t;

/** Bits of drdc_nmea_t::has: which optional fields the sentence carried. */
#define DRDC_NMEA_HAS_POSITION   UINT32_C(0x01)  /**< latitude, longitude */
#define DRDC_NMEA_HAS_ALTITUDE   UINT32_C(0x02)  /**< altitude */
#define DRDC_NMEA_HAS_SEPARATION UINT32_C(0x04)  /**< geoid separation */
#define DRDC_NMEA_HAS_SATELLITES UINT32_C(0x08)  /**< satellites */
#define DRDC_NMEA_HAS_HDOP       UINT32_C(0x10)  /**< HDOP */
#define DRDC_NMEA_HAS_SPEED      UINT32_C(0x20)  /**< speed */
#define DRDC_NMEA_HAS_COURSE     UINT32_C(0x40)  /**< course */
#define DRDC_NMEA_HAS_DATE       UINT32_C(0x80)  /**< year, month, day */
#define DRDC_NMEA_HAS_ZONE       UINT32_C(0x100) /**< local zone */
/** GST RMS and latitude, longitude, altitude deviations */
#define DRDC_NMEA_HAS_GST UINT32_C(0x200)
/** GST error ellipse: sigma_major, sigma_minor, orientation */
#define DRDC_NMEA_HAS_ELLIPSE UINT32_C(0x400)

/** UTC time of day as the receiver sent it. */
typedef struct drdc_nmea_tod {
  int32_t hour;   /**< 0..23 */
  int32_t minute; /**< 0..59 */
  int32_t second; /**< 0..60 (60 only in a leap second) */
  int32_t nsec;   /**< 0..999 999 999 */
} drdc_nmea_tod_t;

/** One decoded sentence. Fields a sentence does not carry are 0. */
typedef struct drdc_nmea {
  drdc_nmea_type_t type; /**< which sentence */
  char talker[3];        /**< talker, NUL-terminated ("GP", "GN", ...) */
  uint32_t has;          /**< DRDC_NMEA_HAS_* bits */
  drdc_nmea_tod_t time;  /**< UTC time of day (every sentence) */
  drdc_nas_t latitude;   /**< nas, north positive (GGA, RMC, GNS) */
  drdc_nas_t longitude;  /**< nas, east positive (GGA, RMC, GNS) */
  /** altitude above mean sea level, Q47.16 m (GGA, GNS) */
  drdc_q47_16_t altitude;
  /** geoid separation (geoid above ellipsoid), Q47.16 m (GGA, GNS) */
  drdc_q47_16_t separation;
  /** GGA fix quality 1..8 (1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, ...) */
  int32_t quality;
  int32_t satellites;        /**< satellites used (GGA, GNS) */
  drdc_q15_16_t hdop;        /**< horizontal dilution of precision (GGA, GNS) */
  drdc_q15_16_t speed;       /**< speed over ground, Q15.16 m/s (RMC) */
  drdc_bam32_t course;       /**< course over ground, true (RMC) */
  char mode[8];              /**< RMC mode or GNS modes, NUL-terminated */
  int32_t year;              /**< RMC (yy -> 1980..2079), ZDA */
  int32_t month;             /**< 1..12 (RMC, ZDA) */
  int32_t day;               /**< 1..31 (RMC, ZDA) */
  int32_t zone_hours;        /**< ZDA local zone hours, -13..13 */
  int32_t zone_minutes;      /**< ZDA local zone minutes, 0..59 */
  drdc_q15_16_t rms;         /**< GST RMS of the pseudorange residuals, m */
  drdc_q15_16_t sigma_major; /**< GST error ellipse semi-major axis, m */
  drdc_q15_16_t sigma_minor; /**< GST error ellipse semi-minor axis, m */
  drdc_bam32_t orientation;  /**< GST semi-major axis from true north */
  drdc_q15_16_t sigma_latitude;  /**< GST latitude 1-sigma error, m */
  drdc_q15_16_t sigma_longitude; /**< GST longitude 1-sigma error, m */
  drdc_q15_16_t sigma_altitude;  /**< GST altitude 1-sigma error, m */
} drdc_nmea_t;

/**
 * Parse one NMEA 0183 sentence.
 *
 * @param text   the sentence from `$`, CR LF optional; not necessarily
 *               NUL-terminated
 * @param length number of characters of `text`; exactly these are read
 * @param[out] out the decoded sentence; unchanged on error
 * @retval DRDC_OK decoded
 * @retval DRDC_E_NULL `text` or `out` is NULL
 * @retval DRDC_E_SYNTAX no `$` first, a malformed number, time,
 *         hemisphere or checksum digit, or more than 10 decimals of
 *         minutes
 * @retval DRDC_E_CHARACTER a character outside printable ASCII before
 *         the checksum (non-ASCII byte, control character, NUL)
 * @retval DRDC_E_TRUNCATED the text ends before `*hh`
 * @retval DRDC_E_OVERLONG more than 80 characters up to the checksum (82
 *         with CR LF)
 * @retval DRDC_E_TRAILING characters after the checksum other than CR LF
 * @retval DRDC_E_CHECKSUM the checksum does not match
 * @retval DRDC_E_SENTENCE not GGA, RMC, GNS, ZDA or GST, or not a
 *         two-letter talker
 * @retval DRDC_E_NO_FIX GGA quality 0, RMC status V, or GNS mode N
 *         for every constellation
 * @retval DRDC_E_MISSING_FIELD a required field is empty or the
 *         sentence has too few fields
 * @retval DRDC_E_HOUR hour of the time above 23
 * @retval DRDC_E_MINUTE minute of the time, or minutes of a latitude or
 *         longitude, 60 or more
 * @retval DRDC_E_SECOND second of the time above 60
 * @retval DRDC_E_DAY day outside 1..31 (RMC, ZDA)
 * @retval DRDC_E_MONTH month outside 1..12 (RMC, ZDA)
 * @retval DRDC_E_YEAR ZDA year outside DRDC_YEAR_MIN..DRDC_YEAR_MAX
 * @retval DRDC_E_RANGE latitude beyond 90 or longitude beyond 180
 *         degrees, a number too long for 64 bits, a value beyond its
 *         format, GGA quality 9, or ZDA zone hours beyond 13
 *
 * Accuracy: positions and times exact; other numbers <= 0.5 LSB. Checked
 * against Python's fractions.Fraction parsing of the same text over a
 * corpus of sentences in the formats of several receiver families and
 * every malformation (tests/ref/gen_nmea.py, tests/nmea/test_nmea.c).
 *
 * @code
 * static const char s[] = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,"
 *                         "545.4,M,46.9,M,,*47\r\n";
 * drdc_nmea_t n;
 * drdc_nmea_parse(s, sizeof s - 1, &n);
 * // n.latitude = 48 deg 7.038 min = 173222280000000 nas
 * @endcode
 */
drdc_status_t drdc_nmea_parse(const char *text, size_t length,
                              drdc_nmea_t *out);

/**
 * UTC instant of a sentence's time of day on the date of an RMC or ZDA
 * sentence.
 *
 * The date belongs to `dated`'s time of day; `s`'s time of day is placed
 * on the day among the date, the day before and the day after that is
 * nearest to `dated`'s time (so a GGA at 00:00:01 after an RMC of
 * 23:59:59 falls on the next day). Use the same sentence for both to
 * date an RMC or ZDA itself.
 *
 * @param leap  leap state (validates second 60), NULL for the built-in one
 * @param dated an RMC or ZDA sentence (has DRDC_NMEA_HAS_DATE)
 * @param s     any sentence (its time of day)
 * @param[out] utc the instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_MISSING_FIELD `dated` carries no date
 * @retval DRDC_E_DAY the date's day does not exist in its month (30
 *         February)
 * @retval DRDC_E_HOUR a time of day's hour outside 0..23 (only in a
 *         hand-filled `dated` or `s`: drdc_nmea_parse() never writes one)
 * @retval DRDC_E_MINUTE a time of day's minute outside 0..59 (the same)
 * @retval DRDC_E_SECOND second 60 other than at the end of a day with a
 *         positive leap second, or a second outside 0..60 (hand-filled)
 * @retval DRDC_E_NANOSECOND a time of day's nsec outside
 *         0..999 999 999 (hand-filled)
 * @retval DRDC_E_RANGE the day before or after the date is outside the
 *         calendar (years 1..9999)
 */
drdc_status_t drdc_nmea_utc(const drdc_time_leap_t *leap,
                            const drdc_nmea_t *dated, const drdc_nmea_t *s,
                            drdc_time_t *utc);

/** @} */

#endif /* DRDC_NMEA_H */
