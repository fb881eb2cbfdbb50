// SPDX-License-Identifier: GPL-3.0-or-later
// ROOMCAD_WIDE_LOOPS marks the functions whose loops run per pixel or per sample: GCC and
// clang compile each twice, for AVX2 and for the x86-64 baseline (SSE2), and pick one when the
// program loads (target_clones), so those loops vectorise twice as wide where the CPU allows
// while the binary still runs everywhere. Both clones compute the same bits: AVX2 brings no
// FMA, render builds with -ffp-contract=off, and the loops use no approximate instructions.
// GCC does not inline the helpers a clone calls (they would run at the baseline's width), so
// there `flatten` inlines them into each clone; clang inlines them by itself and refuses
// `flatten` beside `target_clones`.
#pragma once

#if defined(__x86_64__) && defined(__clang__)
#define ROOMCAD_WIDE_LOOPS __attribute__((target_clones("avx2", "default")))
#elif defined(__x86_64__) && defined(__GNUC__)
#define ROOMCAD_WIDE_LOOPS __attribute__((target_clones("avx2", "default"), flatten))
#else
#define ROOMCAD_WIDE_LOOPS
#endif
