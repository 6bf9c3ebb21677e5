/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @ingroup drdc_nmea
 * @brief The decoders of drdc_nmea_parse_some(), one constant per
 *        sentence type: each in a section of its own, so that a firmware
 *        links the decoders it names and no other.
 */
#include "nmea_impl.h"

const drdc_nmea_decoder_t drdc_nmea_gga_decoder = {DRDC_NMEA_GGA,
                                                   drdc__nmea_gga, 11u};
const drdc_nmea_decoder_t drdc_nmea_rmc_decoder = {DRDC_NMEA_RMC,
                                                   drdc__nmea_rmc, 0u};
const drdc_nmea_decoder_t drdc_nmea_gns_decoder = {DRDC_NMEA_GNS,
                                                   drdc__nmea_gns, 10u};
const drdc_nmea_decoder_t drdc_nmea_zda_decoder = {DRDC_NMEA_ZDA,
                                                   drdc__nmea_zda, 0u};
const drdc_nmea_decoder_t drdc_nmea_gst_decoder = {DRDC_NMEA_GST,
                                                   drdc__nmea_gst, 0u};
const drdc_nmea_decoder_t drdc_nmea_gll_decoder = {DRDC_NMEA_GLL,
                                                   drdc__nmea_gll, 0u};
const drdc_nmea_decoder_t drdc_nmea_vtg_decoder = {DRDC_NMEA_VTG,
                                                   drdc__nmea_vtg, 0u};
const drdc_nmea_decoder_t drdc_nmea_hdt_decoder = {DRDC_NMEA_HDT,
                                                   drdc__nmea_hdt, 0u};
const drdc_nmea_decoder_t drdc_nmea_ths_decoder = {DRDC_NMEA_THS,
                                                   drdc__nmea_ths, 0u};
const drdc_nmea_decoder_t drdc_nmea_gsa_decoder = {DRDC_NMEA_GSA,
                                                   drdc__nmea_gsa, 0u};
