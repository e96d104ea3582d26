/*
 * crt0.S - reset and trap entry for rv32 (machine mode, no C library); see rt.h.
 *
 * _start: set gp (for linker relaxation of small data) and sp, point mtvec at rt_trap_entry
 * (direct mode), copy .data from flash, zero .bss, then rt_init_hook(), main(),
 * rt_exit_hook(main's result).
 *
 * rt_trap_entry: interrupts (mcause bit 31 set) go to rt_irq_handler(mcause) with the
 * caller-saved registers preserved and return with mret; a HAL or platform port defines
 * rt_irq_handler. Exceptions (illegal instruction, access fault, misaligned access, ecall,
 * ebreak outside semihosting) are faults: the stack is reset and rt_fault(mcause, old sp) is
 * called, which does not return.
 */
    /* gcc 12 targets ISA spec 20191213, where the CSR instructions are the separate Zicsr
     * extension; -march stays rv32imac (the multilib), so enable Zicsr here only. */
    .option arch, +zicsr

    .section .text.init, "ax", @progbits
    .globl  _start
    .type   _start, @function
_start:
    .option push
    .option norelax
    la      gp, __global_pointer$
    .option pop
    la      sp, __stack_top__
    la      t0, rt_trap_entry
    csrw    mtvec, t0

    /* .data: word copy from its load address in flash. */
    la      a0, __data_load__
    la      a1, __data_start__
    la      a2, __data_end__
1:  bgeu    a1, a2, 2f
    lw      t0, 0(a0)
    sw      t0, 0(a1)
    addi    a0, a0, 4
    addi    a1, a1, 4
    j       1b
2:  la      a0, __bss_start__
    la      a1, __bss_end__
3:  bgeu    a0, a1, 4f
    sw      zero, 0(a0)
    addi    a0, a0, 4
    j       3b
4:  call    rt_init_hook
    call    main
    call    rt_exit_hook
5:  wfi
    j       5b
    .size   _start, . - _start

    .section .text.rt_trap_entry, "ax", @progbits
    .globl  rt_trap_entry
    .type   rt_trap_entry, @function
    .balign 4
rt_trap_entry:
    /* Exceptions first: they must not use the (possibly overflowed) stack. */
    csrw    mscratch, t0
    csrr    t0, mcause
    bltz    t0, 6f
    csrr    a0, mcause
    mv      a1, sp
    la      sp, __stack_top__
    call    rt_fault
    j       .
6:  csrr    t0, mscratch
    addi    sp, sp, -64
    sw      ra, 0(sp)
    sw      t0, 4(sp)
    sw      t1, 8(sp)
    sw      t2, 12(sp)
    sw      a0, 16(sp)
    sw      a1, 20(sp)
    sw      a2, 24(sp)
    sw      a3, 28(sp)
    sw      a4, 32(sp)
    sw      a5, 36(sp)
    sw      a6, 40(sp)
    sw      a7, 44(sp)
    sw      t3, 48(sp)
    sw      t4, 52(sp)
    sw      t5, 56(sp)
    sw      t6, 60(sp)
    csrr    a0, mcause
    call    rt_irq_handler
    lw      ra, 0(sp)
    lw      t0, 4(sp)
    lw      t1, 8(sp)
    lw      t2, 12(sp)
    lw      a0, 16(sp)
    lw      a1, 20(sp)
    lw      a2, 24(sp)
    lw      a3, 28(sp)
    lw      a4, 32(sp)
    lw      a5, 36(sp)
    lw      a6, 40(sp)
    lw      a7, 44(sp)
    lw      t3, 48(sp)
    lw      t4, 52(sp)
    lw      t5, 56(sp)
    lw      t6, 60(sp)
    addi    sp, sp, 64
    mret
    .size   rt_trap_entry, . - rt_trap_entry
