/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the JAUS Report Global Pose and Report Local Pose
 *        bodies. The first byte picks the message and the form; the rest
 *        is a received body in a heap block of exactly its size (ASan
 *        reports any read past it). A rejected body leaves the output
 *        alone; an accepted one packs again, into a block of exactly its
 *        length, to a body that unpacks to the same values
 *        (unpack -> pack -> unpack), and to the same bytes when only fields
 *        whose step the pose types resolve are present and no angle is +pi.
 *        The same bytes are then read as a pose to pack: a pose that packs
 *        unpacks within half an integer step of each value. Host only.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/jaus_pose.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The pose bodies' common part, whichever the message. */
struct common {
  uint16_t presence;
  int64_t v[8]; /* raw values in bit order, angles as binary angles */
  uint32_t stamp;
};

static void from_global(const drdc_jaus_global_pose_t *b, struct common *c)
{
  c->presence = b->presence;
  c->v[0] = b->pose.latitude;
  c->v[1] = b->pose.longitude;
  c->v[2] = b->pose.height;
  c->v[3] = b->position_rms;
  c->v[4] = b->pose.e.roll;
  c->v[5] = b->pose.e.pitch;
  c->v[6] = b->pose.e.yaw;
  c->v[7] = b->attitude_rms;
  c->stamp = b->time_stamp;
}

static void from_local(const drdc_jaus_local_pose_t *b, struct common *c)
{
  c->presence = b->presence;
  c->v[0] = b->pose.p.x;
  c->v[1] = b->pose.p.y;
  c->v[2] = b->pose.p.z;
  c->v[3] = b->position_rms;
  c->v[4] = b->pose.e.roll;
  c->v[5] = b->pose.e.pitch;
  c->v[6] = b->pose.e.yaw;
  c->v[7] = b->attitude_rms;
  c->stamp = b->time_stamp;
}

static int same(const struct common *a, const struct common *b)
{
  int k;

  if ((a->presence != b->presence) || (a->stamp != b->stamp)) {
    return 0;
  }
  for (k = 0; k < 8; k++) {
    if (a->v[k] != b->v[k]) {
      return 0;
    }
  }
  return 1;
}

/* unpack as the message; -1 for a status other than DRDC_OK */
static drdc_status_t unpack(int local, drdc_jaus_form_t form, const uint8_t *p,
                            size_t n, struct common *c)
{
  drdc_status_t st;

  if (local) {
    drdc_jaus_local_pose_t b;

    memset(&b, 0x5A, sizeof b);
    st = drdc_jaus_local_pose_unpack(p, n, form, &b);
    if (st != DRDC_OK) {
      drdc_jaus_local_pose_t untouched;

      memset(&untouched, 0x5A, sizeof untouched);
      if (memcmp(&b, &untouched, sizeof b) != 0) {
        abort(); /* an error must leave the output alone */
      }
      return st;
    }
    from_local(&b, c);
  } else {
    drdc_jaus_global_pose_t b;

    memset(&b, 0x5A, sizeof b);
    st = drdc_jaus_global_pose_unpack(p, n, form, &b);
    if (st != DRDC_OK) {
      drdc_jaus_global_pose_t untouched;

      memset(&untouched, 0x5A, sizeof untouched);
      if (memcmp(&b, &untouched, sizeof b) != 0) {
        abort();
      }
      return st;
    }
    from_global(&b, c);
  }
  return DRDC_OK;
}

static drdc_status_t pack(int local, drdc_jaus_form_t form,
                          const struct common *c, uint8_t *buf, size_t capacity,
                          size_t *n)
{
  if (local) {
    drdc_jaus_local_pose_t b;

    memset(&b, 0, sizeof b);
    b.presence = c->presence;
    b.pose.p.x = (int32_t)c->v[0];
    b.pose.p.y = (int32_t)c->v[1];
    b.pose.p.z = (int32_t)c->v[2];
    b.position_rms = (int32_t)c->v[3];
    b.pose.e.roll = (uint32_t)c->v[4];
    b.pose.e.pitch = (uint32_t)c->v[5];
    b.pose.e.yaw = (uint32_t)c->v[6];
    b.attitude_rms = (uint32_t)c->v[7];
    b.time_stamp = c->stamp;
    return drdc_jaus_local_pose_pack(&b, form, buf, capacity, n);
  } else {
    drdc_jaus_global_pose_t b;

    memset(&b, 0, sizeof b);
    b.presence = c->presence;
    b.pose.latitude = c->v[0];
    b.pose.longitude = c->v[1];
    b.pose.height = c->v[2];
    b.position_rms = (int32_t)c->v[3];
    b.pose.e.roll = (uint32_t)c->v[4];
    b.pose.e.pitch = (uint32_t)c->v[5];
    b.pose.e.yaw = (uint32_t)c->v[6];
    b.attitude_rms = (uint32_t)c->v[7];
    b.time_stamp = c->stamp;
    return drdc_jaus_global_pose_pack(&b, form, buf, capacity, n);
  }
}

