/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Golden inputs and outputs of the pose conversions ({W-MGRS},
 *        {We-MGRS}, {l} <-> {le} <-> {We}) and of the JAUS Report Global
 *        and Local Pose bodies: packed from random fields (often out of
 *        range, so every error path adds its status) and unpacked from
 *        random bytes of any length.
 */
#include <stddef.h>

#include <drdc/jaus_pose.h>
#include <drdc/geo_pose.h>

#include "golden.h"

/* every field zero: what the digest reads where a conversion failed */
static const drdc_WePose_t we_blank;
static const drdc_WMGRSPose_t wmgrs_blank;
static const drdc_lePose_t le_blank;
static const drdc_lPose_t l_blank;
static const drdc_jaus_global_pose_t global_blank;
static const drdc_jaus_local_pose_t local_blank;

/* about +-90.04 degrees of latitude and +-180.07 of longitude, in nas:
 * a little beyond the valid ranges */
static drdc_nas_t golden_lat(golden_t *g)
{
  return (int64_t)(int32_t)golden_next(g) * 150902;
}

static drdc_nas_t golden_lon(golden_t *g)
{
  return (int64_t)(int32_t)golden_next(g) * 301804;
}

/* any presence vector; one in eight also sets a reserved bit */
static uint16_t golden_presence(golden_t *g)
{
  uint16_t presence = (uint16_t)(golden_next(g) & DRDC_JAUS_PV_ALL);
  if ((golden_next(g) & 7u) == 0u) {
    presence |= UINT16_C(0x0200);
  }
  return presence;
}

static void golden_euler(golden_t *g, drdc_euler_t *e)
{
  e->yaw = golden_next(g);
  e->pitch = golden_next(g);
  e->roll = golden_next(g);
}

#if GOLDEN_TRACE
static const char *const we_names[6] = {"lat_nas", "lon_nas", "height_q47_16",
                                        "yaw",     "pitch",   "roll"};
static const char *const ref_names[6] = {"ref.lat_nas",       "ref.lon_nas",
                                         "ref.height_q47_16", "ref.yaw",
                                         "ref.pitch",         "ref.roll"};

/* The fields of a {We} pose as inputs of the current function. */
static void golden_we(golden_t *g, const char *const names[6],
                      const drdc_WePose_t *w)
{
  golden_in(g, names[0], w->latitude);
  golden_in(g, names[1], w->longitude);
  golden_in(g, names[2], w->height);
  golden_in(g, names[3], w->e.yaw);
  golden_in(g, names[4], w->e.pitch);
  golden_in(g, names[5], w->e.roll);
}

/* The fields of an {le} pose as inputs of the current function. */
static void golden_le(golden_t *g, const drdc_lePose_t *le)
{
  golden_in(g, "x", le->p.x);
  golden_in(g, "y", le->p.y);
  golden_in(g, "z", le->p.z);
  golden_in(g, "yaw", le->e.yaw);
  golden_in(g, "pitch", le->e.pitch);
  golden_in(g, "roll", le->e.roll);
}
#else
#define golden_we(g, names, w) ((void)(g))
#define golden_le(g, le)       ((void)(g))
#endif

static void fold_we(golden_t *g, const drdc_WePose_t *w)
{
  golden_i64(g, w->latitude);
  golden_i64(g, w->longitude);
  golden_i64(g, w->height);
  golden_u32(g, w->e.yaw);
  golden_u32(g, w->e.pitch);
  golden_u32(g, w->e.roll);
}

static void fold_le(golden_t *g, const drdc_lePose_t *le)
{
  golden_i32(g, le->p.x);
  golden_i32(g, le->p.y);
  golden_i32(g, le->p.z);
  golden_u32(g, le->e.yaw);
  golden_u32(g, le->e.pitch);
  golden_u32(g, le->e.roll);
}

static void fold_bytes(golden_t *g, const uint8_t *b, size_t n)
{
  size_t k;
  for (k = 0u; k < n; k++) {
    golden_u32(g, b[k]);
  }
}

