// SPDX-License-Identifier: BSL-1.0
#pragma once
// SEAWIRE_ALWAYS_INLINE, for the functions on the decode path that their callers must see
// through: the field reader, read_field with its checks, and the codecs' read(). Inlined where a
// message's field table is walked, a field's options are constants, the checks it does not have
// compile away and the reader's state stays in registers; left to itself GCC -O2 keeps them out
// of line and tests every option at run time. SEAWIRE_NOINLINE keeps rare paths (a field reader
// moving to its next 64-byte window) out of the code they would otherwise bloat.
// SEAWIRE_FLATTEN inlines everything a function calls into it: the framer's next(), which would
// otherwise call the stream reader's item-returning steps out of line and copy each item only
// to cut it down to a line (the reader with frames is faster left to the compiler).

#if (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE__)
// Unoptimized builds (debug, sanitizers): forced inlining there only makes huge functions that
// are slow to compile and to step through.
#define SEAWIRE_ALWAYS_INLINE inline
#define SEAWIRE_NOINLINE __attribute__((noinline))
#define SEAWIRE_FLATTEN
#elif defined(__GNUC__) || defined(__clang__)
#define SEAWIRE_ALWAYS_INLINE __attribute__((always_inline)) inline
#define SEAWIRE_NOINLINE __attribute__((noinline))
#define SEAWIRE_FLATTEN __attribute__((flatten))
#elif defined(_MSC_VER)
#define SEAWIRE_ALWAYS_INLINE __forceinline
#define SEAWIRE_NOINLINE __declspec(noinline)
#define SEAWIRE_FLATTEN
#else
#define SEAWIRE_ALWAYS_INLINE inline
#define SEAWIRE_NOINLINE
#define SEAWIRE_FLATTEN
#endif
