# Cross-target support: QEMU test boards, firmware images, map files, size and stack reports.
# Included from cmake/inclino.cmake (directory scope of the top level). See docs/build.md.
#
#   inclino_link_qemu_board(exe)
#       turns a test executable into a QEMU program: the image startup of hal/rt, the board
#       hooks of boards/qemu (newlib + semihosting on Cortex-M, a tiny libc shim on rv32),
#       the board's linker script; map file and size report (<exe>.size.txt, not printed).
#   inclino_add_image(NAME n MEMORY fo fk ro rk st [SOURCES ..] [LIBS ..] [WHOLE_LIBS ..] [LINK_CHECK])
#       a freestanding firmware image: -nostdlib -lgcc, the board's memory (flash origin and KiB,
#       RAM origin and KiB, stack bytes; see boards/generic/CMakeLists.txt),
#       --gc-sections, map file; after the link the size report (<n>.size.txt) and the stack
#       report (<n>.stack.txt) are written next to the ELF and printed. WHOLE_LIBS are linked
#       --whole-archive. LINK_CHECK: generous memory and no --gc-sections (inclino_all). Each image
#       gets a CTest test image_<n> (cmake/scripts/check_image.py image). No-op on the host.
#       Options for a board with its own run-time (boards/s32k1): SECTIONS <file>: the section
#       script INCLUDEd instead of hal/rt's (absolute path); NO_RT_STARTUP: the board brings its
#       own vector table and Reset_Handler (inclino_rt_startup is not linked).
#   inclino_cross_finalize()
#       called once at the end of the top level: the link-check image inclino_all, with every
#       module of the global property INCLINO_FREESTANDING_MODULES linked whole.
include_guard(GLOBAL)

if(INCLINO_IS_HOST)
  function(inclino_link_qemu_board exe)
    message(FATAL_ERROR "inclino_link_qemu_board(${exe}): only for cross targets")
  endfunction()
  function(inclino_add_image)
  endfunction()
  function(inclino_cross_finalize)
  endfunction()
  return()
endif()

enable_language(ASM)
find_package(Python3 3.7 COMPONENTS Interpreter REQUIRED)

# Stack analysis: gcc writes <object>.su (frame size per function) and <object>.ci (call graph)
# next to every object of a freestanding module; cmake/scripts/stack_report.py reads them.
list(APPEND INCLINO_FREESTANDING_OPTIONS -fstack-usage -fcallgraph-info=su)

set(INCLINO_SCRIPTS_DIR ${INCLINO_ROOT}/cmake/scripts)
set(INCLINO_RT_DIR ${INCLINO_ROOT}/hal/rt)
set(INCLINO_BOARD_DIR ${INCLINO_ROOT}/boards/qemu)
if(INCLINO_IS_ARM)
  set(INCLINO_RT_LD_DIR ${INCLINO_RT_DIR}/arm)
  set(INCLINO_RT_SECTIONS cortex-m-sections.ld)
  set(INCLINO_QEMU_BOARD_LD ${INCLINO_BOARD_DIR}/${INCLINO_QEMU_MACHINE}.ld)
else()
  set(INCLINO_RT_LD_DIR ${INCLINO_RT_DIR}/riscv)
  set(INCLINO_RT_SECTIONS rv32-sections.ld)
  set(INCLINO_QEMU_BOARD_LD ${INCLINO_BOARD_DIR}/virt-rv32.ld)
endif()

# Where flash and RAM start on each architecture: the origin of the link-check image inclino_all
# (1 MiB / 256 KiB: it only proves that everything links). The boards give their images' memory.
if(INCLINO_IS_ARM)
  set(INCLINO_LINK_CHECK_MEMORY 0x00000000 1024 0x20000000 256 4096)
else()
  set(INCLINO_LINK_CHECK_MEMORY 0x20000000 1024 0x80000000 256 4096)
endif()

# The C library the cross-check compares against: every symbol libgcc defines, float helpers
# excepted, may be referenced by the firmware; anything else undefined is a libc dependency.
separate_arguments(_inclino_cpu_flags UNIX_COMMAND "${INCLINO_CPU_FLAGS}")
execute_process(COMMAND ${CMAKE_C_COMPILER} ${_inclino_cpu_flags} -print-libgcc-file-name
  OUTPUT_VARIABLE INCLINO_LIBGCC OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE _inclino_rc)
