/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief drdc attitude: Euler Z-Y-X angles, quaternions and rotation
 *        matrices converted by the library, one record per line.
 *
 * Text is parsed and printed here (host only, with stdio and strtod);
 * every conversion between representations is a library call, so the
 * numbers are the bits the firmware computes. Decimal degrees become
 * binary angles (2^32 per turn) and unit values Q1.30 at the edge.
 * The tool links no libm: the few helpers it needs are below.
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/orient.h>

#include "commands.h"
#include "lines.h"

/* Largest |angle| accepted, degrees: keeps the turn count exact. */
#define DEGREES_MAX 1e9

static double absd(double x)
{
  return (x < 0.0) ? -x : x;
}

/* Nearest integer, ties away from zero, for |x| < 2^62. */
static long long round_ll(long double x)
{
  return (x < 0.0L) ? -(long long)(0.5L - x) : (long long)(x + 0.5L);
}

enum repr { REPR_EULER, REPR_QUAT, REPR_DCM, REPR_NONE };

static const char *const repr_names[3] = {"euler", "quat", "dcm"};
static const int repr_fields[3] = {3, 4, 9};

/* Largest deviation of a matrix from orthonormality (R R^T - I, per
 * element) and of its determinant from 1 that is accepted as a rotation. */
#define DCM_TOLERANCE 1e-4

static enum repr parse_repr(const char *s)
{
  int i;

  for (i = 0; i < 3; i++) {
    if (strcmp(s, repr_names[i]) == 0) {
      return (enum repr)i;
    }
  }
  return REPR_NONE;
}

/* Split a line into at most 16 finite numbers. Returns the count, or -1
 * with a message in err. */
static int parse_numbers(char *line, double *v, int max, char *err,
                         size_t errlen)
{
  int n = 0;
  char *save = NULL;
  char *tok = strtok_r(line, " \t\r\n,", &save);

  while (tok != NULL) {
    char *end = NULL;
    double x;

    errno = 0;
    x = strtod(tok, &end);
    if ((end == tok) || (*end != '\0')) {
      snprintf(err, errlen, "'%.40s' is not a number", tok);
      return -1;
    }
    /* NaN, infinities (and overflowing text) are rejected */
    if ((x != x) || (absd(x) > 1e300) ||
        ((errno == ERANGE) && (absd(x) > 1.0))) {
      snprintf(err, errlen, "'%.40s' is not a finite number", tok);
      return -1;
    }
    if (n < max) {
      v[n] = x;
    }
    n++;
    tok = strtok_r(NULL, " \t\r\n,", &save);
  }
  return n;
}

/* Decimal degrees (|deg| <= DEGREES_MAX) -> binary angle, rounded to
 * nearest (2^32 per turn); whole turns are removed in integers. */
static drdc_bam32_t bam_of_degrees(double deg)
{
  long double units = ((long double)deg * 4294967296.0L) / 360.0L;
  long long r = round_ll(units);

  return (drdc_bam32_t)((unsigned long long)r & 0xFFFFFFFFull);
}

/* Binary angle -> degrees; exact in double (|a| 360 < 2^41). */
static double degrees_of_bam(drdc_bam32_t a, int half_open_at_180)
{
  int64_t s = (int64_t)(int32_t)a;

  if (half_open_at_180 && (s == INT64_C(-2147483648))) {
    s = INT64_C(2147483648); /* (-180, 180]: -180 prints as 180 */
  }
  return ((double)s * 360.0) / 4294967296.0;
}

/* Q1.30 -> real, exact. */
static double real_of_q30(int32_t x)
{
  return (double)x / 1073741824.0;
}

/* Real in (-2, 2) -> Q1.30, rounded to nearest. */
static int32_t q30_of_real(double x)
{
  return (int32_t)round_ll((long double)x * 1073741824.0L);
}

