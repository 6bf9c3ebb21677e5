/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Compiler attributes and builtins of the library's own
 *        code (internal, not installed): the one place that names them.
 *
 * The library is C99 built by GCC (every target) and clang (the fuzz
 * build); both take these GNU attributes. A function carries one only
 * where a budget of tools/footprint.py (stack depth, linked flash) or a
 * speed goal of docs/performance.md fails without it; the line above it
 * says which.
 */
#ifndef DRDC_COMPILER_H
#define DRDC_COMPILER_H

#include <stdint.h>

/** Keep the function out of line: its frame is not added to the
 *  caller's, so the deepest chain stays that of its deepest callee. */
#define DRDC_NOINLINE __attribute__((noinline))

/** Inline the (static inline) function into every caller, also where
 *  the optimiser's heuristics would call it out of line. */
#define DRDC_ALWAYS_INLINE __attribute__((always_inline))

/** Leading zero bits of a nonzero 32-bit value. __builtin_clz takes an
 *  unsigned int, which has 16 bits where int has (AVR, MSP430): a
 *  uint32_t passed to it would lose its high half there. Counted in 64
 *  bits instead, which every target has: on Cortex-M3, e500 and x86-64
 *  the compiler folds the zero high word away (one clz, cntlzw, bsr). */
static inline unsigned drdc__clz32(uint32_t x)
{
  return (unsigned)__builtin_clzll((unsigned long long)x) - 32u;
}

#endif /* DRDC_COMPILER_H */