static void golden_mgrs_poses(golden_t *g)
{
  drdc_WePose_t we = we_blank;
  drdc_WeMGRSPose_t m;
  drdc_WePose_t back = we_blank;
  int32_t prec;
  size_t k;

  we.latitude = golden_lat(g);
  we.longitude = golden_lon(g);
  we.height = (int64_t)(int32_t)golden_next(g) * 16;
  golden_euler(g, &we.e);
  m.height = 0;
  m.e = we_blank.e;
  for (k = 0u; k < sizeof m.mgrs; k++) {
    m.mgrs[k] = wmgrs_blank.mgrs[k];
  }
  prec = (int32_t)(golden_next(g) % 13u) - 1;
  golden_fn(g, "drdc_pose_wemgrs_from_we");
  golden_we(g, we_names, &we);
  golden_in(g, "prec", prec);
  golden_i32(g, (int32_t)drdc_pose_wemgrs_from_we(&we, prec, &m));
  for (k = 0u; k < sizeof m.mgrs; k++) {
    golden_u32(g, (uint32_t)(unsigned char)m.mgrs[k]);
  }
  golden_i64(g, m.height);
  golden_u32(g, m.e.yaw);
  golden_u32(g, m.e.pitch);
  golden_u32(g, m.e.roll);
  golden_fn(g, "drdc_pose_we_from_wemgrs");
  golden_in_text(g, "mgrs", m.mgrs);
  golden_in(g, "height_q47_16", m.height);
  golden_i32(g, (int32_t)drdc_pose_we_from_wemgrs(&m, &back));
  fold_we(g, &back);
}

static void golden_local_poses(golden_t *g)
{
  drdc_WePose_t ref = we_blank;
  drdc_lePose_t le = le_blank;
  drdc_lPose_t l = l_blank;
  drdc_lePose_t le_back = le_blank;
  drdc_WePose_t we = we_blank;

  ref.latitude = golden_lat(g);
  ref.longitude = golden_lon(g);
  ref.height = (int64_t)(int32_t)golden_next(g) * 4;
  golden_euler(g, &ref.e);
  /* offsets up to +-2048 m: inside the tangent plane's domain */
  le.p.x = (int32_t)golden_next(g) >> 4;
  le.p.y = (int32_t)golden_next(g) >> 4;
  le.p.z = (int32_t)golden_next(g) >> 8;
  golden_euler(g, &le.e);
  golden_fn(g, "drdc_pose_l_from_le");
  golden_le(g, &le);
  golden_i32(g, (int32_t)drdc_pose_l_from_le(&le, &l));
  golden_i32(g, l.q.s);
  golden_i32(g, l.q.x);
  golden_i32(g, l.q.y);
  golden_i32(g, l.q.z);
  golden_fn(g, "drdc_pose_le_from_l");
  golden_in(g, "x", l.p.x);
  golden_in(g, "y", l.p.y);
  golden_in(g, "z", l.p.z);
  golden_in(g, "q.s", l.q.s);
  golden_in(g, "q.x", l.q.x);
  golden_in(g, "q.y", l.q.y);
  golden_in(g, "q.z", l.q.z);
  golden_i32(g, (int32_t)drdc_pose_le_from_l(&l, &le_back));
  fold_le(g, &le_back);
  golden_fn(g, "drdc_pose_we_from_le");
  golden_we(g, ref_names, &ref);
  golden_le(g, &le);
  golden_i32(g, (int32_t)drdc_pose_we_from_le(&ref, 0, &le, &we));
  fold_we(g, &we);
  le_back = le_blank;
  golden_fn(g, "drdc_pose_le_from_we");
  golden_we(g, ref_names, &ref);
  golden_we(g, we_names, &we);
  golden_i32(g, (int32_t)drdc_pose_le_from_we(&ref, 0, &we, &le_back));
  fold_le(g, &le_back);
}

