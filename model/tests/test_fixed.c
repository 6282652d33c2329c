/*
 * test_fixed.c - the fixed-point contract against independent references.
 *
 * The model computes bit-serially (fixed.c); the references here compute the same
 * rounded results another way: long double (64-bit mantissa, exact for these
 * products) with ties-to-even rounding from the FPU, and integer division.
 * Exhaustive at W=8 and W=12, random and edge vectors at W=32.
 */
#include <fenv.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "fixed.h"

static fx_format fmt_of(int w, int f, int sqrt_bits, int div_bits) { return (fx_format){w, f, sqrt_bits, div_bits, 0}; }

static int64_t sat_ref(const fx_format *fmt, long double v)
{
    long double hi = ldexpl(1.0L, fmt->width - 1) - 1, lo = -ldexpl(1.0L, fmt->width - 1);
    return (int64_t)(v > hi ? hi : v < lo ? lo : v);
}

/* round(p / 2^n), ties to even, by the FPU */
static long double round_ref(long double p, int n) { return nearbyintl(ldexpl(p, -n)); }

static int64_t mul_ref(const fx_format *fmt, int64_t a, int64_t b) { return sat_ref(fmt, round_ref((long double)(a * b), fmt->frac)); }

static uint64_t isqrt_ref(uint64_t n)
{
    uint64_t r = (uint64_t)sqrtl((long double)n);
    while (r * r > n) r--;
    while ((r + 1) * (r + 1) <= n) r++;
    return r;
}

/* The root truncated to the resolved bits, then rounded to nearest at the last of them. */
static int64_t sqrt_ref(const fx_format *fmt, uint64_t n)
{
    int lsb = fmt->width - 1 - fmt->sqrt_bits;
    uint64_t unit = UINT64_C(1) << lsb, max = (UINT64_C(1) << (fmt->width - 1)) - 1;
    uint64_t r = isqrt_ref(n);
    if (r > max) return (int64_t)max;
    uint64_t t = r / unit * unit;
    /* round up iff (t + unit/2)^2 <= n, i.e. (2t + unit)^2 <= 4n, exact in long double */
    long double twice = (long double)(2 * t + unit);
    if (twice * twice <= 4.0L * (long double)n) t += unit;
    return (int64_t)(t > max ? max : t);
}

static int64_t div_ref(const fx_format *fmt, uint64_t num, uint64_t den)
{
    int lsb = fmt->width - 1 - fmt->div_bits;
    uint64_t unit = UINT64_C(1) << lsb, max = (UINT64_C(1) << (fmt->width - 1)) - 1;
    uint64_t dividend = num << fmt->frac;
    if (den == 0) return (int64_t)max;
    uint64_t q = dividend / den;
    if (q > max) return (int64_t)max;
    uint64_t t = q / unit * unit;
    /* round up iff the remainder is at least half a unit: 2 (dividend - t den) >= unit den */
    if (2 * (dividend - t * den) >= unit * den) t += unit;
    return (int64_t)(t > max ? max : t);
}

/* ---- exhaustive at narrow widths ---- */

static void exhaust_binary_ops(int w, int f)
{
    fx_format fmt = fmt_of(w, f, w - 1, w - 1);
    int64_t lo = fx_min(&fmt), hi = fx_max(&fmt);
    for (int64_t a = lo; a <= hi; a++)
        for (int64_t b = lo; b <= hi; b++) {
            int64_t mul = fx_mul(&fmt, (fx_t)a, (fx_t)b);
            if (mul != mul_ref(&fmt, a, b)) fail_msg("W=%d F=%d mul %lld * %lld: %lld, expected %lld", w, f, (long long)a, (long long)b, (long long)mul, (long long)mul_ref(&fmt, a, b));
            assert_int_equal(fx_add(&fmt, (fx_t)a, (fx_t)b), sat_ref(&fmt, (long double)(a + b)));
            assert_int_equal(fx_sub(&fmt, (fx_t)a, (fx_t)b), sat_ref(&fmt, (long double)(a - b)));
            assert_int_equal(fx_avg(&fmt, (fx_t)a, (fx_t)b), sat_ref(&fmt, round_ref((long double)(a + b), 1)));
        }
    for (int64_t a = lo; a <= hi; a++) assert_int_equal(fx_half(&fmt, (fx_t)a), round_ref((long double)a, 1));
}

