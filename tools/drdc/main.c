/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief drdc: the host command-line tool. The same library as the
 *        firmware, so its numbers are the bits the MCU computes.
 */
#include <stdio.h>
#include <string.h>

#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#endif

#include <drdc/version.h>

#include "commands.h"

static const char usage[] =
    "usage: drdc [--help | --version] COMMAND [OPTIONS]\n"
    "\n"
    "The libdrdc-fx data-standards library on the host, bit-identical to\n"
    "the firmware builds. Commands read one record per line on standard\n"
    "input and write one line per input line (LF or CR LF, any length up\n"
    "to 1 MiB); a record that cannot be converted gives 'ERROR: <reason>'\n"
    "and the exit status 1 at the end.\n"
    "\n"
    "Commands:\n"
    "  time --from F --to T   convert times between utc, gps, unix, rtems\n"
    "                         and tai (drdc time --help for the formats)\n"
    "  attitude --from F --to T\n"
    "                         convert orientations between euler, quat and\n"
    "                         dcm (drdc attitude --help for the formats)\n"
    "  units                  convert 'VALUE FROM TO' lines between units\n"
    "                         named as GNU units names them (drdc units\n"
    "                         --help)\n"
    "  geo [-g|-d|-:|-u|-m|-c] [-z ZONE|-s|-t|-S|-T] [-n] [-w] [-p PREC]\n"
    "                         convert 'LAT LON' (decimal or DMS),\n"
    "                         'ZONE{n|s} E N' or MGRS lines like\n"
    "                         GeoConvert, to geographic, DMS, UTM/UPS,\n"
    "                         MGRS or convergence and scale, with its\n"
    "                         messages and its input, output and comment\n"
    "                         options (drdc geo --help)\n"
    "  nmea [--strict] [--raw]\n"
    "                         decode NMEA 0183 sentences into key=value\n"
    "                         fields (drdc nmea --help)\n"
    "\n"
    "Options:\n"
    "  --help     this text\n"
    "  --version  the library version\n";

/* Standard input in binary mode on Windows: the text mode of its C
 * library would end the input at the first Ctrl-Z byte and drop each CR
 * before an LF, so lines.c reads the same bytes, LF or CR LF lines, on
 * every system. Standard output stays in text mode there, each line
 * ending in CR LF, as GeoConvert's output (a C++ stream in text mode) and
 * that of Windows's own console programs do. */
static void binary_input(void)
{
#ifdef _WIN32
  (void)_setmode(_fileno(stdin), _O_BINARY);
#endif
}

int main(int argc, char **argv)
{
  binary_input();
  if ((argc == 2) && (strcmp(argv[1], "--help") == 0)) {
    fputs(usage, stdout);
    return 0;
  }
  if ((argc == 2) && (strcmp(argv[1], "--version") == 0)) {
    printf("drdc %s\n", DRDC_VERSION_STRING);
    return 0;
  }
  if ((argc >= 2) && (strcmp(argv[1], "time") == 0)) {
    return drdc_cmd_time(argc - 1, argv + 1);
  }
  if ((argc >= 2) && (strcmp(argv[1], "attitude") == 0)) {
    return drdc_cmd_attitude(argc - 1, argv + 1);
  }
  if ((argc >= 2) && (strcmp(argv[1], "units") == 0)) {
    return drdc_cmd_units(argc - 1, argv + 1);
  }
  if ((argc >= 2) && (strcmp(argv[1], "geo") == 0)) {
    return drdc_cmd_geo(argc - 1, argv + 1);
  }
  if ((argc >= 2) && (strcmp(argv[1], "nmea") == 0)) {
    return drdc_cmd_nmea(argc - 1, argv + 1);
  }
  if (argc < 2) {
    fputs(usage, stderr);
  } else {
    fprintf(stderr, "drdc: unknown command or option '%s' (see drdc --help)\n",
            argv[1]);
  }
  return 2;
}
