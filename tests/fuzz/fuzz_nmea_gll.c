/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the NMEA GLL decoder (tests/fuzz/nmea_sentence_fuzz.h).
 */
#define FUZZ_FORMATTER "GLL"
#define FUZZ_TYPE      DRDC_NMEA_GLL
#include "nmea_sentence_fuzz.h"
