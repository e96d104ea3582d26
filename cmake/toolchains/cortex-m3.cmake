# Cortex-M3 (ARMv7-M, no FPU). Tests run on QEMU's mps2-an385 (a Cortex-M3 at 25 MHz).
set(INCLINO_TARGET cortex-m3)
set(INCLINO_CPU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
set(INCLINO_QEMU_MACHINE mps2-an385)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