static void test_binary_ops_w8(void **state)
{
    (void)state;
    for (int f = 1; f <= 6; f++) exhaust_binary_ops(8, f);
}

static void test_binary_ops_w12(void **state)
{
    (void)state;
    exhaust_binary_ops(12, 6);
    exhaust_binary_ops(12, 10);
}

static void exhaust_sqrt(int w, int sqrt_bits)
{
    fx_format fmt = fmt_of(w, w / 2, sqrt_bits, w - 1);
    for (uint64_t n = 0; n < (UINT64_C(1) << (2 * w)); n++) {
        int64_t got = fx_sqrt(&fmt, n), want = sqrt_ref(&fmt, n);
        if (got != want) fail_msg("W=%d SQRT_BITS=%d sqrt(%llu): %lld, expected %lld", w, sqrt_bits, (unsigned long long)n, (long long)got, (long long)want);
    }
}

static void test_sqrt_w8_every_radicand_every_bits(void **state)
{
    (void)state;
    for (int s = 1; s <= 7; s++) exhaust_sqrt(8, s);
}

static void test_sqrt_w12_every_radicand(void **state)
{
    (void)state;
    exhaust_sqrt(12, 11);
    exhaust_sqrt(12, 6);
}

static void exhaust_div(int w, int f, int div_bits)
{
    fx_format fmt = fmt_of(w, f, w - 1, div_bits);
    for (uint64_t num = 0; num < (UINT64_C(1) << w); num++)
        for (uint64_t den = 0; den < (UINT64_C(1) << w); den++) {
            bool dz = false;
            int64_t got = fx_div(&fmt, (uint32_t)num, (uint32_t)den, &dz), want = div_ref(&fmt, num, den);
            if (got != want || dz != (den == 0))
                fail_msg("W=%d F=%d DIV_BITS=%d div %llu / %llu: %lld (dz %d), expected %lld", w, f, div_bits, (unsigned long long)num,
                         (unsigned long long)den, (long long)got, dz, (long long)want);
        }
}

static void test_div_w8_every_pair_every_bits(void **state)
{
    (void)state;
    for (int d = 1; d <= 7; d++) exhaust_div(8, 4, d);
    exhaust_div(8, 1, 7);
    exhaust_div(8, 6, 7);
}

static void test_div_w12_every_pair(void **state)
{
    (void)state;
    exhaust_div(12, 8, 11);
}

/* fx_unit_div at full precision is num / den rounded to nearest at W-2 fraction bits:
   |u den - num 2^(W-2)| <= den / 2, for every |num| <= den at W = 8 and 10. */
static void exhaust_unit_div(int w)
{
    fx_format f = {w, w / 2, w - 1, w - 1, 0};
    for (int den = 1; den <= (1 << (w - 1)) - 1; den++)
        for (int num = -den; num <= den; num++) {
            bool dz = true;
            fx_t u = fx_unit_div(&f, num, den, &dz);
            int64_t err = (int64_t)u * den - ((int64_t)num << (w - 2));
            if (dz || 2 * (err < 0 ? -err : err) > den) fail_msg("W=%d: %d / %d gave %d (Q2.%d)", w, num, den, u, w - 2);
        }
}

static void test_unit_div_every_pair(void **state)
{
    (void)state;
    exhaust_unit_div(8);
    exhaust_unit_div(10);
}

/* fx_leg: the root r of h^2 - |d|^2 (in Q2F) rounds it to nearest: (r - 1/2)^2 <= x < (r + 1/2)^2
   in LSB units; *miss exactly when |d| > h. Every h, dx, dy at W = 8 (full precision). */
