/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief Subcommands of the host tool drdc, one file each.
 */
#ifndef DRDC_TOOL_COMMANDS_H
#define DRDC_TOOL_COMMANDS_H

/** drdc attitude --from F --to T (tools/drdc/cmd_attitude.c). argv[0] is
 *  "attitude". Returns the exit status: 0, 1 (a line gave ERROR) or 2
 *  (bad arguments). */
int drdc_cmd_attitude(int argc, char **argv);

#endif /* DRDC_TOOL_COMMANDS_H */
