/*
 * gen_vectors - test vectors for the RTL arithmetic units, computed by model/fixed.c,
 * and for the datapaths toward and spring_force, computed by the frame engine.
 *
 * usage: gen_vectors UNIT MODE W F BITS OUT.hex
 *        gen_vectors UNIT random W F SQRT_BITS DIV_BITS [DIM] OUT.hex   (toward, spring; DIM 2 or 3, default 2)
 *   UNIT  add | mul | avg | sqrt | div, and, when built with -DGEN_DATAPATHS (linked
 *         with model/engine_fixed.c, model/scene.c and libinih), toward | toward_pipe
 *         (the same vectors; its latency file is toward_pipe.v's) | spring | spring_pipe (likewise)
 *   MODE  exhaustive (every operand pair, every radicand; meant for W = 8)
 *         random     (every pair of edge values, targeted cases, and random
 *                     operands from a fixed seed; the only mode of toward, spring)
 *   W, F  the format; BITS is SQRT_BITS for sqrt, DIV_BITS for div (ignored else);
 *         toward and spring take both, or one BITS for both
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
 *     toward flags {0, 0, excess, valid}  p_x, p_y, p_z, c_x, c_y, c_z, rest, t_x, t_y, t_z
 *     spring flags {0, 0, 0, valid}  a_x, a_y, a_z, a_px, a_py, a_pz, b_x, b_y, b_z,
 *                                    b_px, b_py, b_pz, rest, ks, kd, f_x, f_y, f_z
 *   (toward, spring: the outputs are 0 when valid = 0; the RTL's are then unused.
 *   In 2D every z field is 0.
 *   The expected values come from the frame engine itself, see GEN_DATAPATHS below.)
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

#ifdef GEN_DATAPATHS
#include "../model/sim.h"
#include "../model/hwgen.h"

/*
 * rtl/toward.v and rtl/spring_force.v: the expected values come from the frame
 * engine's own code (model/engine_body.h through engine_fixed.c), on a two-node
 * graph body (node 0, node 1, edge 0 -> 1) of dim 2 or 3 set up by sim_fx_init on
 * an in-memory scene. Each vector writes its raw inputs into the engine's state and calls:
 *   toward, excess = 0: sim_fx_centred_node(s, 1) with pos[0] = P, pos[1] = C and
 *       dist = rest. Node 1 has no lower neighbour, so it moves to the point
 *       toward(0 -> 1) = P + d * fx_div(rest, |d|); it returns valid.
 *   toward, excess = 1: sim_fx_pair_edge(s, 0) with pos[0] = P (end a), pos[1] = C
 *       (end b) and rest[0] = rest, twice: with b pinned, a' = fx_add(P, e); with a
 *       pinned, b' = fx_sub(C, e). Either gives the excess e back exactly unless it
 *       saturated; when both saturated, e is taken from the composition below, which
 *       must reproduce both a' and b'. `skipped` counts a zero length (valid = 0).
 *   spring: sim_fx_spring_edge(s, 0) with every acc zeroed, so acc[0] = fx_add(0, F)
 *       = F exactly, and acc[1] = fx_sub(0, F); `skipped` counts coincident ends.
 * Every toward vector is also composed from fixed.h in the order rtl/toward.v's
 * header states (d = C - P, len = fx_sqrt(sumsq), r = fx_div(rest, len), then
 * fx_add(P, fx_mul(d, r)) or fx_sub(d, fx_mul(d, r))); the generator stops if the
 * composition and the engine disagree.
 * Inputs are raw W-bit values; rest lengths are kept in 0..fx_max (the engine
 * holds them as signed values). Records always carry three lanes (x, y, z); in 2D
 * the z inputs and outputs are 0.
 *
 * The square root's radicand is the exact sum of the squares of d: a sum of two
 * squares is never 3, 6 or 7 modulo 8, a sum of three never 7 (Legendre). Every
 * radicand class modulo 8 the dimension reaches is drawn on purpose at every
 * magnitude, and the generator stops if a reachable class is missing from the vectors.
 */
static int dim = 2;
static int pipe_steps = 1; /* toward_pipe, spring_pipe: STEPS (their latency only) */
static scene dp_sc;
static sim_fx dp_s;
static double dp_pos[2][3], dp_prev[2][3];
static bool dp_pinned[2];
static scene_edge dp_edge;
static long rad_class[8];   /* vectors per radicand class modulo 8 */

