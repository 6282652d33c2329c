/*
 * fixed.h - Strand's fixed-point arithmetic: the one definition the RTL mirrors.
 *
 * Numbers are signed two's complement, W bits in all, F of them fraction
 * ("Q(W-F).F"), held sign-extended in an int32_t (W <= 32). Every operation here
 * is written the way the hardware computes it: integer operations of stated
 * width, no floating point. rtl/fx_*.v implement the same functions bit for bit
 * and tb/ checks them against this file.
 *
 * Rules (docs/model.md explains them at length):
 *  - Saturation: any result outside [-2^(W-1), 2^(W-1)-1] is clamped, never wrapped.
 *  - Rounding: a value shifted right by n bits is rounded to nearest, ties to even
 *    ("convergent" rounding). It is unbiased, so a resting rope does not creep.
 *  - Square root: radicand is an unsigned 2W-bit integer (a sum of squares of
 *    W-bit values, so in Q(2F)); the root is a non-negative W-bit value in Q.F.
 *    It resolves SQRT_BITS magnitude bits, most significant (bit W-2) first, one
 *    per iteration, then one more iteration decides rounding to nearest at the
 *    last resolved bit. Roots >= 2^(W-1) saturate to 2^(W-1)-1.
 *  - Divide: quotient round(num * 2^F / den) of two non-negative values, DIV_BITS
 *    magnitude bits from bit W-2 down plus one rounding iteration, saturating at
 *    2^(W-1)-1. Division by zero is flagged; callers skip the correction.
 *  - The normalised distance datapath (mantissa = MB > 0): a constraint's vector of
 *    length rest along d, computed on MB-bit mantissas that share one exponent
 *    (fx_along below; docs/model.md, "Positions wide, links narrow").
 */
#ifndef STRAND_FIXED_H
#define STRAND_FIXED_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Limits the model and the RTL both accept. */
#define FX_MIN_WIDTH 8
#define FX_MAX_WIDTH 32

typedef int32_t fx_t;

/* A number format: width, fraction bits, and how many bits the iterative units resolve. */
typedef struct {
    int width;     /* W: total bits, FX_MIN_WIDTH..FX_MAX_WIDTH */
    int frac;      /* F: fraction bits, 1..W-2 */
    int sqrt_bits; /* root magnitude bits resolved, 1..W-1 (W-1 = full precision) */
    int div_bits;  /* quotient magnitude bits resolved, 1..W-1 (W-1 = full precision) */
    int mantissa;  /* MB: 0 the full-width root and divide, else FX_MIN_MANTISSA..FX_MAX_MANTISSA
                      significant bits of the normalised distance datapath (fx_along) */
} fx_format;

/* The normalised datapath's mantissa widths: MB + 1-bit signed words, so MB = 17 makes every
   product one 18 x 18 multiplier; 20 keeps the seed table's cube within 64 bits. */
#define FX_MIN_MANTISSA 6
#define FX_MAX_MANTISSA 20

/* NULL if the format is valid, else a static message saying what is wrong. */
const char *fx_format_check(const fx_format *fmt);

static inline fx_t fx_max(const fx_format *fmt) { return (fx_t)((INT64_C(1) << (fmt->width - 1)) - 1); }
static inline fx_t fx_min(const fx_format *fmt) { return (fx_t)(-(INT64_C(1) << (fmt->width - 1))); }
static inline fx_t fx_one(const fx_format *fmt) { return (fx_t)(INT64_C(1) << fmt->frac); }

/* Clamp a wide intermediate to the W-bit range. */
static inline fx_t fx_sat(const fx_format *fmt, int64_t v)
{
    if (v > fx_max(fmt)) return fx_max(fmt);
    if (v < fx_min(fmt)) return fx_min(fmt);
    return (fx_t)v;
}

/* floor(v / 2^n) for any sign: C's >> on negative values is implementation-defined. */
static inline int64_t fx_asr(int64_t v, int n)
{
    return v >= 0 ? v >> n : -((-(v + 1)) >> n) - 1;
}

/* v / 2^n rounded to nearest, ties to even (n >= 1). Unsaturated. */
static inline int64_t fx_round_shift(int64_t v, int n)
{
    int64_t q = fx_asr(v, n);
    int64_t r = v - q * (INT64_C(1) << n); /* 0 <= r < 2^n */
    int64_t half = INT64_C(1) << (n - 1);
    if (r > half || (r == half && (q & 1))) q++;
    return q;
}

static inline fx_t fx_add(const fx_format *fmt, fx_t a, fx_t b) { return fx_sat(fmt, (int64_t)a + b); }
static inline fx_t fx_sub(const fx_format *fmt, fx_t a, fx_t b) { return fx_sat(fmt, (int64_t)a - b); }
static inline fx_t fx_neg(const fx_format *fmt, fx_t a) { return fx_sat(fmt, -(int64_t)a); }

