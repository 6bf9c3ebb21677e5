/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief JAUS Report Global Pose and Report Local Pose bodies: byte-exact
 *        vectors of the exact model (every field at min, max, zero,
 *        negative and random values; the presence vectors that matter;
 *        both forms), arbitrary received bytes, round trips, named cases
 *        and the bad-input catalogue. The same bytes on every target: the
 *        suite runs on big-endian PowerPC e500 too.
 */
#include <stddef.h>
#include <stdint.h>

#include <drdc/jaus_pose.h>
#include <drdc/time_jaus.h>

#include "suites.h"
#include "unity.h"
#include "vectors_jaus_pose.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* a signed raw angle of the vectors as a binary angle */
static drdc_bam32_t bam(int64_t v)
{
  return (drdc_bam32_t)((uint64_t)v & UINT64_C(0xFFFFFFFF));
}

static void global_from(const int64_t in[8], uint16_t presence, uint32_t stamp,
                        drdc_jaus_global_pose_t *b)
{
  b->presence = presence;
  b->pose.latitude = in[0];
  b->pose.longitude = in[1];
  b->pose.height = in[2];
  b->position_rms = (drdc_q15_16_t)in[3];
  b->pose.e.roll = bam(in[4]);
  b->pose.e.pitch = bam(in[5]);
  b->pose.e.yaw = bam(in[6]);
  b->attitude_rms = (drdc_bam32_t)in[7];
  b->time_stamp = stamp;
}

static void local_from(const int64_t in[8], uint16_t presence, uint32_t stamp,
                       drdc_jaus_local_pose_t *b)
{
  b->presence = presence;
  b->pose.p.x = (drdc_q15_16_t)in[0];
  b->pose.p.y = (drdc_q15_16_t)in[1];
  b->pose.p.z = (drdc_q15_16_t)in[2];
  b->position_rms = (drdc_q15_16_t)in[3];
  b->pose.e.roll = bam(in[4]);
  b->pose.e.pitch = bam(in[5]);
  b->pose.e.yaw = bam(in[6]);
  b->attitude_rms = (drdc_bam32_t)in[7];
  b->time_stamp = stamp;
}

static void expect_global(const int64_t out[8], uint16_t presence,
                          uint32_t stamp, const drdc_jaus_global_pose_t *b)
{
  TEST_ASSERT_EQUAL_HEX16(presence, b->presence);
  TEST_ASSERT_EQUAL_INT64(out[0], b->pose.latitude);
  TEST_ASSERT_EQUAL_INT64(out[1], b->pose.longitude);
  TEST_ASSERT_EQUAL_INT64(out[2], b->pose.height);
  TEST_ASSERT_EQUAL_INT64(out[3], b->position_rms);
  TEST_ASSERT_EQUAL_HEX32(bam(out[4]), b->pose.e.roll);
  TEST_ASSERT_EQUAL_HEX32(bam(out[5]), b->pose.e.pitch);
  TEST_ASSERT_EQUAL_HEX32(bam(out[6]), b->pose.e.yaw);
  TEST_ASSERT_EQUAL_INT64(out[7], b->attitude_rms);
  TEST_ASSERT_EQUAL_HEX32(stamp, b->time_stamp);
}

static void expect_local(const int64_t out[8], uint16_t presence,
                         uint32_t stamp, const drdc_jaus_local_pose_t *b)
{
  TEST_ASSERT_EQUAL_HEX16(presence, b->presence);
  TEST_ASSERT_EQUAL_INT64(out[0], b->pose.p.x);
  TEST_ASSERT_EQUAL_INT64(out[1], b->pose.p.y);
  TEST_ASSERT_EQUAL_INT64(out[2], b->pose.p.z);
  TEST_ASSERT_EQUAL_INT64(out[3], b->position_rms);
  TEST_ASSERT_EQUAL_HEX32(bam(out[4]), b->pose.e.roll);
  TEST_ASSERT_EQUAL_HEX32(bam(out[5]), b->pose.e.pitch);
  TEST_ASSERT_EQUAL_HEX32(bam(out[6]), b->pose.e.yaw);
  TEST_ASSERT_EQUAL_INT64(out[7], b->attitude_rms);
  TEST_ASSERT_EQUAL_HEX32(stamp, b->time_stamp);
}