static int check_rotation(const double *m, char *err, size_t errlen)
{
  int i;
  int j;
  double det;

  for (i = 0; i < 9; i++) {
    if (absd(m[i]) > 1.0 + DCM_TOLERANCE) {
      snprintf(err, errlen, "matrix element %d is beyond +-1", i + 1);
      return -1;
    }
  }
  for (i = 0; i < 3; i++) {
    for (j = 0; j < 3; j++) {
      double d = (m[3 * i] * m[3 * j]) + (m[3 * i + 1] * m[3 * j + 1]) +
                 (m[3 * i + 2] * m[3 * j + 2]) - ((i == j) ? 1.0 : 0.0);

      if (absd(d) > DCM_TOLERANCE) {
        snprintf(err, errlen,
                 "not a rotation matrix (rows not orthonormal"
                 " to 1e-4)");
        return -1;
      }
    }
  }
  det = m[0] * (m[4] * m[8] - m[5] * m[7]) -
        m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (det < 0.0) {
    snprintf(err, errlen,
             "not a rotation matrix (determinant -1: a "
             "reflection)");
    return -1;
  }
  return 0;
}

/* One record. Returns 0 and writes the output line, or -1 and an error. */
static int convert(enum repr from, enum repr to, char *line, char *out,
                   size_t outlen, char *err, size_t errlen)
{
  double v[16];
  int n = parse_numbers(line, v, 16, err, errlen);
  drdc_euler_t e;
  drdc_quat_t q;
  drdc_dcm_t m;
  drdc_status_t st = DRDC_OK;
  int i;

  if (n < 0) {
    return -1;
  }
  if (n != repr_fields[from]) {
    snprintf(err, errlen, "expected %d numbers (%s), got %d", repr_fields[from],
             repr_names[from], n);
    return -1;
  }
  /* Input -> the library's representation of the same kind. */
  switch (from) {
  case REPR_EULER:
    for (i = 0; i < 3; i++) {
      if (absd(v[i]) > DEGREES_MAX) {
        snprintf(err, errlen, "angle beyond +-1e9 degrees");
        return -1;
      }
    }
    e.yaw = bam_of_degrees(v[0]);
    e.pitch = bam_of_degrees(v[1]);
    e.roll = bam_of_degrees(v[2]);
    break;
  case REPR_QUAT: {
    double big = 0.0;

    for (i = 0; i < 4; i++) {
      big = (absd(v[i]) > big) ? absd(v[i]) : big;
    }
    if (big == 0.0) {
      snprintf(err, errlen, "zero quaternion has no orientation");
      return -1;
    }
    /* Any length: scaled so the largest part is 1.0 (an exact power of
     * two would lose nothing, this loses < 2^-31 relative), then the
     * library normalises. */
    q.s = q30_of_real(v[0] / big);
    q.x = q30_of_real(v[1] / big);
    q.y = q30_of_real(v[2] / big);
    q.z = q30_of_real(v[3] / big);
    st = drdc_quat_normalize(&q, &q);
    break;
  }
  default:
    if (check_rotation(v, err, errlen) != 0) {
      return -1;
    }
    for (i = 0; i < 9; i++) {
      m.m[i / 3][i % 3] = q30_of_real(v[i]);
    }
    break;
  }
  if (st != DRDC_OK) {
    snprintf(err, errlen, "%s", drdc_status_name(st));
    return -1;
  }
  /* Conversion: directly when the library has the pair, else through
   * the quaternion. */
  switch (to) {
  case REPR_EULER:
    if (from == REPR_DCM) {
      st = drdc_euler_from_dcm(&m, &e);
    } else {
      if (from == REPR_EULER) {
        st = drdc_euler_canonical(&e, &e); /* exact, no round trip */
      } else {
        st = drdc_euler_from_quat(&q, &e);
      }
    }
    if (st == DRDC_OK) {
      snprintf(out, outlen, "%.8f %.8f %.8f", degrees_of_bam(e.yaw, 1),
               degrees_of_bam(e.pitch, 0), degrees_of_bam(e.roll, 1));
    }
    break;
  case REPR_QUAT:
    if (from == REPR_EULER) {
      st = drdc_quat_from_euler(&e, &q);
    } else if (from == REPR_DCM) {
      st = drdc_quat_from_dcm(&m, &q);
    }
    if (st == DRDC_OK) {
      st = drdc_quat_canonical(&q, &q);
    }
    if (st == DRDC_OK) {
      snprintf(out, outlen, "%.10f %.10f %.10f %.10f", real_of_q30(q.s),
               real_of_q30(q.x), real_of_q30(q.y), real_of_q30(q.z));
    }
    break;
  default:
    if (from == REPR_EULER) {
      st = drdc_dcm_from_euler(&e, &m);
    } else if (from == REPR_QUAT) {
      st = drdc_dcm_from_quat(&q, &m);
    } else {
      /* dcm -> dcm: the nearest rotation, through the quaternion */
      st = drdc_quat_from_dcm(&m, &q);
      if (st == DRDC_OK) {
        st = drdc_dcm_from_quat(&q, &m);
      }
    }
    if (st == DRDC_OK) {
      int len = 0;

      for (i = 0; (i < 9) && (len >= 0) && ((size_t)len < outlen); i++) {
        len += snprintf(out + len, outlen - (size_t)len, "%s%.10f",
                        (i == 0) ? "" : " ", real_of_q30(m.m[i / 3][i % 3]));
      }
    }
    break;
  }
  if (st != DRDC_OK) {
    snprintf(err, errlen, "%s", drdc_status_name(st));
    return -1;
  }
  return 0;
}

