/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_fixed
 * @brief All of fixed/: types, arithmetic, square roots, trigonometry,
 *        hyperbolic functions and libfixmath interop in one include.
 *
 * Rounding everywhere: to nearest, ties away from zero (fixed_types.h).
 * Accuracy of every function: in its header and in docs/accuracy.md.
 */
#ifndef DRDC_FIXED_H
#define DRDC_FIXED_H

#include <drdc/fixed_types.h>
#include <drdc/status.h>
#include <drdc/fixed_arith.h>
#include <drdc/fixed_sqrt.h>
#include <drdc/fixed_trig.h>
#include <drdc/fixed_hyper.h>
#include <drdc/fixed_q5_58.h>
#include <drdc/fixed_fix16.h>
#include <drdc/fixed_format.h>

#endif /* DRDC_FIXED_H */
