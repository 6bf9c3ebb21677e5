/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the NMEA THS decoder (tests/fuzz/nmea_sentence_fuzz.h).
 */
#define FUZZ_FORMATTER "THS"
#define FUZZ_TYPE      DRDC_NMEA_THS
#include "nmea_sentence_fuzz.h"
