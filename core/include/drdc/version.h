/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Version of libdrdc-fx.
 */
#ifndef DRDC_VERSION_H
#define DRDC_VERSION_H

/** Major version: incompatible API changes. */
#define DRDC_VERSION_MAJOR 0
/** Minor version: compatible additions. */
#define DRDC_VERSION_MINOR 1
/** Patch version: fixes. */
#define DRDC_VERSION_PATCH 0
/** The same as text, "major.minor.patch". */
#define DRDC_VERSION_STRING "0.1.0"

#endif /* DRDC_VERSION_H */
