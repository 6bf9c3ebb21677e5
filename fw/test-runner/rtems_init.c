/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief RTEMS application that runs the Unity suites: an Init task and the
 *        RTEMS configuration. Built as test-runner.exe for RTEMS BSPs only,
 *        so `rtems-test` finds it and reads the test markers it prints.
 */
#include <rtems.h>
#include <stdlib.h>

#include "runner.h"

rtems_task Init(rtems_task_argument argument);

rtems_task Init(rtems_task_argument argument)
{
  (void)argument;
  exit(test_runner_run());
}

#define CONFIGURE_APPLICATION_NEEDS_CLOCK_DRIVER
#define CONFIGURE_APPLICATION_NEEDS_SIMPLE_CONSOLE_DRIVER
#define CONFIGURE_MAXIMUM_TASKS 1
#define CONFIGURE_RTEMS_INIT_TASKS_TABLE
/* The suites keep their vectors in const tables; the stack holds only
 * locals, but Unity and the golden digest nest a few calls deep. */
#define CONFIGURE_INIT_TASK_STACK_SIZE (16 * 1024)
#define CONFIGURE_INIT
#include <rtems/confdefs.h>