static const char usage[] =
    "usage: drdc attitude --from F --to T\n"
    "\n"
    "Reads one orientation per line on standard input and writes it in\n"
    "another representation (F, T: euler, quat, dcm):\n"
    "  euler  YAW PITCH ROLL, Z-Y-X, decimal degrees; output with 8\n"
    "         decimals, yaw and roll in (-180, 180], pitch in [-90, 90]\n"
    "         (at pitch +-90: roll 0, all rotation in yaw)\n"
    "  quat   QS QX QY QZ, scalar first; input of any non-zero length is\n"
    "         normalised; output with 10 decimals and QS > 0 (when QS = 0,\n"
    "         the first non-zero part is positive)\n"
    "  dcm    the 9 elements of the body-to-world rotation matrix, row by\n"
    "         row, 10 decimals\n"
    "Body frame x forward, y right, z down; world frame north-east-down.\n"
    "A line that cannot be converted gives 'ERROR: <reason>'; the other\n"
    "lines go on, and the exit status is 1 at the end.\n";

int drdc_cmd_attitude(int argc, char **argv)
{
  enum repr from = REPR_NONE;
  enum repr to = REPR_NONE;
  char *line = NULL;
  size_t cap = 0;
  size_t len = 0;
  int got;
  int status = 0;
  int i;

  for (i = 1; i < argc; i++) {
    if ((strcmp(argv[i], "--help") == 0) || (strcmp(argv[i], "-h") == 0)) {
      fputs(usage, stdout);
      return 0;
    }
    if (((strcmp(argv[i], "--from") == 0) || (strcmp(argv[i], "--to") == 0)) &&
        (i + 1 < argc)) {
      enum repr r = parse_repr(argv[i + 1]);

      if (r == REPR_NONE) {
        fprintf(stderr,
                "drdc attitude: unknown representation '%s' "
                "(euler, quat or dcm)\n",
                argv[i + 1]);
        return 2;
      }
      if (argv[i][2] == 'f') {
        from = r;
      } else {
        to = r;
      }
      i++;
    } else {
      fprintf(stderr, "drdc attitude: unexpected argument '%s'\n%s", argv[i],
              usage);
      return 2;
    }
  }
  if ((from == REPR_NONE) || (to == REPR_NONE)) {
    fprintf(stderr, "drdc attitude: --from and --to are required\n%s", usage);
    return 2;
  }
  while ((got = drdc_tool_read_line(stdin, &line, &cap, &len)) !=
         DRDC_TOOL_LINE_EOF) {
    char out[512];
    char err[128];
    const char *problem;

    if (got == DRDC_TOOL_LINE_ERROR) {
      fputs("drdc attitude: cannot read standard input\n", stderr);
      status = 1;
      break;
    }
    problem = drdc_tool_line_problem(got, line, len);
    if (problem != NULL) {
      printf("ERROR: %s\n", problem);
      status = 1;
      continue;
    }
    if (convert(from, to, line, out, sizeof(out), err, sizeof(err)) == 0) {
      printf("%s\n", out);
    } else {
      printf("ERROR: %s\n", err);
      status = 1;
    }
  }
  free(line);
  return status;
}
