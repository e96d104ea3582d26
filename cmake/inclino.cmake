# Build conventions shared by every module. Included once from the top-level CMakeLists.txt.
#
# Targets (INCLINO_TARGET, set by the toolchain file; "host" when there is none):
#   host           native gcc; every test, host tools, sanitizers (INCLINO_SANITIZE=ON)
#   cortex-m0plus  arm-none-eabi; firmware/driver/HAL tests under qemu-system-arm
#   cortex-m3      idem
#   cortex-m4f     idem (hard float ABI; the firmware itself uses no floating point)
#   rv32imac       riscv64-unknown-elf, freestanding; every firmware module compiled and linked
#
# Module kinds:
#   inclino_add_module(NAME n LAYER l SOURCES .. [INCLUDE dirs] [DEPS targets] [FREESTANDING]
#                      [HOST_ONLY])
#       static library inclino_<n>. LAYER is the module's layer, which must be its folder's
#       (cmake/inclino_layers.cmake); a module may depend only on its own layer or lower ones.
#       FREESTANDING modules (base/, hal/, drivers/, firmware/) are C11 with no libc, no heap and
#       no floating point; they are built for every target. Others (sim/, tools/lib, test
#       fixtures) are hosted C and are built where tests run (host and Cortex-M).
#   inclino_add_test(NAME n SOURCES .. [LIBS ..] [HOST_ONLY] [WILL_FAIL] [EXPECT_STATUS n] [RV32]
#                    [TIMEOUT s] [LABELS ..])
#       a test executable; on Cortex-M it runs under QEMU through CMAKE_CROSSCOMPILING_EMULATOR.
#       EXPECT_STATUS n: the test passes only when the program exits with exactly status n (on
#       rv32 QEMU reports every failure as 1). RV32: the test also runs on rv32imac under
#       qemu-system-riscv32; only for tests that need nothing beyond unit.h, the freestanding
#       headers, <string.h> mem*/str* basics and printf (boards/qemu/rv32/include).
#   inclino_add_host_tool(NAME n SOURCES .. [LIBS ..])  host-only program (C or C++).
#   inclino_add_image(NAME n SOURCES .. [LIBS ..])      cross firmware image with map + size report.

include_guard(GLOBAL)

if(NOT DEFINED INCLINO_TARGET)
  set(INCLINO_TARGET host)
endif()
set(INCLINO_IS_HOST OFF)
set(INCLINO_IS_ARM OFF)
set(INCLINO_IS_RISCV OFF)
if(INCLINO_TARGET STREQUAL "host")
  set(INCLINO_IS_HOST ON)
elseif(INCLINO_TARGET MATCHES "^cortex-m")
  set(INCLINO_IS_ARM ON)
elseif(INCLINO_TARGET STREQUAL "rv32imac")
  set(INCLINO_IS_RISCV ON)
else()
  message(FATAL_ERROR "Unknown INCLINO_TARGET '${INCLINO_TARGET}'")
endif()

# Hosted code (sim/, tests) is built where tests run: on the host natively and on Cortex-M under
# QEMU with newlib. The RISC-V toolchain has no libc, so there only freestanding code is built.
if(INCLINO_IS_HOST OR INCLINO_IS_ARM)
  set(INCLINO_HOSTED ON)
else()
  set(INCLINO_HOSTED OFF)
endif()