static void golden_jaus_bodies(golden_t *g)
{
  drdc_jaus_global_pose_t gb = global_blank;
  drdc_jaus_local_pose_t lb = local_blank;
  drdc_jaus_form_t form;
  uint8_t buf[DRDC_JAUS_POSE_BODY_MAX];
  size_t length = 0u;
  size_t k;

  gb.presence = golden_presence(g);
  gb.pose.latitude = golden_lat(g);
  gb.pose.longitude = golden_lon(g);
  gb.pose.height = (int64_t)(int32_t)golden_next(g); /* +-32 768 m */
  golden_euler(g, &gb.pose.e);
  gb.position_rms = (int32_t)(golden_next(g) & 0x007FFFFFu);
  gb.attitude_rms = golden_next(g) >> 1;
  gb.time_stamp = golden_next(g);
  form = (drdc_jaus_form_t)(golden_next(g) % 2u);
  for (k = 0u; k < sizeof buf; k++) {
    buf[k] = 0u;
  }
  golden_fn(g, "drdc_jaus_global_pose_pack");
  golden_in(g, "presence", gb.presence);
  golden_we(g, we_names, &gb.pose);
  golden_in(g, "form", (int64_t)form);
  golden_i32(g, (int32_t)drdc_jaus_global_pose_pack(&gb, form, buf, sizeof buf,
                                                    &length));
  golden_u32(g, (uint32_t)length);
  fold_bytes(g, buf, sizeof buf);

  /* random bytes of any length back */
  for (k = 0u; k < sizeof buf; k++) {
    buf[k] = (uint8_t)golden_next(g);
  }
  buf[1] &= 0x01u; /* a valid presence vector more often than not */
  length = (size_t)(golden_next(g) % (sizeof buf + 1u));
  if ((golden_next(g) & 1u) == 0u) {
    /* half of them as long as their presence vector says */
    (void)drdc_jaus_pose_size((uint16_t)(buf[0] | ((uint16_t)buf[1] << 8)),
                              &length);
  }
  gb = global_blank;
  golden_fn(g, "drdc_jaus_global_pose_unpack");
  golden_in(g, "length", (int64_t)length);
  golden_in(g, "byte 0", buf[0]);
  golden_in(g, "byte 1", buf[1]);
  golden_in(g, "form", (int64_t)form);
  golden_i32(g, (int32_t)drdc_jaus_global_pose_unpack(buf, length, form, &gb));
  golden_u32(g, gb.presence);
  fold_we(g, &gb.pose);
  golden_i32(g, gb.position_rms);
  golden_u32(g, gb.attitude_rms);
  golden_u32(g, gb.time_stamp);

  lb.presence = golden_presence(g);
  lb.pose.p.x = (int32_t)golden_next(g);
  lb.pose.p.y = (int32_t)golden_next(g);
  lb.pose.p.z = (int32_t)golden_next(g);
  golden_euler(g, &lb.pose.e);
  lb.position_rms = (int32_t)(golden_next(g) & 0x007FFFFFu);
  lb.attitude_rms = golden_next(g) >> 1;
  lb.time_stamp = golden_next(g);
  for (k = 0u; k < sizeof buf; k++) {
    buf[k] = 0u;
  }
  length = 0u;
  golden_fn(g, "drdc_jaus_local_pose_pack");
  golden_in(g, "presence", lb.presence);
  golden_le(g, &lb.pose);
  golden_in(g, "form", (int64_t)form);
  golden_i32(g, (int32_t)drdc_jaus_local_pose_pack(&lb, form, buf, sizeof buf,
                                                   &length));
  golden_u32(g, (uint32_t)length);
  fold_bytes(g, buf, sizeof buf);
  lb = local_blank;
  golden_fn(g, "drdc_jaus_local_pose_unpack");
  golden_in(g, "length", (int64_t)length);
  golden_in(g, "form", (int64_t)form);
  golden_i32(g, (int32_t)drdc_jaus_local_pose_unpack(buf, length, form, &lb));
  golden_u32(g, lb.presence);
  fold_le(g, &lb.pose);
  golden_i32(g, lb.position_rms);
  golden_u32(g, lb.attitude_rms);
  golden_u32(g, lb.time_stamp);
}

void golden_poses(golden_t *g)
{
  int i;

  for (i = 0; i < 256; i++) {
    golden_mgrs_poses(g);
    golden_local_poses(g);
    golden_jaus_bodies(g);
  }
}
