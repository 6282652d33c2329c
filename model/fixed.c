/*
 * fixed.c - the iterative units of fixed.h, written as the hardware runs them:
 * one result bit per loop iteration, most significant first, with the partial
 * remainder kept as an integer. Widths: a radicand is any 2W-bit value (up to
 * 2^64 - 1 at W = 32), but one of 2^(2W-2) or more saturates before the loop, so
 * the loop's remainder and trial terms stay below 2^62; a dividend is below 2^62.
 * Callers pass magnitudes below 2^W (the RTL sees only W bits).
 */
#include "fixed.h"

#include <math.h>

const char *fx_format_check(const fx_format *fmt)
{
    if (fmt->width < FX_MIN_WIDTH || fmt->width > FX_MAX_WIDTH)
        return "width must be 8..32 bits";
    if (fmt->frac < 1 || fmt->frac > fmt->width - 2)
        return "fraction bits must be 1..width-2";
    if (fmt->sqrt_bits < 1 || fmt->sqrt_bits > fmt->width - 1)
        return "sqrt_bits must be 1..width-1";
    if (fmt->div_bits < 1 || fmt->div_bits > fmt->width - 1)
        return "div_bits must be 1..width-1";
    if (fmt->mantissa != 0 && (fmt->mantissa < FX_MIN_MANTISSA || fmt->mantissa > FX_MAX_MANTISSA))
        return "mantissa must be 0 (the full-width datapath) or 6..20 bits";
    return 0;
}

/*
 * Restoring square root. Invariant: rem = radicand - root^2 >= 0. Trying bit b adds
 * (root + 2^b)^2 - root^2 = root * 2^(b+1) + 2^(2b) to root^2.
 */
fx_t fx_sqrt(const fx_format *fmt, uint64_t radicand)
{
    const int mag_bits = fmt->width - 1;
    const uint64_t max = (uint64_t)fx_max(fmt);
    const int lsb = mag_bits - fmt->sqrt_bits; /* lowest resolved root bit */
    uint64_t root = 0;
    uint64_t rem = radicand;
    bool round_up;
    int bit;

    if (radicand >> (2 * mag_bits)) /* root >= 2^(W-1): does not fit */
        return (fx_t)max;
    for (bit = mag_bits - 1; bit >= lsb; bit--) {
        uint64_t step = (root << (bit + 1)) + (UINT64_C(1) << (2 * bit));
        if (rem >= step) {
            rem -= step;
            root |= UINT64_C(1) << bit;
        }
    }
    /* Rounding iteration: would the next bit (worth half an LSB) still fit? */
    if (lsb > 0)
        round_up = rem >= (root << lsb) + (UINT64_C(1) << (2 * (lsb - 1)));
    else
        round_up = rem > root; /* (root + 1/2)^2 <= radicand, in integers */
    if (round_up)
        root += UINT64_C(1) << lsb;
    return (fx_t)(root > max ? max : root);
}

/*
 * Restoring division of num * 2^F by den. Invariant: rem < den * 2^(bit+1) before
 * bit is tried; the dividend is checked first so that the quotient fits W-1 bits.
 */
fx_t fx_div(const fx_format *fmt, uint32_t num, uint32_t den, bool *div_by_zero)
{
    const int mag_bits = fmt->width - 1;
    const uint64_t max = (uint64_t)fx_max(fmt);
    const int lsb = mag_bits - fmt->div_bits;
    const uint64_t dividend = (uint64_t)num << fmt->frac;
    uint64_t quot = 0;
    uint64_t rem = dividend;
    bool round_up;
    int bit;

    if (div_by_zero)
        *div_by_zero = den == 0;
    if (den == 0)
        return (fx_t)max;
    if (dividend >= ((uint64_t)den << mag_bits)) /* quotient >= 2^(W-1) */
        return (fx_t)max;
    for (bit = mag_bits - 1; bit >= lsb; bit--) {
        uint64_t step = (uint64_t)den << bit;
        if (rem >= step) {
            rem -= step;
            quot |= UINT64_C(1) << bit;
        }
    }
    /* Rounding iteration: is the remainder at least half a quotient LSB? Ties round up. */
    if (lsb > 0)
        round_up = rem >= ((uint64_t)den << (lsb - 1));
    else
        round_up = 2 * rem >= den;
    if (round_up)
        quot += UINT64_C(1) << lsb;
    return (fx_t)(quot > max ? max : quot);
}

