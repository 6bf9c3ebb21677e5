/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The test runner as a function, for hosts that own main().
 */
#ifndef DRDC_TEST_RUNNER_H
#define DRDC_TEST_RUNNER_H

/** Run every suite of tests/suites.def between the RTEMS test markers;
 *  return the number of failed tests. */
int test_runner_run(void);

#endif /* DRDC_TEST_RUNNER_H */
