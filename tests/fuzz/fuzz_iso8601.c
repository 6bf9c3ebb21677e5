/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the ISO 8601 parser: any bytes, in a heap block of
 *        exactly their length plus the NUL the parser expects (ASan
 *        reports any read past it). Text accepted must describe a valid
 *        instant, format back to the same text when it was written with 9
 *        fraction digits, and parse again to the same instant; rejected
 *        text leaves the output alone. Host only.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/time.h>
#include <drdc/time_iso8601.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  char *text = malloc(size + 1u);
  drdc_time_t t = {12345, 678};
  drdc_time_t again = {0, 0};
  char out[DRDC_TIME_ISO8601_SIZE];
  drdc_status_t st;

  if (text == NULL) {
    return 0;
  }
  memcpy(text, data, size);
  text[size] = '\0';
  st = drdc_time_iso8601_parse(NULL, text, &t);
  if (drdc_status_is_error(st)) {
    if ((t.sec != 12345) || (t.nsec != 678)) {
      abort(); /* an error must leave the output alone */
    }
  } else {
    if (drdc_status_is_error(drdc_time_check(NULL, &t))) {
      abort();
    }
    if (drdc_time_iso8601_format(NULL, &t, 9, out, sizeof out) != DRDC_OK) {
      abort();
    }
    if ((strlen(text) == 30u) && (strcmp(out, text) != 0)) {
      abort(); /* full-precision text round-trips character for character */
    }
    if (drdc_status_is_error(drdc_time_iso8601_parse(NULL, out, &again)) ||
        (again.sec != t.sec) || (again.nsec != t.nsec)) {
      abort();
    }
  }
  free(text);
  return 0;
}
