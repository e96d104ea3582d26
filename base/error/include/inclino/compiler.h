/*
 * compiler.h - the compiler attributes the freestanding code uses, defined once.
 *
 * INC_NOINLINE: the function is never inlined. For the stack, not for speed: a step whose locals
 * must not join its caller's frame (with link-time optimisation gcc inlines across modules and
 * merges frames; docs/build.md, "Stack analysis"), or a helper kept out of line because one
 * copy is smaller than several. Without gcc or clang it is empty (the code stays correct; only
 * the frames and the size differ).
 */
#ifndef INCLINO_COMPILER_H
#define INCLINO_COMPILER_H

#if defined(__GNUC__)
#define INC_NOINLINE __attribute__((noinline))
#else
#define INC_NOINLINE
#endif

#endif /* INCLINO_COMPILER_H */