/* a * b: the exact 2W-bit product, rounded (ties to even) back to Q.F, saturated. */
static inline fx_t fx_mul(const fx_format *fmt, fx_t a, fx_t b)
{
    return fx_sat(fmt, fx_round_shift((int64_t)a * b, fmt->frac));
}

/* a * b + c * d: the two exact 2W-bit products summed, rounded once (ties to even), saturated.
   The spring's f = ks (len - rest) + kd vn: the damper term alone is a few LSBs a substep. */
static inline fx_t fx_mac2(const fx_format *fmt, fx_t a, fx_t b, fx_t c, fx_t d)
{
    int64_t p = (int64_t)a * b, q = (int64_t)c * d;
    /* only (-2^31)^2 + (-2^31)^2 = 2^63 leaves int64: clamped, the result saturates anyway */
    int64_t sum = p > 0 && q > INT64_MAX - p ? INT64_MAX : p + q;
    return fx_sat(fmt, fx_round_shift(sum, fmt->frac));
}
/* (a + b) / 2 rounded ties to even, from the exact (W+1)-bit sum. Never overflows. */
static inline fx_t fx_avg(const fx_format *fmt, fx_t a, fx_t b)
{
    return fx_sat(fmt, fx_round_shift((int64_t)a + b, 1));
}

/* a / 2 rounded ties to even. */
static inline fx_t fx_half(const fx_format *fmt, fx_t a) { return fx_sat(fmt, fx_round_shift(a, 1)); }

/* Exact sum of squares: the 2W-bit radicand of a length (3 * 2^(2W-2) < 2^(2W)). */
static inline uint64_t fx_sumsq(fx_t dx, fx_t dy, fx_t dz)
{
    return (uint64_t)((int64_t)dx * dx) + (uint64_t)((int64_t)dy * dy) + (uint64_t)((int64_t)dz * dz);
}

/* Square root, see the header comment. Returns a value in 0..fx_max. */
fx_t fx_sqrt(const fx_format *fmt, uint64_t radicand);
/*
 * The other leg of a right triangle with hypotenuse h and one leg (dx, dy, dz):
 * fx_sqrt of the exact 2W-bit difference h^2 - |d|^2. When |d| > h there is no such
 * triangle: *miss is set and 0 returned.
 */
fx_t fx_leg(const fx_format *fmt, fx_t h, fx_t dx, fx_t dy, fx_t dz, bool *miss);

/*
 * Unsigned divide: round(num * 2^F / den) for num, den < 2^W, in 0..fx_max.
 * den == 0 sets *div_by_zero (if given) and returns fx_max; callers skip the result.
 */
fx_t fx_div(const fx_format *fmt, uint32_t num, uint32_t den, bool *div_by_zero);

/* Signed numerator, positive denominator: sign and magnitude around fx_div. */
fx_t fx_div_signed(const fx_format *fmt, fx_t num, fx_t den, bool *div_by_zero);

/*
 * Unit vectors (projection = previous) are held with W-2 fraction bits, Q2.(W-2), so that
 * a correction of length L placed along one is off by L 2^-(W-2) rather than L 2^-F (at
 * Q16.16 and L = 100, 65 LSB: enough error to drain a pendulum's energy). fx_unit_div is
 * fx_div_signed with F = W-2 (num/den for |num| <= den: DIV_BITS bits resolved);
 * fx_mul_unit is a Q.F value times a unit component, the exact product rounded by W-2.
 */
