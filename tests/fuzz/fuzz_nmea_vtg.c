/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Fuzzer of the NMEA VTG decoder (tests/fuzz/nmea_sentence_fuzz.h).
 */
#define FUZZ_FORMATTER "VTG"
#define FUZZ_TYPE      DRDC_NMEA_VTG
#include "nmea_sentence_fuzz.h"
