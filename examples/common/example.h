/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief What each platform of the example gives the application
 *        (pose_report.c), and what the application gives it.
 */
#ifndef EXAMPLE_H
#define EXAMPLE_H

/** Write NUL-terminated text to the console (the platform's). */
void example_write(const char *text);

/** Run the example; returns 0, or 1 after printing an ERROR line. */
int example_run(void);

#endif /* EXAMPLE_H */