static void dp_init(edge_kind kind)
{
    memset(&dp_sc, 0, sizeof dp_sc);
    dp_sc.dim = dim;
    dp_sc.number = NUMBER_FIXED;
    dp_sc.fmt = fmt;
    dp_sc.dt = 1;
    dp_sc.frames = 1;
    dp_sc.substeps = 1;
    dp_sc.iterations = 1;
    dp_sc.integrator = INTEGRATOR_VERLET;
    dp_sc.body = BODY_GRAPH;
    dp_sc.units = 1;
    dp_sc.nodes_per_unit = 2;
    dp_sc.n_nodes = 2;
    dp_sc.pos = dp_pos;
    dp_sc.prev = dp_prev;
    dp_sc.pinned = dp_pinned;
    dp_sc.mass = 1;
    dp_edge = (scene_edge){0, 1, kind, 0.0, 0, 0, 0};
    dp_sc.n_edges = 1;
    dp_sc.edges = &dp_edge;
    dp_sc.en_constraints = kind != EDGE_SPRING;
    dp_sc.en_springs = kind == EDGE_SPRING;
    dp_sc.rule = RULE_PAIRWISE;
    if (!sim_fx_init(&dp_s, &dp_sc, &fmt)) die("sim_fx_init failed");
}

static void dp_node(int i, const fx_t x[3], const fx_t px[3])
{
    for (int k = 0; k < 3; k++) {
        dp_s.pos[i][k] = k < dim ? x[k] : 0;
        dp_s.prev[i][k] = k < dim ? px[k] : 0;
        dp_s.acc[i][k] = 0;
    }
}

/* The radicand of a difference, as the datapaths form it (saturating C - P per lane). */
static void count_radicand(const fx_t a[3], const fx_t b[3])
{
    fx_t d[3] = {0, 0, 0};
    for (int k = 0; k < dim; k++) d[k] = fx_sub(&fmt, b[k], a[k]);
    rad_class[fx_sumsq(d[0], d[1], d[2]) % 8]++;
}

/* Every class modulo 8 a sum of `dim` squares reaches must have vectors. */
static void check_radicand_classes(void)
{
    for (int r = 0; r < 8; r++) {
        int reachable = dim == 3 ? r != 7 : r != 3 && r != 6 && r != 7;
        if (reachable && rad_class[r] == 0) {
            char msg[80];
            snprintf(msg, sizeof msg, "no vector has a radicand of %d modulo 8", r);
            die(msg);
        }
        if (!reachable && rad_class[r] != 0) die("a radicand class no sum of squares reaches: the radicand is miscounted");
    }
}

static fx_t rest_w(void) { return (fx_t)(rng() & (uint64_t)fx_max(&fmt)) >> (rng() % (uint64_t)fmt.width); }

/* Random vectors at W <= 16 are twice as many as above: the wide datapaths
   simulate slowly (about 70 and 110 cycles per vector at W = 32). */
static int dp_scale(void) { return fmt.width > 16 ? 1 : 2; }

/* a + b wrapped to W bits (inputs only: any W-bit value is a valid input). */
static fx_t addw(fx_t a, fx_t b) { return sext((uint64_t)((int64_t)a + b)); }

/* A coordinate: log-uniform magnitude half of the time, any sign. */
static fx_t coord(void) { return sext(rand_w()); }

/* A value of about `mag` (>= 1) or less, either sign. */
static fx_t near(fx_t mag)
{
    fx_t v = (fx_t)(rng() % (uint64_t)mag);
    return (rng() & 1) ? -v : v;
}

/* A difference d (|d[k]| < 2^bits) whose sum of squares is `cls` modulo 8: drawn until one is. */
static bool diff_of_class(int bits, int cls, fx_t d[3])
{
    for (int tries = 0; tries < 4096; tries++) {
        for (int k = 0; k < 3; k++) d[k] = k < dim ? near((fx_t)1 << bits) : 0;
        if ((int)(fx_sumsq(d[0], d[1], d[2]) % 8) == cls) return true;
    }
    return false;
}

