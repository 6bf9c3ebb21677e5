/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief drdc_tool_read_line(): whole lines of any length, CR LF or LF.
 */
#include <stdlib.h>
#include <string.h>

#include "lines.h"

/* Make room for at least `need` bytes in *line; false when out of
 * memory (the old buffer stays valid). */
static int reserve(char **line, size_t *cap, size_t need)
{
  size_t size = (*cap < 128u) ? 128u : *cap;
  char *grown;

  if ((*line != NULL) && (need <= *cap)) {
    return 1;
  }
  while (size < need) {
    size *= 2u;
  }
  grown = realloc(*line, size);
  if (grown == NULL) {
    return 0;
  }
  *line = grown;
  *cap = size;
  return 1;
}

int drdc_tool_read_line(FILE *in, char **line, size_t *cap, size_t *len)
{
  size_t n = 0;
  int too_long = 0;
  int c;

  *len = 0;
  if (!reserve(line, cap, 1u)) {
    return DRDC_TOOL_LINE_ERROR;
  }
  (*line)[0] = '\0';
  c = getc(in);
  if (c == EOF) {
    return ferror(in) ? DRDC_TOOL_LINE_ERROR : DRDC_TOOL_LINE_EOF;
  }
  while ((c != EOF) && (c != '\n')) {
    /* one byte more than the limit is kept: a '\r' that turns out to be
     * the end of a CR LF line at exactly the limit */
    if (n <= DRDC_TOOL_LINE_MAX) {
      if (!reserve(line, cap, n + 2u)) {
        return DRDC_TOOL_LINE_ERROR;
      }
      (*line)[n] = (char)c;
      n++;
    } else {
      too_long = 1;
    }
    c = getc(in);
  }
  if ((c == EOF) && ferror(in)) {
    (*line)[0] = '\0';
    return DRDC_TOOL_LINE_ERROR;
  }
  if ((n > 0u) && ((*line)[n - 1u] == '\r')) {
    n--;
  }
  if (too_long || (n > DRDC_TOOL_LINE_MAX)) {
    (*line)[0] = '\0';
    return DRDC_TOOL_LINE_TOO_LONG;
  }
  (*line)[n] = '\0';
  *len = n;
  return DRDC_TOOL_LINE_OK;
}

const char *drdc_tool_line_problem(int status, const char *line, size_t len)
{
  if (status == DRDC_TOOL_LINE_TOO_LONG) {
    return "line longer than 1048576 bytes";
  }
  if (strlen(line) != len) {
    return "NUL byte in the line";
  }
  return NULL;
}
