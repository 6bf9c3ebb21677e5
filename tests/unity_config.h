/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Unity 2.5.1 configuration shared by every target (included by
 *        unity_internals.h through UNITY_INCLUDE_CONFIG_H).
 */
#ifndef DRDC_UNITY_CONFIG_H
#define DRDC_UNITY_CONFIG_H

/* Bare-metal targets have no setjmp and no floating point. A failed
 * assertion returns from Unity's assertion function; Unity then skips the
 * rest of the test's assertions. */
#define UNITY_EXCLUDE_SETJMP_H
#define UNITY_EXCLUDE_FLOAT
#define UNITY_EXCLUDE_DOUBLE
/* 64-bit assertions: not enabled by default on 32-bit targets. */
#define UNITY_SUPPORT_64

/* Freestanding headers only: the bare-metal PowerPC build has no C
 * library (-nostdinc), so no <math.h>; Unity needs none without floats. */
#define UNITY_EXCLUDE_MATH_H

/* Output through the board console (bsp/drdc_board.h). */
#define UNITY_OUTPUT_CHAR(c)                 bsp_putc(c)
#define UNITY_OUTPUT_CHAR_HEADER_DECLARATION bsp_putc(int)

/* Unity 2.5.1 declares UnityFail() and UnityIgnore() noreturn whatever
 * the setjmp switch says, yet without setjmp they return: undefined
 * behaviour that lets the compiler drop the code after a failure. Turn the
 * attribute into a harmless one for every file that includes unity.h. */
#define noreturn __unused__

#endif /* DRDC_UNITY_CONFIG_H */
