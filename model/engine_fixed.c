/* engine_fixed.c - the frame engine in Strand's fixed-point arithmetic (bit-exact with the RTL). */
#include <stdlib.h>
#include <string.h>

#include "fixed.h"
#include "sim.h"

#define SIM sim_fx
#define P(name) sim_fx_##name
#define NUM fx_t
#define F_ (&s->fmt)
#define ADD(a, b) fx_add(F_, (a), (b))
#define SUB(a, b) fx_sub(F_, (a), (b))
#define MUL(a, b) fx_mul(F_, (a), (b))
#define AVG(a, b) fx_avg(F_, (a), (b))
#define HALF(a) fx_half(F_, (a))
#define ABS(a) ((a) < 0 ? fx_neg(F_, (a)) : (a))
#define LEN(d) fx_sqrt(F_, fx_sumsq((d)[0], (d)[1], (d)[2]))
#define DIV(a, b, dz) fx_div(F_, (uint32_t)(a), (uint32_t)(b), (dz))
#define SDIV(a, b, dz) fx_div_signed(F_, (a), (b), (dz))
#define UNIT(a, b, dz) fx_unit_div(F_, (a), (b), (dz))
#define UMUL(a, u) fx_mul_unit(F_, (a), (u))
#define LEG(h, d, miss) fx_leg(F_, (h), (d)[0], (d)[1], (d)[2], (miss))
#define FROM(x) fx_from_double(F_, (x))
#define LESS(a, b) ((a) < (b))
#define MAC2(a, b, c, d) fx_mac2(F_, (a), (b), (c), (d))
#define ALONG(d, rest, t) along(s, (d), (rest), (t))
#define SPRING_DIR(d, len, u) spring_dir(s, (d), (len), (u))
#define UNITDIR(r, u) unit_dir(s, (r), (u))
#define DIRMUL(a, u) (s->fmt.mantissa ? fx_mul_unit(F_, (a), (u)) : fx_mul(F_, (a), (u)))

/* t = d rest / |d|: the full-width root, divide and products, or the normalised datapath */
static bool along(const sim_fx *s, const fx_t d[3], fx_t rest, fx_t t[3])
{
    bool zero;
    fx_t ratio;
    if (s->fmt.mantissa) return fx_along(&s->fmt, s->dim, d, rest, t);
    ratio = DIV(rest, LEN(d), &zero);
    for (int k = 0; k < 3; k++) t[k] = k < s->dim ? MUL(d[k], ratio) : 0;
    return !zero;
}

/* the unit vector along r in Q2.(W-2): the full-width root and unit divides, or fx_along of length 2^(W-2) */
static bool unit_dir(const sim_fx *s, const fx_t r[3], fx_t u[3])
{
    bool zero;
    fx_t len;
    if (s->fmt.mantissa) return fx_along(&s->fmt, s->dim, r, (fx_t)(INT64_C(1) << (s->fmt.width - 2)), u);
    len = LEN(r);
    for (int k = 0; k < 3; k++) u[k] = 0;
    if (!(len > 0)) return false;
    for (int k = 0; k < s->dim; k++) u[k] = UNIT(r[k], len, &zero);
    return true;
}

/* a spring's length and unit vector: the full-width root and divides (u in Q.F), or fx_spring_dir */
static bool spring_dir(const sim_fx *s, const fx_t d[3], fx_t *len, fx_t u[3])
{
    bool zero;
    if (s->fmt.mantissa) return fx_spring_dir(&s->fmt, s->dim, d, len, u);
    *len = LEN(d);
    for (int k = 0; k < 3; k++) u[k] = 0;
    if (!(*len > 0)) return false;
    for (int k = 0; k < s->dim; k++) u[k] = SDIV(d[k], *len, &zero);
    return true;
}

#include "engine_body.h"