if(NOT _inclino_rc EQUAL 0 OR NOT EXISTS "${INCLINO_LIBGCC}")
  message(FATAL_ERROR "cannot locate libgcc for ${INCLINO_TARGET} (${INCLINO_LIBGCC})")
endif()

# libgcc last on every cross link line, after every library and their transitive dependencies
# (64-bit division, shifts, multiplies on the M0+...). The Cortex-M test boards get it from
# gcc's own link line as well; -nostdlib images and rv32 have only this.
set(CMAKE_C_STANDARD_LIBRARIES "-lgcc")

# Map file, ELF suffix, size report after the link. PRINT: also print the report to the build log.
function(_inclino_cross_postlink exe)
  cmake_parse_arguments(P "PRINT" "" "" ${ARGN})
  set_target_properties(${exe} PROPERTIES SUFFIX ".elf")
  set(dir $<TARGET_FILE_DIR:${exe}>)
  target_link_options(${exe} PRIVATE "LINKER:-Map=${dir}/${exe}.map" "LINKER:--cref")
  if(P_PRINT)
    set(print --print)
  else()
    set(print "")
  endif()
  add_custom_command(TARGET ${exe} POST_BUILD
    COMMAND ${Python3_EXECUTABLE} ${INCLINO_SCRIPTS_DIR}/size_report.py
      --map ${dir}/${exe}.map --elf $<TARGET_FILE:${exe}> --size ${INCLINO_SIZE}
      --readelf ${INCLINO_READELF} --target ${INCLINO_TARGET}
      --out ${dir}/${exe}.size.txt ${print}
    VERBATIM)
endfunction()

function(inclino_link_qemu_board exe)
  target_link_libraries(${exe} PRIVATE inclino_rt_startup inclino_qemu_board)
  if(INCLINO_IS_ARM)
    # newlib nano with semihosting (rdimon); the startup is ours (-nostartfiles), see rt.h.
    target_link_options(${exe} PRIVATE -specs=rdimon.specs -nostartfiles)
  else()
    # No C library on rv32: the board's shim (boards/qemu/rv32) and the mem* of rt.
    target_link_libraries(${exe} PRIVATE inclino_rt)
  endif()
  target_link_options(${exe} PRIVATE -T${INCLINO_QEMU_BOARD_LD} -L${INCLINO_RT_LD_DIR})
  set_property(TARGET ${exe} APPEND PROPERTY LINK_DEPENDS
    ${INCLINO_QEMU_BOARD_LD} ${INCLINO_RT_LD_DIR}/${INCLINO_RT_SECTIONS})
  _inclino_cross_postlink(${exe})
endfunction()

