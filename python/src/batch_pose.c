/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Array loop of the pose conversions of geo_pose.h: {W}, {We},
 *        {W-UTM}, {We-UTM}, {W-MGRS}, {We-MGRS}, {l} and {le}, one public
 *        function call per element.
 *
 * Only python/build_backend.py compiles this file; drdc/_pose.py names
 * the conversions (POSE_* below, in the same order) and the columns of
 * each pose. Numbers travel as rows of int64: the caller has checked that
 * each fits its C field (int32 for Q1.30 and Q15.16, uint32 for binary
 * angles), so every cast here keeps its value. MGRS text travels in rows
 * of `width` bytes, NUL-padded. Outputs of an element whose status is an
 * error are 0.
 *
 * Row layouts (columns in order):
 *   W      lon, lat, height, s, x, y, z                   (7)
 *   We     lon, lat, height, yaw, pitch, roll             (6)
 *   WUTM   zone, north, easting, northing, height, s..z   (9)
 *   WeUTM  zone, north, easting, northing, height, ypr    (8)
 *   WMGRS  height, s, x, y, z (text apart)                (5)
 *   WeMGRS height, yaw, pitch, roll (text apart)          (4)
 *   l      x, y, z, s, qx, qy, qz                         (7)
 *   le     x, y, z, yaw, pitch, roll                      (6)
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <drdc/geo_pose.h>

enum pose_conversion {
  POSE_WUTM_FROM_W = 0,
  POSE_W_FROM_WUTM = 1,
  POSE_WEUTM_FROM_WE = 2,
  POSE_WE_FROM_WEUTM = 3,
  POSE_WMGRS_FROM_W = 4,
  POSE_W_FROM_WMGRS = 5,
  POSE_WEMGRS_FROM_WE = 6,
  POSE_WE_FROM_WEMGRS = 7,
  POSE_W_FROM_L = 8,
  POSE_L_FROM_W = 9,
  POSE_L_FROM_LE = 10,
  POSE_LE_FROM_L = 11,
  POSE_WE_FROM_LE = 12,
  POSE_LE_FROM_WE = 13,
  POSE_GRID_FROM_TRUE = 14,
  POSE_TRUE_FROM_GRID = 15,
  POSE_BAM_FROM_CONVERGENCE = 16
};

static drdc_quat_t quat_in(const int64_t *r)
{
  drdc_quat_t q;

  q.s = (int32_t)r[0];
  q.x = (int32_t)r[1];
  q.y = (int32_t)r[2];
  q.z = (int32_t)r[3];
  return q;
}

static void quat_out(int64_t *r, const drdc_quat_t *q)
{
  r[0] = q->s;
  r[1] = q->x;
  r[2] = q->y;
  r[3] = q->z;
}

static drdc_euler_t euler_in(const int64_t *r)
{
  drdc_euler_t e;

  e.yaw = (uint32_t)r[0];
  e.pitch = (uint32_t)r[1];
  e.roll = (uint32_t)r[2];
  return e;
}

static void euler_out(int64_t *r, const drdc_euler_t *e)
{
  r[0] = e->yaw;
  r[1] = e->pitch;
  r[2] = e->roll;
}

static drdc_WPose_t w_in(const int64_t *r)
{
  drdc_WPose_t w;

  w.longitude = r[0];
  w.latitude = r[1];
  w.height = r[2];
  w.q = quat_in(&r[3]);
  return w;
}

static void w_out(int64_t *r, const drdc_WPose_t *w)
{
  r[0] = w->longitude;
  r[1] = w->latitude;
  r[2] = w->height;
  quat_out(&r[3], &w->q);
}

static drdc_WePose_t we_in(const int64_t *r)
{
  drdc_WePose_t w;

  w.longitude = r[0];
  w.latitude = r[1];
  w.height = r[2];
  w.e = euler_in(&r[3]);
  return w;
}

static void we_out(int64_t *r, const drdc_WePose_t *w)
{
  r[0] = w->longitude;
  r[1] = w->latitude;
  r[2] = w->height;
  euler_out(&r[3], &w->e);
}

static drdc_geo_utm_t utm_in(const int64_t *r)
{
  drdc_geo_utm_t u;

  u.zone = (int32_t)r[0];
  u.north = (r[1] != 0);
  u.easting = r[2];
  u.northing = r[3];
  return u;
}

static void utm_out(int64_t *r, const drdc_geo_utm_t *u)
{
  r[0] = u->zone;
  r[1] = u->north ? 1 : 0;
  r[2] = u->easting;
  r[3] = u->northing;
}