/* ---- toward ---- */
static void vec_toward(const fx_t p[3], const fx_t c[3], fx_t rest, int excess)
{
    fx_t d[3] = {0, 0, 0}, comp[3] = {0, 0, 0}, t[3] = {0, 0, 0};
    bool dz = false;
    int valid;
    if (rest < 0) die("toward: negative rest length");
    for (int k = 0; k < 3; k++)
        if (p[k] < fx_min(&fmt) || p[k] > fx_max(&fmt) || c[k] < fx_min(&fmt) || c[k] > fx_max(&fmt))
            die("toward: an input outside the format");
    count_radicand(p, c);
    /* composed in rtl/toward.v's order: t = d r, or with a mantissa fx_along's t */
    for (int k = 0; k < dim; k++) d[k] = fx_sub(&fmt, c[k], p[k]);
    fx_t tv[3];
    if (fmt.mantissa) {
        dz = !fx_along(&fmt, dim, d, rest, tv);
    } else {
        fx_t r = fx_div(&fmt, (uint32_t)rest, (uint32_t)fx_sqrt(&fmt, fx_sumsq(d[0], d[1], d[2])), &dz);
        for (int k = 0; k < dim; k++) tv[k] = fx_mul(&fmt, d[k], r);
    }
    for (int k = 0; k < dim; k++)
        comp[k] = excess ? fx_sub(&fmt, d[k], tv[k]) : fx_add(&fmt, p[k], tv[k]);
    /* the engine */
    if (!excess) {
        dp_pinned[0] = dp_pinned[1] = false;
        dp_s.dist = rest;
        dp_node(0, p, p);
        dp_node(1, c, c);
        dp_s.skipped = 0;
        valid = sim_fx_centred_node(&dp_s, 1);
        if (valid != (dp_s.skipped == 0)) die("toward: centred_node result and skipped count disagree");
        for (int k = 0; k < dim; k++) {
            if (!valid && dp_s.pos[1][k] != c[k]) die("toward: centred_node moved a node with no direction");
            if (valid) t[k] = dp_s.pos[1][k];
        }
    } else {
        fx_t a1[3], b2[3];
        int valid2;
        dp_s.rest[0] = rest;
        dp_pinned[0] = false; dp_pinned[1] = true;   /* b fixed: a += e */
        dp_node(0, p, p);
        dp_node(1, c, c);
        dp_s.skipped = 0;
        sim_fx_pair_edge(&dp_s, 0);
        valid = dp_s.skipped == 0;
        for (int k = 0; k < dim; k++) a1[k] = dp_s.pos[0][k];
        dp_pinned[0] = true; dp_pinned[1] = false;   /* a fixed: b -= e */
        dp_node(0, p, p);
        dp_node(1, c, c);
        dp_s.skipped = 0;
        sim_fx_pair_edge(&dp_s, 0);
        valid2 = dp_s.skipped == 0;
        for (int k = 0; k < dim; k++) b2[k] = dp_s.pos[1][k];
        dp_pinned[0] = dp_pinned[1] = false;
        if (valid != valid2) die("toward: pair_edge zero length depends on which end is fixed");
        for (int k = 0; k < dim && valid; k++) {
            fx_t e;
            if (a1[k] > fx_min(&fmt) && a1[k] < fx_max(&fmt)) e = a1[k] - p[k];
            else if (b2[k] > fx_min(&fmt) && b2[k] < fx_max(&fmt)) e = c[k] - b2[k];
            else e = comp[k];
            if (fx_add(&fmt, p[k], e) != a1[k] || fx_sub(&fmt, c[k], e) != b2[k]) die("toward: excess not recovered from pair_edge");
            t[k] = e;
        }
        for (int k = 0; k < dim && !valid; k++)
            if (a1[k] != p[k] || b2[k] != c[k]) die("toward: pair_edge moved a node with no direction");
    }
    if (valid != !dz) die("toward: engine and composition disagree on the zero length");
    for (int k = 0; k < dim; k++)
        if (valid && t[k] != comp[k]) die("toward: engine and rtl/toward.v's order of operations disagree");
    rec_begin((unsigned)(excess << 1 | valid));
    for (int k = 0; k < 3; k++) put(digits, (uint64_t)(k < dim ? p[k] : 0));
    for (int k = 0; k < 3; k++) put(digits, (uint64_t)(k < dim ? c[k] : 0));
    put(digits, (uint64_t)rest);
    for (int k = 0; k < 3; k++) put(digits, (uint64_t)t[k]);
    rec_end();
}

