/* SPDX-License-Identifier: BSD-2-Clause */
/* Start-up of the example on QEMU's mpc8544ds (e500v2): map the CCSR
 * (the UART and the reset register) with one TLB1 entry, set the stack,
 * clear .bss, run the example and reset. QEMU has already mapped the image
 * at 0. No interrupts are enabled, so no vectors are needed here. On a
 * real board: the CCSR comes out of reset at 0xFF700000 (QEMU puts it at
 * 0xE0000000), a boot loader may own TLB1 entry 1 (perhaps for the running
 * code), and the IVORs want setting as the board's BSP does. */
#define SPR_MAS0 624
#define SPR_MAS1 625
#define SPR_MAS2 626
#define SPR_MAS3 627
#define SPR_MAS7 944
/* TLB1 entry 1: 1 MiB at 0xE0000000, cache-inhibited and guarded */
#define CCSR_MAS0 0x10010000  /* TLBSEL = 1, ESEL = 1 */
#define CCSR_MAS1 0xC0000500  /* V, IPROT, TSIZE = 5 (1 MiB) */
#define CCSR_MAS2 0xE000000A  /* EPN, I, G */
#define CCSR_MAS3 0xE0000005  /* RPN, SW, SR */

  .section .text.start, "ax"
  .globl _start
_start:
  lis   3, CCSR_MAS0@h
  mtspr SPR_MAS0, 3
  lis   3, CCSR_MAS1@h
  ori   3, 3, CCSR_MAS1@l
  mtspr SPR_MAS1, 3
  lis   3, CCSR_MAS2@h
  ori   3, 3, CCSR_MAS2@l
  mtspr SPR_MAS2, 3
  lis   3, CCSR_MAS3@h
  ori   3, 3, CCSR_MAS3@l
  mtspr SPR_MAS3, 3
  li    3, 0
  mtspr SPR_MAS7, 3
  isync
  tlbwe
  isync
  lis   1, __stack_top@h
  ori   1, 1, __stack_top@l
  li    0, 0
  stwu  0, -16(1)
  lis   3, __bss_start@h
  ori   3, 3, __bss_start@l
  lis   4, __bss_end@h
  ori   4, 4, __bss_end@l
1:
  cmplw 3, 4
  bge   2f
  stw   0, 0(3)
  addi  3, 3, 4
  b     1b
2:
  bl    example_run
  bl    example_stop
3:
  b     3b

  .section .note.GNU-stack, "", @progbits
