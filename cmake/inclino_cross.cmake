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

# Link-time optimisation of the board images (inclino_add_image ... LTO; boards/s32k1). The modules
# stay compiled as they are (machine code, with their .su/.ci for the stack reports), and every
# other link (QEMU tests, inclino_all, images without LTO) uses them. An LTO image links copies
# instead: inclino_cross_finalize gives each freestanding module it needs a twin <module>_lto,
# the same sources, include directories, definitions and options, compiled -flto. The run-time
# ABI and C-library entry points gcc emits calls to after LTO (hal/rt mem.c, the M0+'s
# __aeabi_*divmod of base/fx) must stay real symbols: their sources are listed in the global
# property INCLINO_NO_LTO_SOURCES and the twins compile them -fno-lto.
if(INCLINO_IS_ARM)
  set(_inclino_lto_default ON)
else()
  set(_inclino_lto_default OFF)
endif()
option(INCLINO_IMAGE_LTO "Link the board images with link-time optimisation (Arm cross targets)"
  ${_inclino_lto_default})
set_property(GLOBAL PROPERTY INCLINO_NO_LTO_SOURCES "")
set_property(GLOBAL PROPERTY INCLINO_LTO_IMAGES "")

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
  cmake_parse_arguments(I "LINK_CHECK;NO_RT_STARTUP;LTO" "NAME;SECTIONS;INDIRECT"
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
  set(lto_args "")
  if(I_LTO AND INCLINO_IMAGE_LTO)
    # One link-time unit (-flto-partition=one), compiled with the options of the freestanding
    # code (warnings as errors included: LTO warns at link time too) and its stack analysis:
    # -dumpdir puts that unit's .su/.ci (and nothing else) at <dir>/<img>.lto.ltrans0.ltrans.*,
    # which the stack report reads (--lto).
    # The image's own sources as link-time code too; its libraries become the modules' twins
    # in inclino_cross_finalize.
    # (fat: the size report reads their symbols)
    target_compile_options(${img} PRIVATE -flto -ffat-lto-objects)
    set_property(GLOBAL APPEND PROPERTY INCLINO_LTO_IMAGES ${img})
    target_link_options(${img} PRIVATE -flto -flto-partition=one ${INCLINO_WARNING_OPTIONS}
      ${INCLINO_FREESTANDING_OPTIONS} -dumpdir $<TARGET_FILE_DIR:${img}>/${img}.lto.)
    set(lto_args --lto $<TARGET_FILE_DIR:${img}>/${img}.lto.ltrans0.ltrans)
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
      ${lto_args}
    WORKING_DIRECTORY ${dir}
    VERBATIM)
  if(I_INDIRECT)
    # The worst case with the calls through function pointers must fit the reserved stack.
    add_test(NAME image_stack_${img}
      COMMAND ${Python3_EXECUTABLE} ${INCLINO_SCRIPTS_DIR}/stack_report.py
        --map ${dir}/${img}.map --elf $<TARGET_FILE:${img}> --nm ${INCLINO_NM}
        --target ${INCLINO_TARGET} --out ${CMAKE_CURRENT_BINARY_DIR}/${img}.stack-check.txt
        --indirect ${I_INDIRECT} --limit ${STACK_SIZE} ${lto_args})
    set_tests_properties(image_stack_${img} PROPERTIES LABELS "${INCLINO_TARGET};build"
      TIMEOUT 60)
  endif()

  add_test(NAME image_${img}
    COMMAND ${Python3_EXECUTABLE} ${INCLINO_SCRIPTS_DIR}/check_image.py image
      --elf $<TARGET_FILE:${img}> --map ${dir}/${img}.map --target ${INCLINO_TARGET}
      --nm ${INCLINO_NM} --readelf ${INCLINO_READELF} --size ${INCLINO_SIZE})
  set_tests_properties(image_${img} PROPERTIES LABELS "${INCLINO_TARGET};build" TIMEOUT 60)
endfunction()