/* A recognisable body that must survive every failed call. */
static const int64_t sentinel[8] = {11, 22, 33, 44, 55, 66, 77, 88};
#define SENTINEL_PRESENCE 0x5A5Au
#define SENTINEL_STAMP    UINT32_C(0xA5A5A5A5)

/* Bytes whose integer step the raw format resolves round-trip exactly;
 * the others (altitude, RA 3.x local Z: Q47.16 / Q15.16 step 1.5e-5 m >
 * 1.05e-5 m; Position RMS) may move by one step. */
static uint16_t exact_bits(uint8_t local, drdc_jaus_form_t form)
{
  uint16_t coarse = DRDC_JAUS_PV_POSITION_RMS;

  if ((local == 0u) || (form == DRDC_JAUS_FORM_RA3)) {
    coarse |= DRDC_JAUS_PV_ALTITUDE;
  }
  return (uint16_t)(DRDC_JAUS_PV_ALL & ~coarse);
}

/* Whether an angle present decoded to +-pi: the integer of +pi comes
 * back as the binary angle of -pi and re-encodes as -pi's integer. */
static int at_pi(uint16_t presence, const drdc_euler_t *e)
{
  const drdc_bam32_t pi = UINT32_C(0x80000000);

  return (((presence & DRDC_JAUS_PV_ROLL) != 0u) && (e->roll == pi)) ||
         (((presence & DRDC_JAUS_PV_PITCH) != 0u) && (e->pitch == pi)) ||
         (((presence & DRDC_JAUS_PV_YAW) != 0u) && (e->yaw == pi));
}

/* unpack(b) again through pack and unpack: the same values; the same
 * bytes when only exact fields are present and no angle is +pi. */
static void check_round_trip(uint8_t local, drdc_jaus_form_t form,
                             const uint8_t *bytes, size_t length)
{
  uint8_t again[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 0u;

  if (local == 0u) {
    drdc_jaus_global_pose_t a;
    drdc_jaus_global_pose_t b;

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_jaus_global_pose_unpack(bytes, length, form, &a));
    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_jaus_global_pose_pack(&a, form, again, sizeof again, &n));
    TEST_ASSERT_EQUAL_size_t(length, n);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_jaus_global_pose_unpack(again, n, form, &b));
    TEST_ASSERT_EQUAL_HEX16(a.presence, b.presence);
    TEST_ASSERT_EQUAL_INT64(a.pose.latitude, b.pose.latitude);
    TEST_ASSERT_EQUAL_INT64(a.pose.longitude, b.pose.longitude);
    TEST_ASSERT_EQUAL_INT64(a.pose.height, b.pose.height);
    TEST_ASSERT_EQUAL_INT32(a.position_rms, b.position_rms);
    TEST_ASSERT_EQUAL_HEX32(a.pose.e.roll, b.pose.e.roll);
    TEST_ASSERT_EQUAL_HEX32(a.pose.e.pitch, b.pose.e.pitch);
    TEST_ASSERT_EQUAL_HEX32(a.pose.e.yaw, b.pose.e.yaw);
    TEST_ASSERT_EQUAL_HEX32(a.attitude_rms, b.attitude_rms);
    TEST_ASSERT_EQUAL_HEX32(a.time_stamp, b.time_stamp);
    if (((a.presence & (uint16_t)~exact_bits(local, form)) == 0u) &&
        (at_pi(a.presence, &a.pose.e) == 0)) {
      TEST_ASSERT_EQUAL_HEX8_ARRAY(bytes, again, length);
    }
  } else {
    drdc_jaus_local_pose_t a;
    drdc_jaus_local_pose_t b;

    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_jaus_local_pose_unpack(bytes, length, form, &a));
    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_jaus_local_pose_pack(&a, form, again, sizeof again, &n));
    TEST_ASSERT_EQUAL_size_t(length, n);
    TEST_ASSERT_EQUAL_INT(DRDC_OK,
                          drdc_jaus_local_pose_unpack(again, n, form, &b));
    TEST_ASSERT_EQUAL_HEX16(a.presence, b.presence);
    TEST_ASSERT_EQUAL_INT32(a.pose.p.x, b.pose.p.x);
    TEST_ASSERT_EQUAL_INT32(a.pose.p.y, b.pose.p.y);
    TEST_ASSERT_EQUAL_INT32(a.pose.p.z, b.pose.p.z);
    TEST_ASSERT_EQUAL_INT32(a.position_rms, b.position_rms);
    TEST_ASSERT_EQUAL_HEX32(a.pose.e.roll, b.pose.e.roll);
    TEST_ASSERT_EQUAL_HEX32(a.pose.e.pitch, b.pose.e.pitch);
    TEST_ASSERT_EQUAL_HEX32(a.pose.e.yaw, b.pose.e.yaw);
    TEST_ASSERT_EQUAL_HEX32(a.attitude_rms, b.attitude_rms);
    TEST_ASSERT_EQUAL_HEX32(a.time_stamp, b.time_stamp);
    if (((a.presence & (uint16_t)~exact_bits(local, form)) == 0u) &&
        (at_pi(a.presence, &a.pose.e) == 0)) {
      TEST_ASSERT_EQUAL_HEX8_ARRAY(bytes, again, length);
    }
  }
}

