/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Declarations of the Unity suites listed in suites.def.
 */
#ifndef DRDC_TEST_SUITES_H
#define DRDC_TEST_SUITES_H

#define DRDC_SUITE(name) void name(void);
#include "suites.def"
#if defined(__rtems__)
#include "suites_rtems.def"
#endif
#undef DRDC_SUITE

#endif /* DRDC_TEST_SUITES_H */
