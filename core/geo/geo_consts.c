/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief Series coefficients of core/geo: conformal latitude
 *        and Krueger's alpha and beta (generated: do not edit;
 *        run tools/generate.py). mpmath at 60 digits, rounded
 *        to nearest; Q5.58 unless named otherwise.
 */

#include "geo_projection.h"

const int64_t drdc__geo_chi_from_phi[GEO_CHI_TERMS] = {
  INT64_C(-967461000637978), INT64_C(1353118549491), INT64_C(-2361903110),
  INT64_C(4490620), INT64_C(-8945), INT64_C(18), INT64_C(0), INT64_C(0)
};
const int64_t drdc__geo_phi_from_chi[GEO_CHI_TERMS] = {
  INT64_C(967460092520737), INT64_C(1894213484062), INT64_C(5086229695),
  INT64_C(15529144), INT64_C(50843), INT64_C(174), INT64_C(1), INT64_C(0)
};
const int64_t drdc__geo_alpha[GEO_KRUEGER_TERMS] = {
  INT64_C(241459757772849), INT64_C(219300882214), INT64_C(345197814),
  INT64_C(700161), INT64_C(1646), INT64_C(4)
};
const int64_t drdc__geo_beta[GEO_KRUEGER_TERMS] = {
  INT64_C(241459856760810), INT64_C(17022511755), INT64_C(48234854),
  INT64_C(62396), INT64_C(109), INT64_C(0)
};
