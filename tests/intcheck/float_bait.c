/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Bait for tools/gates/intcheck.py: floating-point code that the
 *        integer-only check must reject on every target. Built with the
 *        target's normal flags (soft-float calls, libm) and with its
 *        hard-float flags (FP instructions). Never linked into anything.
 */
double sin(double x);

double bait_scale(double x, long n);

double bait_scale(double x, long n)
{
  return (x * 2.5) + (double)n + sin(x);
}
