/*
 * lf.h - the libFuzzer entry point's prototype, force-included into every fuzz target
 * (inclino_add_fuzzer, cmake/inclino_fuzz.cmake; docs/fuzzing.md).
 *
 * A target file tests/fuzz/lf_<name>.c (or .cpp) defines LLVMFuzzerTestOneInput: it hands the
 * bytes to one parser, checks what must hold for any input (no crash, no leak, no sanitizer
 * report; properties the parser promises, by abort() when broken) and returns 0. The same file
 * builds as a libFuzzer binary (the `fuzz` preset) and as a corpus replay (tests/fuzz/lf_replay.c)
 * in the other host builds.
 */
#ifndef INCLINO_LF_H
#define INCLINO_LF_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#ifdef __cplusplus
}
#endif

#endif /* INCLINO_LF_H */
