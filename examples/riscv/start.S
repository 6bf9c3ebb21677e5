/* SPDX-License-Identifier: BSD-2-Clause */
/* Start-up of the example on QEMU's virt board (RV32, machine mode, no
 * firmware): QEMU loads the image into RAM and jumps here. Set the global
 * and stack pointers, clear .bss, run the example and stop. No interrupts
 * are enabled, so no trap vector is needed here. */
  .section .text.start, "ax"
  .globl _start
_start:
  .option push
  .option norelax
  la gp, __global_pointer$
  .option pop
  la sp, __stack_top
  la t0, __bss_start
  la t1, __bss_end
1:
  bgeu t0, t1, 2f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 1b
2:
  call example_run
  call example_stop
3:
  j 3b
