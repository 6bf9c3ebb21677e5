/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The example on a PC: standard output.
 */
#include <stdio.h>

#include "example.h"

void example_write(const char *text)
{
  fputs(text, stdout);
}

int main(void)
{
  return example_run();
}
