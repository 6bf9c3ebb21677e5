/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the NMEA GSA decoder (tests/fuzz/nmea_sentence_fuzz.h).
 */
#define FUZZ_FORMATTER "GSA"
#define FUZZ_TYPE      DRDC_NMEA_GSA
#include "nmea_sentence_fuzz.h"
