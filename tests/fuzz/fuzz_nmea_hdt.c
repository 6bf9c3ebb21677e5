/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the NMEA HDT decoder (tests/fuzz/nmea_sentence_fuzz.h).
 */
#define FUZZ_FORMATTER "HDT"
#define FUZZ_TYPE      DRDC_NMEA_HDT
#include "nmea_sentence_fuzz.h"
