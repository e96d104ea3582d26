# Cortex-M0+ (ARMv6-M, Thumb-1 + a few Thumb-2 instructions, no divide, no FPU, no DWT cycle
# counter). QEMU 7.2 has no Cortex-M0+ model; the M3 of mps2-an385 runs ARMv6-M code unchanged.
set(INCLINO_TARGET cortex-m0plus)
set(INCLINO_CPU_FLAGS "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(INCLINO_QEMU_MACHINE mps2-an385)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
