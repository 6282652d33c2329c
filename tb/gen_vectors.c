/*
 * gen_vectors - test vectors for the RTL arithmetic units, computed by model/fixed.c.
 *
 * usage: gen_vectors UNIT MODE W F BITS OUT.hex
 *   UNIT  add | mul | avg | sqrt | div
 *   MODE  exhaustive (every operand pair, every radicand; meant for W = 8)
 *         random     (every pair of edge values, targeted cases, and random
 *                     operands from a fixed seed)
 *   W, F  the format; BITS is SQRT_BITS for sqrt, DIV_BITS for div (ignored else)
 * Writes one record per line for $readmemh and prints the record count on stdout.
 *
 * Record: hex digits, most significant first:
 *   one flag digit, then each operand, then the expected result. A W-bit field
 *   takes ceil(W/4) digits, the sqrt radicand ceil(2W/4). Values are two's
 *   complement truncated to the field width.
 *     add   flags {0, 0, sat, sub}  a, b, y     y = sub ? fx_sub(a, b) : fx_add(a, b)
 *     mul   flags {0, 0, 0, sat}    a, b, y     y = fx_mul(a, b)
 *     avg   flags 0                 a, b, y     y = fx_avg(a, b) (= fx_half(a) when b = 0)
 *     sqrt  flags {0, 0, 0, sat}    rad, y      y = fx_sqrt(rad)
 *     div   flags {0, 0, sat, dbz}  num, den, y y = fx_div(num, den)
 * The "sat" flags are computed here independently of the model, from exact integer
 * arithmetic, and the model's result is checked against them (a clamped result must
 * be the limit).
 */
#include "../model/fixed.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static fx_format fmt;
static FILE *out;
static long count;
static int digits;      /* hex digits of a W-bit field */
static int rad_digits;  /* hex digits of a 2W-bit field */

static void die(const char *msg)
{
    fprintf(stderr, "gen_vectors: %s\n", msg);
    exit(2);
}