static drdc_lPose_t l_in(const int64_t *r)
{
  drdc_lPose_t l;

  l.p.x = (int32_t)r[0];
  l.p.y = (int32_t)r[1];
  l.p.z = (int32_t)r[2];
  l.q = quat_in(&r[3]);
  return l;
}

static void l_out(int64_t *r, const drdc_lPose_t *l)
{
  r[0] = l->p.x;
  r[1] = l->p.y;
  r[2] = l->p.z;
  quat_out(&r[3], &l->q);
}

static drdc_lePose_t le_in(const int64_t *r)
{
  drdc_lePose_t l;

  l.p.x = (int32_t)r[0];
  l.p.y = (int32_t)r[1];
  l.p.z = (int32_t)r[2];
  l.e = euler_in(&r[3]);
  return l;
}

static void le_out(int64_t *r, const drdc_lePose_t *l)
{
  r[0] = l->p.x;
  r[1] = l->p.y;
  r[2] = l->p.z;
  euler_out(&r[3], &l->e);
}

/* The MGRS of row `text` (width bytes) as a C string in `scratch`. */
static const char *text_in(const char *text, size_t width, char *scratch)
{
  memcpy(scratch, text, width);
  scratch[width] = '\0';
  return scratch;
}

/* One element: `in` and `out` its rows (k_out columns), `text` its MGRS
 * row (in or out). On error out stays as the caller cleared it. */