static void vec_toward2(const fx_t p[3], const fx_t c[3], fx_t rest)
{
    vec_toward(p, c, rest, 0);
    vec_toward(p, c, rest, 1);
}

static void gen_toward(void)
{
    const fx_t max = fx_max(&fmt), min = fx_min(&fmt), one = fx_one(&fmt);
    const fx_t lim[] = {min, -1, 0, 1, max};
    const fx_t rests[] = {0, 1, one, max, one / 2 + 1, fx_sat(&fmt, 3 * (int64_t)one)};
    fx_t p[3], c[3];
    int i = 0;
    /* Coordinates at the range limits: saturating differences, both rules (z: a limit by turn). */
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            for (int cc = 0; cc < 5; cc++)
                for (int d = 0; d < 5; d++, i++) {
                    p[0] = lim[a]; p[1] = lim[b]; p[2] = lim[(a + d + i / 25) % 5];
                    c[0] = lim[cc]; c[1] = lim[d]; c[2] = lim[(b + cc + i / 5) % 5];
                    vec_toward(p, c, (i % 7 == 6) ? rest_w() : rests[i % 6], i & 1);
                }
    /* Zero length: C = P, at the corners and anywhere. */
    for (i = 0; i < 40; i++) {
        p[0] = i < 8 ? ((i & 1) ? max : min) : coord();
        p[1] = i < 8 ? ((i & 2) ? max : min) : coord();
        p[2] = i < 8 ? ((i & 4) ? max : min) : coord();
        vec_toward2(p, p, (i % 3) ? rest_w() : rests[i % 6]);
    }
    /* Short differences, every sign (a length of a few LSBs, maybe rounded to 0). */
    for (int dx = -3; dx <= 3; dx++)
        for (int dy = -3; dy <= 3; dy++)
            for (int dzz = (dim == 3 ? -3 : 0); dzz <= (dim == 3 ? 3 : 0); dzz += 2, i++) {
                for (int k = 0; k < 3; k++) p[k] = near(max / 2);
                c[0] = addw(p[0], dx); c[1] = addw(p[1], dy); c[2] = addw(p[2], dzz);
                vec_toward2(p, c, rests[i % 6]);
            }
    /* Along the axes, negative and positive, every magnitude. */
    for (i = 0; i < fmt.width - 1; i++) {
        fx_t m = (fx_t)1 << i;
        for (int ax = 0; ax < dim; ax++)
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                for (int k = 0; k < 3; k++) p[k] = near(max / 4);
                for (int k = 0; k < 3; k++) c[k] = p[k];
                c[ax] = addw(p[ax], sgn * m);
                vec_toward(p, c, sgn < 0 ? rest_w() : rests[i % 6], (i + ax) & 1);
            }
    }
    /* Every radicand class modulo 8 the dimension reaches, at every magnitude of d. */
    for (int bits = 1; bits < fmt.width - 1; bits++)
        for (int cls = 0; cls < 8; cls++) {
            fx_t d[3];
            if (!diff_of_class(bits, cls, d)) continue;   /* unreachable in this dimension */
            for (int k = 0; k < 3; k++) {
                p[k] = near(max / 2);
                c[k] = addw(p[k], d[k]);
            }
            vec_toward(p, c, (bits + cls) % 3 ? rest_w() : rests[cls % 6], (bits + cls) & 1);
        }
    /* Rest length equal to the length (excess about 0), and rest 0 (T = P, e = d). */
    for (i = 0; i < 100; i++) {
        fx_t d[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) {
            p[k] = near(max / 2);
            c[k] = addw(p[k], near(max / 2));
            if (k < dim) d[k] = fx_sub(&fmt, c[k], p[k]);
        }
        fx_t len = fx_sqrt(&fmt, fx_sumsq(d[0], d[1], d[2]));
        vec_toward(p, c, len, i & 1);
        vec_toward(p, c, 0, !(i & 1));
    }
    /* A rope: points about one unit apart, rest about one unit. */
    for (i = 0; i < 400 * dp_scale(); i++) {
        for (int k = 0; k < 3; k++) {
            p[k] = near(max / 2);
            c[k] = addw(p[k], near(2 * one));
        }
        vec_toward(p, c, one / 2 + (fx_t)(rng() % (uint64_t)one), i & 1);
    }
    /* Anything. */
    for (i = 0; i < 800 * dp_scale(); i++) {
        for (int k = 0; k < 3; k++) {
            p[k] = coord();
            c[k] = coord();
        }
        vec_toward(p, c, rest_w(), i & 1);
    }
    check_radicand_classes();
}

