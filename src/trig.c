/* src/trig.c - sine, cosine, atan2, acos, asin and the integer square root
 * of the front end, fixed point only.
 *
 * sin/cos: the angle is folded into [0, 1/8 turn] (quadrant symmetry plus
 * sin(90 deg - x) = cos x) and evaluated with Taylor polynomials in q30:
 * sin to x^7, cos to x^8. At x = pi/4 the first omitted terms are
 * x^9/9! = 3.1e-7 (2^-21.6) and x^10/10! = 2.5e-8, far below the final
 * rounding to q16 (2^-17), so the q16 results are within 2^-17 + 2^-21.
 *
 * atan2: CORDIC vectoring on magnitudes folded into the first octant,
 * 30 iterations in int64 with the angle accumulated in q32 turns. After 30
 * steps the residual angle is below atan(2^-29) (2^-31.6 turns) and the 30
 * rounded table entries add at most 15 * 2^-32 turns: 2^-27 turns in all.
 * 32-bit cores shift on pairs of 32-bit words (cordic_asr).
 */
#include "pipeline_int.h"
#include "bits.h"

/* round(atan(2^-i) / (2 pi) * 2^32), i = 0..29. */
static const uint32_t atan_q32[30] = {
    536870912u, 316933406u, 167458907u, 85004756u, 42667331u, 21354465u, 10679838u,
    5340245u,   2670163u,   1335087u,   667544u,    333772u,    166886u,   83443u,
    41722u,     20861u,     10430u,     5215u,      2608u,      1304u,     652u,
    326u,       163u,       81u,        41u,        20u,        10u,       5u,
    3u,         1u};

#define Q30_ONE ((int64_t)1 << 30)
/* Taylor coefficients in q30: 1/3!, 1/5!, 1/7!, 1/2!, 1/4!, 1/6!, 1/8!. */
#define C_S3 ((int64_t)178956971)
#define C_S5 ((int64_t)8947849)
#define C_S7 ((int64_t)213044)
#define C_C2 ((int64_t)536870912)
#define C_C4 ((int64_t)44739243)
#define C_C6 ((int64_t)1491308)
#define C_C8 ((int64_t)26631)
/* round(2 pi * 2^46): f (2^-17 turns) * K / 2^33 = f in radians, q30. */
#define K_RAD ((int64_t)442139859501778)

static int64_t mul30(int64_t a, int64_t b)
{
    /* |a|, |b| <= 2^30 here, so the product fits easily. */
    return fxl__shr_round(a * b, 30);
}

/* f in [0, 16384] (2^-17 turns), i.e. x in [0, pi/4]; f * K_RAD < 2^63.
 * For even f this is bit for bit the former 2^-16-turn evaluation (the
 * same real value is rounded). */
static void octant_sincos(int32_t f, int64_t *s, int64_t *c)
{
    int64_t x = fxl__shr_round((int64_t)f * K_RAD, 33);
    int64_t x2 = mul30(x, x);
    int64_t p;
    p = C_S5 - mul30(x2, C_S7);
    p = C_S3 - mul30(x2, p);
    p = Q30_ONE - mul30(x2, p);
    *s = mul30(x, p);
    p = C_C6 - mul30(x2, C_C8);
    p = C_C4 - mul30(x2, p);
    p = C_C2 - mul30(x2, p);
    *c = Q30_ONE - mul30(x2, p);
}

void fxl__sincos_fine_q30(uint32_t a17, int32_t *s, int32_t *c)
{
    int32_t f = (int32_t)(a17 & 0x7FFFu);
    unsigned quadrant = (unsigned)(a17 >> 15) & 3u;
    int64_t s0, c0, t;
    if (f <= 0x4000) {
        octant_sincos(f, &s0, &c0);
    } else {
        octant_sincos(0x8000 - f, &c0, &s0);
    }
    if (quadrant == 1u) {
        t = s0; s0 = c0; c0 = -t;
    } else if (quadrant == 2u) {
        s0 = -s0; c0 = -c0;
    } else if (quadrant == 3u) {
        t = s0; s0 = -c0; c0 = t;
    }
    *s = (int32_t)s0; /* |value| <= 2^30 by construction */
    *c = (int32_t)c0;
}

void fxl__sincos_q30(fxl_angle_t a, int32_t *s, int32_t *c)
{
    fxl__sincos_fine_q30((uint32_t)a * 2u, s, c);
}

void fxl_sincos_q16(fxl_angle_t a, fxl_q16_t *s, fxl_q16_t *c)
{
    int32_t s30, c30;
    fxl__sincos_q30(a, &s30, &c30);
    if (s) *s = (fxl_q16_t)fxl__shr_round(s30, 14);
    if (c) *c = (fxl_q16_t)fxl__shr_round(c30, 14);
}

fxl_q16_t fxl_sin_q16(fxl_angle_t a)
{
    fxl_q16_t s;
    fxl_sincos_q16(a, &s, NULL);
    return s;
}

fxl_q16_t fxl_cos_q16(fxl_angle_t a)
{
    fxl_q16_t c;
    fxl_sincos_q16(a, NULL, &c);
    return c;
}

