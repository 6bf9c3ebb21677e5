/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Host sampler for the accuracy plots (tools/accuracy/plots.py):
 *        runs library functions on integer inputs read from standard
 *        input and prints their integer results, so that the plots show
 *        the library's own bits against an independent oracle.
 *
 * One request per line, one answer line each ("ERR <status>" when the
 * function refuses the input):
 *   sincos A              -> SIN COS          (binary angle -> Q1.30)
 *   atan2 Y X             -> A                (int32 -> binary angle)
 *   tmfwd LAT DLON        -> X Y GAMMA        (nas -> Q47.16 m, nas)
 *   utmrev ZONE N|S E N   -> LAT LON          (Q47.16 m -> nas)
 *   euler QS QX QY QZ     -> YAW PITCH ROLL   (Q1.30 -> binary angles)
 *   slerp A4 B4 T         -> S X Y Z          (drdc_quat_slerp)
 *   nlerp A4 B4 T         -> S X Y Z          (drdc_quat_nlerp)
 *   axang QS QX QY QZ     -> AX AY AZ ANGLE   (drdc_axis_angle_from_quat)
 *   dh C N L1..LN         -> R9 T3            (drdc_dh_forward)
 *   dhc C N L1..LN        -> R9 T3            (links composed one by one)
 *   dhinv C N L1..LN      -> R9 T3            (T T^-1 of drdc_dh_forward)
 * where each link L is "a alpha d theta type q" and C the convention;
 * tools/accuracy/orient_bounds.py measures with these.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include <drdc/fixed_trig.h>
#include <drdc/geo.h>
#include <drdc/orient.h>
#include <drdc/orient_kinematics.h>
#include <stdlib.h>

static void answer_status(drdc_status_t st)
{
  printf("ERR %d\n", (int)st);
}

static void print_quat(drdc_status_t st, const drdc_quat_t *q)
{
  if (st == DRDC_OK) {
    printf("%" PRId32 " %" PRId32 " %" PRId32 " %" PRId32 "\n", q->s, q->x,
           q->y, q->z);
  } else {
    answer_status(st);
  }
}

static void print_transform(drdc_status_t st, const drdc_transform_t *t)
{
  unsigned k;
  if (st != DRDC_OK) {
    answer_status(st);
    return;
  }
  for (k = 0u; k < 9u; k++) {
    printf("%" PRId32 " ", t->r.m[k / 3u][k % 3u]);
  }
  printf("%" PRId32 " %" PRId32 " %" PRId32 "\n", t->t.x, t->t.y, t->t.z);
}

/* "C N" then N links of "a alpha d theta type q"; 0 on a syntax error. */
static int read_chain(const char *args, drdc_dh_convention_t *cv,
                      drdc_dh_link_t *links, int32_t *q, unsigned *n)
{
  char *end;
  long long v[6];
  unsigned k;
  unsigned i;
  *cv = (drdc_dh_convention_t)strtol(args, &end, 10);
  *n = (unsigned)strtoul(end, &end, 10);
  if (*n > DRDC_DH_MAX_LINKS) {
    return 0;
  }
  for (k = 0u; k < *n; k++) {
    for (i = 0u; i < 6u; i++) {
      const char *from = end;
      v[i] = strtoll(from, &end, 10);
      if (end == from) {
        return 0;
      }
    }
    links[k].a = (int32_t)v[0];
    links[k].alpha = (uint32_t)v[1];
    links[k].d = (int32_t)v[2];
    links[k].theta = (uint32_t)v[3];
    links[k].type = (drdc_joint_type_t)v[4];
    q[k] = (int32_t)(uint32_t)v[5];
  }
  return 1;
}