/* ---- spring ---- */
/* v: a[3], a_prev[3], b[3], b_prev[3], rest, ks, kd (lanes beyond dim unused: 0) */
enum { SA = 0, SAP = 3, SB = 6, SBP = 9, SREST = 12, SKS = 13, SKD = 14, SN = 15 };

static void vec_spring(fx_t v[SN])
{
    fx_t f[3] = {0, 0, 0};
    int valid;
    for (int k = dim; k < 3; k++) v[SA + k] = v[SAP + k] = v[SB + k] = v[SBP + k] = 0;
    if (v[SREST] < 0) die("spring: negative rest length");
    for (int k = 0; k < SN; k++)
        if (v[k] < fx_min(&fmt) || v[k] > fx_max(&fmt)) die("spring: an input outside the format");
    count_radicand(&v[SA], &v[SB]);
    dp_node(0, &v[SA], &v[SAP]);
    dp_node(1, &v[SB], &v[SBP]);
    dp_s.rest[0] = v[SREST];
    dp_s.ks = v[SKS];
    dp_s.kd = v[SKD];
    dp_s.skipped = 0;
    sim_fx_spring_edge(&dp_s, 0);
    valid = dp_s.skipped == 0;
    for (int k = 0; k < dim; k++) {
        if (dp_s.acc[1][k] != fx_sub(&fmt, 0, dp_s.acc[0][k])) die("spring: B does not take -F");
        if (!valid && dp_s.acc[0][k] != 0) die("spring: a force with coincident ends");
        f[k] = dp_s.acc[0][k];
    }
    rec_begin((unsigned)valid);
    for (int k = 0; k < SN; k++) put(digits, (uint64_t)v[k]);
    for (int k = 0; k < 3; k++) put(digits, (uint64_t)f[k]);
    rec_end();
}

