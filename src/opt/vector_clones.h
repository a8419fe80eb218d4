/* opt/vector_clones: VECTOR_CLONES marks a small dense loop to be compiled
 * for AVX-512, AVX2 and the baseline, the best picked at load time (the
 * build targets baseline x86-64, two doubles per vector); elsewhere the
 * functions are plain ones. The build never contracts a*b+c
 * (-ffp-contract=off), so every clone computes the same bits. */
#ifndef SCAF_OPT_VECTOR_CLONES_H
#define SCAF_OPT_VECTOR_CLONES_H

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__EMSCRIPTEN__)
#define VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define VECTOR_CLONES
#endif

#endif /* SCAF_OPT_VECTOR_CLONES_H */