fx_t fx_unit_div(const fx_format *fmt, fx_t num, fx_t den, bool *div_by_zero)
{
    fx_format u = fx_unit_format(fmt);
    return fx_div_signed(&u, num, den, div_by_zero);
}

fx_t fx_leg(const fx_format *fmt, fx_t h, fx_t dx, fx_t dy, fx_t dz, bool *miss)
{
    uint64_t hh = (uint64_t)((int64_t)h * h), dd = fx_sumsq(dx, dy, dz);
    *miss = dd > hh;
    return *miss ? 0 : fx_sqrt(fmt, hh - dd);
}

fx_t fx_div_signed(const fx_format *fmt, fx_t num, fx_t den, bool *div_by_zero)
{
    uint32_t mag = num < 0 ? (uint32_t)(-(int64_t)num) : (uint32_t)num;
    fx_t q = fx_div(fmt, mag, den < 0 ? 0u : (uint32_t)den, div_by_zero);
    return num < 0 ? -q : q; /* q <= fx_max, so -q never overflows */
}

fx_t fx_from_double(const fx_format *fmt, double v)
{
    double scaled = v * ldexp(1.0, fmt->frac);
    if (scaled >= (double)fx_max(fmt)) return fx_max(fmt);
    if (scaled <= (double)fx_min(fmt)) return fx_min(fmt);
    return (fx_t)llround(scaled);
}

double fx_to_double(const fx_format *fmt, fx_t v) { return ldexp((double)v, -fmt->frac); }

bool fx_fits(const fx_format *fmt, double v)
{
    double scaled = v * ldexp(1.0, fmt->frac);
    return scaled <= (double)fx_max(fmt) + 0.5 && scaled >= (double)fx_min(fmt) - 0.5;
}

/* ---- the normalised distance datapath (fixed.h, fx_along) ---- */

int fx_msb(uint64_t v)
{
    int b = 0;
    while (v >>= 1) b++;
    return b;
}

/* An unsigned mantissa rounded out of v by n bits (n > 0) or shifted left (n <= 0), kept below 2^MB. */
static uint64_t mant_unsigned(int mb, uint64_t v, int n)
{
    uint64_t top = (UINT64_C(1) << mb) - 1;
    uint64_t r = n > 0 ? (uint64_t)fx_round_shift((int64_t)v, n) : v << -n;
    return r > top ? top : r;
}

int fx_norm_lanes(int mb, int dim, const fx_t d[3], int64_t m[3])
{
    uint64_t any = 0, top = (UINT64_C(1) << mb) - 1;
    int s;
    for (int k = 0; k < 3; k++) m[k] = 0;
    for (int k = 0; k < dim; k++) any |= (uint64_t)(d[k] < 0 ? -(int64_t)d[k] : d[k]);
    if (!any) return INT32_MIN;
    s = fx_msb(any) - (mb - 1);
    for (int k = 0; k < dim; k++) {
        int64_t v = s > 0 ? fx_round_shift(d[k], s) : (int64_t)d[k] * (INT64_C(1) << -s);
        m[k] = v > (int64_t)top ? (int64_t)top : v; /* rounding up to 2^MB: clamped; -2^MB fits */
    }
    return s;
}

/*
 * The table entry for index idx = {p, f}: the interval of v it covers is 2^p [1 + f/2^(T-1),
 * 1 + (f+1)/2^(T-1)), its middle vm = 2^p (2^T + 2f + 1) / 2^T = n / 2^T. Y0 = 2^MB / sqrt(vm) in
 * integers: Z = floor(2^(2MB+T+2) / n), Y0 = (isqrt(Z) + 1) / 2 (isqrt(Z) ~ 2 sqrt(2^(2MB+T) / n),
 * so this rounds it to nearest but for the floor of Z); C0 = Y0^3 2^-2MB rounded, clamped.
 */
