/* fixel/config.h - compile-time configuration.
 *
 * Never edit this file. Put your settings in a header of your own and build
 * with -DFXL_CONFIG_FILE='"my_fixel_config.h"'; it is included first and
 * every default below is only used where you did not define the macro.
 * Options are positive (FXL_HAVE_x = 1 means the feature is compiled in).
 */
#ifndef FIXEL_CONFIG_H
#define FIXEL_CONFIG_H

#ifdef FXL_CONFIG_FILE
#include FXL_CONFIG_FILE
#endif

/* Sub-pixel precision of vertex positions (1..6): 4 bits = 1/16 pixel. Vertices are
 * rounded to this grid before rasterization; coverage is exact on it. */
#ifndef FXL_SUBPIXEL_BITS
#define FXL_SUBPIXEL_BITS 4
#endif

/* Default distance in pixels between exact perspective divisions. */
#ifndef FXL_PERSP_SPAN
#define FXL_PERSP_SPAN 16
#endif

/* 16-bit depth buffer support (scaled 1/w, greater is nearer). */
#ifndef FXL_HAVE_DEPTH
#define FXL_HAVE_DEPTH 1
#endif

/* Bilinear filtering (point sampling is always present). */
#ifndef FXL_HAVE_BILINEAR
#define FXL_HAVE_BILINEAR 1
#endif

/* Mip levels, LOD selection and trilinear filtering. Without it a draw of a
 * texture with more than one level must use FXL_MIP_NONE (else
 * FXL_ERR_UNSUPPORTED); fxl_mip_build still builds chains. */
#ifndef FXL_HAVE_MIPMAP
#define FXL_HAVE_MIPMAP 1
#endif

/* FXL_PERSP_AUTO, the error-budgeted adaptive segment length (~2.6 KB of
 * Cortex-M4 code); without it FXL_PERSP_AUTO is FXL_ERR_UNSUPPORTED (an
 * auto_budget <= 0 is FXL_ERR_RANGE first, in every build). */
#ifndef FXL_HAVE_AUTO
#define FXL_HAVE_AUTO 1
#endif

/* Quadratic segments for FXL_PERSP_AUTO (docs/design.md): where chords
 * would need short segments, a parabola through the exact points needs
 * 39-54% fewer divisions for the same budget. 1.8 KB of
 * Cortex-M4 code at -Os, 26 KB at -O2 (a second copy of every one-level
 * span walk and pixel loop); without them AUTO steps chords only. */
#ifndef FXL_HAVE_QUAD
#define FXL_HAVE_QUAD FXL_HAVE_AUTO
#endif
#if FXL_HAVE_QUAD && !FXL_HAVE_AUTO
#error "FXL_HAVE_QUAD needs FXL_HAVE_AUTO"
#endif

/* Reciprocal runs for FXL_PERSP_AUTO (docs/design.md): a triangle whose
 * every segment would be short (a floor receding to the horizon) takes an
 * approximate 1/q at every pixel instead, a 32-bit division and four
 * multiplies, within (|u| + |v|) 2^-18 texel: the 40-degree-rolled floor
 * at 1.19x subdiv16's Cortex-M4 instructions instead of 2.66x (trilinear
 * 1.17x instead of 2.20x). 1.4 KB of Cortex-M4 code at -Os (the
 * every-feature core is 16,302 B with it), 24 KB at -O2 (run walks per
 * variant and a 1 KB seed table); without them such triangles take
 * segments. */
#ifndef FXL_HAVE_RR
#define FXL_HAVE_RR FXL_HAVE_AUTO
#endif
#if FXL_HAVE_RR && !FXL_HAVE_AUTO
#error "FXL_HAVE_RR needs FXL_HAVE_AUTO"
#endif

/* Texel formats other than RGB565, wrap modes other than repeat, colour key,
 * Gouraud colour. Without it the core keeps only the specialised walks, and
 * a draw must suit one: textured, RGB565, repeat on both axes, no colour
 * key, REPLACE, flat, level 0 of at most 2^16 texels, depth either unused
 * or tested and written, and a kind of draw its FXL_FAST_* below keep;
 * anything else is FXL_ERR_UNSUPPORTED (fxl_draw_check tells up front). */
#ifndef FXL_HAVE_GENERIC
#define FXL_HAVE_GENERIC 1
#endif

/* Specialised code per kind of draw (RGB565 repeat-wrapped textures, REPLACE,
 * and flat MODULATE with FXL_FAST_TINT; the rest always takes the generic walk). Each combination of target format,
 * depth and filter has its own pixel loop, and in speed-optimised builds its
 * own span walks: ~5-13 KB of Cortex-M4 code at -O2 each, 267 KB for all
 * (docs/bench/footprint.txt: 273,736 B linked; 109,952 B with
 * FXL_FAST_NATIVE 0 and FXL_FAST_NO_DEPTH 0); at -Os a pixel loop of
 * ~0.2 KB a filter and depth, shared by both formats (bilinear: one loop
 * with depth and without). A product that drives one panel format, or
 * always draws with depth, leaves the rest out.
 * A left-out combination is drawn by the generic walk to the same pixels, bit
 * for bit, only slower; without FXL_HAVE_GENERIC it is FXL_ERR_UNSUPPORTED. */