/* CORDIC's x and y are int64 values, kept as their bit patterns (added
 * modulo 2^64: no sum leaves int64, |x|, |y| < 2^60.3). On 32-bit cores
 * (-DFXL__WORD32=1 forces it on a host, as determinism.sh does) each step's
 * floor shifts are done on the two 32-bit words: a 64-bit shift by a
 * variable is a long sequence there, and fxl__asr's floor shift of a
 * negative value longer still (~36 Cortex-M4 instructions a step at -O2,
 * ~26 by words). The same values either way. */
#if defined(FXL__WORD32)
#define CORDIC_WORDS FXL__WORD32
#else
#define CORDIC_WORDS (UINTPTR_MAX <= 0xFFFFFFFFu)
#endif

/* floor(v / 2^i) of the int64 bit pattern v, 0 < i < 32, as a bit pattern */
static inline uint64_t cordic_asr(uint64_t v, unsigned i)
{
    const uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v;
    if (!CORDIC_WORDS)
        return (uint64_t)FXL__HOT_ASR(fxl__i64_of_bits(v), i);
    return ((uint64_t)(uint32_t)fxl__asr32(fxl__i32_of_bits(hi), (int)i) << 32) | (lo >> i) | (hi << (32u - i));
}

/* atan(y / x) in q32 turns for 0 <= y <= x, x > 0: in [0, 1/8 turn]. */
static uint32_t cordic_octant(int64_t x, int64_t y)
{
    int top = 63 - fxl_clz64((uint64_t)x);
    uint64_t xb, yb;
    uint32_t z;   /* |z| < the table's sum, 0.28 turns < 2^31: z modulo 2^32 */
    int i;
    /* Bring x to [2^58, 2^59): CORDIC grows the vector by 1.647, the folding
     * keeps y <= x, so |x|, |y| stay below 2^60.3. */
    if (top > 58) {
        x = fxl__asr(x, (unsigned)(top - 58));
        y = fxl__asr(y, (unsigned)(top - 58));
    } else {
        x = (int64_t)((uint64_t)x << (58 - top));
        y = (int64_t)((uint64_t)y << (58 - top));
    }
    if (y == 0)
        return 0u;
    /* step 0, whose shifts are by 0: y > 0 here */
    xb = (uint64_t)x + (uint64_t)y;
    yb = (uint64_t)y - (uint64_t)x;
    z = atan_q32[0];
    /* Unrolled in GCC's speed builds for 32-bit cores: each step's shifts
     * are then by constants, three instructions each (-O2 Cortex-M4: ~26 ->
     * ~18 a step, +1.8 KB of code). */
#if CORDIC_WORDS && defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE_SIZE__)
    _Pragma("GCC unroll 29")
#endif
    for (i = 1; i < 30; i++) {
        const uint64_t dx = cordic_asr(yb, (unsigned)i), dy = cordic_asr(xb, (unsigned)i);
        if (yb == 0u)
            break;
        if (yb >> 63) {
            xb -= dx;
            yb += dy;
            z -= atan_q32[i];
        } else {
            xb += dx;
            yb -= dy;
            z += atan_q32[i];
        }
    }
    return z >> 31 ? 0u : z;   /* the true angle is >= 0 */
}

uint32_t fxl__atan2_q32(int64_t y, int64_t x)
{
    int64_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y;
    uint32_t t;
    if (ax == 0 && ay == 0) return 0;
    if (ay <= ax) {
        t = cordic_octant(ax, ay);
    } else {
        t = 0x40000000u - cordic_octant(ay, ax);
    }
    /* Unfold the quadrant; uint32 arithmetic wraps modulo one turn. */
    if (x < 0) t = 0x80000000u - t;
    if (y < 0) t = 0u - t;
    return t;
}

fxl_angle_t fxl_atan2_angle(fxl_q16_t y, fxl_q16_t x)
{
    uint32_t t = fxl__atan2_q32(y, x);
    return (fxl_angle_t)((t + 0x8000u) >> 16);
}

/* sqrt(1 - c^2) in q30 for |c_q30| <= 2^30. */
static int64_t cosine_complement_q30(int64_t c_q30)
{
    uint64_t d = ((uint64_t)1 << 60) - (uint64_t)(c_q30 * c_q30);
    return (int64_t)fxl__isqrt64(d);
}

static int64_t clamp_unit_q30(fxl_q16_t v)
{
    int64_t c = (int64_t)v * 16384;
    if (c > Q30_ONE) c = Q30_ONE;
    if (c < -Q30_ONE) c = -Q30_ONE;
    return c;
}

int32_t fxl_acos_angle(fxl_q16_t c)
{
    int64_t c30 = clamp_unit_q30(c);
    uint32_t t = fxl__atan2_q32(cosine_complement_q30(c30), c30); /* [0, 2^31] */
    return (int32_t)((t + 0x8000u) >> 16);
}

int32_t fxl_asin_angle(fxl_q16_t s)
{
    int64_t s30 = clamp_unit_q30(s);
    uint32_t t = fxl__atan2_q32(s30, cosine_complement_q30(s30));
    /* t is in [0, 2^30] or [3 * 2^30, 2^32): read it as a signed angle. */
    int64_t st = t >= 0x80000000u ? (int64_t)t - ((int64_t)1 << 32) : (int64_t)t;
    return (int32_t)fxl__shr_round(st, 16);
}