static inline fx_format fx_unit_format(const fx_format *fmt)
{
    fx_format u = *fmt;
    u.frac = fmt->width - 2;
    return u;
}
static inline fx_t fx_mul_unit(const fx_format *fmt, fx_t a, fx_t u)
{
    return fx_sat(fmt, fx_round_shift((int64_t)a * u, fmt->width - 2));
}
fx_t fx_unit_div(const fx_format *fmt, fx_t num, fx_t den, bool *div_by_zero);
/*
 * The normalised distance datapath (fmt->mantissa = MB > 0). fx_along gives t, the vector
 * of length `rest` along d (t = d rest / |d|, each lane rounded once into Q.F and
 * saturated): the centred rule's target is P + t, the pairwise rule's excess d - t. It
 * returns false when d = 0 (no direction: the caller skips the correction), as the full-
 * width datapath's divide-by-zero flag does. Every step is an integer operation the RTL
 * mirrors (rtl/fx_along_pipe.v, in toward_pipe, toward_prev_pipe and spring_force_pipe); "round" is ties to
 * even, "clamp" keeps an unsigned mantissa below 2^MB:
 *
 *  1. normalise (fx_norm_lanes): L = the leading bit of |d.x| | |d.y| | |d.z|, s = L - (MB-1),
 *     m_k = d_k 2^-s rounded (s > 0) or exact (s <= 0), positive ones clamped to 2^MB - 1:
 *     the largest |m_k| has MB significant bits, every m_k fits MB + 1 bits signed.
 *  2. x = sum m_k^2, exact, in [2^(2MB-2), 3 2^(2MB)).
 *  3. reciprocal root (fx_rsqrt_norm): Lx = x's leading bit, J = Lx / 2, p = Lx mod 2 (so
 *     v = x / 4^J is in [1, 4), v >= 2 when p = 1); x' = x 2^-(Lx-MB+1) rounded and clamped (MB
 *     bits, v = x' 2^p / 2^(MB-1)); the seed Y0, C0 = Y0^3 (fx_rsqrt_seed) from a table of
 *     2^T entries, T = MB/2 + 1, indexed by p and the T - 1 bits of x below its leading one;
 *     one Newton step Y1 = round((3 Y0 2^(MB-1) - x' C0 2^p) / 2^MB), clamped: Y1 / 2^MB is
 *     1 / sqrt(v) to about 1.5 2^-(2T+2) + 2^-MB.
 *  4. rest (fx_norm_rest): Lr = rest's leading bit (0 for rest <= 1), er = Lr - (MB-1), R =
 *     rest 2^-er rounded and clamped (MB bits; 0 for rest = 0).
 *  5. the ratio's mantissa: Q = R Y1 (exact, < 2^(2MB)), b = Q >= 2^(2MB-1),
 *     Qm = Q 2^-(MB-1+b) rounded and clamped (MB bits).
 *  6. back into the format (fx_denorm): t_k = d_k Qm 2^-(sh+s) rounded (sh + s > 0) or shifted
 *     left, saturated, with sh = J + 1 - b - er: sh + s is in [MB-W, W+MB]. The product takes d
 *     itself, not m_k: t keeps d's direction exactly and only its length, rest / |d|, comes from
 *     mantissas (t = d Qm 2^-(sh+s) = d rest / |d|). Rounded m_k would put the target on a grid
 *     of rest 2^-MB across the link: coarser, for a long link, than a slow swing's step.
 * Error: a few 2^-MB of rest, along d (docs/model.md has the bound).
 */
int fx_msb(uint64_t v); /* floor(log2 v), v > 0 */
/* Step 1: m[0..dim-1] from d; returns the shift s, or INT32_MIN (with m = 0) when d = 0. */
int fx_norm_lanes(int mb, int dim, const fx_t d[3], int64_t m[3]);
/* The seed table's index bits for MB, and its entry idx: *y0 = Y0 and *c0 = C0 (step 3). */
static inline int fx_rsqrt_table_bits(int mb) { return mb / 2 + 1; }
void fx_rsqrt_seed(int mb, int idx, uint32_t *y0, uint32_t *c0);
/* Step 3: Y1 for x in [2^(2MB-2), 2^(2MB+2)); *j = J. */
uint32_t fx_rsqrt_norm(int mb, uint64_t x, int *j);
/* Step 4: R for rest >= 0 (unsigned Q.F); *er = er. */
uint32_t fx_norm_rest(int mb, uint32_t rest, int *er);
/* Step 6 for one lane: the product P = d_k Qm, its shift sh + s. */
fx_t fx_denorm(const fx_format *fmt, int64_t prod, int sh);
/* Steps 1-6. */
bool fx_along(const fx_format *fmt, int dim, const fx_t d[3], fx_t rest, fx_t t[3]);
/*
 * A spring's direction and length on the normalised datapath: u = fx_along(d, 2^(W-2)), the unit
 * vector along d in Q2.(W-2) (d's direction exactly, its length within a few 2^-MB of one), and
 * len = d . u, the exact sum of the DIM products rounded once by W - 2 bits (ties to even) and
 * saturated: |d| within a few 2^-MB. False (no force) when d = 0 or len <= 0. The force's
 * products take u with fx_mul_unit.
 */
bool fx_spring_dir(const fx_format *fmt, int dim, const fx_t d[3], fx_t *len, fx_t u[3]);

/* Conversions for scene constants and reports (not used inside the datapath). */
fx_t fx_from_double(const fx_format *fmt, double v);
double fx_to_double(const fx_format *fmt, fx_t v);

/* Does a double fit the format without saturating? */
bool fx_fits(const fx_format *fmt, double v);

/* Cycles the iterative units take per result: one per resolved bit plus the rounding step. */
static inline int fx_sqrt_iterations(const fx_format *fmt) { return fmt->sqrt_bits + 1; }
static inline int fx_div_iterations(const fx_format *fmt) { return fmt->div_bits + 1; }

#ifdef __cplusplus
}
#endif

#endif