# The link closure of target t (LINK_LIBRARIES / INTERFACE_LINK_LIBRARIES, depth first), targets
# only, each once: into the variable named by out.
function(_inclino_link_closure t out)
  set(seen ${${out}})
  set(stack ${t})
  while(stack)
    list(POP_FRONT stack cur)
    foreach(prop LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
      get_target_property(libs ${cur} ${prop})
      if(NOT libs)
        continue()
      endif()
      foreach(l IN LISTS libs)
        if(TARGET ${l} AND NOT l IN_LIST seen)
          list(APPEND seen ${l})
          list(APPEND stack ${l})
        endif()
      endforeach()
    endforeach()
  endwhile()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

# The -flto twin of freestanding module m (see INCLINO_IMAGE_LTO above), made once. Include
# directories are those of every module in `incs` (the image's closure): the twins link nothing
# themselves, the image links all of them in one group.
function(_inclino_lto_twin m incs)
  if(TARGET ${m}_lto)
    return()
  endif()
  get_target_property(src_dir ${m} SOURCE_DIR)
  get_target_property(srcs ${m} SOURCES)
  set(abs "")
  foreach(f IN LISTS srcs)
    if(IS_ABSOLUTE ${f})
      list(APPEND abs ${f})
    else()
      list(APPEND abs ${src_dir}/${f})
    endif()
  endforeach()
  add_library(${m}_lto STATIC EXCLUDE_FROM_ALL ${abs})
  target_include_directories(${m}_lto PRIVATE $<TARGET_PROPERTY:${m},INCLUDE_DIRECTORIES>)
  foreach(i IN LISTS incs)
    target_include_directories(${m}_lto PRIVATE $<TARGET_PROPERTY:${i},INTERFACE_INCLUDE_DIRECTORIES>)
  endforeach()
  target_compile_definitions(${m}_lto PRIVATE $<TARGET_PROPERTY:${m},COMPILE_DEFINITIONS>)
  target_compile_options(${m}_lto PRIVATE $<TARGET_PROPERTY:${m},COMPILE_OPTIONS> -flto)
endfunction()

function(_inclino_lto_finalize)
  get_property(images GLOBAL PROPERTY INCLINO_LTO_IMAGES)
  get_property(modules GLOBAL PROPERTY INCLINO_FREESTANDING_MODULES)
  get_property(no_lto GLOBAL PROPERTY INCLINO_NO_LTO_SOURCES)
  if(no_lto)
    set_source_files_properties(${no_lto} PROPERTIES COMPILE_OPTIONS -fno-lto)
  endif()
  foreach(img IN LISTS images)
    set(closure "")
    _inclino_link_closure(${img} closure)
    get_target_property(direct ${img} LINK_LIBRARIES)
    set(twins "")
    set(others "")
    foreach(l IN LISTS closure)
      get_target_property(type ${l} TYPE)
      if(l IN_LIST modules)
        _inclino_lto_twin(${l} "${closure}")
        list(APPEND twins ${l}_lto)
      elseif(NOT type STREQUAL "INTERFACE_LIBRARY")
        message(FATAL_ERROR "LTO image ${img}: ${l} is no freestanding module (no twin)")
      endif()
    endforeach()
    foreach(l IN LISTS direct)
      if(NOT TARGET ${l})
        list(APPEND others ${l}) # options and plain libraries (-lgcc, archives by path)
      endif()
    endforeach()
    foreach(i IN LISTS closure)
      target_include_directories(${img} PRIVATE
        $<TARGET_PROPERTY:${i},INTERFACE_INCLUDE_DIRECTORIES>)
    endforeach()
    set_property(TARGET ${img} PROPERTY LINK_LIBRARIES
      -Wl,--start-group ${twins} -Wl,--end-group ${others})
    # the modules themselves too: the size report reads their symbols (the twins hold IR only)
    foreach(l IN LISTS twins)
      string(REGEX REPLACE "_lto$" "" orig ${l})
      add_dependencies(${img} ${orig})
    endforeach()
  endforeach()
endfunction()

function(inclino_cross_finalize)
  if(INCLINO_IMAGE_LTO)
    _inclino_lto_finalize()
  endif()
  get_property(modules GLOBAL PROPERTY INCLINO_FREESTANDING_MODULES)
  inclino_add_image(NAME inclino_all LINK_CHECK
    SOURCES ${INCLINO_RT_DIR}/link_check_main.c
    WHOLE_LIBS ${modules})
endfunction()
