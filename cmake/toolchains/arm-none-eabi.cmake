# Shared part of the Cortex-M toolchain files (cortex-m0plus.cmake, cortex-m3.cmake,
# cortex-m4f.cmake). The including file sets, before include():
#   INCLINO_TARGET        cortex-m0plus | cortex-m3 | cortex-m4f
#   INCLINO_CPU_FLAGS     -mcpu=... -mthumb [-mfpu=... -mfloat-abi=...]
#   INCLINO_QEMU_MACHINE  the qemu-system-arm machine the tests run on (mps2-an385 | mps2-an386)
#
# Every cross link writes a map file and a size report (cmake/inclino_cross.cmake). Test
# executables run under qemu-system-arm through CMAKE_CROSSCOMPILING_EMULATOR; QEMU is required:
# configure fails without it, it never silently skips the tests.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(INCLINO_CROSS_PREFIX arm-none-eabi-)
find_program(INCLINO_CC NAMES ${INCLINO_CROSS_PREFIX}gcc)
if(NOT INCLINO_CC)
  message(FATAL_ERROR "${INCLINO_CROSS_PREFIX}gcc not found. Install the Cortex-M toolchain: "
    "cmake/scripts/install-deps.sh (Debian packages gcc-arm-none-eabi libnewlib-arm-none-eabi).")
endif()
set(CMAKE_C_COMPILER ${INCLINO_CC})
set(CMAKE_ASM_COMPILER ${INCLINO_CC})

# The compiler checks only compile: a link needs a linker script and a startup, which the
# project provides per image.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# -ffunction-sections -fdata-sections + --gc-sections: every function and object in its own
# section, so the linker drops what the image does not reach. The link-check image inclino_all
# turns garbage collection off again (it must link every module whole).
set(CMAKE_C_FLAGS_INIT "${INCLINO_CPU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${INCLINO_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${INCLINO_CPU_FLAGS} -Wl,--gc-sections")
set(CMAKE_C_FLAGS_MINSIZEREL_INIT "-Os -DNDEBUG")

# The binutils the size report and the image checks use.
foreach(tool objdump nm size readelf)
  string(TOUPPER ${tool} var)
  find_program(INCLINO_${var} NAMES ${INCLINO_CROSS_PREFIX}${tool})
  if(NOT INCLINO_${var})
    message(FATAL_ERROR "${INCLINO_CROSS_PREFIX}${tool} not found (package binutils-arm-none-eabi, "
      "pulled in by gcc-arm-none-eabi).")
  endif()
endforeach()

# The tests run under QEMU with semihosting: the test's exit status becomes QEMU's. No display,
# no monitor, no serial port; never -nographic, which reads stdin. CTest appends the ELF path.
find_program(INCLINO_QEMU_ARM NAMES qemu-system-arm)
if(NOT INCLINO_QEMU_ARM)
  message(FATAL_ERROR "qemu-system-arm not found: the ${INCLINO_TARGET} preset runs its tests "
    "under QEMU and does not skip them. Install it with cmake/scripts/install-deps.sh "
    "(Debian package qemu-system-arm).")
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR ${INCLINO_QEMU_ARM} -M ${INCLINO_QEMU_MACHINE}
  -display none -monitor none -serial none
  -semihosting-config enable=on,target=native -kernel)

# Only the cross tools come from the toolchain; headers and libraries from the host never do.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
