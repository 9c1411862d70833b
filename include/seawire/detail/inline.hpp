// SPDX-License-Identifier: BSL-1.0
#pragma once
// SEAWIRE_ALWAYS_INLINE: functions that must be inlined where a field table is walked, so options
// are constants, absent checks compile away and the reader stays in registers (GCC -O2 keeps
// them out of line otherwise): the one-pass readers (the codecs' scan()), the field reader and
// the walk itself (read_field, write_field). The codecs' read(), the converters of the general
// path (a sentence already split, or a line the one-pass path gives up on), are left to the
// compiler: forced inline into every field of every message, they made a file that calls a
// role decoder take 1.7 times as long to compile, for 10-15% fewer instructions on that path
// and none on the one-pass path (GCC 12 -O2; the split_decode modes of the benchmarks).
// SEAWIRE_NOINLINE keeps rare paths out; SEAWIRE_FLATTEN inlines the framer's next() whole.
// SEAWIRE_INLINE_LAMBDA, after a lambda's parameter list, inlines the lambda where it is called
// (GCC leaves a lambda of some size out of line even when it has one caller).

#if (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE__)
// Unoptimized builds (debug, sanitizers): forced inlining there only makes huge functions that
// are slow to compile and to step through.
#define SEAWIRE_ALWAYS_INLINE inline
#define SEAWIRE_NOINLINE __attribute__((noinline))
#define SEAWIRE_FLATTEN
#define SEAWIRE_INLINE_LAMBDA
#elif defined(__GNUC__) || defined(__clang__)
#define SEAWIRE_ALWAYS_INLINE __attribute__((always_inline)) inline
#define SEAWIRE_NOINLINE __attribute__((noinline))
#define SEAWIRE_FLATTEN __attribute__((flatten))
#define SEAWIRE_INLINE_LAMBDA __attribute__((always_inline))
#elif defined(_MSC_VER)
#define SEAWIRE_ALWAYS_INLINE __forceinline
#define SEAWIRE_NOINLINE __declspec(noinline)
#define SEAWIRE_FLATTEN
#define SEAWIRE_INLINE_LAMBDA
#else
#define SEAWIRE_ALWAYS_INLINE inline
#define SEAWIRE_NOINLINE
#define SEAWIRE_FLATTEN
#define SEAWIRE_INLINE_LAMBDA
#endif
