/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief <string.h> of the bare-metal PowerPC image: the four functions
 *        that its board provides (mem.c), and nothing else.
 *
 * The image has no C library. GCC may call these four even in
 * freestanding code, so the board defines them; tests use them too. Any
 * other <string.h> function is a link error on this board, by design.
 */
#ifndef DRDC_PPC_E500_STRING_H
#define DRDC_PPC_E500_STRING_H

#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);

#endif /* DRDC_PPC_E500_STRING_H */
