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
#if defined(__GNUC__) || defined(__clang__)
#define GAPHYS_RESTRICT __restrict
#define GAPHYS_ALWAYS_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define GAPHYS_RESTRICT __restrict
#define GAPHYS_ALWAYS_INLINE __forceinline
#else
#define GAPHYS_RESTRICT
#define GAPHYS_ALWAYS_INLINE inline
#endif
