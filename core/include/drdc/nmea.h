/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief NMEA 0183 input: GGA, RMC, GNS, GLL, VTG, HDT, THS, GSA, ZDA and
 *        GST sentences from any talker, checksum verified, parsed with
 *        integers only into the library's representations, and UTC
 *        stitched from RMC/ZDA dates (those of RMCs without a fix too).
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
 * **Sentences**: GGA, RMC, GNS, GLL (fixes), VTG (course and speed), HDT
 * and THS (true heading), GSA (fix type, satellites used, dilutions of
 * precision), ZDA (date) and GST (error statistics), from any standard
 * talker (GP, GL, GA, GB, BD, GQ, GI, GN, HE, ...); proprietary
 * sentences (`$P...`) are not decoded.
 *
 * **Framing** (NMEA 0183 v4.10): `$` + address (two-letter talker and
 * the sentence formatter) + `,`-separated fields + `*hh` + optional CR
 * LF. Every character between `$` and `*` must be printable ASCII (0x20
 * to 0x7E). The checksum is the XOR of the characters between `$` and
 * `*`, two hex digits (upper or lower case). Fields after the ones
 * defined for a sentence (newer versions of the standard add some) are
 * ignored.
 *
 * **Two modes.** drdc_nmea_parse() takes what receivers in the field
 * send; drdc_nmea_parse_with() and DRDC_NMEA_STRICT keep the letter of
 * NMEA 0183. They differ in three rules only:
 * - *Length.* The standard allows 82 characters from `$` to LF
 *   (DRDC_NMEA_0183_LENGTH_MAX); survey and RTK receivers send longer
 *   GGA and RMC sentences (up to about 100 characters, with 7 to 10
 *   decimals of minutes, the age and the station of the corrections).
 *   The parser takes up to DRDC_NMEA_LENGTH_MAX (128, so 126 up to the
 *   checksum); strict mode 82 (80 up to the checksum).
 * - *Trailing fields.* A receiver may end a sentence after its last
 *   field with a value (GGA without the station id, 13 fields; RMC
 *   without the magnetic variation). Fields keep their positions, so
 *   nothing is ambiguous: the missing ones read as empty, and only the
 *   fields a sentence requires must be there. Strict mode requires every
 *   field of the sentence's NMEA 0183 layout (DRDC_E_MISSING_FIELD).
 * - *GGA quality.* An empty fix-quality field with a position present
 *   is a fix of unknown quality: decoded without DRDC_NMEA_HAS_QUALITY
 *   (quality 0). An empty quality and no position is no fix
 *   (DRDC_E_NO_FIX). Strict mode refuses an empty quality
 *   (DRDC_E_MISSING_FIELD).
 *
 * **Representations**: latitude and longitude are drdc_nas_t
 * (nano-arcseconds), exact for every `ddmm.mmmmmmmmmm` field with up to
 * 10 decimals of minutes (1e-10 minute = 6 nas): every digit the receiver
 * sent is kept; more decimals are refused (DRDC_E_SYNTAX) rather than
 * rounded. North and east are positive. Heights are Q47.16 m, GST
 * deviations Q15.16 m, dilutions of precision Q15.16, speed Q15.16 m/s
 * (from knots x 1852/3600, or km/h x 1000/3600), course, heading and GST
 * orientation drdc_bam32_t (from degrees, wrapped to one turn); each of
 * those is the decimal text rounded once to nearest, ties away from
 * zero (<= 0.5 LSB). Time of day: hour, minute, second (60 in a leap
 * second) and nanoseconds, exact for up to 9 decimals.
 *
 * **Values beyond their format.** A dilution of precision, a speed or a
 * GST deviation beyond the Q15.16 range (|x| >= 32768, e.g. a GST error
 * of 50 000 m before the receiver converges) does not refuse the
 * sentence: the value is written as INT32_MAX (or INT32_MIN if
 * negative) and its DRDC_NMEA_BEYOND_* bit is set in
 * drdc_nmea_t::beyond. Latitude, longitude, altitude and geoid
 * separation describe the fix itself: beyond their range the sentence is
 * refused (DRDC_E_RANGE).
 *
 * **Order of checks** (each malformation has its own status):
 * `$` missing (DRDC_E_SYNTAX); a character outside printable ASCII
 * (DRDC_E_CHARACTER); no `*hh` before the text ends (DRDC_E_OVERLONG if
 * already longer than the mode's limit, else DRDC_E_TRUNCATED); longer
 * than the mode's limit up to the checksum (DRDC_E_OVERLONG); text after
 * the checksum other than CR LF (DRDC_E_TRAILING); wrong checksum
 * (DRDC_E_CHECKSUM); not one of the sentences above or not a two-letter
 * talker (DRDC_E_SENTENCE); the receiver reports no fix (GGA quality 0,
 * RMC or GLL status V, RMC, GLL or VTG mode N, GNS mode N in every
 * position, THS mode V, GSA fix type 1: DRDC_E_NO_FIX); a required field
 * empty or absent (DRDC_E_MISSING_FIELD); a malformed number, letter or
 * hemisphere (DRDC_E_SYNTAX); out-of-range values (DRDC_E_HOUR,
 * DRDC_E_MINUTE for minutes of time or of an angle >= 60, DRDC_E_SECOND,
 * DRDC_E_DAY, DRDC_E_MONTH, DRDC_E_YEAR, DRDC_E_RANGE for a latitude
 * beyond 90 or longitude beyond 180 degrees).
 *
 * The parser reads exactly `length` characters and never past them; it
 * needs no NUL terminator, keeps no state and allocates nothing.
 * @{
 */

/** Longest sentence the parser takes, `$` to LF inclusive: 126
 *  characters up to the checksum, then CR LF. */
#define DRDC_NMEA_LENGTH_MAX 128u

/** Longest sentence of NMEA 0183, `$` to LF inclusive (strict mode). */
#define DRDC_NMEA_0183_LENGTH_MAX 82u

/** drdc_nmea_parse_with() flag: the letter of NMEA 0183 (82 characters,
 *  every field of the layout present, GGA quality required). */
#define DRDC_NMEA_STRICT UINT32_C(0x1)

/** Satellite ids a GSA sentence lists (NMEA 0183: 12 fields). */
#define DRDC_NMEA_GSA_IDS 12u

/** Sentence formatters decoded. */
typedef enum drdc_nmea_type {
  DRDC_NMEA_GGA = 0, /**< fix: time, position, quality, satellites, HDOP,
                          altitude */
  DRDC_NMEA_RMC = 1, /**< recommended minimum: time, status, position,
                          speed, course, date */
  DRDC_NMEA_GNS = 2, /**< GNSS fix (multi-constellation GGA) */
  DRDC_NMEA_ZDA = 3, /**< time and date */
  DRDC_NMEA_GST = 4, /**< pseudorange error statistics */
  DRDC_NMEA_GLL = 5, /**< position, time and status */
  DRDC_NMEA_VTG = 6, /**< course (true, magnetic) and speed over ground */
  DRDC_NMEA_HDT = 7, /**< true heading */
  DRDC_NMEA_THS = 8, /**< true heading with its mode */
  DRDC_NMEA_GSA = 9  /**< fix type, satellites used, PDOP, HDOP, VDOP */
} drdc_nmea_type_t;

/** Bits of drdc_nmea_t::has: which optional fields the sentence carried. */
#define DRDC_NMEA_HAS_POSITION   UINT32_C(0x01)  /**< latitude, longitude */
#define DRDC_NMEA_HAS_ALTITUDE   UINT32_C(0x02)  /**< altitude */
#define DRDC_NMEA_HAS_SEPARATION UINT32_C(0x04)  /**< geoid separation */
#define DRDC_NMEA_HAS_SATELLITES UINT32_C(0x08)  /**< satellites */
#define DRDC_NMEA_HAS_HDOP       UINT32_C(0x10)  /**< HDOP */
#define DRDC_NMEA_HAS_SPEED      UINT32_C(0x20)  /**< speed */
#define DRDC_NMEA_HAS_COURSE     UINT32_C(0x40)  /**< course (true) */
#define DRDC_NMEA_HAS_DATE       UINT32_C(0x80)  /**< year, month, day */
#define DRDC_NMEA_HAS_ZONE       UINT32_C(0x100) /**< local zone */
/** GST RMS and latitude, longitude, altitude deviations */
#define DRDC_NMEA_HAS_GST UINT32_C(0x200)
/** GST error ellipse: sigma_major, sigma_minor, orientation */
#define DRDC_NMEA_HAS_ELLIPSE UINT32_C(0x400)
#define DRDC_NMEA_HAS_TIME    UINT32_C(0x800)  /**< time of day */
#define DRDC_NMEA_HAS_QUALITY UINT32_C(0x1000) /**< GGA fix quality */
#define DRDC_NMEA_HAS_HEADING UINT32_C(0x2000) /**< true heading */
/** course over ground, magnetic (VTG) */
#define DRDC_NMEA_HAS_COURSE_MAGNETIC UINT32_C(0x4000)
#define DRDC_NMEA_HAS_FIX_TYPE        UINT32_C(0x8000)  /**< GSA fix type */
#define DRDC_NMEA_HAS_PDOP            UINT32_C(0x10000) /**< PDOP */
#define DRDC_NMEA_HAS_VDOP            UINT32_C(0x20000) /**< VDOP */
#define DRDC_NMEA_HAS_SYSTEM          UINT32_C(0x40000) /**< GSA system id */

/** Bits of drdc_nmea_t::beyond: values beyond the Q15.16 range, written
 *  as INT32_MAX (INT32_MIN if negative). */
#define DRDC_NMEA_BEYOND_HDOP  UINT32_C(0x01) /**< hdop */
#define DRDC_NMEA_BEYOND_SPEED UINT32_C(0x02) /**< speed */
#define DRDC_NMEA_BEYOND_RMS   UINT32_C(0x04) /**< rms */
/** sigma_major */
#define DRDC_NMEA_BEYOND_SIGMA_MAJOR UINT32_C(0x08)
/** sigma_minor */
#define DRDC_NMEA_BEYOND_SIGMA_MINOR UINT32_C(0x10)
/** sigma_latitude */
#define DRDC_NMEA_BEYOND_SIGMA_LATITUDE UINT32_C(0x20)
/** sigma_longitude */
#define DRDC_NMEA_BEYOND_SIGMA_LONGITUDE UINT32_C(0x40)
/** sigma_altitude */
#define DRDC_NMEA_BEYOND_SIGMA_ALTITUDE UINT32_C(0x80)
#define DRDC_NMEA_BEYOND_PDOP           UINT32_C(0x100) /**< pdop */
#define DRDC_NMEA_BEYOND_VDOP           UINT32_C(0x200) /**< vdop */

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
  uint32_t beyond;       /**< DRDC_NMEA_BEYOND_* bits */
  /** UTC time of day (GGA, RMC, GNS, GLL, ZDA, GST) */
  drdc_nmea_tod_t time;
  drdc_nas_t latitude;  /**< nas, north positive (GGA, RMC, GNS, GLL) */
  drdc_nas_t longitude; /**< nas, east positive (GGA, RMC, GNS, GLL) */
  /** altitude above mean sea level, Q47.16 m (GGA, GNS) */
  drdc_q47_16_t altitude;
  /** geoid separation (geoid above ellipsoid), Q47.16 m (GGA, GNS) */
  drdc_q47_16_t separation;
  /** GGA fix quality 1..8 (1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, ...) */
  int32_t quality;
  /** satellites used (GGA, GNS; GSA: how many ids it lists) */
  int32_t satellites;
  drdc_q15_16_t hdop; /**< horizontal dilution of precision (GGA, GNS,
                           GSA) */
  drdc_q15_16_t pdop; /**< position dilution of precision (GSA) */
  drdc_q15_16_t vdop; /**< vertical dilution of precision (GSA) */
  /** speed over ground, Q15.16 m/s (RMC, VTG) */
  drdc_q15_16_t speed;
  drdc_bam32_t course;          /**< course over ground, true (RMC, VTG) */
  drdc_bam32_t course_magnetic; /**< course over ground, magnetic (VTG) */
  drdc_bam32_t heading;         /**< true heading (HDT, THS) */
  /** mode letters, NUL-terminated: RMC, GLL, VTG, THS (one), GNS (one
   *  per constellation), GSA (M manual, A automatic) */
  char mode[8];
  int32_t fix_type;  /**< GSA: 2 (2D) or 3 (3D) */
  int32_t system_id; /**< GSA system id 1..15 (NMEA 0183 v4.10: 1 GPS,
                          2 GLONASS, 3 Galileo, 4 BDS, 5 QZSS, 6 NavIC) */
  /** GSA: ids of the satellites used, in the order sent (empty fields
   *  skipped); `satellites` of them are valid, the rest 0 */
  uint16_t satellite_ids[DRDC_NMEA_GSA_IDS];
  int32_t year;                  /**< RMC (yy -> 1980..2079), ZDA */
  int32_t month;                 /**< 1..12 (RMC, ZDA) */
  int32_t day;                   /**< 1..31 (RMC, ZDA) */
  int32_t zone_hours;            /**< ZDA local zone hours, -13..13 */
  int32_t zone_minutes;          /**< ZDA local zone minutes, 0..59 */
  drdc_q15_16_t rms;             /**< GST RMS of the pseudorange residuals, m */
  drdc_q15_16_t sigma_major;     /**< GST error ellipse semi-major axis, m */
  drdc_q15_16_t sigma_minor;     /**< GST error ellipse semi-minor axis, m */
  drdc_bam32_t orientation;      /**< GST semi-major axis from true north */
  drdc_q15_16_t sigma_latitude;  /**< GST latitude 1-sigma error, m */
  drdc_q15_16_t sigma_longitude; /**< GST longitude 1-sigma error, m */
  drdc_q15_16_t sigma_altitude;  /**< GST altitude 1-sigma error, m */
} drdc_nmea_t;

/**
 * Parse one NMEA 0183 sentence as receivers send it: up to
 * DRDC_NMEA_LENGTH_MAX characters, trailing fields optional, an empty GGA
 * quality tolerated (see the module's two modes). The same as
 * drdc_nmea_parse_with() with flags 0.
 *
 * @param text   the sentence from `$`, CR LF optional; not necessarily
 *               NUL-terminated
 * @param length number of characters of `text`; exactly these are read
 * @param[out] out the decoded sentence; unchanged on error
 * @retval DRDC_OK decoded (values beyond their format are flagged in
 *         out->beyond, not refused)
 * @retval DRDC_E_NULL `text` or `out` is NULL
 * @retval DRDC_E_SYNTAX no `$` first, a malformed number, time,
 *         hemisphere or checksum digit, or more than 10 decimals of
 *         minutes; GLL: a status other than A or V; GLL, VTG: a mode
 *         letter outside NMEA 0183's set; VTG: a unit letter other than
 *         T, M, N, K in its field (the NMEA 1.5 layout without letters);
 *         HDT: the letter not T; THS: a mode other than A, E, M, S, V;
 *         GSA: a mode not A or M, a satellite id of more than 3 digits,
 *         a system id not one hex digit
 * @retval DRDC_E_CHARACTER a character outside printable ASCII before
 *         the checksum (non-ASCII byte, control character, NUL)
 * @retval DRDC_E_TRUNCATED the text ends before `*hh`
 * @retval DRDC_E_OVERLONG more than 126 characters up to the checksum
 *         (128 with CR LF)
 * @retval DRDC_E_TRAILING characters after the checksum other than CR LF
 * @retval DRDC_E_CHECKSUM the checksum does not match
 * @retval DRDC_E_SENTENCE not GGA, RMC, GNS, GLL, VTG, HDT, THS, GSA, ZDA
 *         or GST, not a two-letter talker, or proprietary (`$P...`,
 *         such as Quectel's `$PQGSA`)
 * @retval DRDC_E_NO_FIX GGA quality 0 (or empty with no position), RMC
 *         status V or mode N, GNS mode N for every constellation; GLL:
 *         status V or mode N; VTG: mode N; THS: mode V (not valid); GSA:
 *         fix type 1 (no fix)
 * @retval DRDC_E_MISSING_FIELD a required field is empty or the
 *         sentence ends before it (GGA, RMC, GNS, ZDA, GST); GLL: the
 *         status, the time or a coordinate empty, or fewer than 6 fields;
 *         VTG: neither a true course nor a speed; HDT: the heading empty;
 *         THS: the mode empty, or the heading with a valid mode; GSA: the
 *         mode or the fix type empty
 * @retval DRDC_E_HOUR hour of the time above 23
 * @retval DRDC_E_MINUTE minute of the time, or minutes of a latitude or
 *         longitude, 60 or more
 * @retval DRDC_E_SECOND second of the time above 60
 * @retval DRDC_E_DAY day outside 1..31 (RMC, ZDA)
 * @retval DRDC_E_MONTH month outside 1..12 (RMC, ZDA)
 * @retval DRDC_E_YEAR ZDA year outside DRDC_YEAR_MIN..DRDC_YEAR_MAX
 * @retval DRDC_E_RANGE latitude beyond 90 or longitude beyond 180
 *         degrees, a number of more than 18 digits or 15 decimals, an
 *         altitude or separation beyond Q47.16, GGA quality 9, ZDA zone
 *         hours beyond 13; GSA: fix type 0 or beyond 3, or system id 0
 *
 * @remark Tolerated: a sentence of 83 to 128 characters (survey and RTK
 *         receivers: GGA and RMC with 7 to 10 decimals of minutes and the
 *         corrections' age and station, e.g. an 87-character GPGGA) is
 *         decoded; strict mode refuses it (DRDC_E_OVERLONG).
 * @remark Tolerated: trailing fields left off after a sentence's last
 *         required one (GGA without the station id or the age, RMC
 *         without the magnetic variation, ZDA without the zone, VTG and
 *         HDT without unit letters, GSA after the fix type) read as
 *         empty; strict mode refuses (DRDC_E_MISSING_FIELD).
 * @remark Tolerated: an empty GGA quality beside a position is decoded
 *         as a fix of unknown quality (DRDC_NMEA_HAS_QUALITY clear);
 *         strict mode refuses it (DRDC_E_MISSING_FIELD).
 * @remark Tolerated: a dilution of precision, speed or GST deviation
 *         beyond Q15.16 (|x| >= 32768, e.g. a GST error of 50 000 m
 *         before convergence) is written as INT32_MAX (INT32_MIN if
 *         negative) with its DRDC_NMEA_BEYOND_* bit set in out->beyond,
 *         in both modes.
 *
 * Accuracy: positions and times exact; other numbers <= 0.5 LSB. Checked
 * against Python's fractions.Fraction parsing of the same text, with the
 * fields located by pynmea2 (an independent decoder), over a corpus of
 * sentences in the formats of several receiver families and every
 * malformation (tests/ref/gen_nmea.py, tests/nmea/test_nmea.c).
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
 * Parse one NMEA 0183 sentence with options: drdc_nmea_parse() with
 * `flags` 0; with DRDC_NMEA_STRICT, the letter of NMEA 0183 (at most 82
 * characters, every field of the layout present, GGA quality required).
 *
 * @param text   the sentence from `$`, CR LF optional
 * @param length number of characters of `text`; exactly these are read
 * @param flags  0 or DRDC_NMEA_STRICT
 * @param[out] out the decoded sentence; unchanged on error
 * @retval DRDC_OK decoded
 * @retval DRDC_E_NULL `text` or `out` is NULL
 * @retval DRDC_E_RANGE `flags` has a bit other than DRDC_NMEA_STRICT, or
 *         as drdc_nmea_parse()
 * @retval DRDC_E_OVERLONG strict: more than 80 characters up to the
 *         checksum (82 with CR LF); else as drdc_nmea_parse()
 * @retval DRDC_E_MISSING_FIELD strict: the sentence has fewer fields
 *         than its NMEA 0183 layout, or the GGA quality is empty; else
 *         as drdc_nmea_parse()
 *
 * Every other status as drdc_nmea_parse(), for the same reasons.
 * Accuracy: as drdc_nmea_parse().
 */
drdc_status_t drdc_nmea_parse_with(const char *text, size_t length,
                                   uint32_t flags, drdc_nmea_t *out);

/** The decoder of one sentence type, for drdc_nmea_parse_some(): a
 *  constant of the library, used only through its address. */
typedef struct drdc_nmea_decoder drdc_nmea_decoder_t;

/** @name Sentence decoders (drdc_nmea_parse_some())
 *  @{ */
extern const drdc_nmea_decoder_t drdc_nmea_gga_decoder; /**< GGA */
extern const drdc_nmea_decoder_t drdc_nmea_rmc_decoder; /**< RMC */
extern const drdc_nmea_decoder_t drdc_nmea_gns_decoder; /**< GNS */
extern const drdc_nmea_decoder_t drdc_nmea_zda_decoder; /**< ZDA */
extern const drdc_nmea_decoder_t drdc_nmea_gst_decoder; /**< GST */
extern const drdc_nmea_decoder_t drdc_nmea_gll_decoder; /**< GLL */
extern const drdc_nmea_decoder_t drdc_nmea_vtg_decoder; /**< VTG */
extern const drdc_nmea_decoder_t drdc_nmea_hdt_decoder; /**< HDT */
extern const drdc_nmea_decoder_t drdc_nmea_ths_decoder; /**< THS */
extern const drdc_nmea_decoder_t drdc_nmea_gsa_decoder; /**< GSA */
/** @} */

/**
 * Parse one NMEA 0183 sentence with only the decoders the caller names:
 * drdc_nmea_parse_with() for the sentence types of `decoders`, and
 * DRDC_E_SENTENCE for every other. A firmware links the decoders it
 * names and no other (drdc_nmea_parse() links all ten): a GGA-only node
 * saves the other nine (docs/performance.md gives the bytes).
 *
 * @param text   the sentence from `$`, CR LF optional
 * @param length number of characters of `text`; exactly these are read
 * @param flags  0 or DRDC_NMEA_STRICT
 * @param decoders `count` addresses of drdc_nmea_<type>_decoder
 *        constants; NULL only with `count` 0
 * @param count  number of `decoders`
 * @param[out] out the decoded sentence; unchanged on error
 * @retval DRDC_OK decoded
 * @retval DRDC_E_NULL `text` or `out` is NULL, `decoders` is NULL with
 *         `count` above 0, or one of them is NULL
 * @retval DRDC_E_RANGE `flags` has a bit other than DRDC_NMEA_STRICT, or
 *         as drdc_nmea_parse()
 * @retval DRDC_E_SENTENCE a sentence of a type none of `decoders` reads,
 *         or as drdc_nmea_parse()
 *
 * Every other status as drdc_nmea_parse_with(), for the same reasons.
 * Accuracy: as drdc_nmea_parse().
 *
 * @code
 * static const drdc_nmea_decoder_t *const fixes[] = {
 *   &drdc_nmea_gga_decoder, &drdc_nmea_rmc_decoder};
 * drdc_nmea_t n;
 * drdc_status_t st = drdc_nmea_parse_some(line, len, 0u, fixes, 2u, &n);
 * // a VTG gives DRDC_E_SENTENCE; its decoder is not linked
 * @endcode
 */
drdc_status_t drdc_nmea_parse_some(const char *text, size_t length,
                                   uint32_t flags,
                                   const drdc_nmea_decoder_t *const *decoders,
                                   size_t count, drdc_nmea_t *out);

/**
 * The date and time of day of an RMC or ZDA sentence, whatever fix it
 * reports, for dating other sentences with drdc_nmea_utc().
 *
 * drdc_nmea_parse() refuses an RMC whose status is V or mode N
 * (DRDC_E_NO_FIX), and with it the date the sentence carries; a receiver
 * that has lost its fix, or one that sends only such RMCs, would leave
 * its GGA fixes without a date. This function keeps that date: the
 * receiver's clock, which it keeps across short outages (before the
 * first fix of a cold start some receivers send a default date, so a log
 * is better dated by its valid RMCs and ZDAs where it has them).
 *
 * The record written is the one drdc_nmea_parse() writes, restricted to
 * the type, the talker, the time of day and the date: RMC: `time`,
 * `year`, `month`, `day`, `has` = DRDC_NMEA_HAS_TIME | DRDC_NMEA_HAS_DATE;
 * ZDA: the whole ZDA record (its local zone too), as drdc_nmea_parse()
 * writes it. Every other field is 0. Of an RMC only the time, the status
 * letter (A or V, for its syntax) and the date are read; its position,
 * speed, course and mode are not (the checksum covers them).
 *
 * @param text   the sentence from `$`, CR LF optional; not necessarily
 *               NUL-terminated
 * @param length number of characters of `text`; exactly these are read
 * @param flags  0, or DRDC_NMEA_STRICT (82 characters, every field of the
 *               sentence's NMEA 0183 layout present)
 * @param[out] out the time of day and date; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL `text` or `out` is NULL
 * @retval DRDC_E_RANGE `flags` has a bit other than DRDC_NMEA_STRICT;
 *         ZDA zone hours beyond 13
 * @retval DRDC_E_SYNTAX no `$` first, a malformed checksum digit, time of
 *         day or date; RMC: a status other than A or V
 * @retval DRDC_E_CHARACTER a character outside printable ASCII before
 *         the checksum
 * @retval DRDC_E_TRUNCATED the text ends before `*hh`
 * @retval DRDC_E_OVERLONG more than 126 characters up to the checksum
 *         (strict: 80)
 * @retval DRDC_E_TRAILING characters after the checksum other than CR LF
 * @retval DRDC_E_CHECKSUM the checksum does not match
 * @retval DRDC_E_SENTENCE neither an RMC nor a ZDA (a GGA carries no
 *         date), or not a sentence drdc_nmea_parse() knows at all
 * @retval DRDC_E_MISSING_FIELD the time of day, the status (RMC), the day,
 *         month or year is empty, or the sentence ends before its date
 *         (strict: before the end of its layout); a receiver's RMC before
 *         its clock is set (`$GPRMC,,V,,,,,,,,,,N`)
 * @retval DRDC_E_HOUR hour of the time above 23
 * @retval DRDC_E_MINUTE minute of the time, or ZDA zone minutes, 60 or
 *         more
 * @retval DRDC_E_SECOND second of the time above 60
 * @retval DRDC_E_DAY day outside 1..31
 * @retval DRDC_E_MONTH month outside 1..12
 * @retval DRDC_E_YEAR ZDA year below DRDC_YEAR_MIN
 *
 * Accuracy: exact (the time of day to the nanosecond, as
 * drdc_nmea_parse()). Checked against pynmeagps's reading of the same
 * sentences (tests/ref/gen_nmea.py, tests/nmea/test_nmea.c).
 *
 * Dating a stream in firmware: keep the last date seen and stitch each
 * fix to it.
 * @code
 * drdc_nmea_t date;  // the last RMC or ZDA date
 * int dated = 0;
 * // for each received sentence s of n characters:
 * drdc_nmea_t fix;
 * drdc_time_t utc;
 * if (drdc_nmea_parse_date(s, n, 0u, &fix) == DRDC_OK) {
 *   date = fix;
 *   dated = 1;
 * }
 * if ((drdc_nmea_parse(s, n, &fix) == DRDC_OK) && (dated != 0) &&
 *     (drdc_nmea_utc(NULL, &date, &fix, &utc) == DRDC_OK)) {
 *   // fix at utc
 * }
 * @endcode
 */
drdc_status_t drdc_nmea_parse_date(const char *text, size_t length,
                                   uint32_t flags, drdc_nmea_t *out);

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
 * @param dated an RMC or ZDA sentence (has DRDC_NMEA_HAS_DATE), from
 *              drdc_nmea_parse() or drdc_nmea_parse_date()
 * @param s     any sentence (its time of day)
 * @param[out] utc the instant; unchanged on error
 * @retval DRDC_OK written
 * @retval DRDC_E_NULL a pointer is NULL
 * @retval DRDC_E_MISSING_FIELD `dated` carries no date, or `dated` or `s`
 *         no time of day (DRDC_NMEA_HAS_TIME clear: VTG, HDT, THS, GSA)
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
