/* SPDX-License-Identifier: BSD-2-Clause */
/*
 * QEMU virt (RV32, machine mode, -bios none): QEMU loads the ELF image
 * into RAM, .data included, and jumps to _start. Set the global and stack
 * pointers, the trap vector, clear .bss, run main() and end with its
 * status; a trap reports itself on its own stack and ends the run.
 */
	/* the CSR instructions are the Zicsr extension, which rv32imac
	 * leaves out in ISA specifications from 2019 on */
	.option arch, +zicsr
	.section .text.start, "ax"
	.globl _start
_start:
	.option push
	.option norelax
	la gp, __global_pointer$
	.option pop
	la sp, __stack_top
	la t0, trap_entry
	csrw mtvec, t0
	la t0, __bss_start
	la t1, __bss_end
1:	bgeu t0, t1, 2f
	sw zero, 0(t0)
	addi t0, t0, 4
	j 1b
2:	call main
	call bsp_exit
3:	j 3b

	/* mtvec direct mode: the handler's address is 4-byte aligned */
	.balign 4
trap_entry:
	la sp, __exception_stack_top
	csrr a0, mcause
	csrr a1, mepc
	csrr a2, mtval
	call bsp_exception_report
4:	j 4b