/* fields whose integer step the raw formats resolve (see jaus_pose.h) */
static int exact_only(int local, drdc_jaus_form_t form, const struct common *c)
{
  uint16_t coarse = DRDC_JAUS_PV_POSITION_RMS;
  int k;

  if (!local || (form == DRDC_JAUS_FORM_RA3)) {
    coarse |= DRDC_JAUS_PV_ALTITUDE;
  }
  if ((c->presence & coarse) != 0u) {
    return 0;
  }
  for (k = 4; k <= 6; k++) {
    if (((c->presence >> k) & 1u) && (c->v[k] == INT64_C(0x80000000))) {
      return 0; /* +pi comes back as -pi */
    }
  }
  return 1;
}

/* half an integer step of field k, in raw units, rounded up, plus 1 */
static int64_t half_step(int local, drdc_jaus_form_t form, int k)
{
  static const long double spans[2][8] = {
      {648e12L, 1296e12L, 45000.0L * 65536, 100.0L * 65536, 4294967296.0L,
       4294967296.0L, 4294967296.0L, 2147483648.0L},
      {200000.0L * 65536, 200000.0L * 65536, 200000.0L * 65536, 100.0L * 65536,
       4294967296.0L, 4294967296.0L, 4294967296.0L, 2147483648.0L},
  };
  long double span = spans[local][k];
  long double steps = (k < 4) ? 4294967295.0L : 65535.0L;

  if (local && (k == 2) && (form == DRDC_JAUS_FORM_RA3)) {
    span = 45000.0L * 65536;
  }
  if ((form == DRDC_JAUS_FORM_RA3) && (k != 3) && (k != 7)) {
    steps -= 1.0L; /* signed RA 3.x types drop one integer */
  }
  return (int64_t)(span / steps / 2.0L) + 1;
}

static void check_pose(int local, drdc_jaus_form_t form,
                       const struct common *in)
{
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t n = 0u;
  struct common out;
  drdc_status_t st;
  int k;

  if (pack(local, form, in, buf, sizeof buf, &n) != DRDC_OK) {
    return;
  }
  st = unpack(local, form, buf, n, &out);
  if (st != DRDC_OK) {
    /* only AS6009 X, Y, Z at 32768 - 2^-16 m decode beyond Q15.16 */
    if (!(local && (st == DRDC_E_OVERFLOW) &&
          (form == DRDC_JAUS_FORM_AS6009))) {
      abort();
    }
    return;
  }
  if ((out.presence != in->presence) ||
      (out.stamp != (((in->presence >> 8) & 1u) ? in->stamp : 0u))) {
    abort();
  }
  for (k = 0; k < 8; k++) {
    int64_t d;

    if (((in->presence >> k) & 1u) == 0u) {
      if (out.v[k] != 0) {
        abort(); /* absent fields are zero */
      }
      continue;
    }
    d = out.v[k] - in->v[k];
    if ((k >= 4) && (k <= 6)) {
      d = (int64_t)(int32_t)(uint32_t)(out.v[k] - in->v[k]); /* modulo a turn */
    }
    if ((d > half_step(local, form, k)) || (d < -half_step(local, form, k))) {
      abort();
    }
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  int local;
  drdc_jaus_form_t form;
  uint8_t *body;
  uint8_t *again;
  size_t n = 0u;
  struct common a;
  struct common b;
  struct common raw;
  drdc_status_t st;

  if (size < 1u) {
    return 0;
  }
  local = data[0] & 1u;
  form = (data[0] & 2u) ? DRDC_JAUS_FORM_AS6009 : DRDC_JAUS_FORM_RA3;
  size -= 1u;
  body = malloc(size + 1u);
  if (body == NULL) {
    return 0;
  }
  memcpy(body, data + 1, size);
  st = unpack(local, form, body, size, &a);
  if (st == DRDC_OK) {
    /* a body re-packs into exactly its own length */
    again = malloc(size);
    if ((again == NULL) ||
        (pack(local, form, &a, again, size, &n) != DRDC_OK) || (n != size) ||
        (unpack(local, form, again, n, &b) != DRDC_OK) || !same(&a, &b)) {
      abort();
    }
    if (exact_only(local, form, &a) && (memcmp(body, again, size) != 0)) {
      abort();
    }
    free(again);
  }
  /* the same bytes as a pose to pack */
  memset(&raw, 0, sizeof raw);
  if (size >= 2u) {
    memcpy(&raw.presence, body, 2u);
    memcpy(raw.v, body + 2,
           (size - 2u) < sizeof raw.v ? (size - 2u) : sizeof raw.v);
    if (size > 2u + sizeof raw.v) {
      memcpy(&raw.stamp, body + 2 + sizeof raw.v,
             (size - 2u - sizeof raw.v) < 4u ? (size - 2u - sizeof raw.v) : 4u);
    }
    /* angles and RMS angle as binary angles, lengths as Q15.16 where the
     * type is 32-bit */
    for (int k = 3; k < 8; k++) {
      raw.v[k] =
          (k == 3) ? (int64_t)(int32_t)raw.v[k] : (int64_t)(uint32_t)raw.v[k];
    }
    if (local) {
      for (int k = 0; k < 3; k++) {
        raw.v[k] = (int32_t)raw.v[k];
      }
    } else if (data[0] & 4u) {
      /* make latitude, longitude and height likely to be in range */
      raw.v[0] %= INT64_C(324000000000001);
      raw.v[1] %= INT64_C(648000000000001);
      raw.v[2] %= INT64_C(35000) << 16;
    }
    check_pose(local, form, &raw);
  }
  free(body);
  return 0;
}
