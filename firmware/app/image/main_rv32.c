/*
 * main_rv32.c - main() of the EPB image on rv32imac.
 *
 * There is no RISC-V HAL port yet, so the application cannot start: this image proves that the
 * modules it needs compile and link for RISC-V and gives the size figures. With a port, this
 * becomes the twin of main_cortex_m.c.
 */
int main(void)
{
    for (;;) {
        __asm volatile("wfi");
    }
}