#ifndef FXL_FAST_NATIVE      /* FXL_PIXFMT_RGB565 targets */
#define FXL_FAST_NATIVE 1
#endif
#ifndef FXL_FAST_SWAPPED     /* FXL_PIXFMT_RGB565_SWAP targets */
#define FXL_FAST_SWAPPED 1
#endif
#ifndef FXL_FAST_NO_DEPTH    /* draws without a depth buffer */
#define FXL_FAST_NO_DEPTH 1
#endif
#ifndef FXL_FAST_DEPTH       /* draws with depth test and write */
#define FXL_FAST_DEPTH FXL_HAVE_DEPTH
#endif
#ifndef FXL_FAST_POINT       /* point sampling */
#define FXL_FAST_POINT 1
#endif
#ifndef FXL_FAST_BILINEAR    /* bilinear filtering */
#define FXL_FAST_BILINEAR FXL_HAVE_BILINEAR
#endif
#ifndef FXL_FAST_MIP         /* two levels blended: point-mip-linear (with
                              * FXL_FAST_POINT), trilinear (with BILINEAR) */
#define FXL_FAST_MIP FXL_HAVE_MIPMAP
#endif
/* Flat-tinted draws (MODULATE with FXL_SHADE_FLAT: every texel times one
 * colour, the cheapest lighting) in speed-optimised builds: 1 adds a
 * tinted copy of each one-level variant kept above, the same walks with
 * the texel modulated before the store, and sends such draws to it. (A
 * white tint draws as REPLACE in every speed build.) Off by default: each copy is ~19-24 KB
 * of Cortex-M4 code at -O2 (docs/design.md, "Flat-tinted draws"). Without
 * it they take the generic walk, 2-7x the instructions a pixel of the
 * untinted draw. Size builds (-Os) and builds without FXL_HAVE_GENERIC
 * (which refuse MODULATE) never build these copies. */
#ifndef FXL_FAST_TINT
#define FXL_FAST_TINT 0
#endif

/* 64-bit division by fixel's own shift-subtract loop instead of the
 * compiler's runtime helper (src/div64.h): 0.7-1.2 KB less Cortex-M code,
 * identical results, slower set-up (one loop iteration per quotient bit).
 * Default: on in size-optimised builds (-Os), off otherwise. */
#ifndef FXL_SMALL_DIV64
#if defined(__OPTIMIZE_SIZE__)
#define FXL_SMALL_DIV64 1
#else
#define FXL_SMALL_DIV64 0
#endif
#endif

/* With FXL_SMALL_DIV64, on cores whose 32-bit division is an instruction
 * (Cortex-M3/M4/M7/M33, RISC-V with M): 1 divides set-up's 64-bit values
 * by a divisor that fits 32 bits (doubled areas and edge heights: any
 * triangle within a 2048-pixel square on the default 1/16 px grid) with
 * those instructions, as speed builds do, instead of the loop, and a
 * gradient with one division instead of two loops. Identical results.
 * Cortex-M4 -Os: +366 B linked, small triangles' draws -24% instructions
 * (docs/porting.md, section 8). Default 0: the every-feature -Os core
 * stays within 16 KiB. No effect on other cores. */
#ifndef FXL_SMALL_DIV64_HW
#define FXL_SMALL_DIV64_HW 0
#endif

/* The perspective reciprocal's first estimate (src/persp.h, every
 * correction point) from a 512-byte table and one multiply instead of a
 * 32-bit division, for cores without a divide instruction (Cortex-M0/M0+:
 * the division is a libgcc call, ~130 instructions). Identical results.
 * Default: on in ARMv6-M speed builds, off elsewhere. Cortex-M0+ -Os with
 * it: +558 B linked, the cube (subdiv16, point) -6.8% instructions.
 * Pointless on cores that divide in hardware. */
#ifndef FXL_DIV_TABLE
#if defined(__ARM_ARCH_6M__) && !defined(__OPTIMIZE_SIZE__)
#define FXL_DIV_TABLE 1
#else
#define FXL_DIV_TABLE 0
#endif
#endif

/* Largest texture side is 1 << FXL_TEX_MAX_LOG2 texels. */
#ifndef FXL_TEX_MAX_LOG2
#define FXL_TEX_MAX_LOG2 12
#endif

#if FXL_SUBPIXEL_BITS < 1 || FXL_SUBPIXEL_BITS > 6
#error "FXL_SUBPIXEL_BITS must be in 1..6 (centres on the grid; edge terms fit 32 bits)"
#endif
#if FXL_PERSP_SPAN < 1 || FXL_PERSP_SPAN > 256 || (FXL_PERSP_SPAN & (FXL_PERSP_SPAN - 1)) != 0
#error "FXL_PERSP_SPAN must be a power of two in 1..256"
#endif
#if FXL_TEX_MAX_LOG2 < 0 || FXL_TEX_MAX_LOG2 > 14
#error "FXL_TEX_MAX_LOG2 must be in 0..14 (u, v are stepped as 16.16 texels)"
#endif
#if FXL_HAVE_MIPMAP && !FXL_HAVE_GENERIC
#error "FXL_HAVE_MIPMAP needs FXL_HAVE_GENERIC (mip sampling runs on the generic span loop)"
#endif
#if !FXL_HAVE_GENERIC && (!(FXL_FAST_NATIVE || FXL_FAST_SWAPPED) || !(FXL_FAST_NO_DEPTH || FXL_FAST_DEPTH) || \
                          !(FXL_FAST_POINT || FXL_FAST_BILINEAR))
#error "without FXL_HAVE_GENERIC keep a specialised walk of each kind (FXL_FAST_*): this build would draw nothing"
#endif
#if (FXL_FAST_DEPTH && !FXL_HAVE_DEPTH) || (FXL_FAST_BILINEAR && !FXL_HAVE_BILINEAR) || \
    (FXL_FAST_MIP && !FXL_HAVE_MIPMAP)
#error "FXL_FAST_DEPTH, _BILINEAR and _MIP need the feature itself (FXL_HAVE_DEPTH, _BILINEAR, _MIPMAP)"
#endif

#endif