/* splitmix64: a fixed, portable pseudo-random sequence. */
static uint64_t rng_state = UINT64_C(0x5374726164313233);
static uint64_t rng(void)
{
    uint64_t z = (rng_state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static uint64_t mask_bits(int n) { return n >= 64 ? ~UINT64_C(0) : (UINT64_C(1) << n) - 1; }
static uint64_t wmask(void) { return mask_bits(fmt.width); }

/* A signed W-bit value from raw bits. */
static fx_t sext(uint64_t v)
{
    uint64_t m = wmask();
    v &= m;
    if (v >> (fmt.width - 1)) return (fx_t)((int64_t)v - (int64_t)(m + 1));
    return (fx_t)v;
}

/* Random W-bit value, log-uniform in magnitude half of the time. */
static uint64_t rand_w(void)
{
    uint64_t r = rng();
    if (r & 1) return (rng() & wmask());
    return ((rng() & wmask()) >> ((r >> 1) % (uint64_t)fmt.width)) ^ (((r >> 8) & 1) ? wmask() : 0);
}

static void put(int ndig, uint64_t v)
{
    fprintf(out, "%0*" PRIx64, ndig, v & mask_bits(4 * ndig));
}

static void rec_begin(unsigned flags) { fprintf(out, "%x", flags & 0xf); }
static void rec_end(void) { fputc('\n', out); count++; }

/* ---- add / sub ---- */
static void vec_add(fx_t a, fx_t b, int sub)
{
    int64_t exact = sub ? (int64_t)a - b : (int64_t)a + b;
    int sat = exact > fx_max(&fmt) || exact < fx_min(&fmt);
    fx_t y = sub ? fx_sub(&fmt, a, b) : fx_add(&fmt, a, b);
    if (sat && y != (exact > 0 ? fx_max(&fmt) : fx_min(&fmt))) die("model add/sub: clamp mismatch");
    rec_begin((unsigned)(sat << 1 | sub));
    put(digits, (uint64_t)a); put(digits, (uint64_t)b); put(digits, (uint64_t)y);
    rec_end();
}

/* ---- mul ---- */
static void vec_mul(fx_t a, fx_t b)
{
    /* Exact rounding to nearest, ties to even, written independently of the model. */
    int64_t p = (int64_t)a * b;
    int64_t unit = INT64_C(1) << fmt.frac;
    int64_t q = p / unit, r = p % unit; /* C99: truncates toward zero */
    if (r < 0) { q--; r += unit; }      /* floor */
    if (2 * r > unit || (2 * r == unit && (q & 1))) q++;
    int sat = q > fx_max(&fmt) || q < fx_min(&fmt);
    fx_t y = fx_mul(&fmt, a, b);
    if (y != (sat ? (q > 0 ? fx_max(&fmt) : fx_min(&fmt)) : (fx_t)q)) die("model fx_mul disagrees with exact rounding");
    rec_begin((unsigned)sat);
    put(digits, (uint64_t)a); put(digits, (uint64_t)b); put(digits, (uint64_t)y);
    rec_end();
}

/* ---- avg / half ---- */
static void vec_avg(fx_t a, fx_t b)
{
    fx_t y = fx_avg(&fmt, a, b);
    if (b == 0 && y != fx_half(&fmt, a)) die("model fx_avg(a, 0) != fx_half(a)");
    rec_begin(0);
    put(digits, (uint64_t)a); put(digits, (uint64_t)b); put(digits, (uint64_t)y);
    rec_end();
}

/* ---- sqrt ---- */
static void vec_sqrt(uint64_t rad)
{
    const int m = fmt.width - 1, lsb = m - fmt.sqrt_bits;
    int sat;
    rad &= mask_bits(2 * fmt.width);
    /* Clamped iff the root rounded at bit lsb reaches 2^m: (2^m - 2^lsb/2)^2 <= rad. */
    if (rad >> (2 * m))
        sat = 1;
    else if (lsb > 0) {
        uint64_t edge = (UINT64_C(1) << m) - (UINT64_C(1) << (lsb - 1));
        sat = rad >= edge * edge;
    } else {
        sat = rad > (UINT64_C(1) << (2 * m)) - (UINT64_C(1) << m);
    }
    fx_t y = fx_sqrt(&fmt, rad);
    if (sat && y != fx_max(&fmt)) die("model fx_sqrt: clamped result is not fx_max");
    if (y < 0 || y > fx_max(&fmt)) die("model fx_sqrt: result out of range");
    rec_begin((unsigned)sat);
    put(rad_digits, rad); put(digits, (uint64_t)y);
    rec_end();
}

/* ---- div ---- */
static void vec_div(uint64_t num, uint64_t den)
{
    const int m = fmt.width - 1, lsb = m - fmt.div_bits;
    bool dbz = false;
    int sat = 0;
    num &= wmask();
    den &= wmask();
    /* Clamped iff num*2^F/den rounded (half up) at bit lsb reaches 2^m:
       2 * num * 2^F >= den * (2^(m+1) - 2^lsb). Both sides < 2^64. */
    if (den != 0)
        sat = (num << (fmt.frac + 1)) >= den * ((UINT64_C(1) << (m + 1)) - (UINT64_C(1) << lsb));
    fx_t y = fx_div(&fmt, (uint32_t)num, (uint32_t)den, &dbz);
    if (dbz != (den == 0)) die("model fx_div: div_by_zero flag wrong");
    if ((dbz || sat) && y != fx_max(&fmt)) die("model fx_div: clamped result is not fx_max");
    if (y < 0 || y > fx_max(&fmt)) die("model fx_div: result out of range");
    rec_begin((unsigned)(sat << 1 | dbz));
    put(digits, num); put(digits, den); put(digits, (uint64_t)y);
    rec_end();
}

/* Edge values of a signed W-bit operand. */
static int signed_edges(fx_t *e)
{
    const int w = fmt.width, f = fmt.frac;
    const fx_t max = fx_max(&fmt), min = fx_min(&fmt), one = fx_one(&fmt);
    const fx_t root_max = (fx_t)1 << ((w - 1 + f) / 2); /* squares near the top */
    fx_t base[] = { 0, 1, -1, 2, -2, 3, -3, max, min, max - 1, min + 1, max / 2, min / 2,
                    max / 2 + 1, min / 2 - 1, one, -one, one + 1, -one - 1, one - 1, -one + 1,
                    one / 2, -one / 2, one / 2 + 1, -one / 2 - 1, 3 * (one / 2), -3 * (one / 2),
                    root_max, -root_max, root_max - 1, -root_max + 1, root_max + 1, -root_max - 1 };
    int n = 0;
    for (size_t i = 0; i < sizeof base / sizeof base[0]; i++) {
        fx_t v = base[i];
        int dup = 0;
        if (v > max || v < min) continue;
        for (int j = 0; j < n; j++) dup |= e[j] == v;
        if (!dup) e[n++] = v;
    }
    return n;
}

/* Edge values of an unsigned W-bit operand (div). */
static int unsigned_edges(uint64_t *e)
{
    const int w = fmt.width, f = fmt.frac;
    const uint64_t all = wmask(), half = UINT64_C(1) << (w - 1), one = UINT64_C(1) << f;
    uint64_t base[] = { 0, 1, 2, 3, all, all - 1, half, half - 1, half + 1, half - 2,
                        one, one - 1, one + 1, one / 2, one * 2, one * 3 / 2,
                        half >> f, (half >> f) + 1, (half >> f) - 1, (all >> f), (all >> f) + 1 };
    int n = 0;
    for (size_t i = 0; i < sizeof base / sizeof base[0]; i++) {
        uint64_t v = base[i] & all;
        int dup = 0;
        for (int j = 0; j < n; j++) dup |= e[j] == v;
        if (!dup) e[n++] = v;
    }
    return n;
}

#define N_RANDOM 4000

static void gen_binary(const char *unit, int exhaustive)
{
    const int w = fmt.width, f = fmt.frac;
    if (exhaustive) {
        for (uint64_t ua = 0; ua <= wmask(); ua++)
            for (uint64_t ub = 0; ub <= wmask(); ub++) {
                fx_t a = sext(ua), b = sext(ub);
                if (!strcmp(unit, "add")) { vec_add(a, b, 0); vec_add(a, b, 1); }
                else if (!strcmp(unit, "mul")) vec_mul(a, b);
                else vec_avg(a, b);
            }
        return;
    }
    fx_t e[64];
    int n = signed_edges(e);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            if (!strcmp(unit, "add")) { vec_add(e[i], e[j], 0); vec_add(e[i], e[j], 1); }
            else if (!strcmp(unit, "mul")) vec_mul(e[i], e[j]);
            else vec_avg(e[i], e[j]);
        }
    /* Targeted: rounding ties (odd * 2^(F-1) for mul, odd sums for avg), half, and
       products at the saturation boundary. */
    for (int i = 0; i < 200; i++) {
        fx_t k = sext(rand_w()) | 1;
        fx_t h = (fx_t)1 << (f - 1);
        fx_t s = (i & 1) ? -1 : 1;
        if (!strcmp(unit, "mul")) {
            vec_mul((fx_t)fx_asr(k, i % w) | 1, s * h);  /* exact ties: odd * half an LSB */
            vec_mul(sext(rand_w()), s * h);
            fx_t r = (fx_t)(rng() % (uint64_t)((fx_t)1 << ((w - 1 + f) / 2))) + 1;
            int64_t c = ((int64_t)fx_max(&fmt) << f) / r; /* r * c near the top of the range */
            if (c >= fx_max(&fmt)) c = fx_max(&fmt) - 1;
            vec_mul(r, (fx_t)c); vec_mul(-r, (fx_t)c); vec_mul(r, (fx_t)c + 1); vec_mul(-r, (fx_t)c + 1);
        } else if (!strcmp(unit, "avg")) {
            fx_t a = sext(rand_w());
            vec_avg(a, 0);                              /* fx_half */
            vec_avg(a, a ^ 1);                          /* odd sum: a tie */
        } else {
            fx_t a = sext(rand_w());
            vec_add(a, fx_max(&fmt) - a, 0); vec_add(a, fx_max(&fmt) - a + 1, 0);
            vec_add(a, a - fx_max(&fmt), 1); vec_add(a, a - fx_max(&fmt) - 1, 1);
        }
    }
    for (int i = 0; i < N_RANDOM; i++) {
        fx_t a = sext(rand_w()), b = sext(rand_w());
        if (!strcmp(unit, "add")) vec_add(a, b, i & 1);
        else if (!strcmp(unit, "mul")) vec_mul(a, b);
        else vec_avg(a, b);
    }
}

static void gen_sqrt(int exhaustive)
{
    const int w = fmt.width, m = w - 1, lsb = m - fmt.sqrt_bits;
    if (exhaustive) {
        for (uint64_t r = 0; r <= mask_bits(2 * w); r++) vec_sqrt(r);
        return;
    }
    const uint64_t top = UINT64_C(1) << (2 * m); /* 2^(2W-2) */
    uint64_t base[] = { 0, 1, 2, 3, 4, 5, 8, 9, 15, 16, 17, top - 1, top, top + 1, top - 2,
                        mask_bits(2 * w), mask_bits(2 * w) - 1, top * 2, top * 2 - 1, top * 2 + 1,
                        top * 3, top * 3 - 1, top / 2, top / 4, top / 4 - 1, top / 4 + 1 };
    for (size_t i = 0; i < sizeof base / sizeof base[0]; i++) vec_sqrt(base[i]);
    /* Around squares, around rounding ties (r + half LSB)^2, and the saturation edge. */
    for (int i = 0; i < 400; i++) {
        uint64_t r = (i < 4) ? ((UINT64_C(1) << m) - 1 - (uint64_t)i) : rng() >> (64 - m + (i % m));
        uint64_t sq = r * r;
        vec_sqrt(sq); vec_sqrt(sq - 1); vec_sqrt(sq + 1); vec_sqrt(sq + r); vec_sqrt(sq + r + 1);
        uint64_t rl = (r >> lsb) << lsb;
        if (lsb > 0) {
            uint64_t t = rl + (UINT64_C(1) << (lsb - 1));
            if (t < (UINT64_C(1) << m)) { vec_sqrt(t * t); vec_sqrt(t * t - 1); vec_sqrt(t * t + 1); }
        }
    }
    if (lsb > 0) {
        uint64_t edge = (UINT64_C(1) << m) - (UINT64_C(1) << (lsb - 1));
        vec_sqrt(edge * edge); vec_sqrt(edge * edge - 1); vec_sqrt(edge * edge + 1);
    } else {
        uint64_t edge = top - (UINT64_C(1) << m);
        vec_sqrt(edge); vec_sqrt(edge + 1); vec_sqrt(edge - 1);
    }
    for (int i = 0; i < N_RANDOM; i++) {
        uint64_t r = rng();
        switch (i % 4) {
        case 0: vec_sqrt(r); break;                                  /* mostly saturating */
        case 1: vec_sqrt(r >> (64 - 2 * m)); break;                  /* in range */
        case 2: vec_sqrt(r >> (64 - 2 * m + (int)(rng() % (uint64_t)(2 * m)))); break; /* log-uniform */
        default: {                                                   /* a real length */
            fx_t dx = sext(rand_w()), dy = sext(rand_w()), dz = (i & 4) ? sext(rand_w()) : 0;
            vec_sqrt(fx_sumsq(dx, dy, dz));
        }
        }
    }
}

static void gen_div(int exhaustive)
{
    const int w = fmt.width, f = fmt.frac, m = w - 1, lsb = m - fmt.div_bits;
    if (exhaustive) {
        for (uint64_t n = 0; n <= wmask(); n++)
            for (uint64_t d = 0; d <= wmask(); d++) vec_div(n, d);
        return;
    }
    uint64_t e[64];
    int n = unsigned_edges(e);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) vec_div(e[i], e[j]);
    for (int i = 0; i < 400; i++) {
        /* Dividends at the overflow edge: num * 2^F = den * 2^m exactly, and around it. */
        uint64_t d = rand_w() >> f;
        uint64_t nn = d << (m - f);
        if (nn <= wmask()) { vec_div(nn, d); vec_div(nn - 1, d); vec_div(nn + 1, d); vec_div(nn, d + 1); }
        /* Rounding ties: num * 2^F = den * (2Q + 1) * 2^(lsb - 1). */
        const int s = (f + 1 - lsb) > 0 ? f + 1 - lsb : 0;
        const int ex = s + lsb - 1 - f;
        uint64_t r = (rng() >> (40 + (i % 20))) | 1, q = rng() >> (44 + (i % 20));
        uint64_t den = r << s, num = (r * (2 * q + 1)) << ex;
        if (lsb == 0) { den = r << (f + 1); num = r * (2 * q + 1); }
        if (den && den <= wmask() && num + 1 <= wmask() && num > 0) {
            vec_div(num, den); vec_div(num - 1, den); vec_div(num + 1, den);
        }
    }
    for (int i = 0; i < N_RANDOM; i++) vec_div(rand_w(), (i % 64) ? rand_w() : 0);
}

