# Cortex-M4F (ARMv7E-M with the single-precision FPU, hard-float ABI). The firmware itself uses no
# floating point (checked on every build, tests/build); only the test harness does. Tests run on
# QEMU's mps2-an386 (a Cortex-M4 with FPU at 25 MHz).
set(INCLINO_TARGET cortex-m4f)
set(INCLINO_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
set(INCLINO_QEMU_MACHINE mps2-an386)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi.cmake)
