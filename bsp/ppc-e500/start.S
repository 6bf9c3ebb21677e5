/* SPDX-License-Identifier: BSD-2-Clause */
/*
 * Start-up for the e500v2 core of QEMU's mpc8544ds machine.
 *
 * QEMU loads the ELF image at its link address (0) and enters _start with
 * a TLB1 entry that maps the image. We add a TLB1 entry for the CCSR
 * register block (UART, reset control), point every interrupt vector at a
 * reporter, set up the stack, clear .bss and call main().
 */

/* Special-purpose registers (Book E / e500) */
#define SPR_SRR0   26
#define SPR_SRR1   27
#define SPR_CSRR0  58
#define SPR_DEAR   61
#define SPR_ESR    62
#define SPR_IVPR   63
#define SPR_IVOR0  400
#define SPR_IVOR32 528
#define SPR_MCSRR0 570
#define SPR_MAS0   624
#define SPR_MAS1   625
#define SPR_MAS2   626
#define SPR_MAS3   627
#define SPR_MAS7   944

/* TLB1 entry 1: CCSR at 0xE0000000, 1 MiB, cache-inhibited and guarded,
 * supervisor read/write, protected from invalidation. */
#define CCSR_MAS0  0x10010000  /* TLBSEL = 1, ESEL = 1 */
#define CCSR_MAS1  0xC0000500  /* V, IPROT, TSIZE = 5 (4^5 KiB = 1 MiB) */
#define CCSR_MAS2  0xE000000A  /* EPN, I, G */
#define CCSR_MAS3  0xE0000005  /* RPN, SW, SR */

  .section .text.start, "ax"
  .globl _start
_start:
  lis   3, CCSR_MAS0@h
  ori   3, 3, CCSR_MAS0@l
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

  /* Interrupt vectors: IVPR holds the upper 16 address bits of the
   * vector stubs, each IVORn the lower 16 bits of stub n. */
  lis   3, ivor_stubs@h
  mtspr SPR_IVPR, 3
  .irp n, 0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15
  li    3, ivor_stub_\n@l
  mtspr SPR_IVOR0 + \n, 3
  .endr
  .irp n, 32,33,34,35
  li    3, ivor_stub_\n@l
  mtspr SPR_IVOR32 + (\n - 32), 3
  .endr
  isync

  /* Stack: 16-byte aligned, terminated back chain. */
  lis   1, __stack_top@h
  ori   1, 1, __stack_top@l
  li    0, 0
  stwu  0, -16(1)
  /* Small-data anchors (see link.ld): unused by code built with
   * -msdata=none, needed by libraries built with a BSP's -msdata. */
  lis   13, _SDA_BASE_@ha
  addi  13, 13, _SDA_BASE_@l
  lis   2, _SDA2_BASE_@ha
  addi  2, 2, _SDA2_BASE_@l

  /* Clear .bss word by word (the linker script aligns both ends to 4). */
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
  bl    main
  bl    bsp_exit
3:
  b     3b

/* One 16-byte stub per interrupt: load its number and go to the common
 * reporter for its class (critical, machine check or base). */
  .section .text.vectors, "ax"
  .globl ivor_stubs
  .globl ivor_stubs_end
  .align 4
ivor_stubs:
  .macro stub n, class
  .align 4
ivor_stub_\n:
  li    3, \n
  b     exception_\class
  .endm
  stub 0, critical
  stub 1, machine_check
  stub 2, base
  stub 3, base
  stub 4, base
  stub 5, base
  stub 6, base
  stub 7, base
  stub 8, base
  stub 9, base
  stub 10, base
  stub 11, base
  stub 12, critical
  stub 13, base
  stub 14, base
  stub 15, critical
  stub 32, base
  stub 33, base
  stub 34, base
  stub 35, base
ivor_stubs_end:

/* r3 = interrupt number; r4 = address of the faulting instruction,
 * r5 = ESR, r6 = DEAR; then report on a stack of its own (the fault may
 * be a broken stack pointer). bsp_exception_report() does not return. */
exception_critical:
  mfspr 4, SPR_CSRR0
  b     exception_report
exception_machine_check:
  mfspr 4, SPR_MCSRR0
  b     exception_report
exception_base:
  mfspr 4, SPR_SRR0
exception_report:
  mfspr 5, SPR_ESR
  mfspr 6, SPR_DEAR
  lis   1, __exception_stack_top@h
  ori   1, 1, __exception_stack_top@l
  li    0, 0
  stwu  0, -16(1)
  bl    bsp_exception_report
4:
  b     4b

  .section .note.GNU-stack, "", @progbits
