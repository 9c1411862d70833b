// SPDX-License-Identifier: BSL-1.0
#pragma once
// SEAWIRE_ALWAYS_INLINE, for the few small functions on the decode path that their callers must
// see through: the field reader and read_field with its checks. Inlined where a message's field
// table is walked, a field's options are constants and the checks it does not have compile
// away; left to itself GCC -O2 keeps them out of line and tests every option at run time
// (measured: decode of RMC/GGA 15% slower).

#if defined(__GNUC__) || defined(__clang__)
#define SEAWIRE_ALWAYS_INLINE __attribute__((always_inline)) inline
#define SEAWIRE_NOINLINE __attribute__((noinline))
#elif defined(_MSC_VER)
#define SEAWIRE_ALWAYS_INLINE __forceinline
#define SEAWIRE_NOINLINE __declspec(noinline)
#else
#define SEAWIRE_ALWAYS_INLINE inline
#define SEAWIRE_NOINLINE
#endif
