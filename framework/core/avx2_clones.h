#pragma once

// MAQUETTE_AVX2_CLONES before a function: GCC compiles it twice, for AVX2 and for any x86-64, and
// the dynamic loader picks one at load (target_clones, an ifunc). Each use is written so that both
// versions give the same bits (the same operations in the same order).
// Under ThreadSanitizer there is one version: GCC 12 instruments the ifunc's resolver, which the
// loader runs while relocating the library, before the sanitizer's runtime has started, and the
// program crashes at load.
#if defined(__SANITIZE_THREAD__)
#define MAQUETTE_AVX2_CLONES
#else
#define MAQUETTE_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#endif
