/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The one line reader of the drdc host tool: every subcommand
 *        reads its input through it, so each input line gives exactly one
 *        output line whatever its length or bytes.
 */
#ifndef DRDC_TOOL_LINES_H
#define DRDC_TOOL_LINES_H

#include <stddef.h>
#include <stdio.h>

/** Longest line a command converts, in bytes without its end of line. A
 *  longer line is read to its end and discarded: the command writes one
 *  'ERROR: line longer than ...' record for it. 1 MiB is far beyond any
 *  record the commands know and small enough for any host. */
#define DRDC_TOOL_LINE_MAX ((size_t)1 << 20)

/** drdc_tool_read_line() read a line: *line holds it. */
#define DRDC_TOOL_LINE_OK 1
/** End of input: no line was read. */
#define DRDC_TOOL_LINE_EOF 0
/** The line was longer than DRDC_TOOL_LINE_MAX and was skipped. */
#define DRDC_TOOL_LINE_TOO_LONG (-1)
/** Out of memory or a read error: stop reading. */
#define DRDC_TOOL_LINE_ERROR (-2)

/**
 * Read the next line of `in`, of any length up to DRDC_TOOL_LINE_MAX.
 *
 * A line ends at '\n' or at the end of input (a last line without '\n'
 * is a line; nothing after the last '\n' is no line). The '\n' and one
 * '\r' just before it (CR LF input) are removed; every other byte, NUL
 * and invalid UTF-8 included, is kept.
 *
 * @param in the stream to read.
 * @param[in,out] line a buffer from malloc() or NULL, grown as needed
 *        (the caller frees it once, after the last call).
 * @param[in,out] cap the size of *line; 0 with NULL.
 * @param[out] len the length of the line, bytes, without the end of line.
 *        (*line)[*len] is '\0'; a NUL inside the line makes strlen() of
 *        it shorter than *len, which callers check.
 * @retval DRDC_TOOL_LINE_OK a line is in *line and *len.
 * @retval DRDC_TOOL_LINE_EOF end of input; *len is 0.
 * @retval DRDC_TOOL_LINE_TOO_LONG the line had more than
 *         DRDC_TOOL_LINE_MAX bytes: it was read up to and with its '\n'
 *         and dropped; *len is 0 and *line is "".
 * @retval DRDC_TOOL_LINE_ERROR out of memory or a read error; *len is 0.
 */
int drdc_tool_read_line(FILE *in, char **line, size_t *cap, size_t *len);

/**
 * Why a line that drdc_tool_read_line() returned cannot be converted by
 * any command, or NULL when it can be parsed.
 *
 * @param status what drdc_tool_read_line() returned (OK or TOO_LONG).
 * @param line, len the line it read.
 * @return "line longer than 1048576 bytes" (TOO_LONG), "NUL byte in the
 *         line" (a NUL before *len), or NULL. The command writes
 *         'ERROR: <reason>' for it, one line.
 */
const char *drdc_tool_line_problem(int status, const char *line, size_t len);

#endif /* DRDC_TOOL_LINES_H */