static void gen_spring(void)
{
    const fx_t max = fx_max(&fmt), min = fx_min(&fmt), one = fx_one(&fmt);
    const fx_t lim[] = {min, -1, 0, 1, max};
    const fx_t rests[] = {0, 1, one, max, fx_sat(&fmt, 3 * (int64_t)one)};
    const fx_t ks_edge[] = {max, max - 1, min, one, one / 16 + 1, -1, 0};
    const fx_t kd_edge[] = {0, max, min, one / 4, 1, -one};
    fx_t v[SN];
    int i = 0;
    /* Ends at the range limits (saturating d), velocities 0, saturating or random. */
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 5; b++)
            for (int c = 0; c < 5; c++)
                for (int d = 0; d < 5; d++, i++) {
                    v[SA] = lim[a]; v[SA + 1] = lim[b]; v[SA + 2] = lim[(a + d + i / 25) % 5];
                    v[SB] = lim[c]; v[SB + 1] = lim[d]; v[SB + 2] = lim[(b + c + i / 5) % 5];
                    for (int k = 0; k < 3; k++) {
                        int j = (i / 3 + k) % 3;
                        v[SAP + k] = j == 0 ? v[SA + k] : j == 1 ? (v[SA + k] < 0 ? max : min) : coord();
                        v[SBP + k] = j == 0 ? v[SB + k] : j == 1 ? (v[SB + k] < 0 ? max : min) : coord();
                    }
                    v[SREST] = (i % 6 == 5) ? rest_w() : rests[i % 5];
                    v[SKS] = ks_edge[i % 7];
                    v[SKD] = kd_edge[i % 6];
                    vec_spring(v);
                }
    /* Coincident ends, moving or not. */
    for (i = 0; i < 60; i++) {
        for (int k = 0; k < 3; k++) {
            v[SA + k] = v[SB + k] = i < 8 ? ((i >> k & 1) ? max : min) : coord();
            v[SAP + k] = (i & 4) ? v[SA + k] : coord();
            v[SBP + k] = (i & 8) ? v[SB + k] : coord();
        }
        v[SREST] = rests[i % 5]; v[SKS] = ks_edge[i % 7]; v[SKD] = kd_edge[i % 6];
        vec_spring(v);
    }
    /* Short differences, every sign. */
    for (int dx = -3; dx <= 3; dx++)
        for (int dy = -3; dy <= 3; dy++)
            for (int r = 0; r < 2; r++, i++) {
                const int dzz = dim == 3 ? (int)(rng() % 7) - 3 : 0;
                for (int k = 0; k < 3; k++) v[SA + k] = near(max / 2);
                v[SB] = addw(v[SA], dx); v[SB + 1] = addw(v[SA + 1], dy); v[SB + 2] = addw(v[SA + 2], dzz);
                for (int k = 0; k < 3; k++) {
                    v[SAP + k] = addw(v[SA + k], near(one));
                    v[SBP + k] = addw(v[SB + k], near(one));
                }
                v[SREST] = rests[i % 5]; v[SKS] = ks_edge[i % 7]; v[SKD] = kd_edge[i % 6];
                vec_spring(v);
            }
    /* Every radicand class modulo 8 the dimension reaches, at every magnitude of d. */
    for (int bits = 1; bits < fmt.width - 1; bits++)
        for (int cls = 0; cls < 8; cls++) {
            fx_t d[3];
            if (!diff_of_class(bits, cls, d)) continue;   /* unreachable in this dimension */
            for (int k = 0; k < 3; k++) {
                v[SA + k] = near(max / 2);
                v[SB + k] = addw(v[SA + k], d[k]);
                v[SAP + k] = addw(v[SA + k], near(one));
                v[SBP + k] = addw(v[SB + k], near(one));
            }
            v[SREST] = rest_w(); v[SKS] = (fx_t)(rng() % (uint64_t)one); v[SKD] = kd_edge[(bits + cls) % 6];
            vec_spring(v);
        }
    /* Saturating velocities and velocity differences. */
    for (i = 0; i < 120; i++) {
        for (int k = 0; k < 3; k++) {
            v[SA + k] = coord(); v[SB + k] = coord();
            v[SAP + k] = (i & 1) ? (v[SA + k] < 0 ? max : min) : addw(v[SA + k], near(one));
            v[SBP + k] = (i & 2) ? (v[SB + k] < 0 ? max : min) : addw(v[SB + k], near(one));
            if (i & 4) { v[SA + k] = max; v[SAP + k] = min + (fx_t)(rng() % 4); v[SB + k] = min; v[SBP + k] = max - (fx_t)(rng() % 4); }
        }
        v[SREST] = rest_w(); v[SKS] = (i & 8) ? ks_edge[i % 7] : coord(); v[SKD] = (i & 16) ? kd_edge[i % 6] : coord();
        vec_spring(v);
    }
    /* Rest length 0 and the rest length equal to the length, large constants. */
    for (i = 0; i < 200; i++) {
        fx_t d[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) {
            v[SA + k] = near(max / 2); v[SB + k] = addw(v[SA + k], near(max / 2));
            v[SAP + k] = addw(v[SA + k], near(one)); v[SBP + k] = addw(v[SB + k], near(one));
            if (k < dim) d[k] = fx_sub(&fmt, v[SB + k], v[SA + k]);
        }
        v[SREST] = (i & 1) ? 0 : fx_sqrt(&fmt, fx_sumsq(d[0], d[1], d[2]));
        v[SKS] = (i & 2) ? ks_edge[i % 7] : (fx_t)(rng() % (uint64_t)max);
        v[SKD] = (i & 4) ? kd_edge[i % 6] : (fx_t)(rng() % (uint64_t)max);
        vec_spring(v);
    }
    /* A spring rope: ends about one unit apart, slow, ks and kd below one. */
    for (i = 0; i < 350 * dp_scale(); i++) {
        for (int k = 0; k < 3; k++) {
            v[SA + k] = near(max / 2); v[SB + k] = addw(v[SA + k], near(2 * one));
            v[SAP + k] = addw(v[SA + k], near(one / 8 + 1)); v[SBP + k] = addw(v[SB + k], near(one / 8 + 1));
        }
        v[SREST] = one / 2 + (fx_t)(rng() % (uint64_t)one);
        v[SKS] = (fx_t)(rng() % (uint64_t)one);
        v[SKD] = (fx_t)(rng() % (uint64_t)(one / 2));
        vec_spring(v);
    }
    /* Anything. */
    for (i = 0; i < 600 * dp_scale(); i++) {
        for (int k = 0; k < SN; k++) v[k] = coord();
        v[SREST] = rest_w();
        vec_spring(v);
    }
    check_radicand_classes();
}
#endif

