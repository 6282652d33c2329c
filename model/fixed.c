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
