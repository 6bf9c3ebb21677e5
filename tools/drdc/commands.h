/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Subcommands of the drdc host tool, one file each.
 */
#ifndef DRDC_TOOL_COMMANDS_H
#define DRDC_TOOL_COMMANDS_H

/** `drdc time --from F --to T`: argv[0] is "time". Returns the exit
 *  status: 0 all lines converted, 1 a line failed, 2 usage error. */
int drdc_cmd_time(int argc, char **argv);

/** drdc attitude --from F --to T (tools/drdc/cmd_attitude.c). argv[0] is
 *  "attitude". Returns the exit status: 0, 1 (a line gave ERROR) or 2
 *  (bad arguments). */
int drdc_cmd_attitude(int argc, char **argv);

/** `drdc units`: argv[0] is "units". Returns the exit status: 0 all lines
 *  converted, 1 a line failed, 2 usage error. */
int drdc_cmd_units(int argc, char **argv);

/** `drdc geo [-g|-d|-:|-u|-m|-c] [-z ZONE|-s|-t] [-n] [-w] [-p PREC]`:
 *  GeoConvert-compatible conversion
 *  (tools/drdc/cmd_geo.c). argv[0] is "geo". Returns the exit status: 0
 *  all lines converted, 1 some line failed, 2 usage error. */
int drdc_cmd_geo(int argc, char **argv);

/** `drdc nmea [--strict] [--raw] [--keep-going]`: decode NMEA 0183
 *  sentences, one per line (tools/drdc/cmd_nmea.c). argv[0] is "nmea".
 *  Returns the exit status: 0 all lines decoded (with --keep-going: all
 *  lines read), 1 some line gave ERROR or the input could not be read, 2
 *  usage error. */
int drdc_cmd_nmea(int argc, char **argv);

#endif /* DRDC_TOOL_COMMANDS_H */
