/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Compiler attributes and builtins of the library's own
 *        code (internal, not installed): the one place that names them.
 *
 * The library is C99 built by GCC (every target) and clang (the fuzz
 * build); both take these GNU attributes. A function carries one only
 * where a budget of waftools/targets.py (stack depth, linked flash) or a
 * speed goal of docs/performance.md fails without it; the line above it
 * says which.
 */
#ifndef DRDC_COMPILER_H
#define DRDC_COMPILER_H

#include <stdint.h>

#if defined(__AVR__)
#include <avr/pgmspace.h> /* PROGMEM, pgm_read_*: DRDC_FLASH_TABLE below */
#endif

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

/*
 * Constant tables in program memory. On the AVR (Harvard: flash and RAM
 * are separate address spaces) a plain `const` table is copied into RAM
 * by the start-up code, and the ATmega2560 has 8 KiB of it. A table
 * marked DRDC_FLASH_TABLE stays in flash there (avr-libc's PROGMEM, a
 * section attribute, so the build keeps -std=c99; GCC's __flash would
 * need -std=gnu99), and every read of it goes through drdc__flash_*(),
 * an LPM load. The section is placed at the start of flash, below the
 * 64 KiB that LPM reaches. Elsewhere, where flash is in the one address
 * space, the mark is empty and the reads are plain loads: the same code
 * as an indexed array.
 */
#if defined(__AVR__)
#define DRDC_FLASH_TABLE PROGMEM

static inline uint32_t drdc__flash_u32(const uint32_t *at)
{
  return (uint32_t)pgm_read_dword(at);
}

static inline int32_t drdc__flash_s32(const int32_t *at)
{
  return (int32_t)pgm_read_dword(at);
}

static inline uint16_t drdc__flash_u16(const uint16_t *at)
{
  return (uint16_t)pgm_read_word(at);
}
#else
#define DRDC_FLASH_TABLE

static inline uint32_t drdc__flash_u32(const uint32_t *at)
{
  return *at;
}

static inline int32_t drdc__flash_s32(const int32_t *at)
{
  return *at;
}

static inline uint16_t drdc__flash_u16(const uint16_t *at)
{
  return *at;
}
#endif

#endif /* DRDC_COMPILER_H */