function(inclino_add_image)
  cmake_parse_arguments(I "LINK_CHECK;NO_RT_STARTUP" "NAME;SECTIONS;INDIRECT"
    "SOURCES;LIBS;WHOLE_LIBS;MEMORY" ${ARGN})
  if(NOT I_NAME)
    message(FATAL_ERROR "inclino_add_image: NAME is required")
  endif()
  set(img ${I_NAME})

  if(I_LINK_CHECK)
    set(mem ${INCLINO_LINK_CHECK_MEMORY})
  else()
    set(mem ${I_MEMORY})
  endif()
  list(LENGTH mem n)
  if(NOT n EQUAL 5)
    message(FATAL_ERROR "inclino_add_image(${img}): MEMORY takes five values (flash origin, "
      "flash KiB, RAM origin, RAM KiB, stack bytes), got '${mem}'")
  endif()
  list(GET mem 0 FLASH_ORIGIN)
  list(GET mem 1 FLASH_KIB)
  list(GET mem 2 RAM_ORIGIN)
  list(GET mem 3 RAM_KIB)
  list(GET mem 4 STACK_SIZE)
  if(I_SECTIONS)
    set(SECTIONS ${I_SECTIONS})
  else()
    set(SECTIONS ${INCLINO_RT_SECTIONS})
  endif()
  set(IMAGE ${img})
  set(ld ${CMAKE_CURRENT_BINARY_DIR}/${img}.ld)
  file(CONFIGURE OUTPUT ${ld} @ONLY CONTENT [=[
/* @IMAGE@.ld - generated by cmake/inclino_cross.cmake for @INCLINO_TARGET@; do not edit. */
MEMORY
{
    FLASH (rx)  : ORIGIN = @FLASH_ORIGIN@, LENGTH = @FLASH_KIB@K
    RAM   (rwx) : ORIGIN = @RAM_ORIGIN@, LENGTH = @RAM_KIB@K
}
__stack_size = @STACK_SIZE@;
INCLUDE @SECTIONS@
]=])

  add_executable(${img} ${I_SOURCES})
  if(NOT I_NO_RT_STARTUP)
    target_link_libraries(${img} PRIVATE inclino_rt_startup)
  endif()
  if(I_WHOLE_LIBS)
    # The archives by path between --whole-archive/--no-whole-archive: every object of every
    # module is linked. ($<LINK_LIBRARY:WHOLE_ARCHIVE> refuses a library that also comes in
    # through another module's dependencies, which is the normal case here.)
    set(whole "-Wl,--whole-archive")
    foreach(lib IN LISTS I_WHOLE_LIBS)
      list(APPEND whole $<TARGET_FILE:${lib}>)
    endforeach()
    list(APPEND whole "-Wl,--no-whole-archive")
    target_link_libraries(${img} PRIVATE ${whole})
    add_dependencies(${img} ${I_WHOLE_LIBS})
  endif()
  target_link_libraries(${img} PRIVATE ${I_LIBS} inclino_rt)
  target_compile_options(${img} PRIVATE ${INCLINO_FREESTANDING_OPTIONS})
  target_compile_definitions(${img} PRIVATE INCLINO_FREESTANDING=1)
  target_link_options(${img} PRIVATE -nostdlib -T${ld} -L${INCLINO_RT_LD_DIR}
    "LINKER:--print-memory-usage")
  if(I_LINK_CHECK)
    target_link_options(${img} PRIVATE "LINKER:--no-gc-sections")
  endif()
  if(I_SECTIONS)
    set_property(TARGET ${img} APPEND PROPERTY LINK_DEPENDS ${ld} ${I_SECTIONS})
  else()
    set_property(TARGET ${img} APPEND PROPERTY LINK_DEPENDS ${ld}
      ${INCLINO_RT_LD_DIR}/${INCLINO_RT_SECTIONS})
  endif()
  _inclino_cross_postlink(${img} PRINT)

  set(dir $<TARGET_FILE_DIR:${img}>)
  set(indirect_args "")
  if(I_INDIRECT)
    set(indirect_args --indirect ${I_INDIRECT})
    set_property(TARGET ${img} APPEND PROPERTY LINK_DEPENDS ${I_INDIRECT})
  endif()
  add_custom_command(TARGET ${img} POST_BUILD
    COMMAND ${Python3_EXECUTABLE} ${INCLINO_SCRIPTS_DIR}/stack_report.py
      --map ${dir}/${img}.map --elf $<TARGET_FILE:${img}> --nm ${INCLINO_NM}
      --target ${INCLINO_TARGET} --out ${dir}/${img}.stack.txt --print ${indirect_args}
    WORKING_DIRECTORY ${dir}
    VERBATIM)
  if(I_INDIRECT)
    # The worst case with the calls through function pointers must fit the reserved stack.
    add_test(NAME image_stack_${img}
      COMMAND ${Python3_EXECUTABLE} ${INCLINO_SCRIPTS_DIR}/stack_report.py
        --map ${dir}/${img}.map --elf $<TARGET_FILE:${img}> --nm ${INCLINO_NM}
        --target ${INCLINO_TARGET} --out ${CMAKE_CURRENT_BINARY_DIR}/${img}.stack-check.txt
        --indirect ${I_INDIRECT} --limit ${STACK_SIZE})
    set_tests_properties(image_stack_${img} PROPERTIES LABELS "${INCLINO_TARGET};build"
      TIMEOUT 60)
  endif()

  add_test(NAME image_${img}
    COMMAND ${Python3_EXECUTABLE} ${INCLINO_SCRIPTS_DIR}/check_image.py image
      --elf $<TARGET_FILE:${img}> --map ${dir}/${img}.map --target ${INCLINO_TARGET}
      --nm ${INCLINO_NM} --readelf ${INCLINO_READELF} --size ${INCLINO_SIZE})
  set_tests_properties(image_${img} PROPERTIES LABELS "${INCLINO_TARGET};build" TIMEOUT 60)
endfunction()

function(inclino_cross_finalize)
  get_property(modules GLOBAL PROPERTY INCLINO_FREESTANDING_MODULES)
  inclino_add_image(NAME inclino_all LINK_CHECK
    SOURCES ${INCLINO_RT_DIR}/link_check_main.c
    WHOLE_LIBS ${modules})
endfunction()
