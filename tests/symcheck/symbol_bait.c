/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Bait for tools/gates/symcheck.py: an object that exports a name
 *        without the drdc_ prefix (one that an application could define
 *        too), which the symbol check must reject on every target. Never
 *        linked into anything.
 */
int nmea_gga(const char *sentence);

int nmea_gga(const char *sentence)
{
  return (sentence != 0) ? (int)sentence[0] : 0;
}