int main(int argc, char **argv)
{
    if (argc < 7 || argc > 11)
        die("usage: gen_vectors add|mul|avg|sqrt|div|toward|toward_pipe|spring|spring_pipe exhaustive|random W F BITS [DIV_BITS [DIM [STEPS [MANTISSA]]]] OUT.hex");
    const char *unit = argv[1];
    const int datapath = !strcmp(unit, "toward") || !strcmp(unit, "toward_pipe") || !strcmp(unit, "spring") || !strcmp(unit, "spring_pipe");
    if (argc >= 8 && !datapath) die("SQRT_BITS and DIV_BITS apart are for toward and spring");
    int exhaustive;
    if (!strcmp(argv[2], "exhaustive")) exhaustive = 1;
    else if (!strcmp(argv[2], "random")) exhaustive = 0;
    else die("MODE must be exhaustive or random");
    fmt.width = atoi(argv[3]);
    fmt.frac = atoi(argv[4]);
    fmt.sqrt_bits = fmt.div_bits = atoi(argv[5]);
    if (argc >= 8) fmt.div_bits = atoi(argv[6]);
#ifdef GEN_DATAPATHS
    if (argc >= 9) dim = atoi(argv[7]);
    if (dim != 2 && dim != 3) die("DIM must be 2 or 3");
    if (argc >= 10) pipe_steps = atoi(argv[8]);
    if (argc == 11) fmt.mantissa = atoi(argv[9]);
    if (pipe_steps < 1 || pipe_steps > 4) die("STEPS must be 1..4");
#endif
    const char *bad = fx_format_check(&fmt);
    if (bad) die(bad);
    if (exhaustive && fmt.width > 12) die("exhaustive vectors are for W <= 12");
    if (exhaustive && datapath) die("toward and spring have random vectors only");
    digits = (fmt.width + 3) / 4;
    rad_digits = (2 * fmt.width + 3) / 4;
    out = fopen(argv[argc - 1], "w");
    if (!out) die("cannot open output file");
    if (!strcmp(unit, "add") || !strcmp(unit, "mul") || !strcmp(unit, "avg")) gen_binary(unit, exhaustive);
    else if (!strcmp(unit, "sqrt")) gen_sqrt(exhaustive);
    else if (!strcmp(unit, "div")) gen_div(exhaustive);
#ifdef GEN_DATAPATHS
    else if (!strcmp(unit, "toward") || !strcmp(unit, "toward_pipe")) { dp_init(EDGE_ROD); gen_toward(); sim_fx_free(&dp_s); }
    else if (!strcmp(unit, "spring") || !strcmp(unit, "spring_pipe")) { dp_init(EDGE_SPRING); gen_spring(); sim_fx_free(&dp_s); }
#endif
    else die("unknown unit");
    if (fclose(out)) die("write failed");
#ifdef GEN_DATAPATHS
    if (datapath) { /* OUT.hex.latency: the datapath's latency, from the one formula (model/timing.c) */
        hw_params hp;
        memset(&hp, 0, sizeof hp);
        hp.dim = dim;
        hp.sqrt_bits = fmt.sqrt_bits;
        hp.div_bits = fmt.div_bits;
        hp.pipe_steps = pipe_steps; /* the pipes' root and divide iterations a stage */
        hp.mantissa = fmt.mantissa;
        char path[1024];
        snprintf(path, sizeof path, "%s.latency", argv[argc - 1]);
        FILE *lf = fopen(path, "w");
        long latency = !strcmp(unit, "toward") ? hw_toward_latency(&hp) : !strcmp(unit, "toward_pipe") ? hw_toward_pipe_latency(&hp)
                     : !strcmp(unit, "spring_pipe") ? hw_spring_pipe_latency(&hp) : hw_spring_latency(&hp);
        if (!lf || fprintf(lf, "%ld\n", latency) < 0 || fclose(lf))
            die("cannot write the latency file");
    }
#endif
    printf("%ld\n", count);
    return 0;
}
