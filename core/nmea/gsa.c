/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief GSA: fix type, the satellites used and the dilutions of
 *        precision.
 */
#include "nmea_impl.h"

/* $--GSA,a,x,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,xx,x.x,x.x,x.x(,h): 17
 * fields, 18 in NMEA 0183 v4.10 with the system id. The mode and the fix
 * type are required; a receiver may end the sentence after them. */
#define GSA_FIELDS          17u
#define GSA_FIELDS_REQUIRED 2u
#define GSA_FIRST_ID        3u  /* satellite ids: fields 3..14 */
#define GSA_PDOP            15u /* then PDOP, HDOP, VDOP, system id */
#define GSA_HDOP            16u
#define GSA_VDOP            17u
#define GSA_SYSTEM          18u
#define GSA_FIX_NONE        1 /* fix types: 1 none, 2 2D, 3 3D */
#define GSA_FIX_3D          3

/* Value of a system id, one hex digit 1..F (NMEA 0183 v4.10 uses 1..6),
 * or -1. */
static int32_t system_id(nmea_field_t f)
{
  int32_t v = -1;
  char c = '\0';

  if (f.n == 1u) {
    c = f.p[0];
  }
  if ((c >= '1') && (c <= '9')) {
    v = (int32_t)c - (int32_t)'0';
  } else if ((c >= 'A') && (c <= 'F')) {
    v = ((int32_t)c - (int32_t)'A') + 10;
  } else {
    v = -1;
  }
  return v;
}

/* The satellite ids of fields 3..14 (1 to 3 digits each, empty fields
 * skipped) into n->satellite_ids; their count into `*count`. */
static drdc_status_t satellite_ids(const nmea_frame_t *fr, drdc_nmea_t *n,
                                   int32_t *count)
{
  drdc_status_t st = DRDC_OK;
  int32_t used = 0;
  size_t i;

  for (i = 0u; (i < DRDC_NMEA_GSA_IDS) && (st == DRDC_OK); i++) {
    int32_t id = 0;

    if (nmea_field(fr, GSA_FIRST_ID + i).n != 0u) {
      st = drdc__nmea_uint(fr, GSA_FIRST_ID + i, 1u, 3u, &id);
      if ((st == DRDC_OK) && (n != NULL)) {
        n->satellite_ids[used] = (uint16_t)id; /* <= 999 */
      }
      used++;
    }
  }
  *count = used;
  return st;
}

drdc_status_t drdc__nmea_gsa(const nmea_frame_t *fr, drdc_nmea_t *n)
{
  nmea_field_t mode = nmea_field(fr, 1u);
  nmea_field_t system = nmea_field(fr, GSA_SYSTEM);
  int32_t fix_type = 0;
  int32_t used = 0;
  char m = '\0';
  char first_system = '\0';
  drdc_status_t st;

  if (nmea_has_fields(fr, GSA_FIELDS_REQUIRED, GSA_FIELDS) == 0) {
    return DRDC_E_MISSING_FIELD;
  }
  st = drdc__nmea_uint(fr, 2u, 1u, 1u, &fix_type);
  if (st != DRDC_OK) {
    return st;
  }
  if (fix_type == GSA_FIX_NONE) {
    return DRDC_E_NO_FIX;
  }
  if ((fix_type < GSA_FIX_NONE) || (fix_type > GSA_FIX_3D)) {
    return DRDC_E_RANGE;
  }
  if (mode.n == 0u) {
    return DRDC_E_MISSING_FIELD;
  }
  m = mode.p[0];
  if ((mode.n != 1u) || ((m != 'A') && (m != 'M'))) {
    return DRDC_E_SYNTAX;
  }
  st = satellite_ids(fr, n, &used);
  if ((st == DRDC_OK) && (nmea_field(fr, GSA_PDOP).n != 0u)) {
    st = drdc__nmea_q15_16(fr, GSA_PDOP, NMEA_METRES_Q15_16, n,
                           (n != NULL) ? &n->pdop : NULL, DRDC_NMEA_HAS_PDOP,
                           DRDC_NMEA_BEYOND_PDOP);
  }
  if ((st == DRDC_OK) && (nmea_field(fr, GSA_HDOP).n != 0u)) {
    st = drdc__nmea_q15_16(fr, GSA_HDOP, NMEA_METRES_Q15_16, n,
                           (n != NULL) ? &n->hdop : NULL, DRDC_NMEA_HAS_HDOP,
                           DRDC_NMEA_BEYOND_HDOP);
  }
  if ((st == DRDC_OK) && (nmea_field(fr, GSA_VDOP).n != 0u)) {
    st = drdc__nmea_q15_16(fr, GSA_VDOP, NMEA_METRES_Q15_16, n,
                           (n != NULL) ? &n->vdop : NULL, DRDC_NMEA_HAS_VDOP,
                           DRDC_NMEA_BEYOND_VDOP);
  }
  if (system.n != 0u) {
    first_system = system.p[0];
  }
  if ((st == DRDC_OK) && (system.n != 0u) && (system_id(system) < 0)) {
    st = ((system.n == 1u) && (first_system == '0')) ? DRDC_E_RANGE
                                                     : DRDC_E_SYNTAX;
  }
  if ((st == DRDC_OK) && (n != NULL)) {
    n->fix_type = fix_type;
    n->mode[0] = m;
    n->mode[1] = '\0';
    n->satellites = used;
    n->has |= DRDC_NMEA_HAS_FIX_TYPE | DRDC_NMEA_HAS_SATELLITES;
    if (system.n != 0u) {
      n->system_id = system_id(system);
      n->has |= DRDC_NMEA_HAS_SYSTEM;
    }
  }
  return st;
}
