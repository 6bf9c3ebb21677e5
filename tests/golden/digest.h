/* SPDX-License-Identifier: BSD-2-Clause */
/* The conformance value: the digest that every target must print (see
 * tests/golden/test_golden.c). Changed only by changes meant to alter
 * results. */
#define DRDC_GOLDEN_DIGEST 0x7a79f8adu

/* The digest of each part (the lines "golden digest of <part>"): a part
 * that differs prints its trace (tests/golden/test_golden.c). The
 * conformance value above is the CRC of these seven. A change of
 * results also rewrites the block digests of golden_expected.c, the
 * output of "golden-trace expected" (build/host/fw/golden-trace/). */
#define DRDC_GOLDEN_DIGEST_TIME        0xd1a91c00u
#define DRDC_GOLDEN_DIGEST_TIME_SCALES 0xd864f481u
#define DRDC_GOLDEN_DIGEST_FIXED       0xf8cab9a9u
#define DRDC_GOLDEN_DIGEST_ORIENT      0x13b49878u
#define DRDC_GOLDEN_DIGEST_INTEROP     0xd574a327u
#define DRDC_GOLDEN_DIGEST_GEO         0x09898737u
#define DRDC_GOLDEN_DIGEST_POSES       0xe4387885u
