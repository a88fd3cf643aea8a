// Compiler hints the generated mv kernels and dispatchers use, where the
// compiler has them; elsewhere they expand to nothing and change no result.
#pragma once

// GAPHYS_RESTRICT: `restrict` for references. The profiled mv kernels take
// their result by reference; without it the compiler must assume each store
// into the result may change an argument and reloads the arguments after every
// store (measured: c3ga gp on 2-blades in mv took 1.7x as long). Every caller
// passes a fresh local result, never an argument.
//
// GAPHYS_ALWAYS_INLINE: puts a dispatcher's switch, and the kernels it calls,
// into the mv function itself, so a profiled call is one call, not three.
#if defined(__GNUC__) || defined(__clang__) || defined(_MSC_VER)
#define GAPHYS_RESTRICT __restrict
#else
#define GAPHYS_RESTRICT
#endif

// A build may define GAPHYS_ALWAYS_INLINE itself. The sanitized build makes
// it plain `inline`: with UBSan, GCC's points-to analysis of the bodies forced
// inline took 50 of the 60 s that engine/src/contact_batches.cpp took to
// compile (6 s with plain inline).
#ifndef GAPHYS_ALWAYS_INLINE
#if defined(__GNUC__) || defined(__clang__)
#define GAPHYS_ALWAYS_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define GAPHYS_ALWAYS_INLINE __forceinline
#else
#define GAPHYS_ALWAYS_INLINE inline
#endif
#endif