option(INCLINO_SANITIZE "Build the host with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(INCLINO_SANITIZE AND NOT INCLINO_IS_HOST)
  message(FATAL_ERROR "INCLINO_SANITIZE is only for the host target")
endif()

if(INCLINO_IS_HOST)
  enable_language(CXX)
  set(CMAKE_CXX_STANDARD 17)
  set(CMAKE_CXX_STANDARD_REQUIRED ON)
  set(CMAKE_CXX_EXTENSIONS OFF)
endif()

set(CMAKE_C_STANDARD 11)
set(CMAKE_C_STANDARD_REQUIRED ON)
set(CMAKE_C_EXTENSIONS OFF)
set(CMAKE_EXPORT_COMPILE_COMMANDS ON)

# -Wall -Wextra -Werror on every build, host and cross.
# INCLINO_WARNING_OPTIONS: the ones that also apply when code is generated at link time (LTO).
set(INCLINO_WARNING_OPTIONS -Wall -Wextra -Werror -Wshadow -Wvla -Wformat=2 -Wundef)
add_compile_options(${INCLINO_WARNING_OPTIONS}
  $<$<COMPILE_LANGUAGE:C>:-Wstrict-prototypes>
  $<$<COMPILE_LANGUAGE:C>:-Wmissing-prototypes>)

if(INCLINO_SANITIZE)
  add_compile_definitions(INCLINO_SANITIZE_BUILD=1) # tests/support/unit.h: UNIT_SANITIZED
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

# Tests run on every target: natively on the host, under QEMU on the cross targets (rv32: only
# the tests marked RV32, since it has no C library; see docs/build.md).
enable_testing()
if(NOT INCLINO_IS_HOST AND NOT CMAKE_CROSSCOMPILING_EMULATOR)
  message(FATAL_ERROR "The ${INCLINO_TARGET} toolchain file sets no CMAKE_CROSSCOMPILING_EMULATOR")
endif()

set(INCLINO_ROOT "${CMAKE_CURRENT_LIST_DIR}/..")
cmake_path(NORMAL_PATH INCLINO_ROOT)

# Compile options for freestanding code (firmware/, drivers/, hal/).
#  -ffreestanding: only <stdint.h>, <stdbool.h>, <stddef.h>, <limits.h>.
#  -fno-tree-loop-distribute-patterns: stops gcc turning loops into memcpy/memset calls.
#  -Wdouble-promotion -Wfloat-equal: a float that slips in is at least loud; the cross checks
#  (tests/build) prove no soft-float helper is linked.
set(INCLINO_FREESTANDING_OPTIONS -ffreestanding $<$<C_COMPILER_ID:GNU>:-fno-tree-loop-distribute-patterns>
  -Wdouble-promotion -Wfloat-equal -Wcast-align -Wpointer-arith)
# On Arm, -mgeneral-regs-only keeps gcc from using the FPU's registers at all: with the M4F's
# hard-float ABI it otherwise moves 64-bit data (int64 covariances, struct copies) through
# d-registers, which the no-float check rightly flags, and any float that slips into firmware
# becomes a compile error.
if(INCLINO_IS_ARM)
  list(APPEND INCLINO_FREESTANDING_OPTIONS -mgeneral-regs-only)
endif()

function(inclino_add_subdirectories)
  file(GLOB children LIST_DIRECTORIES true CONFIGURE_DEPENDS RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}"
       "${CMAKE_CURRENT_SOURCE_DIR}/*")
  list(SORT children)
  foreach(child IN LISTS children)
    if(IS_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/${child}"
       AND EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${child}/CMakeLists.txt")
      add_subdirectory(${child})
    endif()
  endforeach()
endfunction()

# All freestanding modules, collected so that the per-target images link every one of them.
set_property(GLOBAL PROPERTY INCLINO_FREESTANDING_MODULES "")

function(inclino_add_module)
  cmake_parse_arguments(M "FREESTANDING;HOST_ONLY" "NAME;LAYER" "SOURCES;INCLUDE;DEPS;PRIVATE_DEPS" ${ARGN})
  if(NOT M_NAME)
    message(FATAL_ERROR "inclino_add_module: NAME is required")
  endif()
  _inclino_check_module_layer(${M_NAME} "${M_LAYER}")
  if(M_HOST_ONLY AND NOT INCLINO_IS_HOST)
    return()
  endif()
  if(NOT M_FREESTANDING AND NOT INCLINO_HOSTED)
    return()
  endif()
  set(tgt inclino_${M_NAME})
  set_property(GLOBAL APPEND PROPERTY INCLINO_MODULES ${tgt})
  set_property(GLOBAL PROPERTY INCLINO_LAYER_OF_${tgt} ${M_LAYER})
  if(M_SOURCES)
    add_library(${tgt} STATIC ${M_SOURCES})
    set(scope PUBLIC)
  else()
    add_library(${tgt} INTERFACE)
    set(scope INTERFACE)
  endif()
  if(M_INCLUDE)
    target_include_directories(${tgt} ${scope} ${M_INCLUDE})
  endif()
  if(M_DEPS)
    target_link_libraries(${tgt} ${scope} ${M_DEPS})
  endif()
  if(M_PRIVATE_DEPS)
    target_link_libraries(${tgt} PRIVATE ${M_PRIVATE_DEPS})
  endif()
  if(M_FREESTANDING AND M_SOURCES)
    target_compile_options(${tgt} PRIVATE ${INCLINO_FREESTANDING_OPTIONS})
    target_compile_definitions(${tgt} PRIVATE INCLINO_FREESTANDING=1)
    set_property(GLOBAL APPEND PROPERTY INCLINO_FREESTANDING_MODULES ${tgt})
  endif()
endfunction()

function(inclino_add_test)
  cmake_parse_arguments(T "HOST_ONLY;WILL_FAIL;RV32" "NAME;TIMEOUT;EXPECT_STATUS"
    "SOURCES;LIBS;LABELS;ARGS" ${ARGN})
  if(NOT T_NAME)
    message(FATAL_ERROR "inclino_add_test: NAME is required")
  endif()
  if(T_HOST_ONLY AND NOT INCLINO_IS_HOST)
    return()
  endif()
  if(INCLINO_IS_RISCV AND NOT T_RV32)
    return()
  endif()
  set(exe test_${T_NAME})
  add_executable(${exe} ${T_SOURCES})
  target_link_libraries(${exe} PRIVATE inclino_unit ${T_LIBS})
  if(NOT INCLINO_IS_HOST)
    inclino_link_qemu_board(${exe})
  endif()
  if(DEFINED T_EXPECT_STATUS)
    # CTest cannot expect one particular status; a small script runs the program (under the
    # emulator on cross targets) and compares.
    add_test(NAME ${T_NAME} COMMAND ${CMAKE_COMMAND} -DEXPECT_STATUS=${T_EXPECT_STATUS}
      -P ${INCLINO_ROOT}/cmake/scripts/expect_status.cmake
      ${CMAKE_CROSSCOMPILING_EMULATOR} $<TARGET_FILE:${exe}> ${T_ARGS})
  else()
    add_test(NAME ${T_NAME} COMMAND ${exe} ${T_ARGS})
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  set_tests_properties(${T_NAME} PROPERTIES TIMEOUT ${T_TIMEOUT})
  if(T_WILL_FAIL)
    set_tests_properties(${T_NAME} PROPERTIES WILL_FAIL TRUE)
  endif()
  set(labels ${INCLINO_TARGET} ${T_LABELS})
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${labels}")
endfunction()

function(inclino_add_host_tool)
  cmake_parse_arguments(H "" "NAME" "SOURCES;LIBS" ${ARGN})
  if(NOT INCLINO_IS_HOST)
    return()
  endif()
  add_executable(${H_NAME} ${H_SOURCES})
  target_link_libraries(${H_NAME} PRIVATE ${H_LIBS})
endfunction()

include(inclino_layers)

# libFuzzer targets (INCLINO_FUZZ, the `fuzz` preset) and their corpus replays in the other host
# builds: inclino_add_fuzzer(); docs/fuzzing.md.
include(inclino_fuzz)

# Cross-target helpers (board support, images, size report) live in their own file.
include(inclino_cross)

# Test data kept outside the repository (BROAD trials): INCLINO_BROAD_DIR and
# inclino_require_broad(); see docs/data.md.
include(inclino_data)

function(inclino_finalize)
  inclino_check_layers()
  if(NOT INCLINO_IS_HOST)
    inclino_cross_finalize()
  endif()
endfunction()
