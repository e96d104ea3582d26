# RISC-V rv32imac (RV32I + multiply/divide + atomics + compressed, no FPU), ILP32 ABI.
#
# Debian's riscv64-unknown-elf-gcc carries the rv32imac/ilp32 multilib of libgcc but no C
# library, so everything here is freestanding: -ffreestanding everywhere, images link with
# -nostdlib -lgcc. The firmware modules are compiled and linked into the images of
# cmake/inclino_cross.cmake; the few board tests that need no C library (tests/board) run under
# qemu-system-riscv32 (machine virt, semihosting), so the rv32 preset also proves that a failure
# reaches CTest and that its crt0 initialises .data and .bss.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(INCLINO_TARGET rv32imac)

set(INCLINO_CROSS_PREFIX riscv64-unknown-elf-)
find_program(INCLINO_CC NAMES ${INCLINO_CROSS_PREFIX}gcc)
if(NOT INCLINO_CC)
  message(FATAL_ERROR "${INCLINO_CROSS_PREFIX}gcc not found. Install the RISC-V toolchain: "
    "cmake/scripts/install-deps.sh (Debian package gcc-riscv64-unknown-elf).")
endif()
set(CMAKE_C_COMPILER ${INCLINO_CC})
set(CMAKE_ASM_COMPILER ${INCLINO_CC})
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(INCLINO_CPU_FLAGS "-march=rv32imac -mabi=ilp32 -mcmodel=medlow")
set(CMAKE_C_FLAGS_INIT "${INCLINO_CPU_FLAGS} -ffreestanding -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${INCLINO_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${INCLINO_CPU_FLAGS} -nostdlib -Wl,--gc-sections")
set(CMAKE_C_FLAGS_MINSIZEREL_INIT "-Os -DNDEBUG")

foreach(tool objdump nm size readelf)
  string(TOUPPER ${tool} var)
  find_program(INCLINO_${var} NAMES ${INCLINO_CROSS_PREFIX}${tool})
  if(NOT INCLINO_${var})
    message(FATAL_ERROR "${INCLINO_CROSS_PREFIX}${tool} not found (package "
      "binutils-riscv64-unknown-elf, pulled in by gcc-riscv64-unknown-elf).")
  endif()
endforeach()

# The board tests run under QEMU; a missing QEMU fails the configure, it never skips them.
find_program(INCLINO_QEMU_RISCV32 NAMES qemu-system-riscv32)
if(NOT INCLINO_QEMU_RISCV32)
  message(FATAL_ERROR "qemu-system-riscv32 not found: the rv32imac preset runs its board tests "
    "under QEMU and does not skip them. Install it with cmake/scripts/install-deps.sh "
    "(Debian package qemu-system-misc).")
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR ${INCLINO_QEMU_RISCV32} -M virt -bios none
  -display none -monitor none -serial none
  -semihosting-config enable=on,target=native -kernel)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