static drdc_status_t convert(int32_t which, const int64_t *in, int64_t *out,
                             char *text, size_t width, char *scratch)
{
  drdc_status_t st;

  switch (which) {
  case POSE_WUTM_FROM_W: {
    drdc_WPose_t w = w_in(in);
    drdc_WUTMPose_t u;

    st = drdc_pose_wutm_from_w(&w, (int32_t)in[7], &u);
    if (!drdc_status_is_error(st)) {
      utm_out(out, &u.utm);
      out[4] = u.height;
      quat_out(&out[5], &u.q);
    }
    break;
  }
  case POSE_W_FROM_WUTM: {
    drdc_WUTMPose_t u;
    drdc_WPose_t w;

    u.utm = utm_in(in);
    u.height = in[4];
    u.q = quat_in(&in[5]);
    st = drdc_pose_w_from_wutm(&u, &w);
    if (!drdc_status_is_error(st)) {
      w_out(out, &w);
    }
    break;
  }
  case POSE_WEUTM_FROM_WE: {
    drdc_WePose_t w = we_in(in);
    drdc_WeUTMPose_t u;

    st = drdc_pose_weutm_from_we(&w, (int32_t)in[6], &u);
    if (!drdc_status_is_error(st)) {
      utm_out(out, &u.utm);
      out[4] = u.height;
      euler_out(&out[5], &u.e);
    }
    break;
  }
  case POSE_WE_FROM_WEUTM: {
    drdc_WeUTMPose_t u;
    drdc_WePose_t w;

    u.utm = utm_in(in);
    u.height = in[4];
    u.e = euler_in(&in[5]);
    st = drdc_pose_we_from_weutm(&u, &w);
    if (!drdc_status_is_error(st)) {
      we_out(out, &w);
    }
    break;
  }
  case POSE_WMGRS_FROM_W: {
    drdc_WPose_t w = w_in(in);
    drdc_WMGRSPose_t m;

    st = drdc_pose_wmgrs_from_w(&w, (int32_t)in[7], &m);
    if (!drdc_status_is_error(st)) {
      strncpy(text, m.mgrs, width);
      out[0] = m.height;
      quat_out(&out[1], &m.q);
    }
    break;
  }
  case POSE_W_FROM_WMGRS: {
    drdc_WMGRSPose_t m;
    drdc_WPose_t w;

    memset(m.mgrs, 0, sizeof m.mgrs);
    strncpy(m.mgrs, text_in(text, width, scratch), sizeof m.mgrs - 1u);
    m.height = in[0];
    m.q = quat_in(&in[1]);
    /* a text longer than the field cannot be MGRS: the library's own
     * status for a malformed one */
    st = (strlen(scratch) >= sizeof m.mgrs) ? DRDC_E_MGRS
                                            : drdc_pose_w_from_wmgrs(&m, &w);
    if (!drdc_status_is_error(st)) {
      w_out(out, &w);
    }
    break;
  }
  case POSE_WEMGRS_FROM_WE: {
    drdc_WePose_t w = we_in(in);
    drdc_WeMGRSPose_t m;

    st = drdc_pose_wemgrs_from_we(&w, (int32_t)in[6], &m);
    if (!drdc_status_is_error(st)) {
      strncpy(text, m.mgrs, width);
      out[0] = m.height;
      euler_out(&out[1], &m.e);
    }
    break;
  }
  case POSE_WE_FROM_WEMGRS: {
    drdc_WeMGRSPose_t m;
    drdc_WePose_t w;

    memset(m.mgrs, 0, sizeof m.mgrs);
    strncpy(m.mgrs, text_in(text, width, scratch), sizeof m.mgrs - 1u);
    m.height = in[0];
    m.e = euler_in(&in[1]);
    st = (strlen(scratch) >= sizeof m.mgrs) ? DRDC_E_MGRS
                                            : drdc_pose_we_from_wemgrs(&m, &w);
    if (!drdc_status_is_error(st)) {
      we_out(out, &w);
    }
    break;
  }
  case POSE_W_FROM_L: {
    drdc_WPose_t ref = w_in(in);
    drdc_lPose_t l = l_in(&in[8]);
    drdc_WPose_t w;

    st = drdc_pose_w_from_l(&ref, in[7], &l, &w);
    if (!drdc_status_is_error(st)) {
      w_out(out, &w);
    }
    break;
  }
  case POSE_L_FROM_W: {
    drdc_WPose_t ref = w_in(in);
    drdc_WPose_t w = w_in(&in[8]);
    drdc_lPose_t l;

    st = drdc_pose_l_from_w(&ref, in[7], &w, &l);
    if (!drdc_status_is_error(st)) {
      l_out(out, &l);
    }
    break;
  }
  case POSE_L_FROM_LE: {
    drdc_lePose_t le = le_in(in);
    drdc_lPose_t l;

    st = drdc_pose_l_from_le(&le, &l);
    if (!drdc_status_is_error(st)) {
      l_out(out, &l);
    }
    break;
  }
  case POSE_LE_FROM_L: {
    drdc_lPose_t l = l_in(in);
    drdc_lePose_t le;

    st = drdc_pose_le_from_l(&l, &le);
    if (!drdc_status_is_error(st)) {
      le_out(out, &le);
    }
    break;
  }
  case POSE_WE_FROM_LE: {
    drdc_WePose_t ref = we_in(in);
    drdc_lePose_t le = le_in(&in[7]);
    drdc_WePose_t w;

    st = drdc_pose_we_from_le(&ref, in[6], &le, &w);
    if (!drdc_status_is_error(st)) {
      we_out(out, &w);
    }
    break;
  }
  case POSE_LE_FROM_WE: {
    drdc_WePose_t ref = we_in(in);
    drdc_WePose_t w = we_in(&in[7]);
    drdc_lePose_t le;

    st = drdc_pose_le_from_we(&ref, in[6], &w, &le);
    if (!drdc_status_is_error(st)) {
      le_out(out, &le);
    }
    break;
  }
  case POSE_GRID_FROM_TRUE:
  case POSE_TRUE_FROM_GRID: {
    drdc_quat_t q = quat_in(in);
    drdc_quat_t r;

    st = (which == POSE_GRID_FROM_TRUE)
             ? drdc_pose_grid_from_true(&q, in[4], &r)
             : drdc_pose_true_from_grid(&q, in[4], &r);
    if (!drdc_status_is_error(st)) {
      quat_out(out, &r);
    }
    break;
  }
  case POSE_BAM_FROM_CONVERGENCE:
    out[0] = drdc_pose_bam_from_convergence(in[0]);
    st = DRDC_OK;
    break;
  default:
    st = DRDC_E_RANGE;
    break;
  }
  return st;
}

/* n elements: `in` rows of k_in int64, `out` rows of k_out (cleared
 * here), `text` rows of `width` bytes (MGRS in or out; NULL when the
 * conversion has none), `scratch` width + 1 bytes. */
void drdc_batch_pose(int32_t which, size_t n, const int64_t *in, size_t k_in,
                     int64_t *out, size_t k_out, char *text, size_t width,
                     char *scratch, int32_t *status)
{
  size_t i;

  for (i = 0; i < n; i++) {
    int64_t *o = &out[i * k_out];
    char *t = (text != NULL) ? &text[i * width] : NULL;
    drdc_status_t st;

    memset(o, 0, k_out * sizeof *o);
    st = convert(which, &in[i * k_in], o, t, width, scratch);
    status[i] = (int32_t)st;
    if (drdc_status_is_error(st)) {
      memset(o, 0, k_out * sizeof *o);
      if ((t != NULL) &&
          ((which == POSE_WMGRS_FROM_W) || (which == POSE_WEMGRS_FROM_WE))) {
        memset(t, 0, width);
      }
    }
  }
}