static void test_pack_gives_the_model_bytes(void)
{
  size_t i;

  for (i = 0u; i < COUNT(jaus_pose_pack_vectors); i++) {
    const struct jaus_pose_pack_vector *v = &jaus_pose_pack_vectors[i];
    uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
    size_t n = 0u;
    size_t size = 0u;

    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_pose_size(v->presence, &size));
    TEST_ASSERT_EQUAL_size_t(v->length, size);
    if (v->local == 0u) {
      drdc_jaus_global_pose_t b;

      global_from(v->in, v->presence, v->stamp, &b);
      TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_global_pose_pack(
                                         &b, v->form, buf, sizeof buf, &n));
    } else {
      drdc_jaus_local_pose_t b;

      local_from(v->in, v->presence, v->stamp, &b);
      TEST_ASSERT_EQUAL_INT(
          DRDC_OK, drdc_jaus_local_pose_pack(&b, v->form, buf, sizeof buf, &n));
    }
    TEST_ASSERT_EQUAL_size_t(v->length, n);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(v->bytes, buf, n);
  }
}

/* The packed bytes unpacked: the model's values, each within half an
 * integer step of the input (the model's), or DRDC_E_OVERFLOW for a local
 * position that rounds beyond Q15.16. */
static void test_unpack_of_packed_bytes_gives_the_model_values(void)
{
  size_t i;
  size_t overflows = 0u;

  for (i = 0u; i < COUNT(jaus_pose_pack_vectors); i++) {
    const struct jaus_pose_pack_vector *v = &jaus_pose_pack_vectors[i];

    if (v->local == 0u) {
      drdc_jaus_global_pose_t b;

      TEST_ASSERT_EQUAL_INT(v->unpacked, drdc_jaus_global_pose_unpack(
                                             v->bytes, v->length, v->form, &b));
      expect_global(v->out, v->presence, v->stamp, &b);
    } else {
      drdc_jaus_local_pose_t b;

      local_from(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
      TEST_ASSERT_EQUAL_INT(v->unpacked, drdc_jaus_local_pose_unpack(
                                             v->bytes, v->length, v->form, &b));
      if (v->unpacked == DRDC_OK) {
        expect_local(v->out, v->presence, v->stamp, &b);
      } else {
        expect_local(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
        overflows++;
      }
    }
    if (v->unpacked == DRDC_OK) {
      check_round_trip(v->local, v->form, v->bytes, v->length);
    }
  }
  TEST_ASSERT_TRUE(overflows > 0u);
}

static void test_unpack_of_any_bytes_gives_the_model(void)
{
  size_t i;

  for (i = 0u; i < COUNT(jaus_pose_unpack_vectors); i++) {
    const struct jaus_pose_unpack_vector *v = &jaus_pose_unpack_vectors[i];

    if (v->local == 0u) {
      drdc_jaus_global_pose_t b;

      global_from(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
      TEST_ASSERT_EQUAL_INT(v->status, drdc_jaus_global_pose_unpack(
                                           v->bytes, v->length, v->form, &b));
      if (v->status == DRDC_OK) {
        expect_global(v->out, v->presence, v->stamp, &b);
      } else {
        expect_global(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
      }
    } else {
      drdc_jaus_local_pose_t b;

      local_from(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
      TEST_ASSERT_EQUAL_INT(v->status, drdc_jaus_local_pose_unpack(
                                           v->bytes, v->length, v->form, &b));
      if (v->status == DRDC_OK) {
        expect_local(v->out, v->presence, v->stamp, &b);
      } else {
        expect_local(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
      }
    }
    if (v->status == DRDC_OK) {
      check_round_trip(v->local, v->form, v->bytes, v->length);
    }
  }
}

/* The header's example, and a body written out by hand from the standard:
 * presence first, least significant byte first, in bit order. */
static void test_named_cases(void)
{
  static const uint8_t example[] = {0x41, 0x00, 0xff, 0xff,
                                    0xff, 0xbf, 0xff, 0xbf};
  /* RA 3.x: latitude -45 deg -> -round(0.5 x (2^31 - 1)) = -1073741824,
   * yaw -90 deg -> -round(0.5 x 32767) = -16384, stamp day 22 17:00:01 */
  static const uint8_t ra3[] = {0x41, 0x01, 0x00, 0x00, 0x00, 0xc0,
                                0x00, 0xc0, 0x00, 0x04, 0x40, 0xb4};
  drdc_jaus_global_pose_t b;
  drdc_jaus_global_pose_t back;
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 0u;

  global_from(sentinel, DRDC_JAUS_PV_LATITUDE | DRDC_JAUS_PV_YAW, 0u, &b);
  b.pose.latitude = 45 * DRDC_NAS_PER_DEGREE;
  b.pose.e.yaw = UINT32_C(0x40000000);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        drdc_jaus_global_pose_pack(&b, DRDC_JAUS_FORM_AS6009,
                                                   buf, sizeof buf, &n));
  TEST_ASSERT_EQUAL_size_t(sizeof example, n);
  TEST_ASSERT_EQUAL_HEX8_ARRAY(example, buf, n);

  b.presence =
      DRDC_JAUS_PV_LATITUDE | DRDC_JAUS_PV_YAW | DRDC_JAUS_PV_TIME_STAMP;
  b.pose.latitude = -45 * DRDC_NAS_PER_DEGREE;
  b.pose.e.yaw = UINT32_C(0xC0000000);
  b.time_stamp =
      (UINT32_C(22) << 27) | (UINT32_C(17) << 22) | (UINT32_C(1) << 10);
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK,
      drdc_jaus_global_pose_pack(&b, DRDC_JAUS_FORM_RA3, buf, sizeof buf, &n));
  TEST_ASSERT_EQUAL_size_t(sizeof ra3, n);
  TEST_ASSERT_EQUAL_HEX8_ARRAY(ra3, buf, n);
  TEST_ASSERT_EQUAL_INT(
      DRDC_OK,
      drdc_jaus_global_pose_unpack(ra3, sizeof ra3, DRDC_JAUS_FORM_RA3, &back));
  /* -45 degrees was a tie, rounded away to -1073741824, which decodes
   * half a step (75 437 nas) beyond: -1073741824 x 90 deg / (2^31 - 1) */
  TEST_ASSERT_EQUAL_INT64(INT64_C(-162000000075437), back.pose.latitude);
  /* yaw likewise: -16384 x 2^31 / 32767 = -1073774592.6 -> 0xBFFF7FFF */
  TEST_ASSERT_EQUAL_HEX32(UINT32_C(0xBFFF7FFF), back.pose.e.yaw);
  TEST_ASSERT_EQUAL_HEX32(b.time_stamp, back.time_stamp);
  TEST_ASSERT_EQUAL_INT64(0, back.pose.longitude); /* absent: zero */
  TEST_ASSERT_EQUAL_HEX32(0u, back.pose.e.roll);

  /* AS6009 +pi decodes to the binary angle of -pi */
  {
    static const uint8_t pi[] = {0x10, 0x00, 0xff, 0xff};

    TEST_ASSERT_EQUAL_INT(
        DRDC_OK, drdc_jaus_global_pose_unpack(pi, sizeof pi,
                                              DRDC_JAUS_FORM_AS6009, &back));
    TEST_ASSERT_EQUAL_HEX32(UINT32_C(0x80000000), back.pose.e.roll);
  }
}

static void test_sizes_of_every_presence_vector(void)
{
  uint32_t pv;

  for (pv = 0u; pv <= 0x1FFu; pv++) {
    size_t n = 0u;
    size_t want = 2u;
    unsigned bit;

    for (bit = 0u; bit <= 8u; bit++) {
      if (((pv >> bit) & 1u) != 0u) {
        want += ((bit >= 4u) && (bit <= 7u)) ? 2u : 4u;
      }
    }
    TEST_ASSERT_EQUAL_INT(DRDC_OK, drdc_jaus_pose_size((uint16_t)pv, &n));
    TEST_ASSERT_EQUAL_size_t(want, n);
  }
}

static void test_drdc_jaus_pose_size_bad_input(void)
{
  size_t n = 7u;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_pose_size(DRDC_JAUS_PV_ALL, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_jaus_pose_size(0x0200u, &n));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE, drdc_jaus_pose_size(0xFFFFu, &n));
  TEST_ASSERT_EQUAL_size_t(7u, n);
}

/* buf and length stay as they were */
static void expect_untouched(const uint8_t *buf, size_t n)
{
  size_t k;

  TEST_ASSERT_EQUAL_size_t(99u, n);
  for (k = 0u; k < DRDC_JAUS_POSE_BODY_MAX; k++) {
    TEST_ASSERT_EQUAL_HEX8(0xEEu, buf[k]);
  }
}

static void fill(uint8_t *buf)
{
  size_t k;

  for (k = 0u; k < DRDC_JAUS_POSE_BODY_MAX; k++) {
    buf[k] = 0xEEu;
  }
}

/* one good body of each kind: everything present, in range */
static const int64_t good[8] = {0, 0, 0, 0, 0, 0, 0, 0};
static const uint32_t good_stamp = (UINT32_C(1) << 27);

static drdc_status_t pack_global_with(drdc_jaus_global_pose_t *b,
                                      drdc_jaus_form_t form, size_t capacity)
{
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 99u;
  drdc_status_t st;

  fill(buf);
  st = drdc_jaus_global_pose_pack(b, form, buf, capacity, &n);
  if (st != DRDC_OK) {
    expect_untouched(buf, n);
  }
  global_from(good, DRDC_JAUS_PV_ALL, good_stamp, b);
  return st;
}

static void test_drdc_jaus_global_pose_pack_bad_input(void)
{
  drdc_jaus_global_pose_t b;
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 99u;

  global_from(good, DRDC_JAUS_PV_ALL, good_stamp, &b);
  TEST_ASSERT_EQUAL_INT(DRDC_OK, pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_global_pose_pack(NULL, DRDC_JAUS_FORM_RA3,
                                                   buf, sizeof buf, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_global_pose_pack(&b, DRDC_JAUS_FORM_RA3, NULL, sizeof buf, &n));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL,
                        drdc_jaus_global_pose_pack(&b, DRDC_JAUS_FORM_RA3, buf,
                                                   sizeof buf, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, (drdc_jaus_form_t)2, 30u));
  b.presence = 0x0200u;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.pose.height = (INT64_C(35000) << 16) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.pose.height = -(INT64_C(10000) << 16) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.position_rms = -1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.position_rms = (100 << 16) + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.attitude_rms = UINT32_C(0x80000001);
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_global_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.pose.latitude = 90 * DRDC_NAS_PER_DEGREE + 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LATITUDE,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.pose.longitude = -180 * DRDC_NAS_PER_DEGREE - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        pack_global_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.pose.longitude = 181 * DRDC_NAS_PER_DEGREE; /* inside {W}'s [-540, 540) */
  TEST_ASSERT_EQUAL_INT(DRDC_E_LONGITUDE,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = 0u;
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = good_stamp | (UINT32_C(24) << 22);
  TEST_ASSERT_EQUAL_INT(DRDC_E_HOUR,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = good_stamp | (UINT32_C(60) << 16);
  TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = good_stamp | (UINT32_C(61) << 10);
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = good_stamp | UINT32_C(1000);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        pack_global_with(&b, DRDC_JAUS_FORM_RA3, 29u));
  /* an absent field is not checked */
  b.presence = DRDC_JAUS_PV_ALL & (uint16_t)~DRDC_JAUS_PV_LATITUDE;
  b.pose.latitude = INT64_MAX;
  TEST_ASSERT_EQUAL_INT(DRDC_OK, pack_global_with(&b, DRDC_JAUS_FORM_RA3, 26u));
}

static drdc_status_t pack_local_with(drdc_jaus_local_pose_t *b,
                                     drdc_jaus_form_t form, size_t capacity)
{
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 99u;
  drdc_status_t st;

  fill(buf);
  st = drdc_jaus_local_pose_pack(b, form, buf, capacity, &n);
  if (st != DRDC_OK) {
    expect_untouched(buf, n);
  }
  local_from(good, DRDC_JAUS_PV_ALL, good_stamp, b);
  return st;
}

static void test_drdc_jaus_local_pose_pack_bad_input(void)
{
  drdc_jaus_local_pose_t b;
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 99u;

  local_from(good, DRDC_JAUS_PV_ALL, good_stamp, &b);
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_local_pose_pack(NULL, DRDC_JAUS_FORM_RA3, buf, sizeof buf, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_local_pose_pack(&b, DRDC_JAUS_FORM_RA3, NULL, sizeof buf, &n));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_local_pose_pack(&b, DRDC_JAUS_FORM_RA3, buf, sizeof buf, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_local_with(&b, (drdc_jaus_form_t)5, 30u));
  b.presence = 0x8000u;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  /* RA 3.x Z: [-10 000, 35 000] m; AS6009 takes any Q15.16 */
  b.pose.p.z = -(10000 << 16) - 1;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_local_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.pose.p.z = INT32_MIN;
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.position_rms = INT32_MIN;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.attitude_rms = UINT32_MAX;
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        pack_local_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = UINT32_C(7) << 22; /* day 0 */
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY,
                        pack_local_with(&b, DRDC_JAUS_FORM_RA3, 30u));
  b.time_stamp = good_stamp | (UINT32_C(31) << 22);
  TEST_ASSERT_EQUAL_INT(DRDC_E_HOUR,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.time_stamp = good_stamp | (UINT32_C(63) << 16);
  TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.time_stamp = good_stamp | (UINT32_C(63) << 10);
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  b.time_stamp = good_stamp | UINT32_C(1023);
  TEST_ASSERT_EQUAL_INT(DRDC_E_NANOSECOND,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 30u));
  TEST_ASSERT_EQUAL_INT(DRDC_E_BUFFER,
                        pack_local_with(&b, DRDC_JAUS_FORM_AS6009, 0u));
}

/* Received bodies, one per condition: {presence lo, hi, fields...}. */
static const uint8_t empty_body[] = {0x00, 0x00};
static const uint8_t short_body[] = {0x01, 0x00, 0x00, 0x00, 0x00};
static const uint8_t long_body[] = {0x00, 0x00, 0x00};
static const uint8_t reserved_body[] = {0x00, 0x02};
static const uint8_t ra3_min_int32[] = {0x01, 0x00, 0x00, 0x00, 0x00, 0x80};
static const uint8_t ra3_min_int16[] = {0x20, 0x00, 0x00, 0x80};
static const uint8_t day0[] = {0x00, 0x01, 0x00, 0x00, 0x00, 0x00};
static const uint8_t hour24[] = {0x00, 0x01, 0x00, 0x00, 0x00, 0x0e};
static const uint8_t minute60[] = {0x00, 0x01, 0x00, 0x00, 0x3c, 0x08};
static const uint8_t second61[] = {0x00, 0x01, 0x00, 0xf4, 0x00, 0x08};
static const uint8_t msec1000[] = {0x00, 0x01, 0xe8, 0x03, 0x00, 0x08};
/* AS6009 X = 2^31 + 2^30: 50 000 m, beyond Q15.16 */
static const uint8_t x_far[] = {0x01, 0x00, 0x00, 0x00, 0x00, 0xc0};

static drdc_status_t unpack_global(const uint8_t *p, size_t n,
                                   drdc_jaus_form_t form)
{
  drdc_jaus_global_pose_t b;
  drdc_status_t st;

  global_from(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
  st = drdc_jaus_global_pose_unpack(p, n, form, &b);
  if (st != DRDC_OK) {
    expect_global(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
  }
  return st;
}

static void test_drdc_jaus_global_pose_unpack_bad_input(void)
{
  drdc_jaus_global_pose_t b;

  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        unpack_global(empty_body, 2u, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_jaus_global_pose_unpack(
                                         NULL, 2u, DRDC_JAUS_FORM_RA3, &b));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_global_pose_unpack(empty_body, 2u, DRDC_JAUS_FORM_RA3, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_TRUNCATED,
                        unpack_global(empty_body, 0u, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_TRUNCATED,
                        unpack_global(empty_body, 1u, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_TRUNCATED,
      unpack_global(short_body, sizeof short_body, DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERLONG,
      unpack_global(long_body, sizeof long_body, DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        unpack_global(empty_body, 2u, (drdc_jaus_form_t)2));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      unpack_global(reserved_body, sizeof reserved_body, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      unpack_global(ra3_min_int32, sizeof ra3_min_int32, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_OK,
                        unpack_global(ra3_min_int32, sizeof ra3_min_int32,
                                      DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      unpack_global(ra3_min_int16, sizeof ra3_min_int16, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY,
                        unpack_global(day0, sizeof day0, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_HOUR, unpack_global(hour24, sizeof hour24, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE, unpack_global(minute60, sizeof minute60,
                                                     DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, unpack_global(second61, sizeof second61,
                                                     DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NANOSECOND,
      unpack_global(msec1000, sizeof msec1000, DRDC_JAUS_FORM_AS6009));
}

static drdc_status_t unpack_local(const uint8_t *p, size_t n,
                                  drdc_jaus_form_t form)
{
  drdc_jaus_local_pose_t b;
  drdc_status_t st;

  local_from(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
  st = drdc_jaus_local_pose_unpack(p, n, form, &b);
  if (st != DRDC_OK) {
    expect_local(sentinel, SENTINEL_PRESENCE, SENTINEL_STAMP, &b);
  }
  return st;
}

static void test_drdc_jaus_local_pose_unpack_bad_input(void)
{
  drdc_jaus_local_pose_t b;

  TEST_ASSERT_EQUAL_INT(DRDC_E_NULL, drdc_jaus_local_pose_unpack(
                                         NULL, 2u, DRDC_JAUS_FORM_RA3, &b));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NULL,
      drdc_jaus_local_pose_unpack(empty_body, 2u, DRDC_JAUS_FORM_RA3, NULL));
  TEST_ASSERT_EQUAL_INT(DRDC_E_TRUNCATED,
                        unpack_local(empty_body, 1u, DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_TRUNCATED,
      unpack_local(short_body, sizeof short_body, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERLONG,
      unpack_local(long_body, sizeof long_body, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_RANGE,
                        unpack_local(empty_body, 2u, (drdc_jaus_form_t)7));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      unpack_local(reserved_body, sizeof reserved_body, DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      unpack_local(ra3_min_int16, sizeof ra3_min_int16, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_OVERFLOW, unpack_local(x_far, sizeof x_far,
                                                      DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY,
                        unpack_local(day0, sizeof day0, DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_HOUR, unpack_local(hour24, sizeof hour24, DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(DRDC_E_MINUTE, unpack_local(minute60, sizeof minute60,
                                                    DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(DRDC_E_SECOND, unpack_local(second61, sizeof second61,
                                                    DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_NANOSECOND,
      unpack_local(msec1000, sizeof msec1000, DRDC_JAUS_FORM_RA3));
}

/* A local X, Y or Z beyond Q15.16 is the last check of unpacking (the
 * body is decoded twice, to keep the stack shallow: check, then store):
 * a later field's decoding error and a bad time stamp come first, and
 * the body stays as it was. */
static void test_local_overflow_is_the_last_check(void)
{
  /* RA 3.x X = -2^30 (-50 000 m) and roll = -32768 (not an RA 3.x value) */
  static const uint8_t x_far_bad_roll[] = {0x11, 0x00, 0x00, 0x00,
                                           0x00, 0xc0, 0x00, 0x80};
  /* AS6009 X = 50 000 m and a stamp of day 0 */
  static const uint8_t x_far_day0[] = {0x01, 0x01, 0x00, 0x00, 0x00,
                                       0xc0, 0x00, 0x00, 0x00, 0x00};
  /* the same with a valid stamp: day 1 */
  static const uint8_t x_far_day1[] = {0x01, 0x01, 0x00, 0x00, 0x00,
                                       0xc0, 0x00, 0x00, 0x00, 0x08};

  TEST_ASSERT_EQUAL_INT(
      DRDC_E_RANGE,
      unpack_local(x_far_bad_roll, sizeof x_far_bad_roll, DRDC_JAUS_FORM_RA3));
  TEST_ASSERT_EQUAL_INT(DRDC_E_DAY, unpack_local(x_far_day0, sizeof x_far_day0,
                                                 DRDC_JAUS_FORM_AS6009));
  TEST_ASSERT_EQUAL_INT(
      DRDC_E_OVERFLOW,
      unpack_local(x_far_day1, sizeof x_far_day1, DRDC_JAUS_FORM_AS6009));
}

void suite_jaus_pose(void)
{
  UnitySetTestFile(__FILE__);
  RUN_TEST(test_pack_gives_the_model_bytes);
  RUN_TEST(test_unpack_of_packed_bytes_gives_the_model_values);
  RUN_TEST(test_unpack_of_any_bytes_gives_the_model);
  RUN_TEST(test_named_cases);
  RUN_TEST(test_sizes_of_every_presence_vector);
  RUN_TEST(test_drdc_jaus_pose_size_bad_input);
  RUN_TEST(test_drdc_jaus_global_pose_pack_bad_input);
  RUN_TEST(test_drdc_jaus_local_pose_pack_bad_input);
  RUN_TEST(test_drdc_jaus_global_pose_unpack_bad_input);
  RUN_TEST(test_drdc_jaus_local_pose_unpack_bad_input);
  RUN_TEST(test_local_overflow_is_the_last_check);
}
