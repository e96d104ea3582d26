# Coverage-guided fuzzing with libFuzzer (docs/fuzzing.md). Included by cmake/inclino.cmake.
#
#   INCLINO_FUZZ=ON (the `fuzz` configure preset: clang-14, RelWithDebInfo): everything is
#   compiled with coverage instrumentation and ASan + UBSan (-fno-sanitize-recover: any report
#   is a crash), and only the fuzzers and the libraries they link are built (the top-level
#   CMakeLists.txt adds the source folders EXCLUDE_FROM_ALL and tests/fuzz alone).
#
#   inclino_add_fuzzer(NAME x SOURCES lf_x.c [more.c] [LIBS libs...] [RUNS n] [MAX_LEN bytes]
#                      [DICT file])
#       The entry file defines int LLVMFuzzerTestOneInput(const uint8_t *, size_t) (its
#       prototype comes from tests/fuzz/lf.h, force-included). The corpus is
#       tests/fuzz/corpus/x/ (seeds + a minimised corpus, kept in the repository).
#       With INCLINO_FUZZ: the libFuzzer binary lf_x and the CTest `libfuzzer_x`, a bounded run
#       (-runs=RUNS, default INCLINO_FUZZ_RUNS, -seed=1, -max_len=MAX_LEN default 4096) over a
#       fresh scratch corpus plus the kept one; it fails on any crash, leak, timeout or sanitizer
#       report (tests/fuzz/run_libfuzzer.cmake).
#       In every other host build (gcc, and the host-sanitize preset's ASan + UBSan): lf_replay_x,
#       the same entry function over every file of the kept corpus (tests/fuzz/lf_replay.c), and
#       the CTest `fuzz_corpus_x`, so the corpus stays a regression test without clang.
include_guard(GLOBAL)

option(INCLINO_FUZZ "Build the libFuzzer targets only (clang; docs/fuzzing.md)" OFF)
set(INCLINO_FUZZ_RUNS 20000 CACHE STRING "libFuzzer executions per target in the CTest run")
set(INCLINO_FUZZ_DIR ${CMAKE_CURRENT_LIST_DIR}/../tests/fuzz)
cmake_path(NORMAL_PATH INCLINO_FUZZ_DIR)

if(INCLINO_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "INCLINO_FUZZ needs clang (the `fuzz` preset sets clang-14); got ${CMAKE_C_COMPILER_ID}")
  endif()
  if(INCLINO_SANITIZE)
    message(FATAL_ERROR "INCLINO_FUZZ already builds with ASan + UBSan; leave INCLINO_SANITIZE OFF")
  endif()
  add_compile_definitions(INCLINO_FUZZ_BUILD=1 INCLINO_SANITIZE_BUILD=1)
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

function(inclino_add_fuzzer)
  cmake_parse_arguments(F "" "NAME;RUNS;MAX_LEN;DICT" "SOURCES;LIBS" ${ARGN})
  if(NOT F_NAME OR NOT F_SOURCES)
    message(FATAL_ERROR "inclino_add_fuzzer: NAME and SOURCES are required")
  endif()
  if(NOT INCLINO_IS_HOST)
    return()
  endif()
  if(NOT F_RUNS)
    set(F_RUNS ${INCLINO_FUZZ_RUNS})
  endif()
  if(NOT F_MAX_LEN)
    set(F_MAX_LEN 4096)
  endif()
  set(corpus ${INCLINO_FUZZ_DIR}/corpus/${F_NAME})
  if(NOT IS_DIRECTORY ${corpus})
    message(FATAL_ERROR "inclino_add_fuzzer(${F_NAME}): no corpus directory ${corpus}")
  endif()
  if(INCLINO_FUZZ)
    set(exe lf_${F_NAME})
    add_executable(${exe} ${F_SOURCES})
    target_link_options(${exe} PRIVATE -fsanitize=fuzzer)
  else()
    set(exe lf_replay_${F_NAME})
    add_executable(${exe} ${F_SOURCES} ${INCLINO_FUZZ_DIR}/lf_replay.c)
  endif()
  target_compile_options(${exe} PRIVATE -include ${INCLINO_FUZZ_DIR}/lf.h)
  target_include_directories(${exe} PRIVATE ${INCLINO_FUZZ_DIR})
  target_compile_definitions(${exe} PRIVATE _POSIX_C_SOURCE=200809L)
  target_link_libraries(${exe} PRIVATE ${F_LIBS})
  if(INCLINO_FUZZ)
    set(extra "")
    if(F_DICT)
      set(extra -DDICT=${F_DICT})
    endif()
    add_test(NAME libfuzzer_${F_NAME}
      COMMAND ${CMAKE_COMMAND} -DFUZZER=$<TARGET_FILE:${exe}> -DCORPUS=${corpus}
              -DWORK=${CMAKE_CURRENT_BINARY_DIR}/lf_work/${F_NAME} -DRUNS=${F_RUNS}
              -DMAX_LEN=${F_MAX_LEN} ${extra} -P ${INCLINO_FUZZ_DIR}/run_libfuzzer.cmake)
    set_tests_properties(libfuzzer_${F_NAME} PROPERTIES TIMEOUT 300 LABELS "fuzz")
  else()
    add_test(NAME fuzz_corpus_${F_NAME} COMMAND ${exe} ${corpus})
    set_tests_properties(fuzz_corpus_${F_NAME} PROPERTIES TIMEOUT 120 LABELS "${INCLINO_TARGET}")
  endif()
endfunction()