void fx_rsqrt_seed(int mb, int idx, uint32_t *y0, uint32_t *c0)
{
    int t = fx_rsqrt_table_bits(mb);
    int p = idx >> (t - 1), f = idx & ((1 << (t - 1)) - 1);
    uint64_t n = ((UINT64_C(1) << t) + 2 * (uint64_t)f + 1) << p;
    uint64_t z = (UINT64_C(1) << (2 * mb + t + 2)) / n, r = 0, y, cube;
    for (int bit = 31; bit >= 0; bit--) { /* floor(sqrt(z)), z < 2^44 */
        uint64_t tr = r | (UINT64_C(1) << bit);
        if (tr * tr <= z) r = tr;
    }
    y = (r + 1) >> 1;
    cube = y * y * y; /* < 2^(3MB) <= 2^60 */
    *y0 = (uint32_t)y;
    *c0 = (uint32_t)mant_unsigned(mb, cube, 2 * mb);
}

uint32_t fx_rsqrt_norm(int mb, uint64_t x, int *j)
{
    int lx = fx_msb(x), t = fx_rsqrt_table_bits(mb);
    int p = lx & 1, sh = lx - (mb - 1);
    uint64_t xr = mant_unsigned(mb, x, sh), xt = x >> sh;
    int idx = (p << (t - 1)) | (int)((xt >> (mb - t)) & ((UINT64_C(1) << (t - 1)) - 1));
    uint32_t y0, c0;
    int64_t n, y1;
    fx_rsqrt_seed(mb, idx, &y0, &c0);
    *j = lx >> 1;
    n = 3 * (int64_t)y0 * (INT64_C(1) << (mb - 1)) - (int64_t)(xr * c0) * (1 << p);
    y1 = fx_round_shift(n, mb);
    if (y1 < 0) y1 = 0;
    if (y1 > (INT64_C(1) << mb) - 1) y1 = (INT64_C(1) << mb) - 1;
    return (uint32_t)y1;
}

uint32_t fx_norm_rest(int mb, uint32_t rest, int *er)
{
    *er = fx_msb(rest > 1 ? rest : 1) - (mb - 1);
    return (uint32_t)mant_unsigned(mb, rest, *er);
}

fx_t fx_denorm(const fx_format *fmt, int64_t prod, int sh)
{
    if (sh > 0) return fx_sat(fmt, fx_round_shift(prod, sh));
    /* a left shift: |prod| <= 2^(W-1+MB) and sh >= MB-W, so the result stays below 2^(2W-1) <= 2^63 */
    return fx_sat(fmt, prod * (INT64_C(1) << -sh));
}

bool fx_along(const fx_format *fmt, int dim, const fx_t d[3], fx_t rest, fx_t t[3])
{
    const int mb = fmt->mantissa;
    int64_t m[3];
    uint64_t x = 0, q;
    uint32_t y1, r, qm;
    int j, er, b, sn;
    for (int k = 0; k < 3; k++) t[k] = 0;
    if ((sn = fx_norm_lanes(mb, dim, d, m)) == INT32_MIN) return false;
    for (int k = 0; k < dim; k++) x += (uint64_t)(m[k] * m[k]);
    y1 = fx_rsqrt_norm(mb, x, &j);
    r = fx_norm_rest(mb, (uint32_t)rest & (uint32_t)(((uint64_t)1 << fmt->width) - 1), &er); /* the W-bit word, unsigned */
    q = (uint64_t)r * y1;
    b = q >> (2 * mb - 1) ? 1 : 0;
    qm = (uint32_t)mant_unsigned(mb, q, mb - 1 + b);
    for (int k = 0; k < dim; k++) t[k] = fx_denorm(fmt, (int64_t)d[k] * qm, j + 1 - b - er + sn);
    return true;
}

bool fx_spring_dir(const fx_format *fmt, int dim, const fx_t d[3], fx_t *len, fx_t u[3])
{
    int64_t dot = 0;
    *len = 0;
    if (!fx_along(fmt, dim, d, (fx_t)(INT64_C(1) << (fmt->width - 2)), u)) return false;
    /* u is parallel to d, so every product is >= 0 (or a rounding's 0) and the sum stays below
       |d| 2^(W-2) (1 + 2^-5) < 2^63 */
    for (int k = 0; k < dim; k++) dot += (int64_t)d[k] * u[k];
    *len = fx_sat(fmt, fx_round_shift(dot, fmt->width - 2));
    return *len > 0;
}
