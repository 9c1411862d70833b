// SPDX-License-Identifier: BSL-1.0
#pragma once
// Which vector paths are compiled. SEAWIRE_SSE2 is 1 where the compiler targets SSE2 (every
// x86-64) and 0 elsewhere; the byte searches, the checksum and the sentence scan then use their
// portable forms, eight bytes at a time in a 64-bit word and byte by byte, which are also the
// ones constant evaluation runs. Define SEAWIRE_NO_SIMD before including seawire to get the
// portable forms on x86 too: what an ARM board (Raspberry Pi, Jetson) runs, and how the tests
// check those forms on an x86 machine.

#if defined(__SSE2__) && !defined(SEAWIRE_NO_SIMD)
#define SEAWIRE_SSE2 1
#else
#define SEAWIRE_SSE2 0
#endif