static void test_leg_w8(void **state)
{
    fx_format f = {8, 4, 7, 7, 0};
    (void)state;
    for (int h = 0; h <= 127; h++)
        for (int dx = -128; dx <= 127; dx++)
            for (int dy = -128; dy <= 127; dy += 3) {
                bool miss;
                fx_t r = fx_leg(&f, h, dx, dy, 0, &miss);
                int64_t x = (int64_t)h * h - ((int64_t)dx * dx + (int64_t)dy * dy);
                if (miss != (x < 0)) fail_msg("h=%d d=(%d,%d): miss=%d", h, dx, dy, miss);
                if (miss) continue;
                /* 4x = (2r)^2 scale: (2r - 1)^2 <= 4x < (2r + 1)^2, unless r saturated at fx_max */
                if (r < fx_max(&f) && !((r == 0 || (2 * r - 1) * (2 * r - 1) <= 4 * x) && 4 * x < (2 * r + 1) * (2 * r + 1)))
                    fail_msg("h=%d d=(%d,%d): root %d of %lld", h, dx, dy, r, (long long)x);
            }
}

/* ---- W=32: random and edge vectors ---- */

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;
static uint64_t rnd(void) /* splitmix64 */
{
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static fx_t rnd_fx(const fx_format *fmt)
{
    static const int64_t edges[] = {0, 1, -1, 2, -2};
    int pick = (int)(rnd() % 16);
    if (pick < 5) return (fx_t)edges[pick];
    if (pick == 5) return fx_max(fmt);
    if (pick == 6) return fx_min(fmt);
    if (pick == 7) return fx_max(fmt) - 1;
    if (pick == 8) return fx_min(fmt) + 1;
    if (pick == 9) return fx_one(fmt);
    if (pick == 10) return -fx_one(fmt);
    if (pick == 11) return (fx_t)((int64_t)(rnd() % 4096) - 2048) << (rnd() % 8); /* small values */
    return (fx_t)(int32_t)(uint32_t)rnd();
}

static void test_w32_random_and_edges(void **state)
{
    (void)state;
    for (int f = 8; f <= 24; f += 8) {
        fx_format fmt = fmt_of(32, f, 31, 31);
        for (int i = 0; i < 200000; i++) {
            fx_t a = rnd_fx(&fmt), b = rnd_fx(&fmt);
            assert_int_equal(fx_mul(&fmt, a, b), mul_ref(&fmt, a, b));
            assert_int_equal(fx_add(&fmt, a, b), sat_ref(&fmt, (long double)a + b));
            assert_int_equal(fx_avg(&fmt, a, b), round_ref((long double)a + b, 1));
            uint64_t n = fx_sumsq(a, b, rnd_fx(&fmt)) >> (rnd() % 64);
            assert_int_equal(fx_sqrt(&fmt, n), sqrt_ref(&fmt, n));
            uint32_t num = (uint32_t)rnd() >> (rnd() % 32), den = (uint32_t)rnd() >> (rnd() % 32);
            assert_int_equal(fx_div(&fmt, num, den, NULL), div_ref(&fmt, num, den));
        }
    }
    /* reduced precision at W=32: the accuracy knobs */
    for (int bits = 1; bits <= 31; bits += 5) {
        fx_format fmt = fmt_of(32, 16, bits, bits);
        for (int i = 0; i < 20000; i++) {
            uint64_t n = rnd() >> (rnd() % 64);
            uint32_t num = (uint32_t)rnd() >> (rnd() % 32), den = (uint32_t)rnd() >> (rnd() % 32);
            assert_int_equal(fx_sqrt(&fmt, n), sqrt_ref(&fmt, n));
            assert_int_equal(fx_div(&fmt, num, den, NULL), div_ref(&fmt, num, den));
        }
    }
}

/* ---- the rules, stated by hand ---- */

static void test_rounding_ties_to_even(void **state)
{
    fx_format q4 = fmt_of(16, 4, 15, 15); /* 1.0 = 16 */
    (void)state;
    assert_int_equal(fx_mul(&q4, 3, 8), 2);   /* 24/16 = 1.5 -> 2 */
    assert_int_equal(fx_mul(&q4, 1, 8), 0);   /* 0.5 -> 0 */
    assert_int_equal(fx_mul(&q4, 5, 8), 2);   /* 2.5 -> 2 */
    assert_int_equal(fx_mul(&q4, -1, 8), 0);  /* -0.5 -> 0 */
    assert_int_equal(fx_mul(&q4, -3, 8), -2); /* -1.5 -> -2 */
    assert_int_equal(fx_mul(&q4, 3, 9), 2);   /* 27/16 = 1.6875 -> 2 */
    assert_int_equal(fx_mul(&q4, -3, 9), -2);
    assert_int_equal(fx_avg(&q4, 1, 2), 2); /* 1.5 -> 2 */
    assert_int_equal(fx_avg(&q4, 1, 0), 0); /* 0.5 -> 0 */
    assert_int_equal(fx_half(&q4, -3), -2); /* -1.5 -> -2 */
}

/* Ties to even is unbiased: the rounding errors of a symmetric sweep cancel exactly. */
static void test_rounding_has_no_bias(void **state)
{
    fx_format fmt = fmt_of(16, 8, 15, 15);
    long long err = 0;
    (void)state;
    for (int a = 0; a < 4096; a++) err += (long long)fx_mul(&fmt, (fx_t)a, 128) * 2 - a; /* a/2 rounded, error x2 */
    assert_int_equal(err, 0);
}

static void test_saturation_never_wraps(void **state)
{
    fx_format fmt = fmt_of(18, 8, 17, 17);
    (void)state;
    assert_int_equal(fx_add(&fmt, fx_max(&fmt), 1), fx_max(&fmt));
    assert_int_equal(fx_sub(&fmt, fx_min(&fmt), 1), fx_min(&fmt));
    assert_int_equal(fx_mul(&fmt, fx_max(&fmt), fx_max(&fmt)), fx_max(&fmt));
    assert_int_equal(fx_mul(&fmt, fx_min(&fmt), fx_max(&fmt)), fx_min(&fmt));
    assert_int_equal(fx_mul(&fmt, fx_min(&fmt), fx_min(&fmt)), fx_max(&fmt));
    assert_int_equal(fx_neg(&fmt, fx_min(&fmt)), fx_max(&fmt));
    assert_int_equal(fx_avg(&fmt, fx_max(&fmt), fx_max(&fmt)), fx_max(&fmt));
    assert_int_equal(fx_avg(&fmt, fx_min(&fmt), fx_min(&fmt)), fx_min(&fmt));
}

static void test_zero_length_is_flagged(void **state)
{
    fx_format fmt = fmt_of(32, 16, 31, 31);
    bool dz = false;
    (void)state;
    assert_int_equal(fx_div(&fmt, 100, 0, &dz), fx_max(&fmt));
    assert_true(dz);
    fx_div(&fmt, 100, 1, &dz);
    assert_false(dz);
    assert_int_equal(fx_sqrt(&fmt, 0), 0);
    assert_int_equal(fx_div_signed(&fmt, -fx_one(&fmt), 2 * fx_one(&fmt), NULL), -fx_one(&fmt) / 2);
}

static void test_format_check(void **state)
{
    fx_format ok = fmt_of(18, 8, 17, 17), wide = fmt_of(33, 8, 17, 17), frac = fmt_of(18, 17, 17, 17), sq = fmt_of(18, 8, 18, 17),
              dv = fmt_of(18, 8, 17, 0);
    (void)state;
    assert_null(fx_format_check(&ok));
    assert_non_null(fx_format_check(&wide));
    assert_non_null(fx_format_check(&frac));
    assert_non_null(fx_format_check(&sq));
    assert_non_null(fx_format_check(&dv));
}

/* ---- the normalised distance datapath (fx_along) ----
 *
 * along_ref restates fx_along's six steps (fixed.h) in long double: leading ones by frexpl,
 * every "round" as nearbyintl of an exact scaled value (ties to even, FE_TONEAREST), the seed's
 * integer root by sqrtl. Every value here is an integer below 2^62, exact in long double's
 * 64-bit mantissa, so the two must agree bit for bit; a slip in a shift, a rounding or a clamp
 * of either shows. */
static int lead_ref(long double v) /* floor(log2 v), v >= 1 */
{
    int e;
    frexpl(v, &e);
    return e - 1;
}

static long double mant_ref(int mb, long double v, int n) /* v 2^-n rounded, kept below 2^MB */
{
    long double r = nearbyintl(ldexpl(v, -n)), top = ldexpl(1.0L, mb) - 1;
    return r > top ? top : r;
}

static bool along_ref(const fx_format *fmt, int dim, const fx_t d[3], fx_t rest_word, fx_t t[3])
{
    const int mb = fmt->mantissa, tb = mb / 2 + 1;
    long double any = 0, m[3] = {0, 0, 0}, x = 0, top = ldexpl(1.0L, mb) - 1;
    for (int k = 0; k < 3; k++) t[k] = 0;
    for (int k = 0; k < dim; k++) any = fmaxl(any, fabsl((long double)d[k]));
    if (any == 0) return false;
    int l = lead_ref(any);
    for (int k = 0; k < dim; k++) {
        m[k] = nearbyintl(ldexpl((long double)d[k], mb - 1 - l));
        if (m[k] > top) m[k] = top;
        x += m[k] * m[k];
    }
    /* the reciprocal root of x */
    int lx = lead_ref(x), p = lx & 1, j = lx >> 1;
    long double xr = mant_ref(mb, x, lx - (mb - 1));
    long double f = floorl(ldexpl(x, -(lx - tb + 1))) - ldexpl(1.0L, tb - 1); /* the T - 1 bits under x's lead */
    long double n = ldexpl(ldexpl(1.0L, tb) + 2 * f + 1, p);
    long double z = floorl(ldexpl(1.0L, 2 * mb + tb + 2) / n), r = floorl(sqrtl(z));
    while (r * r > z) r--;
    while ((r + 1) * (r + 1) <= z) r++;
    long double y0 = floorl((r + 1) / 2), c0 = mant_ref(mb, y0 * y0 * y0, 2 * mb);
    long double y1 = nearbyintl(ldexpl(3 * y0 * ldexpl(1.0L, mb - 1) - xr * c0 * ldexpl(1.0L, p), -mb));
    y1 = y1 < 0 ? 0 : y1 > top ? top : y1;
    /* rest, the ratio's mantissa, the shift back */
    long double rest = (long double)((uint32_t)rest_word & (uint32_t)(((uint64_t)1 << fmt->width) - 1));
    int lr = lead_ref(rest > 1 ? rest : 1), er = lr - (mb - 1);
    long double rm = mant_ref(mb, rest, er), q = rm * y1;
    int b = q >= ldexpl(1.0L, 2 * mb - 1);
    long double qm = mant_ref(mb, q, mb - 1 + b);
    int sh = j + 1 - b - er + (l - (mb - 1));
    for (int k = 0; k < dim; k++) t[k] = (fx_t)sat_ref(fmt, nearbyintl(ldexpl((long double)d[k] * qm, -sh)));
    return true;
}

static void along_check(const fx_format *fmt, int dim, const fx_t d[3], fx_t rest)
{
    fx_t got[3], want[3];
    bool ok = fx_along(fmt, dim, d, rest, got), ok_ref = along_ref(fmt, dim, d, rest, want);
    bool same = ok == ok_ref;
    for (int k = 0; k < dim; k++) same = same && got[k] == want[k];
    if (!same)
        fail_msg("W=%d MB=%d d=(%d, %d, %d) rest=%d: (%d, %d, %d) ok %d, expected (%d, %d, %d) ok %d", fmt->width, fmt->mantissa, d[0],
                 d[1], dim == 3 ? d[2] : 0, rest, got[0], got[1], got[2], ok, want[0], want[1], want[2], ok_ref);
}

/* Every d at W = 8 in 2D, each with a quarter of the rest words (MB = 6) or a drawn one (MB = 8);
   in 3D every (d.x, d.y) with a seventh of the d.z and a drawn rest. (tb/along_units.cpp checks the
   RTL against fx_along on every d and rest of W = 8.) */
static void test_along_w8_exhaustive(void **state)
{
    (void)state;
    for (int mb = 6; mb <= 8; mb += 2) {
        fx_format fmt = {8, 4, 7, 7, mb};
        for (int dx = -128; dx <= 127; dx++)
            for (int dy = -128; dy <= 127; dy++) {
                fx_t d[3] = {dx, dy, 0};
                if (mb == 6)
                    for (int rest = -128 + (dx + dy + 256) % 4; rest <= 127; rest += 4) along_check(&fmt, 2, d, rest);
                else
                    along_check(&fmt, 2, d, (fx_t)(int8_t)rnd());
                for (int dz = -128 + (dx + dy + 384) % 7; dz <= 127; dz += 7) {
                    fx_t d3[3] = {dx, dy, dz};
                    along_check(&fmt, 3, d3, (fx_t)(int8_t)rnd());
                }
            }
    }
}

/* Random and edge lanes (zero, one, the extremes, very different sizes) at W = 12..32 and
   MB = 6..20, 2D and 3D. */
static void test_along_random_and_edges(void **state)
{
    static const int cfg[][2] = {{32, 17}, {32, 8}, {32, 20}, {32, 6}, {18, 17}, {24, 12}, {12, 11}, {16, 20}};
    (void)state;
    for (size_t c = 0; c < sizeof cfg / sizeof cfg[0]; c++) {
        fx_format fmt = {cfg[c][0], cfg[c][0] / 2, cfg[c][0] - 1, cfg[c][0] - 1, cfg[c][1]};
        for (int i = 0; i < 50000; i++) {
            fx_t d[3];
            for (int k = 0; k < 3; k++) d[k] = fx_sat(&fmt, rnd_fx(&fmt)) >> (rnd() % 3 == 0 ? rnd() % fmt.width : 0);
            along_check(&fmt, 2 + (i & 1), d, fx_sat(&fmt, rnd_fx(&fmt)));
        }
    }
}

/* The contract's accuracy: t is d rest / |d| (exact, long double) within 6 2^-MB rest + 1 LSB
   (the steps' roundings; measured: at most 4.4 2^-MB rest), and the zero vector is flagged. */
static void test_along_error_bound(void **state)
{
    (void)state;
    for (int mb = 6; mb <= 20; mb++) {
        fx_format fmt = {32, 16, 31, 31, mb};
        for (int i = 0; i < 20000; i++) {
            int dim = 2 + (i & 1), bits = 1 + (int)(rnd() % 30);
            fx_t d[3] = {0, 0, 0}, t[3], rest = (fx_t)(rnd() >> (64 - 1 - (int)(rnd() % 29)));
            long double len = 0;
            for (int k = 0; k < dim; k++) {
                d[k] = (fx_t)((int64_t)(rnd() >> (64 - bits)) - ((int64_t)1 << (bits - 1)));
                len += (long double)d[k] * d[k];
            }
            if (!fx_along(&fmt, dim, d, rest, t)) {
                assert_true(len == 0);
                continue;
            }
            for (int k = 0; k < dim; k++) {
                long double exact = (long double)d[k] * rest / sqrtl(len), err = fabsl(t[k] - exact);
                if (err > 6 * ldexpl(rest, -mb) + 1)
                    fail_msg("MB=%d d=(%d, %d, %d) rest=%d: lane %d is %d, exactly %.3Lf", mb, d[0], d[1], d[2], rest, k, t[k], exact);
            }
        }
    }
    fx_format fmt = {32, 16, 31, 31, 17};
    fx_t zero[3] = {0, 0, 0}, t[3] = {1, 1, 1};
    assert_false(fx_along(&fmt, 3, zero, 100, t));
    assert_true(t[0] == 0 && t[1] == 0 && t[2] == 0);
}

/* fx_spring_dir: u is fx_along's vector of length 2^(W-2) along d, len the exact d . u rounded by
   W - 2 bits (checked bit for bit in long double), within 6 2^-MB |d| + 1 LSB of |d|; no
   direction for d = 0. */
static void test_spring_dir(void **state)
{
    static const int cfg[][2] = {{32, 17}, {32, 8}, {24, 14}, {18, 11}, {12, 6}};
    (void)state;
    for (size_t c = 0; c < sizeof cfg / sizeof cfg[0]; c++) {
        fx_format fmt = {cfg[c][0], cfg[c][0] / 2, cfg[c][0] - 1, cfg[c][0] - 1, cfg[c][1]};
        const int w = fmt.width, mb = fmt.mantissa;
        for (int i = 0; i < 20000; i++) {
            int dim = 2 + (i & 1);
            fx_t d[3] = {0, 0, 0}, u[3], want[3], len;
            long double dd = 0, dot = 0;
            for (int k = 0; k < dim; k++) {
                d[k] = fx_sat(&fmt, rnd_fx(&fmt)) >> (rnd() % 3 == 0 ? rnd() % w : 0);
                dd += (long double)d[k] * d[k];
            }
            bool ok = fx_spring_dir(&fmt, dim, d, &len, u);
            bool along = fx_along(&fmt, dim, d, (fx_t)(INT64_C(1) << (w - 2)), want);
            if (dd == 0) {
                assert_false(ok);
                continue;
            }
            for (int k = 0; k < dim; k++) {
                if (u[k] != want[k]) fail_msg("W=%d MB=%d: u is not fx_along's vector of length 2^(W-2)", w, mb);
                dot += (long double)d[k] * u[k];
            }
            assert_true(along);
            long double ref = sat_ref(&fmt, nearbyintl(ldexpl(dot, -(w - 2))));
            if (ok != (ref > 0) || (ok && len != ref))
                fail_msg("W=%d MB=%d d=(%d, %d, %d): len %d, d . u rounded is %.0Lf", w, mb, d[0], d[1], d[2], len, ref);
            long double mag = fminl(sqrtl(dd), (long double)fx_max(&fmt));   /* a length past the range saturates */
            if (ok && fabsl(len - mag) > 6 * ldexpl(mag, -mb) + 1)
                fail_msg("W=%d MB=%d d=(%d, %d, %d): len %d, |d| %.3Lf", w, mb, d[0], d[1], d[2], len, sqrtl(dd));
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_binary_ops_w8),
        cmocka_unit_test(test_binary_ops_w12),
        cmocka_unit_test(test_sqrt_w8_every_radicand_every_bits),
        cmocka_unit_test(test_sqrt_w12_every_radicand),
        cmocka_unit_test(test_div_w8_every_pair_every_bits),
        cmocka_unit_test(test_div_w12_every_pair),
        cmocka_unit_test(test_w32_random_and_edges),
        cmocka_unit_test(test_rounding_ties_to_even),
        cmocka_unit_test(test_rounding_has_no_bias),
        cmocka_unit_test(test_saturation_never_wraps),
        cmocka_unit_test(test_zero_length_is_flagged),
        cmocka_unit_test(test_format_check),
        cmocka_unit_test(test_unit_div_every_pair),
        cmocka_unit_test(test_leg_w8),
        cmocka_unit_test(test_along_w8_exhaustive),
        cmocka_unit_test(test_along_random_and_edges),
        cmocka_unit_test(test_along_error_bound),
        cmocka_unit_test(test_spring_dir),
    };
    fesetround(FE_TONEAREST);
    return cmocka_run_group_tests_name("fixed-point arithmetic", tests, NULL, NULL);
}
