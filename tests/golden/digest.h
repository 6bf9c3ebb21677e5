/* SPDX-License-Identifier: BSD-2-Clause */
/* The conformance value: the digest that every target must print (see
 * tests/golden/test_golden.c). Changed only by changes meant to alter
 * results. */
#define DRDC_GOLDEN_DIGEST 0x6d842393u
