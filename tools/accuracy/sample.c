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
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include <drdc/fixed_trig.h>
#include <drdc/geo.h>
#include <drdc/orient.h>

static void answer_status(drdc_status_t st)
{
  printf("ERR %d\n", (int)st);
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
  }
  printf("ERR syntax\n");
}

int main(void)
{
  char line[256];
  while (fgets(line, (int)sizeof line, stdin) != NULL) {
    sample_line(line);
  }
  return 0;
}