static void sample_line(const char *line)
{
  char op[16];
  if (sscanf(line, "%15s", op) != 1) {
    printf("ERR syntax\n");
    return;
  }
  const char *args = line + strlen(op);
  if (strcmp(op, "sincos") == 0) {
    uint32_t a;
    if (sscanf(args, "%" SCNu32, &a) == 1) {
      printf("%" PRId32 " %" PRId32 "\n", drdc_fx_sin_bam32(a),
             drdc_fx_cos_bam32(a));
      return;
    }
  } else if (strcmp(op, "atan2") == 0) {
    int32_t y, x;
    drdc_bam32_t a;
    if (sscanf(args, "%" SCNd32 " %" SCNd32, &y, &x) == 2) {
      drdc_status_t st = drdc_fx_atan2_bam32(y, x, &a);
      if (st == DRDC_OK) {
        printf("%" PRIu32 "\n", a);
      } else {
        answer_status(st);
      }
      return;
    }
  } else if (strcmp(op, "tmfwd") == 0) {
    int64_t lat, dlon;
    drdc_q47_16_t x, y;
    drdc_nas_t gamma;
    if (sscanf(args, "%" SCNd64 " %" SCNd64, &lat, &dlon) == 2) {
      drdc_status_t st = drdc_geo_tm_forward(lat, dlon, &x, &y, &gamma, NULL);
      if (st == DRDC_OK) {
        printf("%" PRId64 " %" PRId64 " %" PRId64 "\n", x, y, gamma);
      } else {
        answer_status(st);
      }
      return;
    }
  } else if (strcmp(op, "utmrev") == 0) {
    drdc_geo_utm_t u;
    char hemi;
    drdc_nas_t lat, lon;
    if (sscanf(args, "%" SCNd32 " %c %" SCNd64 " %" SCNd64, &u.zone, &hemi,
               &u.easting, &u.northing) == 4) {
      u.north = (hemi == 'N');
      drdc_status_t st = drdc_geo_from_utm(&u, &lat, &lon, NULL, NULL);
      if (st == DRDC_OK) {
        printf("%" PRId64 " %" PRId64 "\n", lat, lon);
      } else {
        answer_status(st);
      }
      return;
    }
  } else if (strcmp(op, "euler") == 0) {
    drdc_quat_t q;
    drdc_euler_t e;
    if (sscanf(args, "%" SCNd32 " %" SCNd32 " %" SCNd32 " %" SCNd32, &q.s, &q.x,
               &q.y, &q.z) == 4) {
      drdc_status_t st = drdc_euler_from_quat(&q, &e);
      if (st == DRDC_OK) {
        printf("%" PRIu32 " %" PRIu32 " %" PRIu32 "\n", e.yaw, e.pitch, e.roll);
      } else {
        answer_status(st);
      }
      return;
    }
  } else if ((strcmp(op, "slerp") == 0) || (strcmp(op, "nlerp") == 0)) {
    drdc_quat_t a, b, r;
    int32_t t;
    if (sscanf(args,
               "%" SCNd32 " %" SCNd32 " %" SCNd32 " %" SCNd32 " %" SCNd32
               " %" SCNd32 " %" SCNd32 " %" SCNd32 " %" SCNd32,
               &a.s, &a.x, &a.y, &a.z, &b.s, &b.x, &b.y, &b.z, &t) == 9) {
      print_quat((op[0] == 's') ? drdc_quat_slerp(&a, &b, t, &r)
                                : drdc_quat_nlerp(&a, &b, t, &r),
                 &r);
      return;
    }
  } else if (strcmp(op, "axang") == 0) {
    drdc_quat_t q;
    drdc_vec3_q1_30_t ax;
    drdc_bam32_t ang;
    if (sscanf(args, "%" SCNd32 " %" SCNd32 " %" SCNd32 " %" SCNd32, &q.s, &q.x,
               &q.y, &q.z) == 4) {
      drdc_status_t st = drdc_axis_angle_from_quat(&q, &ax, &ang);
      if (st == DRDC_OK) {
        printf("%" PRId32 " %" PRId32 " %" PRId32 " %" PRIu32 "\n", ax.x, ax.y,
               ax.z, ang);
      } else {
        answer_status(st);
      }
      return;
    }
  } else if ((strcmp(op, "dh") == 0) || (strcmp(op, "dhc") == 0) ||
             (strcmp(op, "dhinv") == 0)) {
    drdc_dh_convention_t cv;
    drdc_dh_link_t links[DRDC_DH_MAX_LINKS];
    int32_t q[DRDC_DH_MAX_LINKS];
    unsigned n;
    drdc_transform_t t, lt, inv;
    drdc_status_t st;
    unsigned k;
    if (read_chain(args, &cv, links, q, &n)) {
      st = drdc_dh_forward(cv, links, op[2] == 'c' ? 0u : n, q, &t);
      if (op[2] == 'c') {
        for (k = 0u; (k < n) && (st == DRDC_OK); k++) {
          st = drdc_dh_link_transform(cv, &links[k], q[k], &lt);
          if (st == DRDC_OK) {
            st = drdc_transform_compose(&t, &lt, &t);
          }
        }
      } else if (op[2] == 'i') {
        if (st == DRDC_OK) {
          st = drdc_transform_invert(&t, &inv);
        }
        if (st == DRDC_OK) {
          st = drdc_transform_compose(&t, &inv, &t);
        }
      }
      print_transform(st, &t);
      return;
    }
  }
  printf("ERR syntax\n");
}

int main(void)
{
  static char line[4096];
  while (fgets(line, (int)sizeof line, stdin) != NULL) {
    sample_line(line);
  }
  return 0;
}
