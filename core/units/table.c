/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_units
 * @brief The unit table: name (GNU units spelling), dimension (m, kg, s,
 *        K, bit) and SI factor of every unit as an exact rational, each
 *        with the definition it comes from.
 */
#include <drdc/units.h>

/*
 * Units with pi use the convergent pi ~ 245850922 / 78256779 of pi's
 * continued fraction [3; 7, 15, 1, 292, 1, 1, 1, 2, 1, 3, 1, 14, 2, 1]:
 * |error| < 7.8e-17, relative 2.5e-17, far below the 1e-15 asked of the
 * table and below what GNU units prints. Every other factor is exact.
 * Rows: name, { m, kg, s, K, bit }, factor num, factor den, offset num,
 * offset den; all fractions in lowest terms.
 */
static const drdc_unit_t units_table[] = {
  /* length */
  /* SI base unit (metre) */
  { "m", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^3 m */
  { "km", { 1, 0, 0, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* 10^-2 m */
  { "cm", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(100), 0, 1 },
  /* 10^-3 m */
  { "mm", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* 10^-6 m */
  { "um", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* 10^-9 m */
  { "nm", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000000000), 0, 1 },
  /* 10^-6 m */
  { "micron", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* 10^-10 m */
  { "angstrom", { 1, 0, 0, 0, 0 }, INT64_C(1), INT64_C(10000000000), 0, 1 },
  /* 2.54 cm exactly (international inch, 1959) */
  { "inch", { 1, 0, 0, 0, 0 }, INT64_C(127), INT64_C(5000), 0, 1 },
  /* inch */
  { "in", { 1, 0, 0, 0, 0 }, INT64_C(127), INT64_C(5000), 0, 1 },
  /* 12 inch = 0.3048 m exactly (international foot, 1959) */
  { "ft", { 1, 0, 0, 0, 0 }, INT64_C(381), INT64_C(1250), 0, 1 },
  /* ft */
  { "foot", { 1, 0, 0, 0, 0 }, INT64_C(381), INT64_C(1250), 0, 1 },
  /* 3 ft = 0.9144 m */
  { "yd", { 1, 0, 0, 0, 0 }, INT64_C(1143), INT64_C(1250), 0, 1 },
  /* yd */
  { "yard", { 1, 0, 0, 0, 0 }, INT64_C(1143), INT64_C(1250), 0, 1 },
  /* 5280 ft = 1609.344 m */
  { "mile", { 1, 0, 0, 0, 0 }, INT64_C(201168), INT64_C(125), 0, 1 },
  /* international nautical mile, 1852 m exactly */
  { "nmi", { 1, 0, 0, 0, 0 }, INT64_C(1852), INT64_C(1), 0, 1 },
  /* nmi */
  { "nauticalmile", { 1, 0, 0, 0, 0 }, INT64_C(1852), INT64_C(1), 0, 1 },
  /* 6 ft */
  { "fathom", { 1, 0, 0, 0, 0 }, INT64_C(1143), INT64_C(625), 0, 1 },
  /* 40 rod = 660 ft */
  { "furlong", { 1, 0, 0, 0, 0 }, INT64_C(25146), INT64_C(125), 0, 1 },
  /* 66 ft */
  { "chain", { 1, 0, 0, 0, 0 }, INT64_C(12573), INT64_C(625), 0, 1 },
  /* 0.001 inch */
  { "mil", { 1, 0, 0, 0, 0 }, INT64_C(127), INT64_C(5000000), 0, 1 },
  /* astronomical unit, 149 597 870 700 m exactly (IAU 2012) */
  { "au", { 1, 0, 0, 0, 0 }, INT64_C(149597870700), INT64_C(1), 0, 1 },
  /* c x 1 s */
  { "lightsecond", { 1, 0, 0, 0, 0 }, INT64_C(299792458), INT64_C(1), 0, 1 },
  /* c x julianyear (365.25 d) */
  { "lightyear", { 1, 0, 0, 0, 0 }, INT64_C(9460730472580800), INT64_C(1), 0, 1 },
  /* US survey foot, 1200/3937 m exactly */
  { "surveyfoot", { 1, 0, 0, 0, 0 }, INT64_C(1200), INT64_C(3937), 0, 1 },
  /* area */
  /* SI */
  { "m^2", { 2, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* (10^3 m)^2 */
  { "km^2", { 2, 0, 0, 0, 0 }, INT64_C(1000000), INT64_C(1), 0, 1 },
  /* (10^-2 m)^2 */
  { "cm^2", { 2, 0, 0, 0, 0 }, INT64_C(1), INT64_C(10000), 0, 1 },
  /* (10^-3 m)^2 */
  { "mm^2", { 2, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* inch^2 */
  { "in^2", { 2, 0, 0, 0, 0 }, INT64_C(16129), INT64_C(25000000), 0, 1 },
  /* ft^2 */
  { "ft^2", { 2, 0, 0, 0, 0 }, INT64_C(145161), INT64_C(1562500), 0, 1 },
  /* yd^2 */
  { "yd^2", { 2, 0, 0, 0, 0 }, INT64_C(1306449), INT64_C(1562500), 0, 1 },
  /* mile^2 */
  { "mile^2", { 2, 0, 0, 0, 0 }, INT64_C(40468564224), INT64_C(15625), 0, 1 },
  /* 100 are = 10^4 m^2 */
  { "hectare", { 2, 0, 0, 0, 0 }, INT64_C(10000), INT64_C(1), 0, 1 },
  /* 100 m^2 */
  { "are", { 2, 0, 0, 0, 0 }, INT64_C(100), INT64_C(1), 0, 1 },
  /* international acre, 43560 ft^2 (GNU units intacre) */
  { "acre", { 2, 0, 0, 0, 0 }, INT64_C(316160658), INT64_C(78125), 0, 1 },
  /* volume */
  /* SI */
  { "m^3", { 3, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* (10^-2 m)^3 */
  { "cm^3", { 3, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* inch^3 */
  { "in^3", { 3, 0, 0, 0, 0 }, INT64_C(2048383), INT64_C(125000000000), 0, 1 },
  /* ft^3 */
  { "ft^3", { 3, 0, 0, 0, 0 }, INT64_C(55306341), INT64_C(1953125000), 0, 1 },
  /* 10^-3 m^3 (1964 definition) */
  { "liter", { 3, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* liter */
  { "L", { 3, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* liter */
  { "l", { 3, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* 10^-3 liter */
  { "ml", { 3, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* US gallon, 231 in^3 (GNU units' default, UNITS_ENGLISH=US) */
  { "gallon", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(125000000000), 0, 1 },
  /* gallon */
  { "gal", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(125000000000), 0, 1 },
  /* 1/4 gallon */
  { "quart", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(500000000000), 0, 1 },
  /* 1/2 quart */
  { "pint", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(1000000000000), 0, 1 },
  /* US cup, 1/2 pint */
  { "cup", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(2000000000000), 0, 1 },
  /* US fluid ounce, 1/128 gallon */
  { "floz", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(16000000000000), 0, 1 },
  /* US tablespoon, 1/2 floz */
  { "tablespoon", { 3, 0, 0, 0, 0 }, INT64_C(473176473), INT64_C(32000000000000), 0, 1 },
  /* US teaspoon, 1/3 tablespoon */
  { "teaspoon", { 3, 0, 0, 0, 0 }, INT64_C(157725491), INT64_C(32000000000000), 0, 1 },
  /* British gallon, 4.54609 liter exactly */
  { "brgallon", { 3, 0, 0, 0, 0 }, INT64_C(454609), INT64_C(100000000), 0, 1 },
  /* petroleum barrel, 42 gallon */
  { "barrel", { 3, 0, 0, 0, 0 }, INT64_C(9936705933), INT64_C(62500000000), 0, 1 },
  /* barrel */
  { "bbl", { 3, 0, 0, 0, 0 }, INT64_C(9936705933), INT64_C(62500000000), 0, 1 },
  /* mass */
  /* SI base unit (kilogram) */
  { "kg", { 0, 1, 0, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^-3 kg */
  { "g", { 0, 1, 0, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* 10^-6 kg */
  { "mg", { 0, 1, 0, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* 10^3 kg */
  { "tonne", { 0, 1, 0, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* tonne */
  { "t", { 0, 1, 0, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* avoirdupois pound, 0.45359237 kg exactly (1959) */
  { "lb", { 0, 1, 0, 0, 0 }, INT64_C(45359237), INT64_C(100000000), 0, 1 },
  /* lb */
  { "pound", { 0, 1, 0, 0, 0 }, INT64_C(45359237), INT64_C(100000000), 0, 1 },
  /* 1/16 lb */
  { "oz", { 0, 1, 0, 0, 0 }, INT64_C(45359237), INT64_C(1600000000), 0, 1 },
  /* 1/7000 lb */
  { "grain", { 0, 1, 0, 0, 0 }, INT64_C(6479891), INT64_C(100000000000), 0, 1 },
  /* 14 lb */
  { "stone", { 0, 1, 0, 0, 0 }, INT64_C(317514659), INT64_C(50000000), 0, 1 },
  /* US short ton, 2000 lb (GNU units' default) */
  { "ton", { 0, 1, 0, 0, 0 }, INT64_C(45359237), INT64_C(50000), 0, 1 },
  /* 2000 lb */
  { "shortton", { 0, 1, 0, 0, 0 }, INT64_C(45359237), INT64_C(50000), 0, 1 },
  /* 2240 lb */
  { "longton", { 0, 1, 0, 0, 0 }, INT64_C(317514659), INT64_C(312500), 0, 1 },
  /* 480 grain */
  { "troyounce", { 0, 1, 0, 0, 0 }, INT64_C(19439673), INT64_C(625000000), 0, 1 },
  /* metric carat, 200 mg */
  { "carat", { 0, 1, 0, 0, 0 }, INT64_C(1), INT64_C(5000), 0, 1 },
  /* lbf s^2 / ft */
  { "slug", { 0, 1, 0, 0, 0 }, INT64_C(8896443230521), INT64_C(609600000000), 0, 1 },
  /* time */
  /* SI base unit (second) */
  { "s", { 0, 0, 1, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* s */
  { "sec", { 0, 0, 1, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* s */
  { "second", { 0, 0, 1, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^-3 s */
  { "ms", { 0, 0, 1, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* 10^-6 s */
  { "us", { 0, 0, 1, 0, 0 }, INT64_C(1), INT64_C(1000000), 0, 1 },
  /* 10^-9 s */
  { "ns", { 0, 0, 1, 0, 0 }, INT64_C(1), INT64_C(1000000000), 0, 1 },
  /* 60 s */
  { "min", { 0, 0, 1, 0, 0 }, INT64_C(60), INT64_C(1), 0, 1 },
  /* 60 s */
  { "minute", { 0, 0, 1, 0, 0 }, INT64_C(60), INT64_C(1), 0, 1 },
  /* 3600 s */
  { "hr", { 0, 0, 1, 0, 0 }, INT64_C(3600), INT64_C(1), 0, 1 },
  /* 3600 s */
  { "hour", { 0, 0, 1, 0, 0 }, INT64_C(3600), INT64_C(1), 0, 1 },
  /* 86400 s */
  { "day", { 0, 0, 1, 0, 0 }, INT64_C(86400), INT64_C(1), 0, 1 },
  /* 7 day */
  { "week", { 0, 0, 1, 0, 0 }, INT64_C(604800), INT64_C(1), 0, 1 },
  /* 14 day */
  { "fortnight", { 0, 0, 1, 0, 0 }, INT64_C(1209600), INT64_C(1), 0, 1 },
  /* 365.25 day */
  { "julianyear", { 0, 0, 1, 0, 0 }, INT64_C(31557600), INT64_C(1), 0, 1 },
  /* GNU units' year: tropicalyear, 365.242198781 day */
  { "year", { 0, 0, 1, 0, 0 }, INT64_C(9861539367087), INT64_C(312500), 0, 1 },
  /* speed */
  /* SI */
  { "m/s", { 1, 0, -1, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* km / 3600 s */
  { "km/hr", { 1, 0, -1, 0, 0 }, INT64_C(5), INT64_C(18), 0, 1 },
  /* km/hr */
  { "kph", { 1, 0, -1, 0, 0 }, INT64_C(5), INT64_C(18), 0, 1 },
  /* mile/hr */
  { "mph", { 1, 0, -1, 0, 0 }, INT64_C(1397), INT64_C(3125), 0, 1 },
  /* nmi/hr */
  { "knot", { 1, 0, -1, 0, 0 }, INT64_C(463), INT64_C(900), 0, 1 },
  /* knot */
  { "knots", { 1, 0, -1, 0, 0 }, INT64_C(463), INT64_C(900), 0, 1 },
  /* ft / s */
  { "ft/s", { 1, 0, -1, 0, 0 }, INT64_C(381), INT64_C(1250), 0, 1 },
  /* ft/s */
  { "fps", { 1, 0, -1, 0, 0 }, INT64_C(381), INT64_C(1250), 0, 1 },
  /* ft / 60 s */
  { "ft/min", { 1, 0, -1, 0, 0 }, INT64_C(127), INT64_C(25000), 0, 1 },
  /* ft/min */
  { "fpm", { 1, 0, -1, 0, 0 }, INT64_C(127), INT64_C(25000), 0, 1 },
  /* speed of light, 299 792 458 m/s exactly */
  { "c", { 1, 0, -1, 0, 0 }, INT64_C(299792458), INT64_C(1), 0, 1 },
  /* acceleration */
  /* SI */
  { "m/s^2", { 1, 0, -2, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* standard gravity, 9.80665 m/s^2 exactly (CGPM 1901) */
  { "gravity", { 1, 0, -2, 0, 0 }, INT64_C(196133), INT64_C(20000), 0, 1 },
  /* galileo, cm/s^2 */
  { "Gal", { 1, 0, -2, 0, 0 }, INT64_C(1), INT64_C(100), 0, 1 },
  /* Gal */
  { "galileo", { 1, 0, -2, 0, 0 }, INT64_C(1), INT64_C(100), 0, 1 },
  /* ft / s^2 */
  { "ft/s^2", { 1, 0, -2, 0, 0 }, INT64_C(381), INT64_C(1250), 0, 1 },
  /* angle */
  /* SI (dimensionless, as in GNU units) */
  { "radian", { 0, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* pi/180 radian (pi convergent) */
  { "degree", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(7043110110), 0, 1 },
  /* degree */
  { "deg", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(7043110110), 0, 1 },
  /* degree/60 */
  { "arcmin", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(422586606600), 0, 1 },
  /* arcmin */
  { "arcminute", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(422586606600), 0, 1 },
  /* arcmin/60 */
  { "arcsec", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(25355196396000), 0, 1 },
  /* arcsec */
  { "arcsecond", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(25355196396000), 0, 1 },
  /* 1/400 circle */
  { "gon", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(7825677900), 0, 1 },
  /* gon */
  { "grade", { 0, 0, 0, 0, 0 }, INT64_C(122925461), INT64_C(7825677900), 0, 1 },
  /* circle, 2 pi radian */
  { "turn", { 0, 0, 0, 0, 0 }, INT64_C(491701844), INT64_C(78256779), 0, 1 },
  /* turn */
  { "revolution", { 0, 0, 0, 0, 0 }, INT64_C(491701844), INT64_C(78256779), 0, 1 },
  /* 2 pi radian */
  { "circle", { 0, 0, 0, 0, 0 }, INT64_C(491701844), INT64_C(78256779), 0, 1 },
  /* 10^-3 radian */
  { "milliradian", { 0, 0, 0, 0, 0 }, INT64_C(1), INT64_C(1000), 0, 1 },
  /* angular rate */
  /* SI */
  { "radian/s", { 0, 0, -1, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* degree / s */
  { "deg/s", { 0, 0, -1, 0, 0 }, INT64_C(122925461), INT64_C(7043110110), 0, 1 },
  /* degree / s */
  { "degree/s", { 0, 0, -1, 0, 0 }, INT64_C(122925461), INT64_C(7043110110), 0, 1 },
  /* degree / 3600 s */
  { "deg/hr", { 0, 0, -1, 0, 0 }, INT64_C(122925461), INT64_C(25355196396000), 0, 1 },
  /* rev/min */
  { "rpm", { 0, 0, -1, 0, 0 }, INT64_C(122925461), INT64_C(1173851685), 0, 1 },
  /* rev/sec */
  { "rps", { 0, 0, -1, 0, 0 }, INT64_C(491701844), INT64_C(78256779), 0, 1 },
  /* frequency */
  /* 1/s */
  { "Hz", { 0, 0, -1, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^3 Hz */
  { "kHz", { 0, 0, -1, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* 10^6 Hz */
  { "MHz", { 0, 0, -1, 0, 0 }, INT64_C(1000000), INT64_C(1), 0, 1 },
  /* 10^9 Hz */
  { "GHz", { 0, 0, -1, 0, 0 }, INT64_C(1000000000), INT64_C(1), 0, 1 },
  /* force */
  /* SI (kg m/s^2) */
  { "N", { 1, 1, -2, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^3 N */
  { "kN", { 1, 1, -2, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* g cm/s^2 */
  { "dyne", { 1, 1, -2, 0, 0 }, INT64_C(1), INT64_C(100000), 0, 1 },
  /* lb x gravity = 4.4482216152605 N exactly */
  { "lbf", { 1, 1, -2, 0, 0 }, INT64_C(8896443230521), INT64_C(2000000000000), 0, 1 },
  /* 1000 lbf */
  { "kip", { 1, 1, -2, 0, 0 }, INT64_C(8896443230521), INT64_C(2000000000), 0, 1 },
  /* ton force, 2000 lbf */
  { "tonf", { 1, 1, -2, 0, 0 }, INT64_C(8896443230521), INT64_C(1000000000), 0, 1 },
  /* kg x gravity = 9.80665 N */
  { "kgf", { 1, 1, -2, 0, 0 }, INT64_C(196133), INT64_C(20000), 0, 1 },
  /* lb ft/s^2 */
  { "poundal", { 1, 1, -2, 0, 0 }, INT64_C(17281869297), INT64_C(125000000000), 0, 1 },
  /* pressure */
  /* SI (N/m^2) */
  { "Pa", { -1, 1, -2, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^2 Pa */
  { "hPa", { -1, 1, -2, 0, 0 }, INT64_C(100), INT64_C(1), 0, 1 },
  /* 10^3 Pa */
  { "kPa", { -1, 1, -2, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* 10^6 Pa */
  { "MPa", { -1, 1, -2, 0, 0 }, INT64_C(1000000), INT64_C(1), 0, 1 },
  /* 10^5 Pa */
  { "bar", { -1, 1, -2, 0, 0 }, INT64_C(100000), INT64_C(1), 0, 1 },
  /* 10^-3 bar */
  { "mbar", { -1, 1, -2, 0, 0 }, INT64_C(100), INT64_C(1), 0, 1 },
  /* mbar */
  { "millibar", { -1, 1, -2, 0, 0 }, INT64_C(100), INT64_C(1), 0, 1 },
  /* standard atmosphere, 101325 Pa exactly */
  { "atm", { -1, 1, -2, 0, 0 }, INT64_C(101325), INT64_C(1), 0, 1 },
  /* technical atmosphere, kgf/cm^2 */
  { "at", { -1, 1, -2, 0, 0 }, INT64_C(196133), INT64_C(2), 0, 1 },
  /* lbf/in^2 */
  { "psi", { -1, 1, -2, 0, 0 }, INT64_C(8896443230521), INT64_C(1290320000), 0, 1 },
  /* 1000 psi */
  { "ksi", { -1, 1, -2, 0, 0 }, INT64_C(8896443230521), INT64_C(1290320), 0, 1 },
  /* atm/760 */
  { "torr", { -1, 1, -2, 0, 0 }, INT64_C(20265), INT64_C(152), 0, 1 },
  /* mm x 13.5951 g/cm^3 x gravity (GNU units' Hg) */
  { "mmHg", { -1, 1, -2, 0, 0 }, INT64_C(26664477483), INT64_C(200000000), 0, 1 },
  /* inch x 13.5951 g/cm^3 x gravity */
  { "inHg", { -1, 1, -2, 0, 0 }, INT64_C(3386388640341), INT64_C(1000000000), 0, 1 },
  /* energy */
  /* SI (N m) */
  { "J", { 2, 1, -2, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^3 J */
  { "kJ", { 2, 1, -2, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* 10^6 J */
  { "MJ", { 2, 1, -2, 0, 0 }, INT64_C(1000000), INT64_C(1), 0, 1 },
  /* dyne cm */
  { "erg", { 2, 1, -2, 0, 0 }, INT64_C(1), INT64_C(10000000), 0, 1 },
  /* thermochemical calorie, 4.184 J (GNU units' cal) */
  { "cal", { 2, 1, -2, 0, 0 }, INT64_C(523), INT64_C(125), 0, 1 },
  /* cal */
  { "calorie", { 2, 1, -2, 0, 0 }, INT64_C(523), INT64_C(125), 0, 1 },
  /* 10^3 cal */
  { "kcal", { 2, 1, -2, 0, 0 }, INT64_C(4184), INT64_C(1), 0, 1 },
  /* International Table calorie, 4.1868 J */
  { "cal_IT", { 2, 1, -2, 0, 0 }, INT64_C(10467), INT64_C(2500), 0, 1 },
  /* btu_IT: cal_IT x lb x degF / (g K) = 1055.05585262 J */
  { "btu", { 2, 1, -2, 0, 0 }, INT64_C(52752792631), INT64_C(50000000), 0, 1 },
  /* US therm, 105 480 400 J */
  { "therm", { 2, 1, -2, 0, 0 }, INT64_C(105480400), INT64_C(1), 0, 1 },
  /* W x hr */
  { "Wh", { 2, 1, -2, 0, 0 }, INT64_C(3600), INT64_C(1), 0, 1 },
  /* kW x hr */
  { "kWh", { 2, 1, -2, 0, 0 }, INT64_C(3600000), INT64_C(1), 0, 1 },
  /* power */
  /* SI (J/s) */
  { "W", { 2, 1, -3, 0, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^3 W */
  { "kW", { 2, 1, -3, 0, 0 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* 10^6 W */
  { "MW", { 2, 1, -3, 0, 0 }, INT64_C(1000000), INT64_C(1), 0, 1 },
  /* horsepower, 550 ft lbf / s */
  { "hp", { 2, 1, -3, 0, 0 }, INT64_C(37284993579113511), INT64_C(50000000000000), 0, 1 },
  /* hp */
  { "horsepower", { 2, 1, -3, 0, 0 }, INT64_C(37284993579113511), INT64_C(50000000000000), 0, 1 },
  /* 75 kgf m / s */
  { "metrichorsepower", { 2, 1, -3, 0, 0 }, INT64_C(588399), INT64_C(800), 0, 1 },
  /* btu / 3600 s */
  { "btu/hr", { 2, 1, -3, 0, 0 }, INT64_C(52752792631), INT64_C(180000000000), 0, 1 },
  /* temperature */
  /* SI base unit (kelvin), absolute temperature */
  { "K", { 0, 0, 0, 1, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* K */
  { "tempK", { 0, 0, 0, 1, 0 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* temperature: K = degC + 273.15 */
  { "degC", { 0, 0, 0, 1, 0 }, INT64_C(1), INT64_C(1), 5463, 20 },
  /* degC */
  { "tempC", { 0, 0, 0, 1, 0 }, INT64_C(1), INT64_C(1), 5463, 20 },
  /* temperature: K = (degF + 459.67) x 5/9 */
  { "degF", { 0, 0, 0, 1, 0 }, INT64_C(5), INT64_C(9), 45967, 100 },
  /* degF */
  { "tempF", { 0, 0, 0, 1, 0 }, INT64_C(5), INT64_C(9), 45967, 100 },
  /* Rankine: K = degR x 5/9 */
  { "degR", { 0, 0, 0, 1, 0 }, INT64_C(5), INT64_C(9), 0, 1 },
  /* degR */
  { "tempR", { 0, 0, 0, 1, 0 }, INT64_C(5), INT64_C(9), 0, 1 },
  /* data */
  /* base unit (GNU units) */
  { "bit", { 0, 0, 0, 0, 1 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 8 bit */
  { "byte", { 0, 0, 0, 0, 1 }, INT64_C(8), INT64_C(1), 0, 1 },
  /* data rate */
  /* bit/s */
  { "bps", { 0, 0, -1, 0, 1 }, INT64_C(1), INT64_C(1), 0, 1 },
  /* 10^3 bit/s */
  { "kbps", { 0, 0, -1, 0, 1 }, INT64_C(1000), INT64_C(1), 0, 1 },
  /* 10^6 bit/s */
  { "Mbps", { 0, 0, -1, 0, 1 }, INT64_C(1000000), INT64_C(1), 0, 1 },
  /* 10^9 bit/s */
  { "Gbps", { 0, 0, -1, 0, 1 }, INT64_C(1000000000), INT64_C(1), 0, 1 },
  /* 8 bit/s */
  { "byte/s", { 0, 0, -1, 0, 1 }, INT64_C(8), INT64_C(1), 0, 1 },
  /* 10^3 byte/s */
  { "kbyte/s", { 0, 0, -1, 0, 1 }, INT64_C(8000), INT64_C(1), 0, 1 },
};

size_t drdc_units_count(void)
{
  return sizeof(units_table) / sizeof(units_table[0]);
}

const drdc_unit_t *drdc_units_at(size_t index)
{
  const drdc_unit_t *unit = NULL;

  if (index < drdc_units_count()) {
    unit = &units_table[index];
  }
  return unit;
}
