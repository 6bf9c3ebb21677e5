/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_geo
 * @brief WGS-84, UTM and UPS constants of core/geo (generated: do not edit;
 *        run tools/generate.py). mpmath at 60 digits, rounded
 *        to nearest; Q5.58 unless named otherwise.
 */

#ifndef DRDC_GEO_CONSTS_H
#define DRDC_GEO_CONSTS_H

#include <stdint.h>

/** WGS-84 first eccentricity squared e^2 = f (2 - f),
 *  f = 1/298.257223563. */
#define GEO_E2 INT64_C(1929523662660924)
/** WGS-84 first eccentricity e. */
#define GEO_E INT64_C(23582776152997482)
/** b / a = 1 - f (polar over equatorial radius). */
#define GEO_B_OVER_A INT64_C(287263994272646107)
/** e^2 a in metres, Q27.36 (Bowring's step, ecef.c). */
#define GEO_E2A_Q36 INT64_C(2934161726282396)
/** e'^2 b = e^2 a / sqrt(1 - e^2) in metres, Q27.36 (Bowring's
 *  step, ecef.c). */
#define GEO_EP2B_Q36 INT64_C(2944032509878881)
/** k0 A in metres, Q23.40: k0 = 0.9996 times the rectifying
 *  radius A = a / (1 + n) (1 + n^2/4 + n^4/64 + n^6/256),
 *  a = 6 378 137 m. */
#define GEO_K0A_Q40 INT64_C(6998283941355162077)
/** k0 A / a. */
#define GEO_K0A_OVER_A INT64_C(287632289103010426)
/** lim cos(chi) / cos(phi) at the poles: ((1 + e) / (1 - e))^(e/2). */
#define GEO_POLE_RATIO INT64_C(290170724834618951)
/** Largest cos(chi) |sin(lambda)| the series accept: tanh(0.34),
 *  so that cosh(12 eta') stays below 32 (the Q5.58 range). */
#define GEO_TM_MAX_TANH_ETA INT64_C(94388932686895755)
/** Largest |eta| of the inverse series (same reason): 0.34. */
#define GEO_TM_MAX_ETA INT64_C(97998327891581993)
/** UPS: 2 k0 a / c in metres, Q24.39 (k0 = 0.994,
 *  c = sqrt(1 - e^2) ((1 + e) / (1 - e))^(e/2)). */
#define GEO_UPS_K_Q39 INT64_C(6947439316371376541)
/** UPS: 2 k0 / c. */
#define GEO_UPS_2K0_OVER_C INT64_C(571085109068951680)
/** Radians per nano-arcsecond in Q5.58 is 1397 plus this
 *  fraction (pi 2^58 / 648e12 = 1397.38029...). */
#define GEO_NAS_RAD_FRACTION INT64_C(109613060018604784)

#endif /* DRDC_GEO_CONSTS_H */