int main(int argc, char **argv)
{
    if (argc != 7) die("usage: gen_vectors add|mul|avg|sqrt|div exhaustive|random W F BITS OUT.hex");
    const char *unit = argv[1];
    int exhaustive;
    if (!strcmp(argv[2], "exhaustive")) exhaustive = 1;
    else if (!strcmp(argv[2], "random")) exhaustive = 0;
    else die("MODE must be exhaustive or random");
    fmt.width = atoi(argv[3]);
    fmt.frac = atoi(argv[4]);
    fmt.sqrt_bits = fmt.div_bits = atoi(argv[5]);
    const char *bad = fx_format_check(&fmt);
    if (bad) die(bad);
    if (exhaustive && fmt.width > 12) die("exhaustive vectors are for W <= 12");
    digits = (fmt.width + 3) / 4;
    rad_digits = (2 * fmt.width + 3) / 4;
    out = fopen(argv[6], "w");
    if (!out) die("cannot open output file");
    if (!strcmp(unit, "add") || !strcmp(unit, "mul") || !strcmp(unit, "avg")) gen_binary(unit, exhaustive);
    else if (!strcmp(unit, "sqrt")) gen_sqrt(exhaustive);
    else if (!strcmp(unit, "div")) gen_div(exhaustive);
    else die("unknown unit");
    if (fclose(out)) die("write failed");
    printf("%ld\n", count);
    return 0;
}
