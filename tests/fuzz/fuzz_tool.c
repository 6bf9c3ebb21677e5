/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the host tool's input lines: any bytes as standard
 *        input of `drdc time`, `drdc attitude`, `drdc units` and
 *        `drdc nmea` (the first byte picks the command and its formats),
 *        through the tool's own code under ASan and UBSan. A finding is a
 * crash, a sanitizer report, or an exit status other than 0 (all lines
 * converted) or 1 (some line gave ERROR). Host only.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "commands.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const scales[] = {"utc", "gps", "unix", "rtems", "tai"};
static const char *const reprs[] = {"euler", "quat", "dcm"};
/* first bytes from here on drive `drdc nmea` (odd: --strict, even: --raw);
 * below it, time, attitude and units as pick % 3 */
#define NMEA_PICK 0xF0u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static FILE *sink;
  FILE *in;
  unsigned pick;
  int status;

  if (size == 0u) {
    return 0;
  }
  if (sink == NULL) {
    sink = freopen("/dev/null", "w", stdout);
    if (sink == NULL) {
      abort();
    }
  }
  pick = data[0];
  in = fmemopen((void *)(uintptr_t)(data + 1), size - 1u, "r");
  if (in == NULL) {
    return 0;
  }
  /* the commands read standard input: point it at the bytes */
  stdin = in;
  if (pick >= NMEA_PICK) {
    char *argv[] = {"nmea", ((pick & 1u) != 0u) ? "--strict" : "--raw", NULL};
    status = drdc_cmd_nmea(2, argv);
  } else if ((pick % 3u) == 0u) {
    char *argv[] = {"time",
                    "--from",
                    (char *)scales[(pick / 3u) % 5u],
                    "--to",
                    (char *)scales[(pick / 15u) % 5u],
                    NULL};
    status = drdc_cmd_time(5, argv);
  } else if ((pick % 3u) == 1u) {
    char *argv[] = {"attitude",
                    "--from",
                    (char *)reprs[(pick / 3u) % 3u],
                    "--to",
                    (char *)reprs[(pick / 9u) % 3u],
                    NULL};
    status = drdc_cmd_attitude(5, argv);
  } else {
    char *argv[] = {"units", NULL};
    status = drdc_cmd_units(1, argv);
  }
  fclose(in);
  if ((status != 0) && (status != 1)) {
    abort();
  }
  return 0;
}
