/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Images that test the harness: one behaviour per SELFTEST_KIND
 *        (numbers in wscript's SELFTEST_KINDS; verdicts in test_harness.py).
 */
#include "drdc_board.h"
#include "unity.h"

#define KIND_PASS         1
#define KIND_FAIL         2
#define KIND_HANG         3
#define KIND_CRASH        4
#define KIND_FLOOD        5
#define KIND_FAKE_SUMMARY 6
#define KIND_SILENT       7

void setUp(void)
{
}

void tearDown(void)
{
}

static void test_arithmetic_holds(void)
{
  volatile int two = 2;

  TEST_ASSERT_EQUAL_INT(4, two + two);
}

__attribute__((__unused__)) static void test_deliberate_failure(void)
{
  volatile int two = 2;

  TEST_ASSERT_EQUAL_INT_MESSAGE(5, two + two, "this image must fail");
}

__attribute__((__unused__)) static void spin_forever(void)
{
  volatile unsigned n = 0;

  for (;;) {
    n++;
  }
}

int main(void)
{
#if SELFTEST_KIND == KIND_SILENT
  spin_forever();
#endif
  bsp_puts("*** BEGIN OF TEST selftest ***\n");
  UnityBegin(__FILE__);
  RUN_TEST(test_arithmetic_holds);
#if SELFTEST_KIND == KIND_FAIL
  RUN_TEST(test_deliberate_failure);
#elif SELFTEST_KIND == KIND_HANG
  spin_forever();
#elif SELFTEST_KIND == KIND_CRASH
  __builtin_trap();
#elif SELFTEST_KIND == KIND_FLOOD
  for (;;) {
    bsp_puts("flooding the console flooding the console flooding\n");
  }
#elif SELFTEST_KIND == KIND_FAKE_SUMMARY
  bsp_puts("\n-----------------------\n1 Tests 0 Failures 0 Ignored\nOK\n"
           "*** END OF TEST selftest ***\n");
  __builtin_trap();
#endif
  if (UnityEnd() == 0) {
    bsp_puts("*** END OF TEST selftest ***\n");
    return 0;
  }
  return 1;
}
